// An explicit axisymmetric FE body: mesh + parts (element ranges with one material each) +
// per-element material state (struct of arrays). Updated-Lagrangian, hypoelastic stress update:
//   strain increment at the mid-step configuration x^{n-1/2}, Jaumann rotation in the r-z plane,
//   pressure from the total volume ratio (eps_v = 1 - V/V0) on one value per element
//   (mean dilatation, B-bar), deviator per Gauss point (2x2; selective reduced integration).
// Central differences with lumped (row-sum) mass: v^{n+1/2} = v^{n-1/2} + dt_avg (f_ext - f_int)/m,
// u^{n+1} = u^n + dt v^{n+1/2} (Belytschko, Liu & Moran 2000, Sec. 6.2). Element forces are stored
// per element and gathered per node in ascending element order, so results do not depend on
// the OpenMP thread count. Units: SI; stresses tension positive, pressure compression positive.
#pragma once
#include <vector>

#include "fe/materials.hpp"
#include "fe/mesh.hpp"

namespace kolsky::fe {

/// A contiguous range of elements sharing one material.
struct Part {
  Material material;
  int first_element = 0, n_elements = 0;
};

/// Material state per element (struct of arrays over all elements of the body).
struct ElementState {
  std::vector<double> volume0, volume;  ///< reference and current ring volume (m^3)
  std::vector<double> pressure;         ///< compression + (Pa)
  std::vector<double> eps_max;          ///< largest eps_v reached (compaction history)
  std::vector<double> deviator;         ///< 16 per element: [gauss][rr, zz, tt, rz] (Pa)
  std::vector<double> work;             ///< material work done on the element so far (J)
  std::vector<double> force;            ///< 8 per element: internal force at t^n (N)
  std::vector<double> courant;          ///< courant_length at the last update (m)
};

class Body {
 public:
  /// Validates the materials, builds the incidence, lumps the masses, records V0. threads:
  /// OpenMP threads for the element and gather loops (1 = serial; results are bitwise the same
  /// for any count).
  Body(Mesh mesh, std::vector<Part> parts, int threads);

  Mesh& mesh() { return mesh_; }
  const Mesh& mesh() const { return mesh_; }
  Nodes& nodes() { return mesh_.nodes; }
  const Nodes& nodes() const { return mesh_.nodes; }
  const std::vector<Part>& parts() const { return parts_; }
  const ElementState& state() const { return state_; }

  /// Stresses from the increment u^n - u^{n-1}, internal forces at t^n into nodes().f*_int.
  /// Throws NumericalError when an element inverts (det J <= 0).
  void update_internal_forces();
  /// One central-difference step from t^n with f = f_ext - f_int; mass-proportional damping
  /// c (1/s, 0 for dynamics). The first step is a half step in velocity (v^{1/2} = v^0 + dt a/2).
  void advance(double dt, double mass_damping);

  /// Kinetic energy at t^n of the last advance, sum m v^{n-1/2} v^{n+1/2} / 2 (J).
  double kinetic_energy() const { return kinetic_; }
  double damping_work() const { return damping_work_; }   ///< J dissipated by mass damping
  double material_work() const;                           ///< sum of element work (J)
  /// Complementary energy s:s/(4G) + p^2/(2K) of the LinearElastic parts (J): the stored
  /// elastic energy, a state function for the conservation checks.
  double elastic_energy() const;
  /// Courant bound 0.9 min_e courant_length / c_max, geometry of the last force update (s).
  double stable_dt() const;
  /// Volume-weighted mean axial stress of element e (tension +, Pa).
  double axial_stress(int e) const;
  bool finite() const;
  /// Simulated time, the sum of the steps taken (s).
  double time() const { return time_; }

 private:
  Mesh mesh_;
  std::vector<Part> parts_;
  ElementState state_;
  std::vector<double> part_wave_speed_;
  int threads_ = 1;
  double kinetic_ = 0, damping_work_ = 0, dt_prev_ = 0, time_ = 0;
  bool started_ = false;
};

}  // namespace kolsky::fe
