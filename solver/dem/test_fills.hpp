// Simple fills for tests and benchmarks (not the project's packing generator, dem/packing.hpp):
// a simple-cubic lattice, and random sequential addition (RSA) of non-overlapping spheres with
// uniformly distributed radii inside a box or a cylinder, largest first. Deterministic for a
// seed (own 53-bit uniform mapping of std::mt19937_64, independent of the standard library's
// distributions).
#pragma once
#include <cstdint>
#include <vector>

#include "dem/particles.hpp"

namespace kolsky::dem {

/// nx x ny x nz equal spheres of radius r (m) at centre spacing `spacing` (m) from `origin`.
Particles cubic_lattice(int nx, int ny, int nz, double r, double spacing, const Vec3& origin,
                        int material, const std::vector<Material>& materials);

/// Region of an RSA fill: a box [lo, hi], or the cylinder of radius `radius` around the z axis
/// with lo.z <= z <= hi.z when radius > 0. Spheres lie entirely inside.
struct FillRegion {
  Vec3 lo, hi;
  double radius = 0;
};

/// RSA of n spheres with radii uniform in [r_min, r_max] (m). Throws kolsky::InputError if a
/// sphere finds no free place after `max_attempts` tries (the region is too full for RSA,
/// whose jamming limit is a solid fraction of about 0.38).
Particles random_packing(int n, double r_min, double r_max, const FillRegion& region,
                         std::uint64_t seed, int material, const std::vector<Material>& materials,
                         int max_attempts = 100000);

/// Random velocities with components uniform in [-speed, speed] (m/s); deterministic.
void randomize_velocities(Particles& p, double speed, std::uint64_t seed);

}  // namespace kolsky::dem
