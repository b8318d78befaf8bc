// Test fills: lattice, random sequential addition, random velocities (see test_fills.hpp).
#include "dem/test_fills.hpp"

#include <algorithm>
#include <cmath>
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

}  // namespace kolsky::dem
