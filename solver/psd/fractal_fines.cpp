// Eq. 5.16 fractal mass redistribution and the PSD of particles plus redistributed fines.
#include "psd/fractal_fines.hpp"

#include <cmath>
#include <stdexcept>

#include "psd/sampling.hpp"

namespace kolsky::psd {

namespace {

void check_range(double d_min, double d_max, double alpha) {
  if (!(std::isfinite(d_min) && d_min > 0.0 && std::isfinite(d_max) && d_max > d_min))
    throw std::invalid_argument("fractal fines: need 0 < d_min < d_max (m)");
  if (!std::isfinite(alpha)) throw std::invalid_argument("fractal fines: alpha must be finite");
}

}  // namespace

double fractal_passing_fraction(double d, double d_min, double d_max, double alpha) {
  check_range(d_min, d_max, alpha);
  if (std::isnan(d)) throw std::invalid_argument("fractal_passing_fraction: d is NaN");
  if (d <= d_min) return 0.0;
  if (d >= d_max) return 1.0;
  const double e = 3.0 - alpha;
  // Within 1e-9 of alpha = 3 the power form loses digits to cancellation; the log form is its
  // limit and is accurate there to O(e).
  if (std::abs(e) < 1e-9) return std::log(d / d_min) / std::log(d_max / d_min);
  // Written with ratios to d_min so that the result does not depend on the length unit.
  return std::expm1(e * std::log(d / d_min)) / std::expm1(e * std::log(d_max / d_min));
}

GrainSizeCurve fractal_curve(double d_min, double d_max, double alpha, std::size_t n_points) {
  check_range(d_min, d_max, alpha);
  if (n_points < 2) throw std::invalid_argument("fractal_curve: need at least 2 points");
  GrainSizeCurve c;
  for (std::size_t i = 0; i < n_points; ++i) {
    const double t = static_cast<double>(i) / static_cast<double>(n_points - 1);
    const double d = i + 1 == n_points ? d_max : d_min * std::pow(d_max / d_min, t);
    c.diameter.push_back(d);
    c.percent_passing.push_back(100.0 * fractal_passing_fraction(d, d_min, d_max, alpha));
  }
  c.percent_passing.back() = 100.0;  // exact, whatever pow rounded to
  return c;
}

std::vector<double> passing_with_fines(std::span<const double> diameters,
                                       std::span<const FractalFines> fines,
                                       std::span<const double> sizes) {
  double fines_total = 0.0;
  for (const auto& f : fines) {
    check_range(f.d_min, f.d_max, f.alpha);
    if (!(std::isfinite(f.volume) && f.volume >= 0.0))
      throw std::invalid_argument("passing_with_fines: fines volume must be finite and >= 0");
    fines_total += f.volume;
  }
  const double grains_total = diameters.empty() ? 0.0 : solid_volume(diameters);
  const double total = grains_total + fines_total;
  if (!(total > 0.0)) throw std::invalid_argument("passing_with_fines: no mass at all");

  std::vector<double> out(sizes.size(), 0.0);
  if (!diameters.empty()) {
    const auto grains = sample_passing(diameters, sizes);
    for (std::size_t k = 0; k < sizes.size(); ++k) out[k] = grains[k] / 100.0 * grains_total;
  }
  for (const auto& f : fines)
    for (std::size_t k = 0; k < sizes.size(); ++k)
      out[k] += f.volume * fractal_passing_fraction(sizes[k], f.d_min, f.d_max, f.alpha);
  for (double& v : out) v = 100.0 * v / total;
  return out;
}

}  // namespace kolsky::psd
