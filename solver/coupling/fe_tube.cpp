#include "coupling/fe_tube.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"

namespace kolsky::coupling {

namespace {

void require(bool ok, const std::string& path, const std::string& rule) {
  if (!ok) throw InputError("", path, rule);
}

fe::Body build(const FeTubeParams& p, fe::Block& block) {
  const fe::MeshedTube& t = p.tube;
  require(p.specimen_length > 0.0, "specimen.length", "must be > 0");
  require(p.specimen_radius > 0.0, "specimen.diameter", "must be > 0");
  require(t.thickness > 0.0, "specimen.tube_thickness", "must be > 0");
  require(t.length >= p.specimen_length, "specimen.tube_length", "must be >= the specimen length");
  require(t.n_r >= 1 && t.n_z >= 1, "specimen.tube", "the tube mesh needs n_r, n_z >= 1");
  t.material.validate("specimen.tube");
  fe::Mesh mesh;
  const double zc = 0.5 * p.specimen_length;
  block = fe::add_block(mesh, p.specimen_radius, p.specimen_radius + t.thickness, zc - 0.5 * t.length,
                        zc + 0.5 * t.length, t.n_r, t.n_z);
  std::vector<fe::Part> parts{fe::Part{t.material, block.first_element, block.n_elements()}};
  return fe::Body(std::move(mesh), std::move(parts), p.threads);
}

}  // namespace

FeTube::FeTube(const FeTubeParams& p, const dem::DemSystem& sys) : p_(p), body_(build(p, block_)) {
  if (sys.n_cylinders() != 1 || sys.cylinder(0).compliance)
    throw InputError("", "specimen.tube", "an FE tube needs the specimen's rigid cylinder to drive");
  if (std::abs(sys.cylinder(0).radius - p.specimen_radius) > 1e-12 * p.specimen_radius)
    throw InputError("", "specimen.diameter", "the grains' cylinder and the FE tube's inner radius must agree");
  const double h = p.tube.length / block_.n_z;
  for (int j = 0; j <= block_.n_z; ++j) {
    wall_.push_back(block_.node(0, j));
    const double span = (j == 0 || j == block_.n_z) ? 0.5 * h : h;
    wall_area_.push_back(2.0 * std::numbers::pi * p.specimen_radius * span);
  }
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
  const dem::WallProfile wall = tube_profile(nd, wall_);
  RingLoads l(wall_.size());
  const auto& x = sys.particles().x;
  sys.for_each_wall_force(slot_, [&](int i, const dem::Vec3& f_grain) {
    const dem::Vec3& xi = x[static_cast<std::size_t>(i)];
    add_contact(l, wall, xi.z, xi, -1.0 * f_grain);
  });
  for (std::size_t a = 0; a < wall_.size(); ++a) {
    const auto n = static_cast<std::size_t>(wall_[a]);
    // Trapezoid over [t^{n-1}, t^n], as MeshedBarsTube books its surface loads.
    surface_work_ += 0.5 * (prev_fr_[a] + l.f_r[a]) * (nd.ur[n] - nd.ur_prev[n]) +
                     0.5 * (prev_fz_[a] + l.f_z[a]) * (nd.uz[n] - nd.uz_prev[n]);
    prev_fr_[a] = l.f_r[a];
    prev_fz_[a] = l.f_z[a];
    nd.fr_ext[n] += l.f_r[a];
    nd.fz_ext[n] += l.f_z[a];
  }
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
