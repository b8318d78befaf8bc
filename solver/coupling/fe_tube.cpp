#include "coupling/fe_tube.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace kolsky::coupling {

namespace {

fe::Body build(const FeTubeParams& p, fe::Block& block) {
  if (!(p.specimen_length > 0.0)) throw InputError("", "specimen.length", "must be > 0");
  if (!(p.specimen_radius > 0.0)) throw InputError("", "specimen.diameter", "must be > 0");
  fe::Mesh mesh;
  std::vector<fe::Part> parts;
  block = fe::add_tube_block(mesh, parts, p.tube, p.specimen_length, p.specimen_radius);
  return fe::Body(std::move(mesh), std::move(parts), p.threads);
}

}  // namespace

FeTube::FeTube(const FeTubeParams& p, const dem::DemSystem& sys) : p_(p), body_(build(p, block_)) {
  if (sys.n_cylinders() != 1 || sys.cylinder(0).compliance)
    throw InputError("", "specimen.tube", "an FE tube needs the specimen's rigid cylinder to drive");
  if (std::abs(sys.cylinder(0).radius - p.specimen_radius) > 1e-12 * p.specimen_radius)
    throw InputError("", "specimen.diameter", "the grains' cylinder and the FE tube's inner radius must agree");
  fe::tube_wall_surface(block_, p.tube.length, p.specimen_radius, wall_, wall_area_);
  prev_fr_.assign(wall_.size(), 0.0);
  prev_fz_.assign(wall_.size(), 0.0);
  slot_ = dem::WallSlots{sys.n_planes(), sys.n_cylinders()}.slot(dem::WallKind::cylinder, 0);
  const auto& radius = sys.particles().radius;
  const double r_min = *std::min_element(radius.begin(), radius.end());
  node_dt_ = surface_node_dt(sys.cylinder(0).law, body_.nodes(), wall_, wall_area_, r_min);
}

double FeTube::stable_dt() const { return std::min(body_.stable_dt(), node_dt_); }

void FeTube::drive(dem::DemSystem& sys) const { sys.drive_cylinder(0, tube_profile(body_.nodes(), wall_)); }

void FeTube::load_and_advance(const dem::DemSystem& sys, double dt) {
  body_.update_internal_forces();
  fe::Nodes& nd = body_.nodes();
  std::fill(nd.fr_ext.begin(), nd.fr_ext.end(), 0.0);
  std::fill(nd.fz_ext.begin(), nd.fz_ext.end(), 0.0);
  const RingLoads l = wall_ring_loads(sys, slot_, tube_profile(nd, wall_), false);
  fe::add_surface_loads(nd, wall_, l.f_r, l.f_z, prev_fr_, prev_fz_, surface_work_);
  radial_force_ = l.radial;
  peak_radial_ = std::max(peak_radial_, std::abs(l.radial));
  peak_lateral_ = std::max(peak_lateral_, std::hypot(l.resultant.x, l.resultant.y));
  body_.advance(dt, 0.0);
}

double FeTube::mean_wall_displacement() const {
  const fe::Nodes& nd = body_.nodes();
  double num = 0.0, den = 0.0;
  for (std::size_t a = 0; a < wall_.size(); ++a) {
    num += wall_area_[a] * nd.ur[static_cast<std::size_t>(wall_[a])];
    den += wall_area_[a];
  }
  return num / den;
}

}  // namespace kolsky::coupling
