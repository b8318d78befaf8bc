// Drawing grain diameters from a grain-size curve, and the grain-size curve of a sample.
// Method (docs/psd.md): stratified by the curve's bins. Going from fine to coarse, bin k is
// filled with grains drawn from its own number density (mass uniform in log d within the bin,
// so dN/dd ~ d^-4, inverse CDF d = (a^-3 - u (a^-3 - b^-3))^(-1/3)) until the cumulative solid
// volume reaches P_k/100 * V_s; the grain that would overshoot is kept only if that lands
// closer. Hence after every bin |V_cum - P_k V_s/100| <= v(d_k)/2, so the sample's mass curve
// matches the input at every input size within max_passing_deviation_bound(), which falls
// like 1/count (plain i.i.d. draws from the number density fall only like 1/sqrt(count)).
// Random numbers: xoshiro256** (core/rng.hpp), so a seed gives the same sample on
// every platform. Units: m, m^3.
#pragma once
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "psd/grain_size_curve.hpp"

namespace kolsky::psd {

/// Safety limit on the sample size (grains); a larger request is almost always a unit slip.
inline constexpr std::size_t kMaxSampleGrains = 50'000'000;

/// Diameters (m) whose mass distribution follows `curve` and whose total solid volume is within
/// half the largest grain (pi d_max^3 / 12) of `solid_volume` (m^3, > 0); sorted descending
/// (large first, as packing algorithms want). Same curve, volume and seed: same sample.
/// Throws std::invalid_argument (InvalidCurve for the curve) on bad input or when the expected
/// count exceeds max_grains.
std::vector<double> sample_diameters(const GrainSizeCurve& curve, double solid_volume,
                                     std::uint64_t seed,
                                     std::size_t max_grains = kMaxSampleGrains);

/// Whether sample_diameters(curve, solid_volume, seed, max_grains) would return any grain,
/// with the same checks and throws, found without drawing the sample: the draw stops at the
/// first grain kept, so the cost is one draw per bin of the curve at most, however many grains
/// the volume holds (the scene reader asks this of every DEM scene, dem/packing.cpp draws).
bool holds_a_grain(const GrainSizeCurve& curve, double solid_volume, std::uint64_t seed,
                   std::size_t max_grains = kMaxSampleGrains);

/// Total solid volume of spheres with these diameters (m^3).
double solid_volume(std::span<const double> diameters);

/// Mean-volume-equivalent diameter of a sample, (sum d^3 / n)^(1/3) (m).
double mean_volume_diameter(std::span<const double> diameters);

/// Percent passing by mass (volume, one density) of a sample at each size: 100 * (volume of
/// grains with d <= size) / (total volume). Sizes in any order; result in the same order.
std::vector<double> sample_passing(std::span<const double> diameters,
                                   std::span<const double> sizes);

/// max over the curve's sizes of |sample_passing - curve passing| (percentage points).
double max_passing_deviation(const GrainSizeCurve& curve, std::span<const double> diameters);

/// The guarantee of sample_diameters in percentage points: with v = pi d_max^3/6,
/// 100 v / (V_s - v/2), where V_s is the target solid volume (derivation in docs/psd.md).
double max_passing_deviation_bound(const GrainSizeCurve& curve, double solid_volume);

}  // namespace kolsky::psd
