// The FE side of the FE-DEM coupling (coupling/fe_dem.hpp, docs/coupling.md): the two meshed
// bars, and optionally a meshed tube, as one explicit axisymmetric FE body with no specimen
// mesh: the space between the bar faces belongs to the DEM grains.
//   Geometry as in MeshedShpb (meshed_shpb.hpp): incident bar z in [-L_I, 0], transmission bar
//   z in [L_s, L_s + L_T], n_r radial Q4 B-bar elements of about element_length axially; the
//   tube r in [R_s, R_s + t], centred on the specimen, free ends; the bars pass freely through
//   it (no bar-tube contact, as in MeshedShpb).
//   Loads at t^n: the applied stress sigma_app(t) (compression +) on the incident far end
//   (ring-area weighted), plus whatever surface loads the coupling adds on the three contact
//   surfaces (incident face, transmission face, tube inner wall) before advance().
//   Energy: kinetic + material work of the body = work of the far-end traction + work of the
//   surface loads (both trapezoid in force over each step's displacement, the pairing central
//   differences conserve). Gauges: the surface axial strain of MeshedShpb. Units: SI.
#pragma once
#include <functional>
#include <optional>
#include <vector>

#include "core/specimen_geometry.hpp"
#include "fe/body.hpp"
#include "fe/fe_specimen.hpp"
#include "fe/meshed_shpb.hpp"

namespace kolsky::fe {

struct MeshedBarsTubeParams {
  MeshedBar incident, transmission;
  int bar_n_r = 4;
  double bar_element_length = 2e-3;  ///< m
  double specimen_length = kSpecimenLength;        ///< L_s, the gap between the faces, m
  double specimen_radius = kSpecimenDiameter / 2;  ///< R_s, the tube's inner radius, m
  std::optional<MeshedTube> tube;    ///< none: the grains' tube is not part of the FE body
  std::function<double(double)> applied_stress;  ///< Pa at t, compression +
  int threads = 1;
};

/// The meshed tube around the specimen gap as a block of `mesh` with its Part: r in
/// [R_s, R_s + t], centred on the gap (z in [L_s/2 - l/2, L_s/2 + l/2]), free ends. Throws
/// InputError ("specimen.tube_thickness", "specimen.tube_length", "specimen.tube").
Block add_tube_block(Mesh& mesh, std::vector<Part>& parts, const MeshedTube& t, double specimen_length,
                     double specimen_radius);
/// The tube's inner-wall nodes (ascending z) and their tributary areas 2 pi R_s x span (m^2).
void tube_wall_surface(const Block& tube, double tube_length, double specimen_radius, std::vector<int>& nodes,
                       std::vector<double>& areas);
/// Adds the loads f_r, f_z (N, one per node of `nodes`) at t^n to the external forces and their
/// work over [t^{n-1}, t^n] (trapezoid in force over the step's displacement) to `work`;
/// prev_* hold the loads of t^{n-1} and take these.
void add_surface_loads(Nodes& nd, const std::vector<int>& nodes, const std::vector<double>& f_r,
                       const std::vector<double>& f_z, std::vector<double>& prev_fr, std::vector<double>& prev_fz,
                       double& work);

/// The three surfaces the grains touch; node lists ascending in r (faces) or z (tube wall).
enum class Surface { incident_face = 0, transmission_face = 1, tube_wall = 2 };

class MeshedBarsTube {
 public:
  /// Throws InputError (paths "bars.*", "specimen.tube_*", "pulse").
  explicit MeshedBarsTube(const MeshedBarsTubeParams& p);

  double stable_dt() const { return body_.stable_dt(); }  ///< element Courant bound (s)
  /// Internal forces at t^n; external forces reset to the far-end traction sigma_app(t).
  void begin_forces(double t);
  /// Adds surface loads at t^n (N, per node of surface(s), along +r and +z) and books their
  /// work. Once per surface between begin_forces and advance.
  void add_surface_loads(Surface s, const std::vector<double>& f_r, const std::vector<double>& f_z);
  /// Central-difference step t^n -> t^{n+1}.
  void advance(double dt);

  bool has_surface(Surface s) const { return !surfaces_[static_cast<int>(s)].empty(); }
  const std::vector<int>& surface(Surface s) const { return surfaces_[static_cast<int>(s)]; }
  /// Tributary area of each node of surface(s) (m^2; ring areas of a face, 2 pi R x span of
  /// the tube wall) in the reference configuration.
  const std::vector<double>& surface_area(Surface s) const { return areas_[static_cast<int>(s)]; }
  /// Ring-area weighted mean of u_z (velocity = false) or v_z of bar 0/1's face (m, m/s).
  double face_mean(int bar, bool velocity) const;
  /// Surface axial strain at gauge k of bar 0 (incident) or 1, tension + (MeshedShpb's rule).
  double gauge_strain(int bar, std::size_t k) const;

  double kinetic_energy() const { return body_.kinetic_energy(); }
  double material_work() const { return body_.material_work(); }
  double applied_work() const { return applied_work_; }  ///< work of the far-end traction (J)
  double surface_work() const { return surface_work_; }  ///< work of the surface loads (J)
  bool finite() const { return body_.finite(); }
  const Body& body() const { return body_; }
  Body& body() { return body_; }

 private:
  struct Gauge { int edge = 0; double weight = 0; };
  double edge_strain(const Block& b, int j) const;
  MeshedBarsTubeParams p_;
  Block incident_, transmission_;
  std::optional<Block> tube_;
  Body body_;
  std::vector<int> surfaces_[3];
  std::vector<double> areas_[3];
  std::vector<double> prev_fr_[3], prev_fz_[3];  // surface loads at t^{n-1}
  std::vector<double> bar_ring_area_, load_prev_;
  std::vector<Gauge> gauges_[2];
  double applied_work_ = 0, surface_work_ = 0;
};

}  // namespace kolsky::fe
