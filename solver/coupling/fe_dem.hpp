// Coupled FEM-DEM SHPB (Chapter 3: LS-DYNA's DES spheres between FE bars inside an FE steel
// tube), kolsky's way (docs/coupling.md):
//   FE: fe::MeshedBarsTube (the two meshed bars, optionally the meshed tube; no specimen mesh).
//   DEM: a DemSpecimen whose end planes and cylinder take the FE surfaces' shapes each step
//   (dem::WallProfile via surface_coupling.hpp): a grain touches a bar face at the face's
//   axial displacement at the grain's radius, and the tube wall at its radial displacement at
//   the grain's z, through the scene's grain-wall law (penalty contact; LS-DYNA's DES-to-
//   segment stiffness is not established, docs/coupling.md).
//   Step n (both integrators central differences on the same t^n, one dt): FE internal forces
//   and far-end traction at t^n -> FE surfaces at t^n drive the DEM walls -> DEM forces at t^n
//   (second half kick of the step in progress) -> the wall-contact forces, reversed, become
//   ring loads on the FE surface nodes -> FE step, DEM first half kick and drift.
//   Energy: FE kinetic + material work + DEM kinetic + stored (minus the packing's initial
//   contact energy) + dissipated = work of the applied pulse; the interface work drops out as
//   the FE side's work of the ring loads is minus the walls' work on the grains, up to the
//   O(dt) of the lagged wall velocity. Checked each step as the other assemblies do.
#pragma once
#include <string>

#include "coupling/surface_coupling.hpp"
#include "dem/dem_specimen.hpp"
#include "fe/meshed_bars_tube.hpp"

namespace kolsky::coupling {

struct FeDemParams {
  fe::MeshedBarsTubeParams fe;
  bool check_dt = true;            ///< refuse a step above stable_dt()
  bool check_energy = true;        ///< stop on energy growth (energy_tolerance)
  double energy_tolerance = 0.01;  ///< relative to the peak of the energies
};

/// Energy ledger of the coupled body (J).
struct FeDemEnergy {
  double fe_kinetic = 0, fe_material_work = 0;
  double dem_kinetic = 0, dem_stored = 0, dem_dissipated = 0;  ///< stored: minus the initial
  double applied_work = 0;    ///< work of the far-end traction
  double interface_work = 0;  ///< work of the ring loads on the FE body (about -DEM gain)
  double held() const { return fe_kinetic + fe_material_work + dem_kinetic + dem_stored + dem_dissipated; }
  double balance_error() const { return held() - applied_work; }
};

/// What the axisymmetric reduction leaves out, over the run so far: the lateral resultant
/// |(sum F_x, sum F_y)| and the moment about the axis of the contact forces on each surface,
/// which the ring loads cannot carry, against the axial (faces) or radial (tube) force.
struct OffAxisTally {
  double peak_axial[2] = {0, 0};    ///< largest |sum F_z| on each face (N)
  double peak_lateral[2] = {0, 0};  ///< largest lateral resultant on each face (N)
  double peak_torque[2] = {0, 0};   ///< largest |moment about z| on each face (N m)
  double peak_tube_radial = 0, peak_tube_lateral = 0;  ///< tube wall (N)
  /// max over faces of peak_lateral / peak_axial (0 while unloaded)
  double face_fraction() const;
  double tube_fraction() const;  ///< peak_tube_lateral / peak_tube_radial
};

class FeDemShpb {
 public:
  /// Throws InputError for a specimen this coupling cannot drive: held until loaded
  /// ("specimen.hold_until_loaded"), preload on the supports ("specimen.preload_on_supports"),
  /// breakage ("specimen.breakage"), a non-linear wall law, a cylinder with compliance.
  FeDemShpb(const FeDemParams& p, dem::DemSpecimen specimen);

  /// min(FE Courant bound, DEM raw limit, grain springs on the FE surface nodes): a node of
  /// mass m with tributary area A carries at most A / (pi r_min^2) grains, so sqrt(m / (N k))
  /// of the wall law's stiffest spring (with its damping factor). Raw: the loop's safety
  /// factor applies.
  double stable_dt() const;
  void step(double t, double dt);  ///< forces(t), then advance(dt)
  /// step() in its two halves, for a loop with a point between them (shpb/assembly.hpp): the
  /// walls shaped by the FE surfaces and the forces at t^n exchanged, then the dt check and
  /// both sides' step to t^{n+1} with the energy check.
  void forces(double t);
  void advance(double dt);

  /// Axial contact force of the grains on bar 0/1's face at t^n, compression + (N): the sum of
  /// its ring loads.
  double face_force(int bar) const { return face_force_[bar]; }
  double tube_force() const { return tube_force_; }  ///< radial force on the FE tube wall (N)
  double specimen_area() const;                       ///< pi R_s^2
  /// (mean u_z of the incident face - mean u_z of the transmission face) / L_s, ring-area
  /// weighted (compression +).
  double mean_strain() const;
  double face_rate(int bar) const;  ///< mean face velocity into the specimen (m/s)
  double gauge_strain(int bar, std::size_t k) const { return fe_.gauge_strain(bar, k); }
  FeDemEnergy energy() const;
  const OffAxisTally& off_axis() const { return off_axis_; }
  const RingLoads& last_loads(fe::Surface s) const { return loads_[static_cast<int>(s)]; }
  bool finite() const { return fe_.finite() && dem_.finite(); }

  const fe::MeshedBarsTube& fe() const { return fe_; }
  fe::MeshedBarsTube& fe() { return fe_; }
  const dem::DemSpecimen& dem() const { return dem_; }

 private:
  void map_wall(fe::Surface s, int slot, const dem::WallProfile& profile, bool plane);
  FeDemParams p_;
  fe::MeshedBarsTube fe_;
  dem::DemSpecimen dem_;
  double node_dt_ = 0;
  bool started_ = false;
  RingLoads loads_[3];
  double face_force_[2] = {0, 0}, tube_force_ = 0, peak_energy_ = 0;
  OffAxisTally off_axis_;
  long n_steps_ = 0;
};

}  // namespace kolsky::coupling
