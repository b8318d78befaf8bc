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
  bool contacts_change = touches_removed(net_, old_to_new);

  std::vector<int> survivors;  // new index k <- old survivors[k]
  survivors.reserve(n_kept);
  for (std::size_t i = 0; i < n; ++i)
    if (old_to_new[i] >= 0) survivors.push_back(static_cast<int>(i));
  carry_ledger(ledger_, old_to_new, survivors, n_new);

  // Owner blocks: survivors stay in theirs (emptied blocks vanish), added grains in new ones.
  carry_owner_blocks(net_, old_to_new, n_kept, e.added.size(), opt_.owner_block);

  p_ = compacted(std::move(p_), survivors, e.added);
  remap(net_, old_to_new, n_new, walls_.size());
  skin_ = opt_.skin_over_min_radius * *std::min_element(p_.radius.begin(), p_.radius.end());
  stable_dt_ = compute_stable_dt();
  if (!contacts_change) contacts_change = added_grains_touch(n_kept);

  // A contact gained or lost: evaluate now, as begin_step would first (history unchanged, no
  // time advance), so the stored energy the edit moved is booked exactly. Otherwise the
  // survivors' forces and stored energies stand as they are.
  if (contacts_change) compute_forces(0.0);
  const DemEnergy after = energy();
  book_edit(ledger_, before, after);

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
  permute_ledger(ledger_, order);
  remap(net_, old_to_new, p_.size(), walls_.size());
  net_.block_first = uniform_owner_blocks(p_.size(), opt_.owner_block);
  added_since_sort_ = 0;
  ++n_resorts_;
  return old_to_new;
}

}  // namespace kolsky::dem
