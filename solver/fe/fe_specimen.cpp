#include "fe/fe_specimen.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>
#include <type_traits>

#include "core/stability_check.hpp"
#include "core/errors.hpp"
#include "fe/stability.hpp"

namespace kolsky::fe {

namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

void require(bool ok, const std::string& path, const std::string& rule) {
  if (!ok) throw InputError("", "fe." + path, rule);
}

// Checks the parameters and builds specimen (+ tube) blocks and parts.
Body make_body(const FeSpecimenParams& p, Block& specimen, std::optional<Block>& tube) {
  Mesh mesh;
  std::vector<Part> parts;
  add_specimen_blocks(p, mesh, parts, specimen, tube);
  return Body(std::move(mesh), std::move(parts), p.threads);
}

}  // namespace

void add_specimen_blocks(const FeSpecimenParams& p, Mesh& mesh, std::vector<Part>& parts, Block& specimen,
                         std::optional<Block>& tube) {
  require(p.radius > 0.0, "radius", "must be > 0");
  require(p.length > 0.0, "length", "must be > 0");
  require(p.n_r >= 1 && p.n_z >= 1, "n_r", "n_r and n_z must be >= 1");
  require(p.friction_faces >= 0.0, "friction_faces", "must be >= 0");
  require(p.friction_tube >= 0.0, "friction_tube", "must be >= 0");
  require(p.penalty_scale > 0.0, "penalty_scale", "must be > 0");
  require(p.mass_damping >= 0.0, "mass_damping", "must be >= 0");
  require(p.energy_tolerance > 0.0, "energy_tolerance", "must be > 0");
  require(p.contact_damping >= 0.0 && p.contact_damping < 1.0, "contact_damping", "must lie in [0, 1)");
  specimen = add_block(mesh, 0.0, p.radius, 0.0, p.length, p.n_r, p.n_z);
  parts.push_back(Part{p.material, specimen.first_element, specimen.n_elements()});
  if (const auto* t = std::get_if<MeshedTube>(&p.tube)) {
    require(t->thickness > 0.0, "tube.thickness", "must be > 0");
    require(t->length >= p.length, "tube.length", "must be >= the specimen length");
    require(t->n_r >= 1 && t->n_z >= 1, "tube.n_r", "n_r and n_z must be >= 1");
    const double zc = 0.5 * p.length;
    tube = add_block(mesh, p.radius, p.radius + t->thickness, zc - 0.5 * t->length,
                     zc + 0.5 * t->length, t->n_r, t->n_z);
    parts.push_back(Part{t->material, tube->first_element, tube->n_elements()});
  }
  if (const auto* t = std::get_if<SpringTube>(&p.tube)) {
    require(t->thickness > 0.0, "tube.thickness", "must be > 0");
    t->material.validate("fe.tube.material");
  }
}

ContactSet tube_contact_set(const FeSpecimenParams& p, const Block& specimen, double modulus) {
  ContactSet c;
  if (std::holds_alternative<NoTube>(p.tube)) return c;
  const double h_z = p.length / p.n_z, h_r = p.radius / p.n_r;
  const double wall = std::holds_alternative<SpringTube>(p.tube)
                          ? lame_wall_stiffness(std::get<SpringTube>(p.tube).material, p.radius,
                                                std::get<SpringTube>(p.tube).thickness)
                          : 0.0;
  for (int j = 0; j <= p.n_z; ++j) {
    const double span = (j == 0 || j == p.n_z) ? 0.5 * h_z : h_z;
    const double ring = kTwoPi * p.radius * span;
    double k = p.penalty_scale * modulus * ring / h_r;
    if (wall > 0.0) k = 1.0 / (1.0 / k + 1.0 / (wall * ring));  // penalty in series with the tube
    c.node.push_back(specimen.node(p.n_r, j));
    c.stiffness.push_back(k);
  }
  c.friction = p.friction_tube;
  c.reset_history();
  return c;
}

void apply_tube_contact(const Tube& tube, ContactSet& c, Nodes& nd, double radius,
                        const std::vector<int>& tube_surface) {
  std::visit(
      [&](const auto& t) {
        using T = std::decay_t<decltype(t)>;
        if constexpr (std::is_same_v<T, RigidTube> || std::is_same_v<T, SpringTube>)
          contact_cylinder(c, nd, radius);
        else if constexpr (std::is_same_v<T, MeshedTube>)
          contact_polyline(c, nd, tube_surface);
      },
      tube);
}

void set_contact_damping(ContactSet& c, const Nodes& nd, double zeta) {
  c.damping.clear();
  for (std::size_t k = 0; k < c.node.size(); ++k)
    c.damping.push_back(2.0 * zeta * std::sqrt(c.stiffness[k] * nd.mass[static_cast<std::size_t>(c.node[k])]));
}

double energy_check_floor(const FeSpecimenParams& p) {
  constexpr double kStrainFloor = 1e-9;
  return 0.5 * max_constrained_modulus(p.material) * std::numbers::pi * p.radius * p.radius * p.length *
         kStrainFloor * kStrainFloor;
}

void face_contact_sets(const FeSpecimenParams& p, const Block& specimen, const Nodes& nodes,
                       double modulus, ContactSet& front, ContactSet& back) {
  const double h_z = p.length / p.n_z;
  std::vector<double> r_station;
  for (int i = 0; i <= p.n_r; ++i) r_station.push_back(nodes.r0[static_cast<std::size_t>(specimen.node(i, 0))]);
  const auto area = ring_tributary_areas(r_station);
  for (int i = 0; i <= p.n_r; ++i) {
    const double k = p.penalty_scale * modulus * area[static_cast<std::size_t>(i)] / h_z;
    front.node.push_back(specimen.node(i, 0));
    back.node.push_back(specimen.node(i, p.n_z));
    front.stiffness.push_back(k);
    back.stiffness.push_back(k);
  }
  front.friction = back.friction = p.friction_faces;
  front.reset_history();
  back.reset_history();
}

FeSpecimen::FeSpecimen(const FeSpecimenParams& p)
    : p_(p), body_(make_body(p, specimen_, tube_block_)), energy_floor_(energy_check_floor(p)) {
  const Nodes& nd = body_.nodes();
  const double modulus = max_constrained_modulus(p.material);
  // Bar faces: every node of the end rows, stiffness from its ring area and the layer depth.
  face_contact_sets(p, specimen_, nd, modulus, front_, back_);
  back_.surface_position = p.length;

  tube_ = tube_contact_set(p, specimen_, modulus);
  if (tube_block_)
    for (int j = 0; j <= tube_block_->n_z; ++j) tube_surface_.push_back(tube_block_->node(0, j));
  // Normal dampers: a fraction contact_damping of critical for each slave node on its spring.
  for (ContactSet* c : {&front_, &back_, &tube_}) set_contact_damping(*c, nd, p.contact_damping);
}

double FeSpecimen::area() const { return std::numbers::pi * p_.radius * p_.radius; }

double FeSpecimen::mean_strain() const {
  return (faces_.intrusion_front + faces_.intrusion_back) / p_.length;
}

std::vector<SpringStencil> FeSpecimen::springs(bool abs_weights) const {
  std::vector<SpringStencil> s;
  const Nodes& nd = body_.nodes();
  contact_springs(front_, nd, nullptr, 1, abs_weights, s);
  contact_springs(back_, nd, nullptr, 1, abs_weights, s);
  contact_springs(tube_, nd, tube_block_ ? &tube_surface_ : nullptr, 0, abs_weights, s);
  return s;
}

double FeSpecimen::stable_dt() const {
  // A damper driven by the lagged velocity v^{n-1/2} lowers the limit of its spring to
  // (2/omega)(sqrt(1 + zeta^2) - zeta) (Belytschko, Liu & Moran 2000, Sec. 6.3.3).
  const double z = p_.contact_damping, f = std::sqrt(1.0 + z * z) - z;
  return compose_stable_dt(body_.stable_dt(), spring_eigen_bound(body_.nodes(), springs(true)) / (f * f));
}

double FeSpecimen::critical_dt(int n_lanczos, bool with_contact) const {
  return fe::critical_dt(body_, with_contact ? springs(false) : std::vector<SpringStencil>{}, n_lanczos);
}

FaceForces FeSpecimen::forces(const FaceState& at) {
  body_.update_internal_forces();
  Nodes& nd = body_.nodes();
  std::fill(nd.fr_ext.begin(), nd.fr_ext.end(), 0.0);
  std::fill(nd.fz_ext.begin(), nd.fz_ext.end(), 0.0);
  FaceForces f;
  f.front = contact_plane(front_, nd, at.intrusion_front, at.rate_front, +1);
  f.back = contact_plane(back_, nd, p_.length - at.intrusion_back, -at.rate_back, -1);
  apply_tube_contact(p_.tube, tube_, nd, p_.radius, tube_surface_);
  // Work of the faces on the specimen, trapezoid in force (exact for a linear spring).
  face_work_ += 0.5 * (face_forces_.front + f.front) * (at.intrusion_front - faces_.intrusion_front) +
                0.5 * (face_forces_.back + f.back) * (at.intrusion_back - faces_.intrusion_back);
  faces_ = at;
  face_forces_ = f;
  return f;
}

void FeSpecimen::advance(double dt) {
  if (p_.check_dt)
    check_time_step(dt, stable_dt(), "fe specimen", body_.time(), "element Courant bound with contact springs");
  body_.advance(dt, p_.mass_damping);
  if (n_steps_ == 0) initial_kinetic_ = body_.kinetic_energy();
  ++n_steps_;
  if (!body_.finite())
    throw NumericalError("fe specimen: non-finite state", body_.time());
  const FeEnergy e = energy_ledger();
  peak_energy_ = std::max({peak_energy_, std::fabs(e.held()), std::fabs(e.face_work) + e.initial_kinetic});
  // The first steps are not judged: a face starting at full speed leaves an O(dt) kinetic-energy
  // mismatch that is large next to the still tiny energies, while an unstable mode needs tens
  // of steps to grow from round-off (x1.9 per step at 1.05 times the critical dt).
  constexpr long kWarmupSteps = 16;
  // Judged against the peak energy, or the floor (a 1e-9 strain of the whole specimen) while
  // the energies are still at round-off level.
  if (p_.check_energy && n_steps_ > kWarmupSteps)
    check_energy_growth({e.held(), e.face_work + e.initial_kinetic,
                         std::max(peak_energy_, energy_floor_ / p_.energy_tolerance)},
                        p_.energy_tolerance, "fe specimen", body_.time());
}

FeEnergy FeSpecimen::energy_ledger() const {
  FeEnergy e;
  e.kinetic = body_.kinetic_energy();
  e.material_work = body_.material_work();
  e.contact_elastic = front_.normal_energy() + back_.normal_energy() + tube_.normal_energy();
  e.normal_work = front_.normal_work + back_.normal_work + tube_.normal_work;
  e.friction_work = front_.friction_work + back_.friction_work + tube_.friction_work;
  e.damping_work = body_.damping_work();
  e.face_work = face_work_;
  e.initial_kinetic = initial_kinetic_;
  return e;
}

SpecimenEnergy FeSpecimen::energy() const {
  const FeEnergy e = energy_ledger();
  return SpecimenEnergy{e.kinetic, e.held() - e.kinetic};
}

double FeSpecimen::max_penetration() const {
  return std::max({front_.max_penetration(), back_.max_penetration(), tube_.max_penetration()});
}

double FeSpecimen::face_shear() const { return front_.total_shear() + back_.total_shear(); }

double FeSpecimen::wall_force() const { return tube_.total_normal(); }

std::vector<double> FeSpecimen::layer_axial_stress() const {
  std::vector<double> s(static_cast<std::size_t>(specimen_.n_z), 0.0);
  const auto& vol = body_.state().volume;
  for (int j = 0; j < specimen_.n_z; ++j) {
    double num = 0.0, den = 0.0;
    for (int i = 0; i < specimen_.n_r; ++i) {
      const int e = specimen_.element(i, j);
      num -= vol[static_cast<std::size_t>(e)] * body_.axial_stress(e);
      den += vol[static_cast<std::size_t>(e)];
    }
    s[static_cast<std::size_t>(j)] = num / den;
  }
  return s;
}

}  // namespace kolsky::fe
