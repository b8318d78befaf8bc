// Spatial orders of the particles: sort_spatially() and sort_morton() order them cell by cell
// so neighbours sit close in memory (docs/dem.md, "Performance"); morton_order() is the
// permutation the Morton sort applies (DemSystem's re-sort after an edit, particle_edit.cpp).
#pragma once
#include <vector>

#include "dem/particles.hpp"

namespace kolsky::dem {

/// Reorders particles by the cell (z, then y, then x) of a grid of the given size (m).
/// Throws kolsky::InputError ("dem.sort.cell") unless cell > 0 and extent / cell < 2^20.
void sort_spatially(Particles& p, double cell);

/// Reorders particles along the Morton (Z-order) curve of the cells of a grid of the given size
/// (m): the cells of every 2 x 2 x 2, 4 x 4 x 4, ... block come consecutively, so neighbours in
/// all three directions sit close in memory, not only those along x (docs/dem.md,
/// "Performance"). Same errors as sort_spatially.
void sort_morton(Particles& p, double cell);
/// The order sort_morton applies: new index k takes old particle order[k].
std::vector<int> morton_order(const Particles& p, double cell);

}  // namespace kolsky::dem
