// Test assemblies: lattice, random sequential addition, spatial sort (see assembly.hpp).
#include "dem/assembly.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <random>
#include <string>

#include "core/errors.hpp"

namespace kolsky::dem {

namespace {
double uniform01(std::mt19937_64& g) { return static_cast<double>(g() >> 11) * 0x1.0p-53; }
}  // namespace

Particles cubic_lattice(int nx, int ny, int nz, double r, double spacing, const Vec3& origin,
                        int material, const std::vector<Material>& materials) {
  Particles p;
  p.reserve(static_cast<std::size_t>(nx) * ny * nz);
  for (int k = 0; k < nz; ++k)
    for (int j = 0; j < ny; ++j)
      for (int i = 0; i < nx; ++i)
        p.add(origin + Vec3{i * spacing, j * spacing, k * spacing}, r, material, materials);
  return p;
}

Particles random_packing(int n, double r_min, double r_max, const FillRegion& region,
                         std::uint64_t seed, int material, const std::vector<Material>& materials,
                         int max_attempts) {
  std::mt19937_64 gen(seed);
  std::vector<double> radii(n);
  for (auto& r : radii) r = r_min + (r_max - r_min) * uniform01(gen);
  std::sort(radii.begin(), radii.end(), std::greater<>());
  // Occupancy grid of cell 2 r_max: a new sphere can only overlap spheres in the 27 cells
  // around its own.
  const double cell = 2 * r_max;
  const Vec3 ext = region.hi - region.lo;
  const int nx = std::max(1, static_cast<int>(ext.x / cell) + 1);
  const int ny = std::max(1, static_cast<int>(ext.y / cell) + 1);
  const int nz = std::max(1, static_cast<int>(ext.z / cell) + 1);
  std::vector<std::vector<int>> grid(static_cast<std::size_t>(nx) * ny * nz);
  auto index = [&](double u, double lo, int m) {
    return std::clamp(static_cast<int>((u - lo) / cell), 0, m - 1);
  };
  Particles p;
  p.reserve(n);
  for (int s = 0; s < n; ++s) {
    const double r = radii[s];
    bool placed = false;
    for (int attempt = 0; attempt < max_attempts && !placed; ++attempt) {
      const Vec3 c{region.lo.x + r + (ext.x - 2 * r) * uniform01(gen),
                   region.lo.y + r + (ext.y - 2 * r) * uniform01(gen),
                   region.lo.z + r + (ext.z - 2 * r) * uniform01(gen)};
      if (region.radius > 0 && std::hypot(c.x, c.y) > region.radius - r) continue;
      const int ix = index(c.x, region.lo.x, nx), iy = index(c.y, region.lo.y, ny),
                iz = index(c.z, region.lo.z, nz);
      bool free = true;
      for (int z = std::max(0, iz - 1); free && z <= std::min(nz - 1, iz + 1); ++z)
        for (int y = std::max(0, iy - 1); free && y <= std::min(ny - 1, iy + 1); ++y)
          for (int x = std::max(0, ix - 1); free && x <= std::min(nx - 1, ix + 1); ++x)
            for (int q : grid[(static_cast<std::size_t>(z) * ny + y) * nx + x]) {
              const double d = r + p.radius[q];
              if (norm2(p.x[q] - c) < d * d) {
                free = false;
                break;
              }
            }
      if (!free) continue;
      grid[(static_cast<std::size_t>(iz) * ny + iy) * nx + ix].push_back(static_cast<int>(p.size()));
      p.add(c, r, material, materials);
      placed = true;
    }
    if (!placed)
      throw InputError("", "dem.packing", "no free place for sphere " + std::to_string(s) +
                                              " after " + std::to_string(max_attempts) + " tries");
  }
  return p;
}

void randomize_velocities(Particles& p, double speed, std::uint64_t seed) {
  std::mt19937_64 gen(seed);
  for (auto& v : p.v)
    v = {speed * (2 * uniform01(gen) - 1), speed * (2 * uniform01(gen) - 1),
         speed * (2 * uniform01(gen) - 1)};
}

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
