// Meshed bars: the whole SHPB (incident bar, specimen + tube, transmission bar) as one explicit
// axisymmetric FE body, the alternative to the 1-D characteristic bars of bar/ (Sec. 2.3.1:
// LS-DYNA meshed the bars; docs/fe.md "Meshed bars").
//   Geometry: the specimen block of FeSpecimen at z in [0, L_s] (with its tube), the incident
//   bar at z in [-L_I, 0], the transmission bar at z in [L_s, L_s + L_T]; bars are linear-elastic
//   Q4 B-bar blocks with n_r radial elements and elements of about element_length axially.
//   Loading: the applied stress sigma_app(t) (compression +) as a uniform traction on the
//   incident bar's far end (ring-area weighted nodal forces); the transmission bar's far end is
//   free. So the bars carry Pochhammer-Chree dispersion and radial inertia, and the bar faces
//   are not plane; the 1-D bars carry neither.
//   Bar faces <-> specimen: penalty contact of the specimen's end rows against the bar-face
//   node polylines (normal z), the stiffness, damping and friction of FeSpecimen's rigid
//   planes, so that the bar model is the only difference. The bars pass freely through the
//   tube (their radial expansion at 50 MPa is ~1 um; no bar-tube contact).
//   Gauges: surface axial strain (tension +) at the gauge position, linear between the
//   element-edge strains of the outer node column (what a foil gauge on the surface reads).
//   Energy: kinetic + material work + contact work of the whole body = work of the applied
//   traction (trapezoid in force, the pairing central differences conserve); each step checks
//   it as FeSpecimen does. Units: SI.
#pragma once
#include <functional>
#include <string>
#include <vector>

#include "core/specimen_geometry.hpp"
#include "fe/fe_specimen.hpp"

namespace kolsky::fe {

/// One meshed bar (the radius is also the face radius the specimen meets).
struct MeshedBar {
  LinearElastic material{200e9, 0.33, 8100};  ///< Sec. 2.3.1 steel
  double length = 1.0;                        ///< m
  double radius = kBarDiameter / 2;           ///< m
  std::vector<double> gauges;                 ///< distances from the specimen face, m
};

/// Throws InputError("", "bars.<side>.<key>", rule) for a non-positive length or radius, a bad
/// material or a gauge outside (0, length); shared by MeshedShpb and MeshedBarsTube.
void check_meshed_bar(const MeshedBar& b, const std::string& side);
/// Axial element count of a bar of this length at element length h (at least 2).
int axial_element_count(double length, double h);

struct MeshedShpbParams {
  FeSpecimenParams specimen;       ///< specimen, tube, contact and check parameters
  MeshedBar incident, transmission;
  int bar_n_r = 4;                 ///< radial elements of each bar
  double bar_element_length = 2e-3;  ///< target axial element length, m
  /// Stress applied at the incident bar's far end at time t (Pa, compression +).
  std::function<double(double)> applied_stress;
};

/// Energy ledger of the meshed assembly (J).
struct MeshedEnergy {
  double kinetic = 0, material_work = 0, contact_work = 0;  ///< contact: normal + friction
  double applied_work = 0;                                  ///< work of the far-end traction
  double held() const { return kinetic + material_work + contact_work; }
  double balance_error() const { return held() - applied_work; }
};

class MeshedShpb {
 public:
  /// Throws InputError for invalid parameters (paths "fe.*", "bars.*").
  explicit MeshedShpb(const MeshedShpbParams& p);

  double stable_dt() const;  ///< element bound composed with every contact spring (s)
  /// Forces at t^n (stresses, applied traction sigma_app(t), contacts), then the central-
  /// difference step to t^{n+1}. Throws NumericalError when dt exceeds stable_dt() (check_dt),
  /// on non-finite state or when the energy balance breaks.
  void step(double t, double dt);
  /// step() in its two halves, for a loop with a point between them (shpb/assembly.hpp): the
  /// forces at t^n, then the step to t^{n+1} with its checks.
  void forces(double t);
  void advance(double dt);

  FaceForces face_forces() const { return faces_; }  ///< contact forces on the faces at t^n (N)
  double specimen_area() const;                      ///< pi R_s^2
  /// (mean u_z of the incident face - mean u_z of the transmission face) / L_s, ring-area
  /// weighted means (compression +).
  double mean_strain() const;
  /// Ring-area weighted mean face velocity into the specimen (m/s), 0 incident / 1 transmission.
  double face_rate(int bar) const;
  /// Surface axial strain at gauge k of bar 0 (incident) or 1 (transmission), tension +.
  double gauge_strain(int bar, std::size_t k) const;
  MeshedEnergy energy_ledger() const;
  bool finite() const { return body_.finite(); }

  const Body& body() const { return body_; }
  Body& body() { return body_; }
  const Block& bar_block(int bar) const { return bar == 0 ? incident_ : transmission_; }
  const Block& specimen_block() const { return specimen_; }
  const ContactSet& face_contact(int bar) const { return bar == 0 ? front_ : back_; }

 private:
  // Gauge: linear between the strains of outer-surface edges `edge` and `edge + 1` (weight on
  // the second), the edge strains taken at their midpoints.
  struct Gauge { int edge = 0; double weight = 0; };
  std::vector<SpringStencil> springs() const;
  double edge_strain(const Block& b, int j) const;
  double face_mean(const Block& b, int j, bool velocity) const;
  MeshedShpbParams p_;
  Block specimen_, incident_, transmission_;
  std::optional<Block> tube_block_;
  Body body_;
  ContactSet front_, back_, tube_;
  std::vector<int> tube_surface_, incident_face_, transmission_face_;
  std::vector<double> bar_ring_area_;  // tributary ring area of a bar-face node, by radial station
  std::vector<Gauge> gauges_[2];
  std::vector<double> load_prev_;      // far-end nodal forces at t^{n-1}
  FaceForces faces_{};
  double applied_work_ = 0, peak_energy_ = 0;
  long n_steps_ = 0;
};

}  // namespace kolsky::fe
