// DemSystem: construction, walls, time stepping, neighbour-list upkeep, energies and the
// stable time step (see dem_system.hpp). The contact kernels live in dem_forces.cpp.
#include "dem/dem_system.hpp"

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <numbers>
#include <limits>
#include <sstream>
#include <stdexcept>

#include <omp.h>

#include "core/errors.hpp"
#include "core/stability_check.hpp"
#include "dem/contact_hertz_mindlin.hpp"
#include "dem/integrator.hpp"

namespace kolsky::dem {

double RollingRetardation::factor(double dt) const {
  if (factor_per_reference_step == 1.0 || factor_per_reference_step == 0.0)
    return factor_per_reference_step;
  return std::pow(factor_per_reference_step, dt / reference_dt);
}

void DemSystem::ContactStore::resize(std::size_t n, std::size_t n_slots) {
  out.assign(n_slots, ContactOut{});
  active.assign(n, 0);
  elastic.assign(n, 0.0);
}

DemSystem::DemSystem(Particles particles, std::vector<Material> materials, ContactLaw law,
                     DemOptions options)
    : p_(std::move(particles)), materials_(std::move(materials)), law_(std::move(law)),
      opt_(options) {
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
  dissipated_.assign(p_.size(), 0.0);
  reset_owner_blocks();
  stable_dt_ = compute_stable_dt();
}

void DemSystem::reset_owner_blocks() {
  const int n = static_cast<int>(p_.size()), block = opt_.owner_block;
  block_first_.clear();
  for (int i0 = 0; i0 < n; i0 += block) block_first_.push_back(i0);
  block_first_.push_back(n);
}

// A new plane goes in at the end of the planes, before the cylinders (the slot rule); the
// slots change, so the wall histories restart.
int DemSystem::add_plane(const PlaneWall& w) {
  walls_.insert(walls_.begin() + n_planes_, make_wall(w));
  ++n_planes_;
  wall_particle_.clear();
  wall_first_.clear();
  list_valid_ = forces_valid_ = false;
  stable_dt_ = compute_stable_dt();
  return n_planes_ - 1;
}

int DemSystem::add_cylinder(const CylinderWall& w) {
  walls_.push_back(make_wall(w));
  wall_particle_.clear();
  wall_first_.clear();
  list_valid_ = forces_valid_ = false;
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
  list_valid_ = forces_valid_ = false;
  particles_changed_ = true;
  return p_;
}

void DemSystem::refresh_after_edit() {
  // Radii, masses or the particle count may have changed: revalidate and rederive.
  validate(p_, materials_.size());
  skin_ = opt_.skin_over_min_radius * *std::min_element(p_.radius.begin(), p_.radius.end());
  dissipated_.resize(p_.size(), 0.0);
  if (pairs_.first.size() != p_.size() + 1) pairs_ = PairList{};
  if (block_first_.back() != static_cast<int>(p_.size())) reset_owner_blocks();
  wall_particle_.clear();
  wall_first_.clear();
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

namespace {
using Clock = std::chrono::steady_clock;
double seconds_since(Clock::time_point t0) {
  return std::chrono::duration<double>(Clock::now() - t0).count();
}

// The last count chosen by any DemSystem's governor in this process (0: none yet), the start of
// the next governor (ThreadGovernorOptions::start_threads). Only the speed depends on it.
std::atomic<int> g_last_step_threads{0};

}  // namespace

int DemSystem::threads_for_step() {
  const int cap = omp_get_max_threads();
  if (!opt_.adapt_threads || cap <= 1) return cap;
  if (governor_.max_threads() != cap) {
    ThreadGovernorOptions o = opt_.governor;
    if (o.start_threads == 0) o.start_threads = g_last_step_threads.load(std::memory_order_relaxed);
    governor_ = ThreadGovernor(cap, o);
  }
  return governor_.threads();
}

void DemSystem::begin_step(double dt) {
  if (particles_changed_) refresh_after_edit();
  check_dt(dt);
  if (pending_dt_ > 0) finish_step();
  step_threads_ = threads_for_step();
  const ScopedThreads scope(step_threads_);
  const auto t0 = Clock::now();
  if (!forces_valid_) compute_forces(0.0);
  kick_drift(0.5 * dt, dt);
  time_ += dt;
  pending_dt_ = dt;
  step_seconds_ = seconds_since(t0);
}

void DemSystem::finish_step() {
  const ScopedThreads scope(step_threads_);
  const auto t0 = Clock::now();
  const double dt = pending_dt_;
  compute_forces(dt);
  kick_retard(0.5 * dt, dt);
  pending_dt_ = 0;
  // Only the DEM's own work is timed: what the caller does between steps (bars, output)
  // does not depend on this choice and would only add noise to the comparison.
  if (step_threads_ > 0 && opt_.adapt_threads && governor_.max_threads() > 1) {
    const long switches = governor_.switches();
    governor_.record(step_seconds_ + seconds_since(t0));
    if (governor_.switches() != switches)
      g_last_step_threads.store(governor_.threads(), std::memory_order_relaxed);
  }
  step_threads_ = 0;
}

// The grains by the integrator (integrator.hpp), then the walls: a compliant ring's half
// kick, then each wall's drift (wall.hpp; the walls do not interact, so one pass does both).
void DemSystem::kick_drift(double h, double dt) {
  max_disp2_ = dem::kick_drift(p_, h, dt, list_valid_ ? x_at_build_.data() : nullptr, max_disp2_);
  for (Wall& w : walls_) {
    kick(w, h);
    drift(w, time_, dt);
  }
}

// Second half kick and the rotational retardation (Eqs. 4.12-4.14) of the grains, then the rings.
void DemSystem::kick_retard(double h, double dt) {
  dem::kick_retard(p_, h, opt_.rolling.factor(dt), dissipated_);
  for (Wall& w : walls_) kick(w, h);
}

bool DemSystem::needs_rebuild() const {
  if (!list_valid_) return true;
  const double half = 0.5 * skin_;
  if (max_disp2_ > half * half) return true;
  return std::any_of(walls_.begin(), walls_.end(), [half](const Wall& w) { return moved_since_build(w) > half; });
}

void DemSystem::rebuild() {
  pairs_ = build_pair_list(p_.x, p_.radius, skin_, pairs_);
  build_wall_candidates();
  const int n = static_cast<int>(p_.size());
  // Counting sort into slots, by partner (then pair order), of the pairs whose partner lies in
  // another owner block; a partner in the owner's block gets its side in the sweep (slot -1).
  partner_first_.assign(static_cast<std::size_t>(n) + 1, 0);
  std::vector<int> block_of(static_cast<std::size_t>(n));
  for (std::size_t b = 0; b + 1 < block_first_.size(); ++b)
    std::fill(block_of.begin() + block_first_[b], block_of.begin() + block_first_[b + 1], static_cast<int>(b));
  auto crosses = [&](std::size_t k) { return block_of[pairs_.i[k]] != block_of[pairs_.j[k]]; };
  for (std::size_t k = 0; k < pairs_.size(); ++k)
    if (crosses(k)) ++partner_first_[pairs_.j[k] + 1];
  for (int q = 0; q < n; ++q) partner_first_[q + 1] += partner_first_[q];
  pair_slot_.resize(pairs_.size());
  std::vector<int> fill(partner_first_.begin(), partner_first_.end() - 1);
  for (std::size_t k = 0; k < pairs_.size(); ++k)
    pair_slot_[k] = crosses(k) ? fill[pairs_.j[k]]++ : -1;
  pair_out_.resize(pairs_.size(), static_cast<std::size_t>(partner_first_[n]));
  // A carried non-zero history counts as active: the batched sweep clears the history of a
  // pair only when it goes from active to not touching (dem_forces_batched.cpp). The slots
  // stay zero; every evaluation rewrites active[] before anything reads it.
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    const Vec3& h = pairs_.history[k];
    pair_out_.active[k] = h.x != 0 || h.y != 0 || h.z != 0;
  }
  wall_first_of_.assign(static_cast<std::size_t>(n) + 1, 0);
  for (int q : wall_particle_) ++wall_first_of_[q + 1];
  for (int q = 0; q < n; ++q) wall_first_of_[q + 1] += wall_first_of_[q];
  wall_entry_.resize(wall_particle_.size());
  fill.assign(wall_first_of_.begin(), wall_first_of_.end() - 1);
  for (std::size_t c = 0; c < wall_particle_.size(); ++c)
    wall_entry_[fill[wall_particle_[c]]++] = static_cast<int>(c);
  x_at_build_ = p_.x;
  max_disp2_ = 0;
  for (Wall& w : walls_) mark_built(w);
  list_valid_ = true;
  ++n_rebuilds_;
}

void DemSystem::build_wall_candidates() {
  const auto n_slots = walls_.size();  // by slot (walls.hpp, WallSlots)
  std::vector<int> particle, first(n_slots + 1, 0);
  std::vector<Vec3> history;
  const bool carry = wall_first_.size() == n_slots + 1;
  for (std::size_t w = 0; w < n_slots; ++w) {
    std::size_t a = carry ? wall_first_[w] : 0;
    const std::size_t a_end = carry ? wall_first_[w + 1] : 0;
    for (std::size_t i = 0; i < p_.size(); ++i) {
      // The candidates' round-off need not be the kernel's: only touching contacts give forces.
      if (gap_at(walls_[w], p_.x[i], p_.radius[i]) >= skin_) continue;
      particle.push_back(static_cast<int>(i));
      Vec3 h{};
      while (a < a_end && wall_particle_[a] < static_cast<int>(i)) ++a;
      if (a < a_end && wall_particle_[a] == static_cast<int>(i)) h = wall_history_[a];
      history.push_back(h);
    }
    first[w + 1] = static_cast<int>(particle.size());
  }
  wall_particle_.swap(particle);
  wall_first_.swap(first);
  wall_history_.swap(history);
  wall_out_.resize(wall_particle_.size(), wall_particle_.size());
  wall_normal_.resize(wall_particle_.size());
  wall_elastic_normal_.resize(wall_particle_.size());
}

DemEnergy DemSystem::energy() const {
  DemEnergy e;
  e.kinetic = p_.kinetic_energy();
  for (double u : pair_out_.elastic) e.elastic += u;  // pair order; zero where not touching
  for (std::size_t c = 0; c < wall_particle_.size(); ++c)
    if (wall_out_.active[c]) e.elastic += wall_out_.out[c].elastic;
  // A ring's energies and a plane's work; the zeros the other shapes add change no sum (a
  // sum of these terms is never -0).
  for (const Wall& w : walls_) {
    const WallEnergy we = energy_of(w);
    e.kinetic += we.kinetic;
    e.elastic += we.elastic;
    e.wall_work += we.work;
  }
  for (double d : dissipated_) e.dissipated += d;
  e.dissipated += removed_dissipated_;
  e.edited = edited_energy_;
  return e;
}

std::size_t DemSystem::n_contacts() const {
  return static_cast<std::size_t>(std::count(pair_out_.active.begin(), pair_out_.active.end(), 1));
}

std::size_t DemSystem::n_wall_contacts() const {
  return static_cast<std::size_t>(std::count(wall_out_.active.begin(), wall_out_.active.end(), 1));
}

bool DemSystem::finite() const {
  if (!p_.finite()) return false;
  return std::all_of(walls_.begin(), walls_.end(), [](const Wall& w) { return is_finite(w); });
}

}  // namespace kolsky::dem
