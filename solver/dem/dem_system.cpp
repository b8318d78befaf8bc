// DemSystem: construction, walls, time stepping, neighbour-list upkeep and the stable time
// step (see dem_system.hpp). The contact kernels live in contact_forces*.cpp.
#include "dem/dem_system.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <stdexcept>

#include "core/errors.hpp"
#include "core/stability_check.hpp"
#include "dem/contact_forces.hpp"
#include "dem/contact_hertz_mindlin.hpp"
#include "dem/integrator.hpp"

namespace kolsky::dem {

DemSystem::DemSystem(Particles particles, std::vector<Material> materials, ContactLaw law,
                     DemOptions options)
    : p_(std::move(particles)), materials_(std::move(materials)), law_(std::move(law)),
      opt_(options), exec_(options.adapt_threads, options.governor) {
  validate(materials_);
  validate(p_, materials_.size());
  if (p_.size() == 0) throw InputError("", "dem.particles", "at least one particle is needed");
  // Every law answers the same two questions (contact_law.hpp, the law interface).
  const int n_mat = static_cast<int>(materials_.size());
  std::visit(
      [n_mat](const auto& l) {
        if (!l.fits(n_mat))
          throw InputError("", "dem.contact_law", "built for a different number of materials");
        l.validate("dem.contact_law");
      },
      law_);
  if (!(opt_.skin_over_min_radius > 0))
    throw InputError("", "dem.skin_over_min_radius", "must be > 0");
  if (!(opt_.owner_block > 0)) throw InputError("", "dem.owner_block", "must be > 0");
  if (!(opt_.smallest_radius_to_come >= 0))
    throw InputError("", "dem.smallest_radius_to_come", "must be >= 0");
  const double k = opt_.rolling.factor_per_reference_step;
  if (!(k >= 0 && k <= 1)) throw InputError("", "dem.rolling.factor", "must be in [0, 1]");
  if (!(opt_.rolling.reference_dt > 0))
    throw InputError("", "dem.rolling.reference_dt", "must be > 0");
  skin_ = opt_.skin_over_min_radius * *std::min_element(p_.radius.begin(), p_.radius.end());
  ledger_.dissipated.assign(p_.size(), 0.0);
  net_.block_first = uniform_owner_blocks(p_.size(), opt_.owner_block);
  stable_dt_ = compute_stable_dt();
}

// A new plane goes in at the end of the planes, before the cylinders (the slot rule); the
// slots change, so the wall histories restart.
int DemSystem::add_plane(const PlaneWall& w) {
  walls_.insert(walls_.begin() + n_planes_, make_wall(w));
  ++n_planes_;
  forget_wall_contacts(net_);
  net_.valid = forces_valid_ = false;
  stable_dt_ = compute_stable_dt();
  return n_planes_ - 1;
}

int DemSystem::add_cylinder(const CylinderWall& w) {
  walls_.push_back(make_wall(w));
  forget_wall_contacts(net_);
  net_.valid = forces_valid_ = false;
  stable_dt_ = compute_stable_dt();
  return n_cylinders() - 1;
}

// The wall of a kind and index; std::out_of_range for an index its kind does not have.
Wall& DemSystem::wall_of(WallKind kind, int k) {
  const int n_kind = kind == WallKind::plane ? n_planes() : n_cylinders();
  if (k < 0 || k >= n_kind) throw std::out_of_range("DemSystem: no such wall");
  return walls_[wall_slots().slot(kind, k)];
}

void DemSystem::drive_plane(int plane, double offset, double speed) {
  drive(std::get<Plane>(wall_of(WallKind::plane, plane).shape), offset, speed);
}

void DemSystem::drive_plane_profile(int plane, WallProfile profile) {
  drive_profile(std::get<Plane>(wall_of(WallKind::plane, plane).shape), std::move(profile));
}

void DemSystem::drive_cylinder(int cylinder, WallProfile profile) {
  drive_profile(std::get<Cylinder>(wall_of(WallKind::cylinder, cylinder).shape), std::move(profile));
}

Particles& DemSystem::mutable_particles() {
  net_.valid = forces_valid_ = false;
  particles_changed_ = true;
  return p_;
}

void DemSystem::refresh_after_edit() {
  // Radii, masses or the particle count may have changed: revalidate and rederive.
  validate(p_, materials_.size());
  skin_ = opt_.skin_over_min_radius * *std::min_element(p_.radius.begin(), p_.radius.end());
  ledger_.dissipated.resize(p_.size(), 0.0);
  reset_for_particles(net_, p_.size(), opt_.owner_block);
  stable_dt_ = compute_stable_dt();
  particles_changed_ = false;
}

double DemSystem::compute_stable_dt() const {
  const double inf = std::numeric_limits<double>::infinity();
  double m_min = inf, r_max = 0, rayleigh = inf;
  for (std::size_t i = 0; i < p_.size(); ++i) {
    m_min = std::min(m_min, p_.mass[i]);
    r_max = std::max(r_max, p_.radius[i]);
    rayleigh = std::min(rayleigh, rayleigh_time_step(p_.radius[i], materials_[p_.material[i]]));
  }
  if (const double r = opt_.smallest_radius_to_come; r > 0)
    for (const Material& m : materials_) {
      m_min = std::min(m_min, sphere_mass(r, m.density));
      rayleigh = std::min(rayleigh, rayleigh_time_step(r, m));
    }
  // Every law, of the grains and of each wall, states its own limit through the same member,
  // stable_dt(LawLimits) (contact_law.hpp): the Rayleigh step for a Hertz law (Li et al.
  // 2005), sqrt(m/k)(sqrt(1 + zeta^2) - zeta) of its stiffest spring on the lightest grain for
  // a linear one (Eqs. 3.1-3.2 for LS-DYNA's). `linear` gathers them all with the tube's ring
  // mode, so no law type is named here; the Rayleigh step arrives through the Hertz laws' own
  // limit. The minimum is the raw limit: no safety factor here (the stepping loop owns it).
  const LawLimits limits{m_min, r_max, rayleigh};
  const auto limit_of = [&](const auto& family) {
    return std::visit([&](const auto& law) { return law.stable_dt(limits); }, family);
  };
  double limit = limit_of(law_);
  for (const Wall& w : walls_) limit = std::min(limit, wall_stable_dt(w, limits));
  return limit;
}

double DemSystem::stable_dt() const {
  if (!particles_changed_) return stable_dt_;
  validate(p_, materials_.size());  // edited since the last step: derive afresh
  return compute_stable_dt();
}

void DemSystem::check_dt(double dt) const {
  if (dt > 0 && dt <= stable_dt_ * (1 + 1e-12)) return;  // refreshed by begin_step
  if (!(dt > 0)) throw InputError("", "dem.dt", "must be > 0");
  check_time_step(dt, stable_dt_, "dem", time_,
                  "min of the Rayleigh step of the smallest grain, sqrt(m/k) of the stiffest linear "
                  "contact and the tube ring mode");
}

void DemSystem::step(double dt) {
  begin_step(dt);
  finish_step();
}

void DemSystem::begin_step(double dt) {
  if (particles_changed_) refresh_after_edit();
  check_dt(dt);
  if (pending_dt_ > 0) finish_step();
  exec_.first_half([&] {
    if (!forces_valid_) compute_forces(0.0);
    kick_drift(0.5 * dt, dt);
    time_ += dt;
    pending_dt_ = dt;
  });
}

void DemSystem::finish_step() {
  exec_.second_half([&] {
    const double dt = pending_dt_;
    compute_forces(dt);
    kick_retard(0.5 * dt, dt);
    pending_dt_ = 0;
  });
}

// The grains by the integrator (integrator.hpp), then the walls: a compliant ring's half
// kick, then each wall's drift (wall.hpp; the walls do not interact, so one pass does both).
void DemSystem::kick_drift(double h, double dt) {
  net_.max_disp2 = dem::kick_drift(p_, h, dt, net_.valid ? net_.x_at_build.data() : nullptr, net_.max_disp2);
  for (Wall& w : walls_) {
    kick(w, h);
    drift(w, time_, dt);
  }
}

// Second half kick and the rotational retardation (Eqs. 4.12-4.14) of the grains, then the rings.
void DemSystem::kick_retard(double h, double dt) {
  dem::kick_retard(p_, h, opt_.rolling.factor(dt), ledger_.dissipated);
  for (Wall& w : walls_) kick(w, h);
}

void DemSystem::compute_forces(double dt) {
  if (particles_changed_) refresh_after_edit();
  if (needs_rebuild(net_, skin_, walls_)) rebuild();
  evaluate_contacts(net_, p_, ledger_.dissipated, law_, opt_.batched_hertz_mindlin, walls_, dt);
  forces_valid_ = true;
}

void DemSystem::rebuild() {
  dem::rebuild(net_, p_, walls_, skin_);
  for (Wall& w : walls_) mark_built(w);
}

// The facade's edit (particle_edit.hpp does the carrying): energies booked against evaluated
// forces before and after, as begin_step would evaluate them first.
EditMap DemSystem::edit(const ParticleEdit& e) {
  if (pending_dt_ > 0) throw std::logic_error("DemSystem::edit between begin_step and finish_step");
  if (particles_changed_) refresh_after_edit();
  std::vector<int> old_to_new = edit_index_map(e, p_.size(), materials_.size());
  const std::size_t n_kept = p_.size() - e.removed.size();
  if (!forces_valid_) compute_forces(0.0);
  const DemEnergy before = energy();
  bool contacts_change = apply_edit(p_, net_, ledger_, walls_.size(), e, old_to_new, opt_.owner_block);
  skin_ = opt_.skin_over_min_radius * *std::min_element(p_.radius.begin(), p_.radius.end());
  stable_dt_ = compute_stable_dt();
  if (!contacts_change) contacts_change = added_grains_touch(p_, walls_, n_kept, skin_);
  // A contact gained or lost: evaluate now, as begin_step would first (history unchanged, no
  // time advance), so the stored energy the edit moved is booked exactly. Otherwise the
  // survivors' forces and stored energies stand as they are.
  if (contacts_change) compute_forces(0.0);
  book_edit(ledger_, before, energy());

  added_since_sort_ += e.added.size();
  EditMap map{std::move(old_to_new), std::vector<int>(e.added.size())};
  std::iota(map.added_at.begin(), map.added_at.end(), static_cast<int>(n_kept));
  if (opt_.resort_added_fraction > 0 &&
      static_cast<double>(added_since_sort_) > opt_.resort_added_fraction * static_cast<double>(p_.size())) {
    const std::vector<int> sorted = resort_for_locality(p_, net_, ledger_, walls_.size(), opt_.owner_block);
    added_since_sort_ = 0;
    ++n_resorts_;
    for (int& q : map.old_to_new)
      if (q >= 0) q = sorted[static_cast<std::size_t>(q)];
    for (int& q : map.added_at) q = sorted[static_cast<std::size_t>(q)];
  }
  return map;
}

bool DemSystem::finite() const {
  if (!p_.finite()) return false;
  return std::all_of(walls_.begin(), walls_.end(), [](const Wall& w) { return is_finite(w); });
}

}  // namespace kolsky::dem
