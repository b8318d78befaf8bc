// Verlet pair list for polydisperse spheres. Each pair is searched from its larger grain, for
// partners no larger than itself, over the cells of a uniform grid of side 2 r_min + skin that
// overlap the cube of half-width 2 r_i + skin around it: the many small grains scan 27 small
// cells, only the few large ones a wide stencil (a single-level scheme: adequate for the 4:1
// size ratio of the sand packings). A pair (i < j) is kept when |x_i - x_j| < r_i + r_j +
// skin; the list stays valid until some particle has moved more than skin/2 (DemSystem checks
// this). Pairs are sorted by (i, j) and grouped by i (CSR), identically for any thread count;
// the tangential history of a pair that is in both the old and the new list is carried over
// (keyed by the pair (i, j)).
#pragma once
#include <vector>

#include "dem/vec3.hpp"

namespace kolsky::dem {

/// Half pair list in CSR form: the pairs of particle i are k in [first[i], first[i+1]),
/// with partner j[k] > i in increasing order; history[k] is the tangential displacement.
struct PairList {
  std::vector<int> first;  // size n + 1
  std::vector<int> j;
  std::vector<int> i;      // owner of each pair (redundant with first, for the force loop)
  std::vector<Vec3> history;

  std::size_t size() const { return j.size(); }
};

/// Builds the pair list of positions x and radii r (m) with the given skin (m), carrying the
/// history of pairs present in `old` (which must describe the same particles, or be empty).
/// Parallel with OpenMP; the result does not depend on the number of threads.
PairList build_pair_list(const std::vector<Vec3>& x, const std::vector<double>& r, double skin,
                         const PairList& old);

}  // namespace kolsky::dem
