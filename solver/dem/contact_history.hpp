// The tangential histories of a DEM assembly's contacts, keyed so that they survive a rebuild
// of the contact lists: grain pairs by (i, j), wall contacts by (wall slot, particle). It is
// the part of a checkpoint (dem_state.hpp) that a specimen's preparation hands to its run, so
// that the run starts in the frictional equilibrium the preparation ended in: without it every
// contact starts with no tangential force, and a packing held together by friction falls
// apart at rest (docs/dem.md, "A specimen at rest"). SI units (history: m, as the laws keep it).
#pragma once
#include <vector>

#include "dem/vec3.hpp"

namespace kolsky::dem {

struct ContactHistory {
  // Pairs (i < j) with a non-zero history, sorted by (i, j).
  std::vector<int> pair_i, pair_j;
  std::vector<Vec3> pair_history;
  // Wall contacts with a non-zero history: wall slot (WallSlots: planes first, then
  // cylinders), particle, sorted by (slot, particle).
  std::vector<int> wall_slot, wall_particle;
  std::vector<Vec3> wall_history;

  bool empty() const { return pair_i.empty() && wall_slot.empty(); }
};

}  // namespace kolsky::dem
