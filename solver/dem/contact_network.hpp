// The contact network of a DEM assembly, a value type beside the particles it links (issue 32):
// the grain-pair list (CSR, pairs i < j) with each pair's tangential history; the owner blocks
// the force sweep runs over, and the slots through which a pair across blocks hands its
// partner's side to the gather; the wall-contact candidates by wall slot with their
// histories; and what the last force evaluation wrote per contact (touching flags, stored
// energies, wall normal forces). rebuild() makes it from the particles' positions (the
// neighbour list, neighbour_list.hpp) and the walls; remap() carries it through particle edits
// by key; save_network / restore_network are its own part of a checkpoint (dem_state.hpp).
// It holds no law: the force kernels (contact_forces*.cpp) evaluate the laws into its outputs.
//
// Towards MPI (not implemented; docs/dem.md, "Towards MPI"): one rank owns grains
// [0, n_owned) of its Particles and holds ghost copies of its neighbours' boundary grains at
// [n_owned, n). The network is then built from the local + ghost grains with owners i < n_owned
// only (ghosts last, so a half list i < j puts every ghost partner at j): owner blocks cover the
// owned grains, every pair with a ghost partner crosses blocks and its partner side lands in a
// slot, and the slots of the ghosts are the buffer sent back to their owners. Wall candidates
// are owned grains only (walls are global). Histories cross ranks keyed by grain id, not index.
#pragma once
#include <cmath>
#include <cstddef>
#include <variant>
#include <vector>

#include "dem/contact_history.hpp"
#include "dem/neighbour_list.hpp"
#include "dem/particles.hpp"
#include "dem/vec3.hpp"
#include "dem/wall.hpp"

namespace kolsky::dem {

/// What a contact hands to the grain that gathers it (for a pair: the partner j's side, since
/// the owner i sums its own while computing; for a wall: the grain's), and its stored energy.
/// One 64-byte cache line per contact, so that the scattered store of a pair's partner side
/// touches one line, not two or three.
struct alignas(64) ContactOut {
  Vec3 force, torque;
  double dissipated = 0;
  double elastic = 0;
};

/// Per-contact outputs of one force evaluation. For walls, active[c] flags a touching contact
/// c. For pairs, active[k] and elastic[k] (the stored energy; out[].elastic stays 0) are
/// indexed by pair (written in order while the owners are swept), and the slots and energies
/// of pairs that do not touch hold zeros (cleared when a contact separates, and at every
/// rebuild), so that the gather and the energy add every one without a branch: adding +0 to a
/// sum that started at +0 leaves it bitwise unchanged (such a sum is never -0). For pairs,
/// out holds the cross-block slots only.
struct ContactStore {
  std::vector<ContactOut> out;
  std::vector<unsigned char> active;
  std::vector<double> elastic;  // pairs only
  /// n contacts (active, elastic), n_slots outputs (out); all inactive, all zero.
  void resize(std::size_t n, std::size_t n_slots);
};

struct ContactNetwork {
  // Grain pairs (CSR by owner i, partners j > i) with their tangential histories.
  PairList pairs;
  // Owner blocks: grains [block_first[b], block_first[b+1]), never empty; uniform at the start
  // and after a locality re-sort, carried through edits (each survivor keeps its block).
  std::vector<int> block_first;
  // Pair k whose partner lies in another owner block (else pair_slot[k] = -1) stores its
  // partner's side in slot pair_slot[k] of pair_out; the slots of grain q are
  // [partner_first[q], partner_first[q+1]) (pair order), so the gather streams through memory.
  std::vector<int> pair_slot, partner_first;
  ContactStore pair_out;
  // r* = r_i r_j / (r_i + r_j) and m* = m_i m_j / (m_i + m_j) of each listed pair, with the
  // law's own expressions (so the same bits), once per list instead of at every step: the
  // batched Hertz-Mindlin sweep forms them at its first evaluation after a rebuild (which
  // empties them); radii and masses change only through edits or mutable_particles(), which
  // invalidate the lists. Two of the batch law's 13 roots and divisions.
  std::vector<double> pair_r_eff, pair_m_eff;
  // Wall-contact candidates grouped by wall slot (WallSlots: planes, then cylinders), sorted by
  // grain, with their histories, outputs and normal forces (total, and the elastic part).
  std::vector<int> wall_particle, wall_first;
  std::vector<Vec3> wall_history;
  ContactStore wall_out;
  std::vector<double> wall_normal, wall_elastic_normal;  // N
  // Gather lists of the wall contacts: those of grain q are wall_entry[wall_first_of[q] ...].
  std::vector<int> wall_first_of, wall_entry;
  // Validity: positions at the last rebuild and the largest squared displacement since (m^2).
  std::vector<Vec3> x_at_build;
  double max_disp2 = 0;
  bool valid = false;  // false: rebuild before the next evaluation
  std::size_t n_rebuilds = 0;

  /// Whether the wall-candidate lists describe `n_walls` walls (else there are none yet).
  bool has_wall_lists(std::size_t n_walls) const { return wall_first.size() == n_walls + 1; }
};

/// The network's part of a checkpoint: the non-zero tangential histories (by key), the owner
/// blocks (empty: the uniform blocks) and the rebuild count (bookkeeping only).
struct ContactNetworkState : ContactHistory {
  std::size_t n_rebuilds = 0;
  std::vector<int> owner_blocks;
};

/// Blocks of `block` grains over n grains (the last one shorter): {0, block, ..., n}.
std::vector<int> uniform_owner_blocks(std::size_t n, int block);
/// Whether some grain moved more than skin/2 since the last rebuild, or a wall's surface did
/// (or the lists are invalid).
bool needs_rebuild(const ContactNetwork& net, double skin, const std::vector<Wall>& walls);
/// Rebuilds the pair list (carrying histories by pair), the wall candidates (carrying theirs by
/// (slot, grain)), the cross-block slots and the gather lists from the particles' positions.
/// The caller marks its walls built (mark_built).
void rebuild(ContactNetwork& net, const Particles& p, const std::vector<Wall>& walls, double skin);
/// Forgets the wall candidates (the walls changed: their slots no longer key the histories).
void forget_wall_contacts(ContactNetwork& net);
/// After the particles were replaced: drops a pair list of another particle count and the
/// wall candidates; uniform owner blocks if theirs do not cover n grains.
void reset_for_particles(ContactNetwork& net, std::size_t n, int block);

/// Carries the lists and per-contact outputs through an index map (old_to_new[i]: new index of
/// grain i, -1 removed): pairs of two survivors, re-sorted (a pair whose order flips gets its
/// history negated), wall contacts by (slot, new grain). Invalidates the lists (the next
/// evaluation rebuilds them and carries by key).
void remap(ContactNetwork& net, const std::vector<int>& old_to_new, std::size_t n_new, std::size_t n_walls);
/// Owner blocks after an edit: survivors stay in theirs (emptied blocks vanish), n_added grains
/// appended after the n_kept survivors form new blocks of at most `block`.
void carry_owner_blocks(ContactNetwork& net, const std::vector<int>& old_to_new, std::size_t n_kept,
                        std::size_t n_added, int block);
/// Whether a touching contact of the last evaluation involves a grain the map removes.
bool touches_removed(const ContactNetwork& net, const std::vector<int>& old_to_new);

/// The non-zero tangential histories (-0.0 kept: not bitwise zero), pairs then walls, by key.
ContactHistory contact_history(const ContactNetwork& net, std::size_t n_particles, std::size_t n_walls);
/// Throws kolsky::InputError ("dem.state") for histories that are unsorted or name no grain or
/// wall of a system of n_particles grains and n_walls walls.
void check_contact_history(const ContactHistory& h, std::size_t n_particles, std::size_t n_walls);
/// Makes the histories the "previous" lists of the next rebuild (which carries them by key),
/// every contact inactive. Precondition: check_contact_history passed.
void attach_contact_history(ContactNetwork& net, const ContactHistory& h, std::size_t n_particles,
                            std::size_t n_walls);

ContactNetworkState save_network(const ContactNetwork& net, std::size_t n_particles, std::size_t n_walls);
/// Throws kolsky::InputError ("dem.state") for bad histories or owner blocks that do not rise
/// strictly from 0 to n_particles.
void check_network_state(const ContactNetworkState& s, std::size_t n_particles, std::size_t n_walls);
/// Precondition: check_network_state passed. Uniform blocks of `block` when s has none.
void restore_network(ContactNetwork& net, const ContactNetworkState& s, std::size_t n_particles,
                     std::size_t n_walls, int block);

/// The energy stored in the contacts of the last evaluation (J): pairs in pair order, then the
/// touching wall contacts in list order.
double stored_energy(const ContactNetwork& net);
std::size_t n_touching_pairs(const ContactNetwork& net);
std::size_t n_touching_wall_contacts(const ContactNetwork& net);

/// Calls f(i, force on grain i) for every touching contact of wall `slot` in candidate order.
template <class F> void for_each_wall_force(const ContactNetwork& net, int slot, F&& f) {
  if (net.wall_first.size() <= static_cast<std::size_t>(slot) + 1) return;
  for (int c = net.wall_first[slot]; c < net.wall_first[slot + 1]; ++c)
    if (net.wall_out.active[c]) f(net.wall_particle[c], net.wall_out.out[c].force);
}

/// Calls pair(i, j, x_j - x_i, |x_j - x_i|) for every touching grain pair of the last
/// evaluation (pair order), then wall(i, slot, unit normal towards the wall, overlap, elastic
/// normal force) for every touching wall contact (by slot, then grain): one serial pass over
/// the flags the sweep wrote, recomputing only the geometry of those contacts with the sweep's
/// own formulas (contact_forces.cpp; wall.hpp), so a contact is visited exactly when it produced a
/// force. Serial and in a fixed order: its users decide things (which grains break) that must
/// not depend on the thread count. A template, so that the caller's work is inlined.
template <class Pair, class OnWall>
void for_each_touching_contact(const ContactNetwork& net, const Particles& p, const std::vector<Wall>& walls,
                               Pair&& pair, OnWall&& wall) {
  const PairList& pairs = net.pairs;
  for (std::size_t k = 0; k < pairs.size(); ++k) {
    if (!net.pair_out.active[k]) continue;
    const int i = pairs.i[k], j = pairs.j[k];
    const Vec3 d = p.x[j] - p.x[i];
    pair(i, j, d, std::sqrt(dot(d, d)));
  }
  // Wall contacts by slot, each wall's shape resolved once: the kernel's gap and normal
  // (wall.hpp), so the overlap is the one that produced the force.
  for (int s = 0; s < static_cast<int>(walls.size()); ++s) {
    std::visit(
        [&](const auto& shape) {
          for (int c = net.wall_first[s]; c < net.wall_first[s + 1]; ++c) {
            if (!net.wall_out.active[c]) continue;
            const int i = net.wall_particle[c];
            const Vec3& x = p.x[i];
            wall(i, s, normal_at(shape, x), -gap_at(shape, x, p.radius[i]), net.wall_elastic_normal[c]);
          }
        },
        walls[s].shape);
  }
}

}  // namespace kolsky::dem
