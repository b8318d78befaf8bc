// The contact network (contact_network.hpp): rebuild from positions, carry through edits and
// checkpoints by key, and the sums over its per-contact outputs.
//
// Why a checkpoint stores histories by key and not the lists: restore_network invalidates the
// lists, so the next evaluation rebuilds them from the restored positions and re-attaches the
// histories by key (the same carry as an ordinary rebuild). The rebuild timing differs from the
// uninterrupted run, but it cannot change a result: only touching pairs produce forces, every
// list contains all of them, and all sums run over touching contacts in (owner, partner) /
// (wall, particle) order, which no list composition changes (test_dem_restart.cpp).
#include "dem/contact_network.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"

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

// The candidates of every wall (by slot), carrying each candidate's history by (slot, grain).
void build_wall_candidates(ContactNetwork& net, const Particles& p, const std::vector<Wall>& walls,
                           double skin) {
  const auto n_slots = walls.size();  // by slot (walls.hpp, WallSlots)
  std::vector<int> particle, first(n_slots + 1, 0);
  std::vector<Vec3> history;
  const bool carry = net.has_wall_lists(n_slots);
  for (std::size_t w = 0; w < n_slots; ++w) {
    std::size_t a = carry ? net.wall_first[w] : 0;
    const std::size_t a_end = carry ? net.wall_first[w + 1] : 0;
    for (std::size_t i = 0; i < p.size(); ++i) {
      // The candidates' round-off need not be the kernel's: only touching contacts give forces.
      if (gap_at(walls[w], p.x[i], p.radius[i]) >= skin) continue;
      particle.push_back(static_cast<int>(i));
      Vec3 h{};
      while (a < a_end && net.wall_particle[a] < static_cast<int>(i)) ++a;
      if (a < a_end && net.wall_particle[a] == static_cast<int>(i)) h = net.wall_history[a];
      history.push_back(h);
    }
    first[w + 1] = static_cast<int>(particle.size());
  }
  net.wall_particle.swap(particle);
  net.wall_first.swap(first);
  net.wall_history.swap(history);
  net.wall_out.resize(net.wall_particle.size(), net.wall_particle.size());
  net.wall_normal.resize(net.wall_particle.size());
  net.wall_elastic_normal.resize(net.wall_particle.size());
}

// Counting sort into slots, by partner (then pair order), of the pairs whose partner lies in
// another owner block; a partner in the owner's block gets its side in the sweep (slot -1).
void assign_partner_slots(ContactNetwork& net, int n) {
  const PairList& pairs = net.pairs;
  net.partner_first.assign(static_cast<std::size_t>(n) + 1, 0);
  std::vector<int> block_of(static_cast<std::size_t>(n));
  for (std::size_t b = 0; b + 1 < net.block_first.size(); ++b)
    std::fill(block_of.begin() + net.block_first[b], block_of.begin() + net.block_first[b + 1], static_cast<int>(b));
  auto crosses = [&](std::size_t k) { return block_of[pairs.i[k]] != block_of[pairs.j[k]]; };
  for (std::size_t k = 0; k < pairs.size(); ++k)
    if (crosses(k)) ++net.partner_first[pairs.j[k] + 1];
  for (int q = 0; q < n; ++q) net.partner_first[q + 1] += net.partner_first[q];
  net.pair_slot.resize(pairs.size());
  std::vector<int> fill(net.partner_first.begin(), net.partner_first.end() - 1);
  for (std::size_t k = 0; k < pairs.size(); ++k)
    net.pair_slot[k] = crosses(k) ? fill[pairs.j[k]]++ : -1;
  net.pair_out.resize(pairs.size(), static_cast<std::size_t>(net.partner_first[n]));
}


// The wall-contact part of remap: per wall slot, the survivors' contacts sorted by new grain.
void remap_wall_contacts(ContactNetwork& net, const std::vector<int>& old_to_new, std::size_t n_slots) {
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
    for (int c = net.wall_first[w]; c < net.wall_first[w + 1]; ++c) {
      const int q = old_to_new[net.wall_particle[c]];
      if (q >= 0) slot.push_back({q, net.wall_history[c], net.wall_out.out[c], net.wall_out.active[c],
                                  net.wall_normal[c], net.wall_elastic_normal[c]});
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
  net.wall_particle.swap(particle);
  net.wall_first.swap(first);
  net.wall_history.swap(history);
  net.wall_out.out.swap(out);
  net.wall_out.active.swap(active);
  net.wall_out.elastic.assign(net.wall_particle.size(), 0.0);  // pairs only; kept sized
  net.wall_normal.swap(normal);
  net.wall_elastic_normal.swap(elastic_normal);
}

}  // namespace

void ContactStore::resize(std::size_t n, std::size_t n_slots) {
  out.assign(n_slots, ContactOut{});
  active.assign(n, 0);
  elastic.assign(n, 0.0);
}

std::vector<int> uniform_owner_blocks(std::size_t n_grains, int block) {
  const int n = static_cast<int>(n_grains);
  std::vector<int> first;
  for (int i0 = 0; i0 < n; i0 += block) first.push_back(i0);
  first.push_back(n);
  return first;
}

bool needs_rebuild(const ContactNetwork& net, double skin, const std::vector<Wall>& walls) {
  if (!net.valid) return true;
  const double half = 0.5 * skin;
  if (net.max_disp2 > half * half) return true;
  return std::any_of(walls.begin(), walls.end(), [half](const Wall& w) { return moved_since_build(w) > half; });
}

void rebuild(ContactNetwork& net, const Particles& p, const std::vector<Wall>& walls, double skin) {
  net.pairs = build_pair_list(p.x, p.radius, skin, net.pairs);
  net.pair_r_eff.clear();  // formed again by the first batched evaluation of this list
  net.pair_m_eff.clear();
  build_wall_candidates(net, p, walls, skin);
  const int n = static_cast<int>(p.size());
  assign_partner_slots(net, n);
  // A carried non-zero history counts as active: the batched sweep clears the history of a
  // pair only when it goes from active to not touching (contact_forces_batched.cpp). The slots
  // stay zero; every evaluation rewrites active[] before anything reads it.
  for (std::size_t k = 0; k < net.pairs.size(); ++k) {
    const Vec3& h = net.pairs.history[k];
    net.pair_out.active[k] = h.x != 0 || h.y != 0 || h.z != 0;
  }
  net.wall_first_of.assign(static_cast<std::size_t>(n) + 1, 0);
  for (int q : net.wall_particle) ++net.wall_first_of[q + 1];
  for (int q = 0; q < n; ++q) net.wall_first_of[q + 1] += net.wall_first_of[q];
  net.wall_entry.resize(net.wall_particle.size());
  std::vector<int> fill(net.wall_first_of.begin(), net.wall_first_of.end() - 1);
  for (std::size_t c = 0; c < net.wall_particle.size(); ++c)
    net.wall_entry[fill[net.wall_particle[c]]++] = static_cast<int>(c);
  net.x_at_build = p.x;
  net.max_disp2 = 0;
  net.valid = true;
  ++net.n_rebuilds;
}

void forget_wall_contacts(ContactNetwork& net) {
  net.wall_particle.clear();
  net.wall_first.clear();
}

void reset_for_particles(ContactNetwork& net, std::size_t n, int block) {
  if (net.pairs.first.size() != n + 1) net.pairs = PairList{};
  if (net.block_first.empty() || net.block_first.back() != static_cast<int>(n))
    net.block_first = uniform_owner_blocks(n, block);
  forget_wall_contacts(net);
}

double stored_energy(const ContactNetwork& net) {
  double e = 0;
  for (double u : net.pair_out.elastic) e += u;  // pair order; zero where not touching
  for (std::size_t c = 0; c < net.wall_particle.size(); ++c)
    if (net.wall_out.active[c]) e += net.wall_out.out[c].elastic;
  return e;
}

std::size_t n_touching_pairs(const ContactNetwork& net) {
  return static_cast<std::size_t>(std::count(net.pair_out.active.begin(), net.pair_out.active.end(), 1));
}

std::size_t n_touching_wall_contacts(const ContactNetwork& net) {
  return static_cast<std::size_t>(std::count(net.wall_out.active.begin(), net.wall_out.active.end(), 1));
}

ContactHistory contact_history(const ContactNetwork& net, std::size_t n_particles, std::size_t n_walls) {
  ContactHistory h;
  const PairList& pairs = net.pairs;
  if (pairs.first.size() == n_particles + 1) {  // else no list yet (or edited particles)
    for (std::size_t k = 0; k < pairs.size(); ++k) {
      if (!stored(pairs.history[k])) continue;
      h.pair_i.push_back(pairs.i[k]);
      h.pair_j.push_back(pairs.j[k]);
      h.pair_history.push_back(pairs.history[k]);
    }
  }
  if (net.has_wall_lists(n_walls)) {
    for (std::size_t w = 0; w < n_walls; ++w)
      for (int c = net.wall_first[w]; c < net.wall_first[w + 1]; ++c) {
        if (!stored(net.wall_history[c])) continue;
        h.wall_slot.push_back(static_cast<int>(w));
        h.wall_particle.push_back(net.wall_particle[c]);
        h.wall_history.push_back(net.wall_history[c]);
      }
  }
  return h;
}

void check_contact_history(const ContactHistory& s, std::size_t n, std::size_t n_slots) {
  const std::size_t n_pairs = s.pair_i.size();
  if (s.pair_j.size() != n_pairs || s.pair_history.size() != n_pairs)
    bad_state("pair histories: i, j and history differ in length");
  for (std::size_t k = 0; k < n_pairs; ++k) {
    const int i = s.pair_i[k], j = s.pair_j[k];
    const bool ordered = k == 0 || i > s.pair_i[k - 1] || (i == s.pair_i[k - 1] && j > s.pair_j[k - 1]);
    if (!(i >= 0 && i < j && j < static_cast<int>(n) && ordered))
      bad_state("pair histories must be sorted pairs i < j of existing particles");
  }
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

void attach_contact_history(ContactNetwork& net, const ContactHistory& s, std::size_t n, std::size_t n_slots) {
  PairList old;
  old.first.assign(n + 1, 0);
  for (int i : s.pair_i) ++old.first[static_cast<std::size_t>(i) + 1];
  for (std::size_t q = 0; q < n; ++q) old.first[q + 1] += old.first[q];
  old.i = s.pair_i;
  old.j = s.pair_j;
  old.history = s.pair_history;
  net.pairs = std::move(old);
  net.pair_out.resize(net.pairs.size(), 0);  // all inactive; slots sized by the coming rebuild
  net.wall_first.assign(n_slots + 1, 0);
  for (int w : s.wall_slot) ++net.wall_first[static_cast<std::size_t>(w) + 1];
  for (std::size_t w = 0; w < n_slots; ++w) net.wall_first[w + 1] += net.wall_first[w];
  net.wall_particle = s.wall_particle;
  net.wall_history = s.wall_history;
  net.wall_out.resize(net.wall_particle.size(), net.wall_particle.size());
  net.wall_normal.assign(net.wall_particle.size(), 0.0);
  net.wall_elastic_normal.assign(net.wall_particle.size(), 0.0);
  net.valid = false;  // rebuilt (with the carry above) at the next force evaluation
  net.max_disp2 = 0;
}

ContactNetworkState save_network(const ContactNetwork& net, std::size_t n_particles, std::size_t n_walls) {
  ContactNetworkState s;
  static_cast<ContactHistory&>(s) = contact_history(net, n_particles, n_walls);
  s.n_rebuilds = net.n_rebuilds;
  s.owner_blocks = net.block_first;
  return s;
}

void check_network_state(const ContactNetworkState& s, std::size_t n, std::size_t n_walls) {
  const auto& b = s.owner_blocks;
  if (!b.empty()) {
    bool ok = b.size() >= 2 && b.front() == 0 && b.back() == static_cast<int>(n);
    for (std::size_t k = 1; ok && k < b.size(); ++k) ok = b[k] > b[k - 1];
    if (!ok) bad_state("owner blocks must rise strictly from 0 to the particle count");
  }
  check_contact_history(s, n, n_walls);
}

void restore_network(ContactNetwork& net, const ContactNetworkState& s, std::size_t n, std::size_t n_walls,
                     int block) {
  net.n_rebuilds = s.n_rebuilds;
  net.block_first = s.owner_blocks.empty() ? uniform_owner_blocks(n, block) : s.owner_blocks;
  attach_contact_history(net, s, n, n_walls);
}

void remap(ContactNetwork& net, const std::vector<int>& old_to_new, std::size_t n_new, std::size_t n_slots) {
  // Pairs: both grains kept. A monotone map keeps (i, j) sorted; a general one may flip a pair,
  // whose history (of j relative to i) then changes sign, and needs a sort.
  struct Carried {
    int i, j;
    Vec3 history;
    unsigned char active;
    double elastic;
  };
  const PairList& pairs = net.pairs;
  std::vector<Carried> kept;
  kept.reserve(pairs.size());
  const bool have_outputs = net.pair_out.active.size() == pairs.size();
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    const int a = old_to_new[pairs.i[k]], b = old_to_new[pairs.j[k]];
    if (a < 0 || b < 0) continue;
    const unsigned char act = have_outputs ? net.pair_out.active[k] : 0;
    const double el = have_outputs ? net.pair_out.elastic[k] : 0.0;
    if (a < b) kept.push_back({a, b, pairs.history[k], act, el});
    else kept.push_back({b, a, -pairs.history[k], act, el});
  }
  auto pair_less = [](const Carried& x, const Carried& y) { return x.i != y.i ? x.i < y.i : x.j < y.j; };
  if (!std::is_sorted(kept.begin(), kept.end(), pair_less)) std::sort(kept.begin(), kept.end(), pair_less);
  PairList list;
  list.first.assign(n_new + 1, 0);
  net.pair_out.resize(kept.size(), 0);  // slots: sized by the coming rebuild
  for (std::size_t k = 0; k < kept.size(); ++k) {
    ++list.first[static_cast<std::size_t>(kept[k].i) + 1];
    list.i.push_back(kept[k].i);
    list.j.push_back(kept[k].j);
    list.history.push_back(kept[k].history);
    net.pair_out.active[k] = kept[k].active;
    net.pair_out.elastic[k] = kept[k].elastic;
  }
  for (std::size_t q = 0; q < n_new; ++q) list.first[q + 1] += list.first[q];
  net.pairs = std::move(list);
  if (net.has_wall_lists(n_slots)) remap_wall_contacts(net, old_to_new, n_slots);
  net.valid = false;  // slots, gather lists and x_at_build are rebuilt from the carried lists
  net.max_disp2 = 0;
}

void carry_owner_blocks(ContactNetwork& net, const std::vector<int>& old_to_new, std::size_t n_kept,
                        std::size_t n_added, int block) {
  std::vector<int> blocks{0};
  for (std::size_t b = 0; b + 1 < net.block_first.size(); ++b) {
    int kept = 0;
    for (int i = net.block_first[b]; i < net.block_first[b + 1]; ++i) kept += old_to_new[i] >= 0 ? 1 : 0;
    if (kept > 0) blocks.push_back(blocks.back() + kept);
  }
  for (std::size_t a = 0; a < n_added; a += static_cast<std::size_t>(block))
    blocks.push_back(static_cast<int>(n_kept + std::min(n_added, a + block)));
  net.block_first.swap(blocks);
}

bool touches_removed(const ContactNetwork& net, const std::vector<int>& old_to_new) {
  const PairList& pairs = net.pairs;
  for (std::size_t k = 0; k < pairs.size(); ++k)
    if (net.pair_out.active[k] && (old_to_new[pairs.i[k]] < 0 || old_to_new[pairs.j[k]] < 0)) return true;
  for (std::size_t c = 0; c < net.wall_particle.size(); ++c)
    if (net.wall_out.active[c] && old_to_new[net.wall_particle[c]] < 0) return true;
  return false;
}

}  // namespace kolsky::dem
