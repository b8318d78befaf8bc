// DemSystem / DemSpecimen checkpoint and restart (see dem_state.hpp for what is stored and why
// the pair lists are rebuilt rather than stored).
#include "dem/dem_state.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"
#include "dem/dem_specimen.hpp"
#include "dem/dem_system.hpp"

namespace kolsky::dem {

namespace {

// Zero histories are not stored (a rebuild starts every new contact at zero). -0.0 is kept:
// it is not bitwise zero, and the test of this module compares bits.
bool stored(const Vec3& h) {
  return h.x != 0 || h.y != 0 || h.z != 0 || std::signbit(h.x) || std::signbit(h.y) ||
         std::signbit(h.z);
}

[[noreturn]] void bad_state(const std::string& rule) {
  throw InputError("", "dem.state", rule);
}

}  // namespace

DemState DemSystem::save_state() const {
  DemState s;
  s.particles = p_;
  s.dissipated = dissipated_;
  s.time = time_;
  s.pending_dt = pending_dt_;
  s.forces_valid = forces_valid_;
  s.n_rebuilds = n_rebuilds_;
  s.owner_blocks = block_first_;
  s.removed_dissipated = removed_dissipated_;
  s.edited_energy = edited_energy_;
  s.added_since_sort = added_since_sort_;
  static_cast<ContactHistory&>(s) = contact_history();
  // The checkpoint keeps its two wall records (the layout io/ writes): walls by slot.
  for (const Wall& w : walls_) {
    if (const auto* p = std::get_if<Plane>(&w.shape))
      s.planes.push_back({p->offset, p->speed, w.force, p->offset_at_force, p->work});
    else if (const auto* c = std::get_if<Cylinder>(&w.shape))
      s.tubes.push_back({c->u, c->u_dot, w.force});
  }
  return s;
}

void DemSystem::restore_state(const DemState& s) {
  // The particle count may differ from the system's: edits (breakage) change it.
  const std::size_t n = s.particles.size();
  if (n == 0) bad_state("the state has no particles");
  if (s.planes.size() != static_cast<std::size_t>(n_planes()) ||
      s.tubes.size() != static_cast<std::size_t>(n_cylinders()))
    bad_state("the state has other walls than the system");
  if (s.dissipated.size() != n) bad_state("dissipated energy: one value per particle needed");
  validate(s.particles, materials_.size());
  const auto& b = s.owner_blocks;
  if (!b.empty()) {
    bool ok = b.size() >= 2 && b.front() == 0 && b.back() == static_cast<int>(n);
    for (std::size_t k = 1; ok && k < b.size(); ++k) ok = b[k] > b[k - 1];
    if (!ok) bad_state("owner blocks must rise strictly from 0 to the particle count");
  }
  check_contact_history(s, n);

  p_ = s.particles;
  dissipated_ = s.dissipated;
  time_ = s.time;
  pending_dt_ = s.pending_dt;
  forces_valid_ = s.forces_valid;
  n_rebuilds_ = s.n_rebuilds;
  removed_dissipated_ = s.removed_dissipated;
  edited_energy_ = s.edited_energy;
  added_since_sort_ = s.added_since_sort;
  if (b.empty()) reset_owner_blocks();
  else block_first_ = b;
  particles_changed_ = false;
  skin_ = opt_.skin_over_min_radius * *std::min_element(p_.radius.begin(), p_.radius.end());
  stable_dt_ = compute_stable_dt();
  std::size_t next_plane = 0, next_tube = 0;
  for (Wall& w : walls_) {
    if (auto* p = std::get_if<Plane>(&w.shape)) {
      const DemState::Plane& q = s.planes[next_plane++];
      p->offset = q.offset;
      p->speed = q.speed;
      w.force = q.force;
      p->offset_at_force = q.offset_at_force;
      p->work = q.work;
    } else if (auto* c = std::get_if<Cylinder>(&w.shape)) {
      const DemState::Tube& q = s.tubes[next_tube++];
      c->u = q.u;
      c->u_dot = q.u_dot;
      w.force = q.force;
    }
  }

  attach_contact_history(s);
}

ContactHistory DemSystem::contact_history() const {
  ContactHistory h;
  if (pairs_.first.size() == p_.size() + 1) {  // else no list yet (or edited particles)
    for (std::size_t k = 0; k < pairs_.size(); ++k) {
      if (!stored(pairs_.history[k])) continue;
      h.pair_i.push_back(pairs_.i[k]);
      h.pair_j.push_back(pairs_.j[k]);
      h.pair_history.push_back(pairs_.history[k]);
    }
  }
  const auto n_slots = walls_.size();
  if (wall_first_.size() == n_slots + 1) {
    for (std::size_t w = 0; w < n_slots; ++w)
      for (int c = wall_first_[w]; c < wall_first_[w + 1]; ++c) {
        if (!stored(wall_history_[c])) continue;
        h.wall_slot.push_back(static_cast<int>(w));
        h.wall_particle.push_back(wall_particle_[c]);
        h.wall_history.push_back(wall_history_[c]);
      }
  }
  return h;
}

void DemSystem::check_contact_history(const ContactHistory& s, std::size_t n) const {
  const std::size_t n_pairs = s.pair_i.size();
  if (s.pair_j.size() != n_pairs || s.pair_history.size() != n_pairs)
    bad_state("pair histories: i, j and history differ in length");
  for (std::size_t k = 0; k < n_pairs; ++k) {
    const int i = s.pair_i[k], j = s.pair_j[k];
    const bool ordered = k == 0 || i > s.pair_i[k - 1] || (i == s.pair_i[k - 1] && j > s.pair_j[k - 1]);
    if (!(i >= 0 && i < j && j < static_cast<int>(n) && ordered))
      bad_state("pair histories must be sorted pairs i < j of existing particles");
  }
  const auto n_slots = walls_.size();
  const std::size_t n_wall = s.wall_slot.size();
  if (s.wall_particle.size() != n_wall || s.wall_history.size() != n_wall)
    bad_state("wall histories: slot, particle and history differ in length");
  for (std::size_t c = 0; c < n_wall; ++c) {
    const int w = s.wall_slot[c], q = s.wall_particle[c];
    const bool ordered = c == 0 || w > s.wall_slot[c - 1] ||
                         (w == s.wall_slot[c - 1] && q > s.wall_particle[c - 1]);
    if (!(w >= 0 && w < static_cast<int>(n_slots) && q >= 0 && q < static_cast<int>(n) && ordered))
      bad_state("wall histories must be sorted by (wall, particle) and name existing ones");
  }
}

void DemSystem::attach_contact_history(const ContactHistory& s) {
  const std::size_t n = p_.size();
  const auto n_slots = walls_.size();
  // The histories become the "previous" lists of the next rebuild, which carries them by key.
  PairList old;
  old.first.assign(n + 1, 0);
  for (int i : s.pair_i) ++old.first[static_cast<std::size_t>(i) + 1];
  for (std::size_t q = 0; q < n; ++q) old.first[q + 1] += old.first[q];
  old.i = s.pair_i;
  old.j = s.pair_j;
  old.history = s.pair_history;
  pairs_ = std::move(old);
  pair_out_.resize(pairs_.size(), 0);  // all inactive; slots sized by the coming rebuild
  wall_first_.assign(n_slots + 1, 0);
  for (int w : s.wall_slot) ++wall_first_[static_cast<std::size_t>(w) + 1];
  for (std::size_t w = 0; w < n_slots; ++w) wall_first_[w + 1] += wall_first_[w];
  wall_particle_ = s.wall_particle;
  wall_history_ = s.wall_history;
  wall_out_.resize(wall_particle_.size(), wall_particle_.size());
  wall_normal_.assign(wall_particle_.size(), 0.0);
  wall_elastic_normal_.assign(wall_particle_.size(), 0.0);
  list_valid_ = false;  // rebuilt (with the carry above) at the next force evaluation
  max_disp2_ = 0;
}

void DemSystem::seed_contact_history(const ContactHistory& h) {
  if (pending_dt_ > 0) throw std::logic_error("DemSystem::seed_contact_history inside a step");
  check_contact_history(h, p_.size());
  attach_contact_history(h);
  forces_valid_ = false;
}

DemSpecimenState DemSpecimen::save_state() const {
  DemSpecimenState s{sys_.save_state(), faces_, stepping_, elastic_0_, held_, held_work_, std::nullopt};
  if (breakage_) {
    const BreakageState& b = *breakage_;
    DemBreakageState out;
    out.id = b.id;
    out.strength = b.strength;
    out.generation.assign(b.generation.begin(), b.generation.end());
    out.n_primary = b.ledger.n_primary;
    out.n_secondary = b.ledger.n_secondary;
    out.lost_volume = b.ledger.lost_volume;
    for (const psd::FractalFines& f : b.ledger.fines) {
      out.fines_volume.push_back(f.volume);
      out.fines_d_min.push_back(f.d_min);
      out.fines_d_max.push_back(f.d_max);
      out.fines_alpha.push_back(f.alpha);
    }
    out.kinetic_removed = b.kinetic_removed;
    out.insertion_energy = b.insertion_energy;
    out.steps_since_check = steps_since_check_;
    out.time_since_check = time_since_check_;
    s.breakage = std::move(out);
  }
  return s;
}

void DemSpecimen::restore_state(const DemSpecimenState& s) {
  sys_.restore_state(s.system);
  faces_ = s.faces;
  stepping_ = s.stepping;
  elastic_0_ = s.elastic_0;
  held_ = s.held;
  held_work_ = s.held_work;
  held_faces_ = s.faces;  // while held, the faces of the last forces() call
  if (s.breakage.has_value() != breakage_.has_value())
    throw InputError("", "dem.state.breakage", breakage_ ? "the checkpoint has no breakage state, the scene has breakage"
                                                         : "the checkpoint has breakage, the scene has none");
  if (!breakage_) return;
  const DemBreakageState& in = *s.breakage;
  const std::size_t n = s.system.particles.size();
  if (in.id.size() != n || in.strength.size() != n || in.generation.size() != n)
    throw InputError("", "dem.state.breakage", "per-grain arrays do not match the particle count");
  BreakageState& b = *breakage_;
  b.id = in.id;
  b.strength = in.strength;
  b.generation.assign(in.generation.begin(), in.generation.end());
  b.ledger.n_primary = in.n_primary;
  b.ledger.n_secondary = in.n_secondary;
  b.ledger.lost_volume = in.lost_volume;
  b.ledger.fines.clear();
  for (std::size_t k = 0; k < in.fines_volume.size(); ++k)
    b.ledger.fines.push_back({in.fines_volume[k], in.fines_d_min[k], in.fines_d_max[k], in.fines_alpha[k]});
  b.kinetic_removed = in.kinetic_removed;
  b.insertion_energy = in.insertion_energy;
  steps_since_check_ = in.steps_since_check;
  time_since_check_ = in.time_since_check;
}

}  // namespace kolsky::dem
