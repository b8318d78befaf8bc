// Spatial orders of the particles: cell order and Morton order (see spatial_sort.hpp).
#include "dem/spatial_sort.hpp"

#include <algorithm>
#include <cstdint>
#include <numeric>
#include <string>

#include "core/errors.hpp"

namespace kolsky::dem {

namespace {

// Stable order of the particles by key(cx, cy, cz) of their cell in a grid of side `cell`
// from the lowest corner; cell indices below 2^20 per axis. order[k] = old index of new k.
template <class Key>
std::vector<int> order_by_cell(const Particles& p, double cell, Key key_of) {
  if (p.size() == 0) return {};
  Vec3 lo = p.x[0], hi = p.x[0];
  for (const auto& x : p.x) {
    lo = {std::min(lo.x, x.x), std::min(lo.y, x.y), std::min(lo.z, x.z)};
    hi = {std::max(hi.x, x.x), std::max(hi.y, x.y), std::max(hi.z, x.z)};
  }
  const double extent = std::max({hi.x - lo.x, hi.y - lo.y, hi.z - lo.z});
  if (!(cell > 0) || !(extent / cell < (1 << 20)))
    throw InputError("", "dem.sort.cell",
                     "the cell must be > 0 and the extent / cell below 2^20 (got cell " +
                         std::to_string(cell) + " m, extent " + std::to_string(extent) + " m)");
  std::vector<std::uint64_t> key(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    const auto c = [&](double u, double l) { return static_cast<std::uint64_t>((u - l) / cell); };
    key[i] = key_of(c(p.x[i].x, lo.x), c(p.x[i].y, lo.y), c(p.x[i].z, lo.z));
  }
  std::vector<int> order(p.size());
  std::iota(order.begin(), order.end(), 0);
  std::stable_sort(order.begin(), order.end(), [&](int a, int b) { return key[a] < key[b]; });
  return order;
}

// The bits of v (< 2^21) spread to every third bit.
std::uint64_t spread_bits(std::uint64_t v) {
  v = (v | v << 32) & 0x1f00000000ffffull;
  v = (v | v << 16) & 0x1f0000ff0000ffull;
  v = (v | v << 8) & 0x100f00f00f00f00full;
  v = (v | v << 4) & 0x10c30c30c30c30c3ull;
  v = (v | v << 2) & 0x1249249249249249ull;
  return v;
}

}  // namespace

void sort_spatially(Particles& p, double cell) {
  p.permute(order_by_cell(p, cell, [](std::uint64_t cx, std::uint64_t cy, std::uint64_t cz) {
    return cz << 40 | cy << 20 | cx;
  }));
}

std::vector<int> morton_order(const Particles& p, double cell) {
  return order_by_cell(p, cell, [](std::uint64_t cx, std::uint64_t cy, std::uint64_t cz) {
    return spread_bits(cx) | spread_bits(cy) << 1 | spread_bits(cz) << 2;
  });
}

void sort_morton(Particles& p, double cell) { p.permute(morton_order(p, cell)); }

}  // namespace kolsky::dem
