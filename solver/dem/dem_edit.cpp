// DemSystem::edit: remove and add grains between steps, carrying everything that survives
// (dem_system.hpp). Breakage (Sec. 5.2.3) replaces one grain by 14 fragments many times in a
// run; dropping the lists as mutable_particles() does would zero every tangential spring in
// the specimen at each break.
//
// What is carried, and why it keeps results bitwise where nothing physical changed:
//  - particle arrays (forces too) and the per-particle dissipation, compacted in order;
//  - pair histories and per-pair outputs keyed by the pair, wall histories and outputs keyed by
//    (wall slot, particle): the lists are rebuilt at the next evaluation and carry by key, as
//    after a restart (dem_state.hpp: list composition never changes a result);
//  - the owner-block partition: each survivor keeps its block, so the same pairs cross blocks
//    and every grain's sums keep their order (pair_forces); added grains form new blocks.
// Energy: removed grains take their kinetic energy, contact energy and booked dissipation out
// of the arrays; the first two go to DemEnergy::edited, the last to the dissipated total.
#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"
#include "dem/dem_system.hpp"
#include "dem/spatial_sort.hpp"

namespace kolsky::dem {

namespace {

/// v reordered: entry k is v[order[k]] (order may leave entries out).
template <class T>
std::vector<T> gathered(const std::vector<T>& v, const std::vector<int>& order) {
  std::vector<T> out(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[k] = v[static_cast<std::size_t>(order[k])];
  return out;
}

/// The survivors in `order` (Particles::permute keeps only those), then `added` with no force.
Particles compacted(Particles p, const std::vector<int>& order, const Particles& added) {
  p.permute(order);
  const auto append = [](auto& to, const auto& from) { to.insert(to.end(), from.begin(), from.end()); };
  append(p.x, added.x);
  append(p.v, added.v);
  append(p.omega, added.omega);
  p.f.resize(p.x.size());  // no contact has acted on them yet
  p.torque.resize(p.x.size());
  append(p.radius, added.radius);
  append(p.mass, added.mass);
  append(p.inertia, added.inertia);
  append(p.material, added.material);
  return p;
}

}  // namespace

EditMap DemSystem::edit(const ParticleEdit& e) {
  if (pending_dt_ > 0) throw std::logic_error("DemSystem::edit between begin_step and finish_step");
  if (particles_changed_) refresh_after_edit();
  const std::size_t n = p_.size();
  std::vector<int> old_to_new(n, 0);
  for (std::size_t k = 0; k < e.removed.size(); ++k) {
    const int q = e.removed[k];
    const std::string at = "dem.edit.removed[" + std::to_string(k) + "]";
    if (q < 0 || static_cast<std::size_t>(q) >= n)
      throw InputError("", at, "index " + std::to_string(q) + " is not a particle (0.." + std::to_string(n - 1) + ")");
    if (old_to_new[q] < 0) throw InputError("", at, "particle " + std::to_string(q) + " is removed twice");
    old_to_new[q] = -1;
  }
  if (e.added.size() > 0) validate(e.added, materials_.size());
  const std::size_t n_kept = n - e.removed.size(), n_new = n_kept + e.added.size();
  if (n_new == 0) throw InputError("", "dem.edit", "the edit would leave no particle");
  for (std::size_t i = 0, next = 0; i < n; ++i)
    if (old_to_new[i] >= 0) old_to_new[i] = static_cast<int>(next++);

  // Energies are booked against evaluated forces (as begin_step would evaluate them first).
  if (!forces_valid_) compute_forces(0.0);
  const DemEnergy before = energy();
  bool contacts_change = false;
  for (std::size_t k = 0; k < pairs_.size() && !contacts_change; ++k)
    contacts_change = pair_out_.active[k] && (old_to_new[pairs_.i[k]] < 0 || old_to_new[pairs_.j[k]] < 0);
  for (std::size_t c = 0; c < wall_particle_.size() && !contacts_change; ++c)
    contacts_change = wall_out_.active[c] && old_to_new[wall_particle_[c]] < 0;

  std::vector<int> survivors;  // new index k <- old survivors[k]
  survivors.reserve(n_kept);
  for (std::size_t i = 0; i < n; ++i) {
    if (old_to_new[i] >= 0) survivors.push_back(static_cast<int>(i));
    else removed_dissipated_ += dissipated_[i];
  }
  dissipated_ = gathered(dissipated_, survivors);
  dissipated_.resize(n_new, 0.0);

  // Owner blocks: survivors stay in theirs (emptied blocks vanish), added grains in new ones.
  std::vector<int> blocks{0};
  for (std::size_t b = 0; b + 1 < block_first_.size(); ++b) {
    int kept = 0;
    for (int i = block_first_[b]; i < block_first_[b + 1]; ++i) kept += old_to_new[i] >= 0 ? 1 : 0;
    if (kept > 0) blocks.push_back(blocks.back() + kept);
  }
  for (std::size_t a = 0; a < e.added.size(); a += static_cast<std::size_t>(opt_.owner_block))
    blocks.push_back(static_cast<int>(n_kept + std::min(e.added.size(), a + opt_.owner_block)));
  block_first_.swap(blocks);

  p_ = compacted(std::move(p_), survivors, e.added);
  remap_contacts(old_to_new, n_new);
  skin_ = opt_.skin_over_min_radius * *std::min_element(p_.radius.begin(), p_.radius.end());
  stable_dt_ = compute_stable_dt();
  if (!contacts_change) contacts_change = added_grains_touch(n_kept);

  // A contact gained or lost: evaluate now, as begin_step would first (history unchanged, no
  // time advance), so the stored energy the edit moved is booked exactly. Otherwise the
  // survivors' forces and stored energies stand as they are.
  if (contacts_change) compute_forces(0.0);
  const DemEnergy after = energy();
  edited_energy_ += (before.kinetic + before.elastic) - (after.kinetic + after.elastic);

  added_since_sort_ += e.added.size();
  EditMap map{std::move(old_to_new), std::vector<int>(e.added.size())};
  std::iota(map.added_at.begin(), map.added_at.end(), static_cast<int>(n_kept));
  if (opt_.resort_added_fraction > 0 &&
      static_cast<double>(added_since_sort_) > opt_.resort_added_fraction * static_cast<double>(n_new)) {
    const std::vector<int> sorted = resort_for_locality();
    for (int& q : map.old_to_new)
      if (q >= 0) q = sorted[static_cast<std::size_t>(q)];
    for (int& q : map.added_at) q = sorted[static_cast<std::size_t>(q)];
  }
  return map;
}

void DemSystem::remap_contacts(const std::vector<int>& old_to_new, std::size_t n_new) {
  // Pairs: both grains kept. A monotone map keeps (i, j) sorted; a general one may flip a pair,
  // whose history (of j relative to i) then changes sign, and needs a sort.
  struct Carried {
    int i, j;
    Vec3 history;
    unsigned char active;
    double elastic;
  };
  std::vector<Carried> kept;
  kept.reserve(pairs_.size());
  const bool have_outputs = pair_out_.active.size() == pairs_.size();
  for (std::size_t k = 0; k < pairs_.size(); ++k) {
    const int a = old_to_new[pairs_.i[k]], b = old_to_new[pairs_.j[k]];
    if (a < 0 || b < 0) continue;
    const unsigned char act = have_outputs ? pair_out_.active[k] : 0;
    const double el = have_outputs ? pair_out_.elastic[k] : 0.0;
    if (a < b) kept.push_back({a, b, pairs_.history[k], act, el});
    else kept.push_back({b, a, -pairs_.history[k], act, el});
  }
  auto pair_less = [](const Carried& x, const Carried& y) { return x.i != y.i ? x.i < y.i : x.j < y.j; };
  if (!std::is_sorted(kept.begin(), kept.end(), pair_less)) std::sort(kept.begin(), kept.end(), pair_less);
  PairList list;
  list.first.assign(n_new + 1, 0);
  pair_out_.resize(kept.size(), 0);  // slots: sized by the coming rebuild
  for (std::size_t k = 0; k < kept.size(); ++k) {
    ++list.first[static_cast<std::size_t>(kept[k].i) + 1];
    list.i.push_back(kept[k].i);
    list.j.push_back(kept[k].j);
    list.history.push_back(kept[k].history);
    pair_out_.active[k] = kept[k].active;
    pair_out_.elastic[k] = kept[k].elastic;
  }
  for (std::size_t q = 0; q < n_new; ++q) list.first[q + 1] += list.first[q];
  pairs_ = std::move(list);

  // Wall contacts: per wall slot, sorted by (new) particle.
  const auto n_slots = walls_.size();  // by slot (WallSlots)
  if (wall_first_.size() == n_slots + 1) {
    struct WallEntry {
      int particle;
      Vec3 history;
      ContactOut out;
      unsigned char active;
      double normal, elastic_normal;
    };
    std::vector<int> particle, first{0};
    std::vector<Vec3> history;
    std::vector<ContactOut> out;
    std::vector<unsigned char> active;
    std::vector<double> normal, elastic_normal;
    for (std::size_t w = 0; w < n_slots; ++w) {
      std::vector<WallEntry> slot;
      for (int c = wall_first_[w]; c < wall_first_[w + 1]; ++c) {
        const int q = old_to_new[wall_particle_[c]];
        if (q >= 0) slot.push_back({q, wall_history_[c], wall_out_.out[c], wall_out_.active[c], wall_normal_[c],
                                 wall_elastic_normal_[c]});
      }
      std::stable_sort(slot.begin(), slot.end(), [](const WallEntry& x, const WallEntry& y) { return x.particle < y.particle; });
      for (const WallEntry& c : slot) {
        particle.push_back(c.particle);
        history.push_back(c.history);
        out.push_back(c.out);
        active.push_back(c.active);
        normal.push_back(c.normal);
        elastic_normal.push_back(c.elastic_normal);
      }
      first.push_back(static_cast<int>(particle.size()));
    }
    wall_particle_.swap(particle);
    wall_first_.swap(first);
    wall_history_.swap(history);
    wall_out_.out.swap(out);
    wall_out_.active.swap(active);
    wall_out_.elastic.assign(wall_particle_.size(), 0.0);  // pairs only; kept sized
    wall_normal_.swap(normal);
    wall_elastic_normal_.swap(elastic_normal);
  }
  list_valid_ = false;  // slots, gather lists and x_at_build_ are rebuilt from the carried lists
  max_disp2_ = 0;
}

bool DemSystem::added_grains_touch(std::size_t first_added) const {
  const std::size_t n = p_.size();
  if (first_added == n) return false;
  // The candidate list of the new configuration (skin 0 would do; the system's skin is as
  // cheap and keeps one grid rule), then the exact overlap test of the force kernels.
  const PairList touching = build_pair_list(p_.x, p_.radius, skin_, PairList{});
  for (std::size_t k = 0; k < touching.size(); ++k) {
    const int i = touching.i[k], j = touching.j[k];
    if (static_cast<std::size_t>(std::max(i, j)) < first_added) continue;
    const double rsum = p_.radius[i] + p_.radius[j];
    if (norm2(p_.x[j] - p_.x[i]) < rsum * rsum) return true;
  }
  // The kernel's overlap test against every wall, with its FE profile if it has one.
  for (std::size_t q = first_added; q < n; ++q)
    for (const Wall& w : walls_)
      if (-gap_at(w, p_.x[q], p_.radius[q]) > 0) return true;
  return false;
}

std::vector<int> DemSystem::resort_for_locality() {
  const double cell = 2.0 * *std::min_element(p_.radius.begin(), p_.radius.end());
  const std::vector<int> order = morton_order(p_, cell);  // new k <- old order[k]
  std::vector<int> old_to_new(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) old_to_new[static_cast<std::size_t>(order[k])] = static_cast<int>(k);
  p_.permute(order);
  dissipated_ = gathered(dissipated_, order);
  remap_contacts(old_to_new, p_.size());
  reset_owner_blocks();
  added_since_sort_ = 0;
  ++n_resorts_;
  return old_to_new;
}

}  // namespace kolsky::dem
