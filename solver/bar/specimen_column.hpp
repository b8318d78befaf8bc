// 1-D specimen column between the bar faces: lumped-mass two-node elements, central
// differences, uniaxial strain. Two material laws share the column:
//   LinearElastic        sigma = D eps (D: constrained modulus)
//   TabulatedCompaction  loading along a table sigma(eps) (the compaction EOS of Sec. 2.3.4
//                        used as axial stress in 1-D), unloading/reloading along a line of
//                        slope unloading_modulus from the largest strain reached; no tension.
// Coupling (core/specimen_coupling.hpp): the bars own the face nodes; the column receives the
// face intrusions and returns the face forces, the interface every specimen model implements.
#pragma once
#include <variant>
#include <vector>

#include "core/specimen_coupling.hpp"
#include "core/specimen_geometry.hpp"
#include "core/table.hpp"

namespace kolsky::bar {

struct LinearElastic {
  double constrained_modulus = 230e6;  ///< D, Pa
};

struct TabulatedCompaction {
  Table1D loading;                 ///< x: strain (compression +), y: stress (Pa); starts at (0, 0)
  double unloading_modulus = 1e9;  ///< Pa
};

using ColumnMaterial = std::variant<LinearElastic, TabulatedCompaction>;

struct ColumnParams {
  double length = kSpecimenLength;      ///< L_s, m
  double diameter = kSpecimenDiameter;  ///< m
  double density = 1500.0;   ///< kg/m^3
  int n_elements = 100;
  ColumnMaterial material = LinearElastic{};
};

using kolsky::FaceForces;
using kolsky::FaceState;
using kolsky::SpecimenEnergy;

class SpecimenColumn {
 public:
  explicit SpecimenColumn(const ColumnParams& p);

  double area() const { return area_; }
  double length() const { return p_.length; }
  /// Lumped mass of each face node, carried by the bar face DOF (kg).
  double face_mass() const { return 0.5 * element_mass_; }
  /// Courant limit h / c_max for the stiffest tangent of the material (s).
  double stable_dt() const;

  /// Sets the face nodes to the given state at t^n, evaluates element stresses, and returns
  /// the face forces at t^n.
  FaceForces forces(const FaceState& faces);
  /// Advances interior nodes from t^n to t^{n+1} with the forces of the last forces() call.
  void advance(double dt);

  /// Interior kinetic energy at t^n plus internal work; the face nodes' kinetic energy belongs
  /// to the bar face degrees of freedom that carry their mass.
  SpecimenEnergy energy() const;
  /// Engineering strain of the whole column, (intrusion_front + intrusion_back) / L.
  double mean_strain() const;
  const std::vector<double>& element_stress() const { return stress_; }
  const std::vector<double>& element_strain() const { return strain_; }
  /// Largest strain each element has reached (the compaction law's history).
  const std::vector<double>& element_max_strain() const { return max_strain_; }
  /// Largest finite-value check: false if any state is NaN/Inf.
  bool finite() const;

  /// Checkpoint/restart: node and element state (the face nodes included).
  struct State {
    std::vector<double> u, v, strain, stress, max_strain, work;
    double kinetic_interior = 0;
  };
  State save_state() const;
  /// Throws kolsky::InputError ("specimen.state") when the element count differs.
  void restore_state(const State& s);

 private:
  double stress_of(size_t e, double strain) const;
  ColumnParams p_;
  double area_, h_, element_mass_;
  std::vector<double> u_, v_;          // node displacement (+x, from IB to TB) and velocity
  std::vector<double> strain_, stress_, max_strain_;
  std::vector<double> work_;           // internal work per element (J)
  double kinetic_interior_ = 0;
};

}  // namespace kolsky::bar
