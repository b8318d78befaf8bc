// Cell-grid construction of the Verlet pair list (see neighbour_list.hpp).
#include "dem/neighbour_list.hpp"

#include <omp.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <limits>

namespace kolsky::dem {

namespace {

struct CellGrid {
  Vec3 lo;
  double cell = 1;
  int nx = 1, ny = 1, nz = 1;
  std::vector<int> start, items;  // particles of cell c: items[start[c] .. start[c+1])
  // Position and radius of items[s] at s: the scan of a row of cells then reads one
  // contiguous run instead of gathering x[j] and r[j] from all over the arrays.
  struct Item {
    Vec3 x;
    double r;
  };
  std::vector<Item> item;

  int clamp_index(double u, int n) const {
    const double c = std::floor(u / cell);
    return c < 0 ? 0 : (c >= n ? n - 1 : static_cast<int>(c));
  }
  int cell_of(const Vec3& p) const {
    return (clamp_index(p.z - lo.z, nz) * ny + clamp_index(p.y - lo.y, ny)) * nx +
           clamp_index(p.x - lo.x, nx);
  }
};

CellGrid make_grid(const std::vector<Vec3>& x, const std::vector<double>& r, double cell) {
  CellGrid g;
  Vec3 lo{std::numeric_limits<double>::max(), std::numeric_limits<double>::max(),
          std::numeric_limits<double>::max()};
  Vec3 hi = -lo;
  for (const auto& p : x) {
    lo = {std::min(lo.x, p.x), std::min(lo.y, p.y), std::min(lo.z, p.z)};
    hi = {std::max(hi.x, p.x), std::max(hi.y, p.y), std::max(hi.z, p.z)};
  }
  // Cap the cell count near 2 per particle: a stray particle far away then coarsens the grid
  // instead of exhausting memory.
  const double max_cells = std::max<double>(64, 2.0 * static_cast<double>(x.size()));
  auto dims = [&](double c) {
    return std::array<double, 3>{std::floor((hi.x - lo.x) / c) + 1,
                                 std::floor((hi.y - lo.y) / c) + 1,
                                 std::floor((hi.z - lo.z) / c) + 1};
  };
  auto d = dims(cell);
  while (d[0] * d[1] * d[2] > max_cells) {
    cell *= 1.26;  // ~2^(1/3): halves the cell count per pass
    d = dims(cell);
  }
  g.lo = lo;
  g.cell = cell;
  g.nx = static_cast<int>(d[0]);
  g.ny = static_cast<int>(d[1]);
  g.nz = static_cast<int>(d[2]);
  const std::size_t n_cells = static_cast<std::size_t>(g.nx) * g.ny * g.nz;
  std::vector<int> cell_of(x.size());
  g.start.assign(n_cells + 1, 0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    cell_of[i] = g.cell_of(x[i]);
    ++g.start[cell_of[i] + 1];
  }
  for (std::size_t c = 0; c < n_cells; ++c) g.start[c + 1] += g.start[c];
  g.items.resize(x.size());
  std::vector<int> fill(g.start.begin(), g.start.end() - 1);
  for (std::size_t i = 0; i < x.size(); ++i) g.items[fill[cell_of[i]]++] = static_cast<int>(i);
  g.item.resize(x.size());
  for (std::size_t s = 0; s < x.size(); ++s) g.item[s] = {x[g.items[s]], r[g.items[s]]};
  return g;
}

}  // namespace

PairList build_pair_list(const std::vector<Vec3>& x, const std::vector<double>& r, double skin,
                         const PairList& old) {
  const int n = static_cast<int>(x.size());
  PairList out;
  out.first.assign(static_cast<std::size_t>(n) + 1, 0);
  if (n == 0) return out;
  const double r_min = *std::min_element(r.begin(), r.end());
  const CellGrid g = make_grid(x, r, 2 * r_min + skin);

  // (1) Each pair is found once, from its larger grain (equal radii: from the lower index),
  // within the reach 2 r_i + skin >= r_i + r_j + skin, so the small grains, most of the
  // packing, search only a small neighbourhood. Each thread scans a contiguous block of
  // grains and records (owner, partner) = (min, max) as one key.
  // (2) Keys are placed by owner (counts per thread and owner, then offsets), and (3) each
  // owner's partners sorted, which makes the list the same for any thread count.
  std::vector<std::vector<std::uint64_t>> found;
  std::vector<std::vector<int>> at;  // at[t][q]: thread t's count, then its next slot, for owner q
#pragma omp parallel if (n >= 2048)  // small systems: a parallel region costs more than it saves
  {
    const int nt = omp_get_num_threads(), t = omp_get_thread_num();
#pragma omp single
    {
      found.resize(nt);
      at.resize(nt);
    }
    const int b0 = static_cast<int>(static_cast<std::int64_t>(n) * t / nt);
    const int b1 = static_cast<int>(static_cast<std::int64_t>(n) * (t + 1) / nt);
    std::vector<std::uint64_t>& keys = found[t];
    std::size_t m = 0;  // keys found; keys[m ...] is scratch
    for (int i = b0; i < b1; ++i) {
      const Vec3 p = x[i];
      const double ri = r[i];
      const double reach = 2 * ri + skin;
      const int x0 = g.clamp_index(p.x - reach - g.lo.x, g.nx);
      const int x1 = g.clamp_index(p.x + reach - g.lo.x, g.nx);
      const int y0 = g.clamp_index(p.y - reach - g.lo.y, g.ny);
      const int y1 = g.clamp_index(p.y + reach - g.lo.y, g.ny);
      const int z0 = g.clamp_index(p.z - reach - g.lo.z, g.nz);
      const int z1 = g.clamp_index(p.z + reach - g.lo.z, g.nz);
      for (int cz = z0; cz <= z1; ++cz)
        for (int cy = y0; cy <= y1; ++cy) {
          // Cells x0..x1 of a row are consecutive, so are their items.
          const int row = (cz * g.ny + cy) * g.nx;
          const int s0 = g.start[row + x0], s1 = g.start[row + x1 + 1];
          if (keys.size() < m + static_cast<std::size_t>(s1 - s0))
            keys.resize(2 * (m + static_cast<std::size_t>(s1 - s0)));
          // Branch-free: about half the candidates are larger than i, in no predictable order.
          for (int s = s0; s < s1; ++s) {
            const int j = g.items[s];
            const double rj = g.item[s].r;
            const double cut = ri + rj + skin;
            const bool from_here = (rj < ri) | ((rj == ri) & (j > i));
            const bool near = norm2(g.item[s].x - p) < cut * cut;
            const auto lo = static_cast<std::uint64_t>(j < i ? j : i);
            const auto hi = static_cast<std::uint64_t>(j < i ? i : j);
            keys[m] = lo << 32 | hi;
            m += from_here & near;
          }
        }
    }
    keys.resize(m);
    std::vector<int>& mine = at[t];
    mine.assign(static_cast<std::size_t>(n), 0);
    for (std::uint64_t k : keys) ++mine[k >> 32];
#pragma omp barrier
#pragma omp single
    {
      for (int q = 0; q < n; ++q) {
        int slot = out.first[q];
        for (auto& c : at) {
          const int count = c[q];
          c[q] = slot;
          slot += count;
        }
        out.first[q + 1] = slot;
      }
      out.j.resize(out.first[n]);
      out.i.resize(out.first[n]);
      out.history.assign(out.first[n], Vec3{});
    }
    for (std::uint64_t k : keys) out.j[mine[k >> 32]++] = static_cast<int>(k & 0xffffffffu);
#pragma omp barrier
    for (int i = b0; i < b1; ++i) {
      // A handful of partners per owner: insertion sort.
      for (int k = out.first[i] + 1; k < out.first[i + 1]; ++k)
        for (int q = k; q > out.first[i] && out.j[q - 1] > out.j[q]; --q)
          std::swap(out.j[q - 1], out.j[q]);
      std::fill(out.i.begin() + out.first[i], out.i.begin() + out.first[i + 1], i);
      // Carry the history: merge the sorted partner lists of i in the old and new lists.
      if (old.first.size() != out.first.size()) continue;
      int a = old.first[i];
      const int a_end = old.first[i + 1];
      for (int k = out.first[i]; k < out.first[i + 1] && a < a_end; ++k) {
        while (a < a_end && old.j[a] < out.j[k]) ++a;
        if (a < a_end && old.j[a] == out.j[k]) out.history[k] = old.history[a];
      }
    }
  }
  return out;
}

}  // namespace kolsky::dem
