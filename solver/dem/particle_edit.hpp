// Particle edits as free functions over a DEM assembly's components (issue 32): remove and add
// grains between steps, carrying everything that survives through the particles, the contact
// network and the energy ledger; and the locality re-sort. Breakage (Sec. 5.2.3) replaces one
// grain by 14 fragments many times in a run; dropping the lists as
// DemSystem::mutable_particles() does would zero every tangential spring in the specimen at
// each break. DemSystem::edit composes them with the force evaluations and the energy booking
// around them (docs/dem.md, "Particle edits").
//
// What is carried, and why it keeps results bitwise where nothing physical changed:
//  - particle arrays (forces too) and the per-particle dissipation, compacted in order;
//  - pair histories and per-pair outputs keyed by the pair, wall histories and outputs keyed by
//    (wall slot, particle): the lists are rebuilt at the next evaluation and carry by key, as
//    after a restart (contact_network.cpp: list composition never changes a result);
//  - the owner-block partition: each survivor keeps its block, so the same pairs cross blocks
//    and every grain's sums keep their order (contact_forces.cpp); added grains form new blocks.
// Towards MPI: a rank edits its owned grains only; added grains get fresh global ids.
#pragma once
#include <cstddef>
#include <vector>

#include "dem/contact_network.hpp"
#include "dem/energy_ledger.hpp"
#include "dem/particles.hpp"
#include "dem/wall.hpp"

namespace kolsky::dem {

/// One particle edit (a grain replaced by its fragments, Sec. 5.2.3): remove the grains
/// `removed` (indices, unique, any order), then append `added` (positions, velocities, spins,
/// radii, materials, masses and inertias; their forces are ignored). Survivors keep their
/// order, added grains follow them (unless the edit triggers a locality re-sort).
struct ParticleEdit {
  std::vector<int> removed;
  Particles added;
};

/// Where an edit put every grain: old_to_new[i] = the new index of old grain i (-1: removed),
/// added_at[k] = the new index of added grain k.
struct EditMap {
  std::vector<int> old_to_new, added_at;
};

/// The index map of edit e of n grains: old_to_new[i] = the new index of grain i (survivors in
/// order), -1 for a removed one. Throws kolsky::InputError ("dem.edit...") for an index that is
/// no grain or is removed twice, an invalid added grain, or an edit that would leave none.
std::vector<int> edit_index_map(const ParticleEdit& e, std::size_t n, std::size_t n_materials);

/// Applies edit e with its map (edit_index_map) to the components: survivors compacted in order
/// and the added grains appended with no force (particles); the removed grains' dissipation
/// booked and the survivors' carried (ledger); the lists and outputs carried by key and each
/// survivor kept in its owner block, added grains in new blocks of at most owner_block
/// (network). Returns whether a touching contact of the last evaluation was lost with a
/// removed grain. Precondition: the network's outputs are those of the current particles.
bool apply_edit(Particles& p, ContactNetwork& net, EnergyLedger& ledger, std::size_t n_walls,
                const ParticleEdit& e, const std::vector<int>& old_to_new, int owner_block);

/// Whether a grain from first_added on overlaps another grain or a wall, by the force
/// kernels' exact overlap tests (candidates from a pair list with the given skin, m).
bool added_grains_touch(const Particles& p, const std::vector<Wall>& walls, std::size_t first_added, double skin);

/// Re-sorts every grain along the Morton curve of cells of the smallest diameter
/// (spatial_sort.hpp) with its dissipation and contacts, and starts uniform owner blocks of
/// owner_block. Returns old_to_new of the re-sort. Results move by round-off (each grain's
/// summation order changes), never physics.
std::vector<int> resort_for_locality(Particles& p, ContactNetwork& net, EnergyLedger& ledger, std::size_t n_walls,
                                     int owner_block);

}  // namespace kolsky::dem
