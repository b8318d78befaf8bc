// Solid fraction of a cylindrical specimen (r < D/2, 0 < z < L) as a function of the distance
// to the nearest wall (tube or end plane). Spheres cannot cross a wall, so the layer within
// about one grain of it is looser than the bulk (Mueller 1992 for the radial profile of packed
// beds); at a fixed overall porosity the core is then denser than the whole, by an amount that
// grows with the grain size. This is what makes the Chapter 4 specimen's toe depend on the
// upscaling factor N (reproductions/chapter4/README.md, "What the toe is").
//
// Measured by counting the points of a regular lattice that fall inside a grain (the union of
// the spheres: overlapping grains are not counted twice). The error of such a count for one
// sphere of radius r at spacing h is a boundary term of order (h/r)^(3/2) in relative terms with
// a sign set by the sphere's offset to the lattice; over many randomly placed grains these
// average out (verification/test_dem_wall_layer.cpp measures it).
#pragma once
#include <cstddef>
#include <vector>

#include "dem/particles.hpp"

namespace kolsky::dem {

struct WallLayerProfile {
  double bin_width = 0;             ///< m, width of a wall-distance bin
  std::vector<long long> points;    ///< lattice points per bin (bin b: [b w, (b + 1) w))
  std::vector<long long> solid;     ///< of those, the points inside a grain

  /// Solid fraction of bin b (NaN when the bin holds no point).
  double fraction(std::size_t b) const;
  /// Solid fraction of the region at least `distance` (m) from every wall; 0 gives the whole.
  double fraction_beyond(double distance) const;
  /// Share of the specimen volume at least `distance` (m) from every wall.
  double volume_share_beyond(double distance) const;
};

/// Profile of the cylinder of `diameter` and `length` (m; axis z, 0 < z < length, centred on
/// x = y = 0) sampled at lattice `spacing` (m) in bins of `bin_width` (m), the last bin open to
/// the axis. Deterministic; the counts are integers, so any thread count gives the same result.
/// Throws kolsky::InputError on a non-positive size, spacing or bin width.
WallLayerProfile wall_layer_profile(const Particles& p, double diameter, double length,
                                    double spacing, double bin_width);

}  // namespace kolsky::dem
