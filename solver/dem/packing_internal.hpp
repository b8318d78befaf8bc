// Internals shared by the packing files (packing.cpp: generation; packing_census.cpp: the
// census of a finished packing; prestress.cpp; wall_layer.cpp): a uniform cell grid over the
// packing cylinder, and the progress hook.
#pragma once
#include <algorithm>
#include <vector>

#include "dem/packing.hpp"

namespace kolsky::dem {

// Reports p through in.on_progress, when one is set.
inline void progress(const PackingParams& in, const PackingProgress& p) {
  if (in.on_progress) in.on_progress(p);
}

// Uniform cell grid over the cylinder's bounding box [-R, R]^2 x [0, L].
struct CellGrid {
  double cell, R, L;
  int nx, nz;
  std::vector<std::vector<int>> cells;

  CellGrid(double cell_size, double radius, double length)
      : cell(cell_size), R(radius), L(length) {
    nx = std::max(1, static_cast<int>(2 * R / cell) + 1);
    nz = std::max(1, static_cast<int>(L / cell) + 1);
    cells.resize(static_cast<std::size_t>(nx) * nx * nz);
  }
  int ix(double u) const { return std::clamp(static_cast<int>((u + R) / cell), 0, nx - 1); }
  int iz(double u) const { return std::clamp(static_cast<int>(u / cell), 0, nz - 1); }
  std::vector<int>& at(int x, int y, int z) {
    return cells[(static_cast<std::size_t>(z) * nx + y) * nx + x];
  }
  void insert(const Vec3& c, int id) { at(ix(c.x), ix(c.y), iz(c.z)).push_back(id); }
  // Calls f(q) for every id in the 27 cells around c; stops when f returns false.
  template <class F> bool visit(const Vec3& c, F&& f) {
    const int cx = ix(c.x), cy = ix(c.y), cz = iz(c.z);
    for (int z = std::max(0, cz - 1); z <= std::min(nz - 1, cz + 1); ++z)
      for (int y = std::max(0, cy - 1); y <= std::min(nx - 1, cy + 1); ++y)
        for (int x = std::max(0, cx - 1); x <= std::min(nx - 1, cx + 1); ++x)
          for (int q : at(x, y, z))
            if (!f(q)) return false;
    return true;
  }
};

/// Census of the final state (coordination with and without walls and rattlers, largest
/// overlap, Hertz contact-virial stress), grains put at rest with the requested material
/// index, porosity from the final radii (packing_census.cpp).
void take_census(PackingResult& res, const PackingParams& in);

}  // namespace kolsky::dem
