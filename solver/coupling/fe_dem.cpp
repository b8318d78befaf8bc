#include "coupling/fe_dem.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <type_traits>

#include "core/errors.hpp"
#include "core/stability_check.hpp"

namespace kolsky::coupling {

namespace {

dem::DemSpecimen checked(dem::DemSpecimen s) {
  const dem::DemSystem& sys = s.system();
  if (s.held())
    throw InputError("", "specimen.hold_until_loaded",
                     "the FE-DEM coupling steps the grains from t = 0: set it to false");
  if (s.breakage())
    throw InputError("", "specimen.breakage", "not supported with meshed bars (Chapter 3 has no breakage)");
  if (sys.n_cylinders() != 1 || sys.cylinder(0).compliance)
    throw InputError("", "specimen.tube", "the FE-DEM coupling needs the specimen's rigid cylinder");
  return s;
}

}  // namespace

double OffAxisTally::face_fraction() const {
  double f = 0;
  for (int b = 0; b < 2; ++b)
    if (peak_axial[b] > 0) f = std::max(f, peak_lateral[b] / peak_axial[b]);
  return f;
}

double OffAxisTally::tube_fraction() const {
  return peak_tube_radial > 0 ? peak_tube_lateral / peak_tube_radial : 0.0;
}

FeDemShpb::FeDemShpb(const FeDemParams& p, dem::DemSpecimen specimen)
    : p_(p), fe_(p.fe), dem_(checked(std::move(specimen))) {
  if (!(p.energy_tolerance > 0)) throw InputError("", "time.energy_tolerance", "must be > 0");
  const dem::DemSystem& sys = dem_.system();
  if (std::abs(dem_.length() - p.fe.specimen_length) > 1e-12 * p.fe.specimen_length ||
      std::abs(std::sqrt(dem_.area() / std::numbers::pi) - p.fe.specimen_radius) > 1e-12 * p.fe.specimen_radius)
    throw InputError("", "specimen.length", "the grains' cylinder and the FE gap must agree");
  const double r_min = *std::min_element(sys.particles().radius.begin(), sys.particles().radius.end());
  node_dt_ = std::numeric_limits<double>::infinity();
  const fe::Nodes& nd = fe_.body().nodes();
  for (int s = 0; s < 3; ++s) {
    const auto surf = static_cast<fe::Surface>(s);
    if (!fe_.has_surface(surf)) continue;
    const dem::WallLaw& law = s < 2 ? sys.plane(s == 0 ? dem_.front_plane() : dem_.back_plane()).law
                                    : sys.cylinder(0).law;
    node_dt_ = std::min(node_dt_, surface_node_dt(law, nd, fe_.surface(surf), fe_.surface_area(surf), r_min));
  }
  for (int s = 0; s < 3; ++s) loads_[s] = RingLoads(fe_.surface(static_cast<fe::Surface>(s)).size());
}

double FeDemShpb::stable_dt() const { return std::min({fe_.stable_dt(), dem_.stable_dt(), node_dt_}); }

double FeDemShpb::specimen_area() const {
  return std::numbers::pi * p_.fe.specimen_radius * p_.fe.specimen_radius;
}

void FeDemShpb::map_wall(fe::Surface s, int slot, const dem::WallProfile& profile, bool plane) {
  RingLoads& l = loads_[static_cast<int>(s)];
  l = wall_ring_loads(dem_.system(), slot, profile, plane);
  fe_.add_surface_loads(s, l.f_r, l.f_z);
}

void FeDemShpb::step(double t, double dt) {
  forces(t);
  advance(dt);
}

void FeDemShpb::forces(double t) {
  fe_.begin_forces(t);
  const fe::Nodes& nd = fe_.body().nodes();
  dem::DemSystem& sys = dem_.coupled_system();
  const dem::WallProfile front = face_profile(nd, fe_.surface(fe::Surface::incident_face), FaceSide::front);
  const dem::WallProfile back = face_profile(nd, fe_.surface(fe::Surface::transmission_face), FaceSide::back);
  sys.drive_plane_profile(dem_.front_plane(), front);
  sys.drive_plane_profile(dem_.back_plane(), back);
  std::optional<dem::WallProfile> wall;
  if (fe_.has_surface(fe::Surface::tube_wall)) {
    wall = tube_profile(nd, fe_.surface(fe::Surface::tube_wall));
    sys.drive_cylinder(0, *wall);
  }
  // Forces at t^n: the second half of the DEM step in progress, or a first evaluation.
  if (started_) sys.finish_step();
  else sys.compute_forces();
  const dem::WallSlots slots{sys.n_planes(), sys.n_cylinders()};
  map_wall(fe::Surface::incident_face, slots.slot(dem::WallKind::plane, dem_.front_plane()), front, true);
  map_wall(fe::Surface::transmission_face, slots.slot(dem::WallKind::plane, dem_.back_plane()), back, true);
  if (wall) map_wall(fe::Surface::tube_wall, slots.slot(dem::WallKind::cylinder, 0), *wall, false);
  face_force_[0] = -loads_[0].axial;  // the grains push the incident face towards -z
  face_force_[1] = loads_[1].axial;
  tube_force_ = wall ? loads_[2].radial : sys.cylinder_force(0);
  for (int b = 0; b < 2; ++b) {
    const RingLoads& l = loads_[b];
    off_axis_.peak_axial[b] = std::max(off_axis_.peak_axial[b], std::abs(l.axial));
    off_axis_.peak_lateral[b] = std::max(off_axis_.peak_lateral[b], std::hypot(l.resultant.x, l.resultant.y));
    off_axis_.peak_torque[b] = std::max(off_axis_.peak_torque[b], std::abs(l.torque_z));
  }
  if (wall) {
    off_axis_.peak_tube_radial = std::max(off_axis_.peak_tube_radial, std::abs(loads_[2].radial));
    off_axis_.peak_tube_lateral =
        std::max(off_axis_.peak_tube_lateral, std::hypot(loads_[2].resultant.x, loads_[2].resultant.y));
  }
}

void FeDemShpb::advance(double dt) {
  // Checked before either side moves, after the forces of t^n as in fe::MeshedShpb: the FE
  // elements' Courant lengths are then those of t^n (the internal forces refresh them).
  if (p_.check_dt)
    check_time_step(dt, stable_dt(), "fe-dem", fe_.body().time(),
                    "FE Courant bound, DEM contact limit, grain springs on the FE surface nodes");
  fe_.advance(dt);
  dem::DemSystem& sys = dem_.coupled_system();
  sys.begin_step(dt);
  started_ = true;
  ++n_steps_;
  if (!finite()) throw NumericalError("fe-dem: non-finite state", fe_.body().time());
  const FeDemEnergy e = energy();
  // Judged against the largest of the energy held, the work delivered and the packing's
  // contact energy at the start (the 1-D assembly, one_dim_bars.cpp, counts that energy too):
  // a packing's residual overlaps release it from t = 0, before any pulse arrives (Chapter 3's
  // packings, docs/coupling.md "Energy").
  peak_energy_ = std::max({peak_energy_, std::abs(e.held()), std::abs(e.applied_work),
                           dem_.initial_elastic_energy()});
  constexpr long kWarmupSteps = 16;  // as the FE assemblies
  if (p_.check_energy && n_steps_ > kWarmupSteps)
    check_energy_growth({e.held(), e.applied_work, peak_energy_}, p_.energy_tolerance, "fe-dem", fe_.body().time());
}

double FeDemShpb::mean_strain() const {
  return (fe_.face_mean(0, false) - fe_.face_mean(1, false)) / p_.fe.specimen_length;
}

double FeDemShpb::face_rate(int bar) const {
  return bar == 0 ? fe_.face_mean(0, true) : -fe_.face_mean(1, true);
}

FeDemEnergy FeDemShpb::energy() const {
  FeDemEnergy e;
  e.fe_kinetic = fe_.kinetic_energy();
  e.fe_material_work = fe_.material_work();
  const dem::DemEnergy d = dem_.system().energy();
  e.dem_kinetic = d.kinetic;
  e.dem_stored = d.elastic - dem_.initial_elastic_energy();
  e.dem_dissipated = d.dissipated;
  e.applied_work = fe_.applied_work();
  e.interface_work = fe_.surface_work();
  return e;
}

}  // namespace kolsky::coupling
