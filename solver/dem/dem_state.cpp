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

[[noreturn]] void bad_state(const std::string& rule) {
  throw InputError("", "dem.state", rule);
}

}  // namespace

DemState DemSystem::save_state() const {
  DemState s;
  s.particles = p_;
  s.time = time_;
  s.pending_dt = pending_dt_;
  s.forces_valid = forces_valid_;
  static_cast<ContactNetworkState&>(s) = save_network(net_, p_.size(), walls_.size());
  static_cast<EnergyLedger&>(s) = ledger_;
  s.added_since_sort = added_since_sort_;
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
  check_ledger_state(s, n);
  validate(s.particles, materials_.size());
  check_network_state(s, n, walls_.size());

  p_ = s.particles;
  time_ = s.time;
  pending_dt_ = s.pending_dt;
  forces_valid_ = s.forces_valid;
  ledger_ = s;
  added_since_sort_ = s.added_since_sort;
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

  restore_network(net_, s, n, walls_.size(), opt_.owner_block);
}

ContactHistory DemSystem::contact_history() const {
  return dem::contact_history(net_, p_.size(), walls_.size());
}

void DemSystem::seed_contact_history(const ContactHistory& h) {
  if (pending_dt_ > 0) throw std::logic_error("DemSystem::seed_contact_history inside a step");
  check_contact_history(h, p_.size(), walls_.size());
  attach_contact_history(net_, h, p_.size(), walls_.size());
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
