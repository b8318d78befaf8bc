#include "dem/wall_layer.hpp"

#include <algorithm>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "dem/packing_internal.hpp"

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
  // centre in the point's cell or a neighbouring one (a centre just outside the cylinder is
  // clamped into the edge cell, which the points next to it visit too).
  double r_max = 0;
  for (double r : p.radius) r_max = std::max(r_max, r);
  CellGrid grid(std::max(2 * r_max, spacing), R, length);
  for (std::size_t i = 0; i < p.size(); ++i) grid.insert(p.x[i], static_cast<int>(i));

  const int n_xy = static_cast<int>(diameter / spacing), n_z = static_cast<int>(length / spacing);
  // Centre the lattice in the bounding box so that it is symmetric about the axis.
  const double off_xy = -0.5 * (n_xy - 1) * spacing, off_z = 0.5 * (length - (n_z - 1) * spacing);
#pragma omp parallel
  {
    std::vector<long long> pts(n_bins, 0), sol(n_bins, 0);
#pragma omp for schedule(static)
    for (int iz = 0; iz < n_z; ++iz) {
      const double z = off_z + iz * spacing;
      for (int iy = 0; iy < n_xy; ++iy) {
        const double y = off_xy + iy * spacing;
        for (int ix = 0; ix < n_xy; ++ix) {
          const double x = off_xy + ix * spacing;
          const double rr = std::sqrt(x * x + y * y);
          if (rr >= R) continue;
          const double to_wall = std::min({R - rr, z, length - z});
          const std::size_t bin = std::min(n_bins - 1, static_cast<std::size_t>(to_wall / bin_width));
          ++pts[bin];
          const bool inside = !grid.visit({x, y, z}, [&](int g) {
            return norm2(Vec3{x, y, z} - p.x[g]) >= p.radius[g] * p.radius[g];
          });
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
