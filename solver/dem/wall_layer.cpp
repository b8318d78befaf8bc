#include "dem/wall_layer.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"

namespace kolsky::dem {

double WallLayerProfile::fraction(std::size_t b) const {
  return b < points.size() && points[b] > 0 ? static_cast<double>(solid[b]) / points[b] : NAN;
}

double WallLayerProfile::fraction_beyond(double distance) const {
  long long in = 0, all = 0;
  for (std::size_t b = 0; b < points.size(); ++b)
    if (b * bin_width >= distance * (1 - 1e-12)) in += solid[b], all += points[b];
  return all > 0 ? static_cast<double>(in) / all : NAN;
}

double WallLayerProfile::volume_share_beyond(double distance) const {
  long long part = 0, all = 0;
  for (std::size_t b = 0; b < points.size(); ++b) {
    all += points[b];
    if (b * bin_width >= distance * (1 - 1e-12)) part += points[b];
  }
  return all > 0 ? static_cast<double>(part) / all : NAN;
}

WallLayerProfile wall_layer_profile(const Particles& p, double diameter, double length,
                                    double spacing, double bin_width) {
  auto require = [](bool ok, const std::string& field, const std::string& rule) {
    if (!ok) throw InputError("", "wall_layer_profile." + field, rule);
  };
  require(diameter > 0 && std::isfinite(diameter), "diameter", "must be > 0");
  require(length > 0 && std::isfinite(length), "length", "must be > 0");
  require(spacing > 0 && spacing < std::min(diameter, length), "spacing",
          "must be > 0 and below the specimen's size");
  require(bin_width > 0 && std::isfinite(bin_width), "bin_width", "must be > 0");

  const double R = diameter / 2;
  WallLayerProfile out;
  out.bin_width = bin_width;
  const std::size_t n_bins = static_cast<std::size_t>(std::min(R, length / 2) / bin_width) + 1;
  out.points.assign(n_bins, 0);
  out.solid.assign(n_bins, 0);

  // Grains on a cell grid of side >= the largest diameter: a grain holding a point has its
  // centre in the point's cell or a neighbouring one.
  double r_max = 0;
  for (double r : p.radius) r_max = std::max(r_max, r);
  const double cell = std::max(2 * r_max, spacing);
  const double x0 = -R - r_max, z0 = -r_max;
  const int nc_xy = static_cast<int>((diameter + 2 * r_max) / cell) + 1;
  const int nc_z = static_cast<int>((length + 2 * r_max) / cell) + 1;
  auto cell_of = [&](double u, double lo, int n) {
    return std::clamp(static_cast<int>(std::floor((u - lo) / cell)), 0, n - 1);
  };
  auto cell_index = [&](int a, int b, int c) { return (static_cast<long>(c) * nc_xy + b) * nc_xy + a; };
  const long n_cells = static_cast<long>(nc_xy) * nc_xy * nc_z;
  std::vector<int> start(n_cells + 1, 0), members(p.size());
  std::vector<long> home(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) {
    home[i] = cell_index(cell_of(p.x[i].x, x0, nc_xy), cell_of(p.x[i].y, x0, nc_xy),
                         cell_of(p.x[i].z, z0, nc_z));
    ++start[home[i] + 1];
  }
  for (long c = 0; c < n_cells; ++c) start[c + 1] += start[c];
  {
    std::vector<int> fill(start.begin(), start.end() - 1);
    for (std::size_t i = 0; i < p.size(); ++i) members[fill[home[i]]++] = static_cast<int>(i);
  }

  const int n_xy = static_cast<int>(diameter / spacing), n_z = static_cast<int>(length / spacing);
  // Centre the lattice in the bounding box so that it is symmetric about the axis.
  const double off_xy = -0.5 * (n_xy - 1) * spacing, off_z = 0.5 * (length - (n_z - 1) * spacing);
#pragma omp parallel
  {
    std::vector<long long> pts(n_bins, 0), sol(n_bins, 0);
#pragma omp for schedule(static)
    for (int iz = 0; iz < n_z; ++iz) {
      const double z = off_z + iz * spacing;
      const int cz = cell_of(z, z0, nc_z);
      for (int iy = 0; iy < n_xy; ++iy) {
        const double y = off_xy + iy * spacing;
        const int cy = cell_of(y, x0, nc_xy);
        for (int ix = 0; ix < n_xy; ++ix) {
          const double x = off_xy + ix * spacing;
          const double rr = std::sqrt(x * x + y * y);
          if (rr >= R) continue;
          const double to_wall = std::min({R - rr, z, length - z});
          const std::size_t bin = std::min(n_bins - 1, static_cast<std::size_t>(to_wall / bin_width));
          ++pts[bin];
          const int cx = cell_of(x, x0, nc_xy);
          bool inside = false;
          for (int c = std::max(0, cz - 1); c <= std::min(nc_z - 1, cz + 1) && !inside; ++c)
            for (int b = std::max(0, cy - 1); b <= std::min(nc_xy - 1, cy + 1) && !inside; ++b) {
              const long row = cell_index(0, b, c);
              const int a0 = std::max(0, cx - 1), a1 = std::min(nc_xy - 1, cx + 1);
              for (int k = start[row + a0]; k < start[row + a1 + 1]; ++k) {
                const int g = members[k];
                const Vec3 d{x - p.x[g].x, y - p.x[g].y, z - p.x[g].z};
                if (norm2(d) < p.radius[g] * p.radius[g]) {
                  inside = true;
                  break;
                }
              }
            }
          sol[bin] += inside;
        }
      }
    }
#pragma omp critical
    for (std::size_t b = 0; b < n_bins; ++b) out.points[b] += pts[b], out.solid[b] += sol[b];
  }
  return out;
}

}  // namespace kolsky::dem
