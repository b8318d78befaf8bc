// Particle edits over the components (particle_edit.hpp).
#include "dem/particle_edit.hpp"

#include <algorithm>
#include <string>

#include "core/errors.hpp"
#include "dem/neighbour_list.hpp"
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

std::vector<int> edit_index_map(const ParticleEdit& e, std::size_t n, std::size_t n_materials) {
  std::vector<int> old_to_new(n, 0);
  for (std::size_t k = 0; k < e.removed.size(); ++k) {
    const int q = e.removed[k];
    const std::string at = "dem.edit.removed[" + std::to_string(k) + "]";
    if (q < 0 || static_cast<std::size_t>(q) >= n)
      throw InputError("", at, "index " + std::to_string(q) + " is not a particle (0.." + std::to_string(n - 1) + ")");
    if (old_to_new[q] < 0) throw InputError("", at, "particle " + std::to_string(q) + " is removed twice");
    old_to_new[q] = -1;
  }
  if (e.added.size() > 0) validate(e.added, n_materials);
  const std::size_t n_new = n - e.removed.size() + e.added.size();
  if (n_new == 0) throw InputError("", "dem.edit", "the edit would leave no particle");
  for (std::size_t i = 0, next = 0; i < n; ++i)
    if (old_to_new[i] >= 0) old_to_new[i] = static_cast<int>(next++);
  return old_to_new;
}

bool apply_edit(Particles& p, ContactNetwork& net, EnergyLedger& ledger, std::size_t n_walls,
                const ParticleEdit& e, const std::vector<int>& old_to_new, int owner_block) {
  const std::size_t n = p.size();
  const std::size_t n_kept = n - e.removed.size(), n_new = n_kept + e.added.size();
  const bool lost_contact = touches_removed(net, old_to_new);
  std::vector<int> survivors;  // new index k <- old survivors[k]
  survivors.reserve(n_kept);
  for (std::size_t i = 0; i < n; ++i)
    if (old_to_new[i] >= 0) survivors.push_back(static_cast<int>(i));
  carry_ledger(ledger, old_to_new, survivors, n_new);
  carry_owner_blocks(net, old_to_new, n_kept, e.added.size(), owner_block);
  p = compacted(std::move(p), survivors, e.added);
  remap(net, old_to_new, n_new, n_walls);
  return lost_contact;
}

bool added_grains_touch(const Particles& p, const std::vector<Wall>& walls, std::size_t first_added, double skin) {
  const std::size_t n = p.size();
  if (first_added == n) return false;
  // The candidate list of the new configuration (skin 0 would do; the system's skin is as
  // cheap and keeps one grid rule), then the exact overlap test of the force kernels.
  const PairList touching = build_pair_list(p.x, p.radius, skin, PairList{});
  for (std::size_t k = 0; k < touching.size(); ++k) {
    const int i = touching.i[k], j = touching.j[k];
    if (static_cast<std::size_t>(std::max(i, j)) < first_added) continue;
    const double rsum = p.radius[i] + p.radius[j];
    if (norm2(p.x[j] - p.x[i]) < rsum * rsum) return true;
  }
  // The kernel's overlap test against every wall, with its FE profile if it has one.
  for (std::size_t q = first_added; q < n; ++q)
    for (const Wall& w : walls)
      if (-gap_at(w, p.x[q], p.radius[q]) > 0) return true;
  return false;
}

std::vector<int> resort_for_locality(Particles& p, ContactNetwork& net, EnergyLedger& ledger, std::size_t n_walls,
                                     int owner_block) {
  const double cell = 2.0 * *std::min_element(p.radius.begin(), p.radius.end());
  const std::vector<int> order = morton_order(p, cell);  // new k <- old order[k]
  std::vector<int> old_to_new(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) old_to_new[static_cast<std::size_t>(order[k])] = static_cast<int>(k);
  p.permute(order);
  permute_ledger(ledger, order);
  remap(net, old_to_new, p.size(), n_walls);
  net.block_first = uniform_owner_blocks(p.size(), owner_block);
  return old_to_new;
}

}  // namespace kolsky::dem
