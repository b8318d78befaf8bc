// Stratified sampling of grain diameters from a grain-size curve (see sampling.hpp for the method
// and its bound), and the mass curve of a sample.
#include "psd/sampling.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/rng.hpp"

namespace kolsky::psd {

namespace {

double sphere_volume(double d) { return std::numbers::pi / 6.0 * d * d * d; }

// Draws grains until the cumulative volume `v_cum` reaches `target`, drawing each diameter
// with `draw()` and handing each kept one to `keep(d)`. The grain that would overshoot is kept
// only if that lands closer to the target, so afterwards |v_cum - target| <= v(last draw)/2
// (or v_cum > target already). Returns false as soon as keep() does (the caller stops).
template <class Draw, class Keep>
bool fill_to(double target, Draw&& draw, Keep& keep, double& v_cum) {
  while (v_cum < target) {
    const double d = draw();
    const double v = sphere_volume(d);
    const bool overshoots = v_cum + v > target;
    if (!overshoots || (v_cum + v - target) < (target - v_cum)) {
      v_cum += v;
      if (!keep(d)) return false;
    }
    if (overshoots) break;  // kept or not, the bin is now within v/2 of its target
  }
  return true;
}

/// The expected grain count, after checking the curve, the volume and the limit.
double checked_expected_count(const GrainSizeCurve& curve, double solid_volume,
                              std::size_t max_grains) {
  curve.validate();
  if (!(std::isfinite(solid_volume) && solid_volume > 0.0))
    throw std::invalid_argument("sample_diameters: solid volume must be finite and > 0 m^3");
  const double expected = solid_volume / mean_grain_volume(curve);
  if (!(expected <= static_cast<double>(max_grains)))
    throw std::invalid_argument("sample_diameters: about " + std::to_string(expected) +
                                " grains expected, more than the limit of " +
                                std::to_string(max_grains) + " (check the units of the volume)");
  return expected;
}

/// The stratified draw (sampling.hpp), fine to coarse, each kept diameter handed to keep(d),
/// which returns false to stop: sample_diameters keeps them all, holds_a_grain stops at the
/// first. Both see the same draws for the same curve, volume and seed.
template <class Keep>
void draw_sample(const GrainSizeCurve& curve, double solid_volume, std::uint64_t seed,
                 Keep keep) {
  const auto& x = curve.diameter;
  const auto& p = curve.percent_passing;
  Xoshiro256ss rng(seed);
  double v_cum = 0.0;

  // The lump at the smallest size (first row's passing): identical grains.
  const double d0 = x.front();
  if (!fill_to(p.front() / 100.0 * solid_volume, [d0] { return d0; }, keep, v_cum)) return;

  for (std::size_t k = 1; k < x.size(); ++k) {
    if (!(p[k] > p[k - 1])) continue;  // an empty bin holds no grains
    const double a = x[k - 1], b = x[k];
    const double ia = std::pow(a, -3.0), ib = std::pow(b, -3.0);
    // Inverse CDF of dN/dd ~ d^-4 on (a, b]; clamped because pow may round past an end. The
    // lower end is excluded so every grain of this bin counts as coarser than a (sample_passing
    // counts d <= size as passing), which keeps the per-bin volume bound exact.
    const double above_a = std::nextafter(a, b);
    auto draw = [&rng, above_a, b, ia, ib] {
      const double u = rng.uniform_open();
      return std::clamp(std::pow(ia - u * (ia - ib), -1.0 / 3.0), above_a, b);
    };
    // The last bin's target is the whole volume (p = 100 exactly, by validation).
    if (!fill_to(p[k] / 100.0 * solid_volume, draw, keep, v_cum)) return;
  }
}

}  // namespace

std::vector<double> sample_diameters(const GrainSizeCurve& curve, double solid_volume,
                                     std::uint64_t seed, std::size_t max_grains) {
  const double expected = checked_expected_count(curve, solid_volume, max_grains);
  std::vector<double> out;
  out.reserve(static_cast<std::size_t>(expected * 1.02) + 16);
  draw_sample(curve, solid_volume, seed, [&out](double d) {
    out.push_back(d);
    return true;
  });
  std::sort(out.begin(), out.end(), std::greater<double>());
  return out;
}

bool holds_a_grain(const GrainSizeCurve& curve, double solid_volume, std::uint64_t seed,
                   std::size_t max_grains) {
  checked_expected_count(curve, solid_volume, max_grains);
  bool any = false;
  draw_sample(curve, solid_volume, seed, [&any](double) { return !(any = true); });
  return any;
}

double solid_volume(std::span<const double> diameters) {
  double v = 0.0;
  for (double d : diameters) v += sphere_volume(d);
  return v;
}

double mean_volume_diameter(std::span<const double> diameters) {
  if (diameters.empty()) throw std::invalid_argument("mean_volume_diameter: empty sample");
  double s = 0.0;
  for (double d : diameters) s += d * d * d;
  return std::cbrt(s / static_cast<double>(diameters.size()));
}

std::vector<double> sample_passing(std::span<const double> diameters,
                                   std::span<const double> sizes) {
  if (diameters.empty()) throw std::invalid_argument("sample_passing: empty sample");
  std::vector<double> d(diameters.begin(), diameters.end());
  std::sort(d.begin(), d.end());
  // cumulative[i] = volume of the i smallest grains (one density: mass is proportional).
  std::vector<double> cumulative(d.size() + 1, 0.0);
  for (std::size_t i = 0; i < d.size(); ++i)
    cumulative[i + 1] = cumulative[i] + sphere_volume(d[i]);
  const double total = cumulative.back();
  std::vector<double> out;
  out.reserve(sizes.size());
  for (double s : sizes) {
    const auto n = static_cast<std::size_t>(std::upper_bound(d.begin(), d.end(), s) - d.begin());
    out.push_back(100.0 * cumulative[n] / total);
  }
  return out;
}

double max_passing_deviation(const GrainSizeCurve& curve, std::span<const double> diameters) {
  curve.validate();
  const auto got = sample_passing(diameters, curve.diameter);
  double worst = 0.0;
  for (std::size_t k = 0; k < got.size(); ++k)
    worst = std::max(worst, std::abs(got[k] - curve.percent_passing[k]));
  return worst;
}

double max_passing_deviation_bound(const GrainSizeCurve& curve, double solid_volume) {
  curve.validate();
  const double v = sphere_volume(curve.d_max());
  if (!(solid_volume > v / 2.0))
    throw std::invalid_argument("max_passing_deviation_bound: the solid volume must exceed "
                                "half the largest grain");
  return 100.0 * v / (solid_volume - v / 2.0);
}

}  // namespace kolsky::psd
