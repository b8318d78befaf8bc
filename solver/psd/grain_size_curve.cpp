// Grain-size curves: validation, interpolation linear in log d, D_x, scaling, mean grain volume.
// The bin integral behind mean_grain_volume is derived in docs/psd.md.
#include "psd/grain_size_curve.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>

namespace kolsky::psd {

namespace {

std::string where(std::size_t row) {
  return row == InvalidCurve::kWholeCurve ? std::string("grain-size curve")
                                          : "grain-size curve: row " + std::to_string(row + 1);
}

std::string num(double v) {
  std::ostringstream s;
  s.precision(6);
  s << v;
  return s.str();
}

void require_positive_factor(double factor) {
  if (!(std::isfinite(factor) && factor > 0.0))
    throw std::invalid_argument("grain-size scaling: factor must be finite and > 0, got " +
                                num(factor));
}

GrainSizeCurve scaled(const GrainSizeCurve& curve, double factor) {
  curve.validate();
  GrainSizeCurve out = curve;
  for (double& d : out.diameter) d *= factor;
  return out;
}

// Number of grains per unit solid volume in the bin [a, b] per unit mass fraction, times pi/6:
// integral over ln d of d^-3 / ln(b/a) = a^-3 (1 - (a/b)^3) / (3 ln(b/a)); expm1 keeps it exact
// for narrow bins where b/a -> 1 (the limit is a^-3).
double bin_inverse_cube(double a, double b) {
  const double r = std::log(b / a);
  return std::pow(a, -3.0) * (-std::expm1(-3.0 * r)) / (3.0 * r);
}

}  // namespace

InvalidCurve::InvalidCurve(std::size_t row, const std::string& rule)
    : std::invalid_argument(where(row) + ": " + rule), row_(row) {}

void GrainSizeCurve::validate() const {
  if (diameter.size() != percent_passing.size())
    throw InvalidCurve(InvalidCurve::kWholeCurve,
                       "diameter and percent_passing differ in length (" +
                           std::to_string(diameter.size()) + " vs " +
                           std::to_string(percent_passing.size()) + ")");
  if (diameter.empty()) throw InvalidCurve(InvalidCurve::kWholeCurve, "no rows");
  for (std::size_t i = 0; i < diameter.size(); ++i) {
    const double d = diameter[i], p = percent_passing[i];
    if (!(std::isfinite(d) && d > 0.0))
      throw InvalidCurve(i, "diameter must be finite and > 0 m, got " + num(d));
    if (!(std::isfinite(p) && p >= 0.0 && p <= 100.0))
      throw InvalidCurve(i, "percent passing must be finite and in [0, 100], got " + num(p));
    if (i > 0 && !(d > diameter[i - 1]))
      throw InvalidCurve(i, "diameters must strictly increase (" + num(d) + " m after " +
                                num(diameter[i - 1]) + " m)");
    if (i > 0 && p < percent_passing[i - 1])
      throw InvalidCurve(i, "percent passing must not decrease (" + num(p) + " after " +
                                num(percent_passing[i - 1]) + ")");
  }
  if (percent_passing.back() != 100.0)
    throw InvalidCurve(diameter.size() - 1,
                       "the largest size must pass 100 % (the curve must hold all the mass), got " +
                           num(percent_passing.back()));
}

double passing_at(const GrainSizeCurve& curve, double d) {
  const auto& x = curve.diameter;
  const auto& p = curve.percent_passing;
  if (std::isnan(d)) throw std::invalid_argument("passing_at: diameter is NaN");
  if (d < x.front()) return 0.0;
  if (d >= x.back()) return 100.0;
  const auto hi = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), d) - x.begin());
  const std::size_t lo = hi - 1;
  const double t = std::log(d / x[lo]) / std::log(x[hi] / x[lo]);
  return p[lo] + t * (p[hi] - p[lo]);
}

double percentile_diameter(const GrainSizeCurve& curve, double x_percent) {
  curve.validate();
  if (!(x_percent > 0.0 && x_percent <= 100.0))
    throw std::invalid_argument("percentile_diameter: x must be in (0, 100], got " +
                                num(x_percent));
  const auto& x = curve.diameter;
  const auto& p = curve.percent_passing;
  if (x_percent <= p.front()) return x.front();  // inside the lump at the smallest size
  std::size_t hi = 1;
  while (p[hi] < x_percent) ++hi;  // terminates: p.back() == 100 >= x_percent
  const double t = (x_percent - p[hi - 1]) / (p[hi] - p[hi - 1]);
  return x[hi - 1] * std::pow(x[hi] / x[hi - 1], t);
}

double uniformity_coefficient(const GrainSizeCurve& curve) { return d60(curve) / d10(curve); }

double curvature_coefficient(const GrainSizeCurve& curve) {
  const double d30v = d30(curve);
  return d30v * d30v / (d10(curve) * d60(curve));
}

GrainSizeCurve upscale(const GrainSizeCurve& curve, double factor) {
  require_positive_factor(factor);
  return scaled(curve, factor);
}

GrainSizeCurve downscale(const GrainSizeCurve& curve, double factor) {
  require_positive_factor(factor);
  return scaled(curve, 1.0 / factor);
}

double mean_grain_volume(const GrainSizeCurve& curve) {
  curve.validate();
  const auto& x = curve.diameter;
  const auto& p = curve.percent_passing;
  // sum over bins of mass fraction * <d^-3>: grains per unit solid volume is (6/pi) times this.
  double inv_cube = p.front() / 100.0 * std::pow(x.front(), -3.0);
  for (std::size_t i = 1; i < x.size(); ++i) {
    const double f = (p[i] - p[i - 1]) / 100.0;
    if (f > 0.0) inv_cube += f * bin_inverse_cube(x[i - 1], x[i]);
  }
  return std::numbers::pi / 6.0 / inv_cube;
}

double mean_volume_diameter(const GrainSizeCurve& curve) {
  return std::cbrt(6.0 * mean_grain_volume(curve) / std::numbers::pi);
}

double cylinder_volume(double diameter, double length) {
  if (!(std::isfinite(diameter) && diameter > 0.0 && std::isfinite(length) && length > 0.0))
    throw std::invalid_argument("cylinder_volume: diameter and length must be finite and > 0");
  return std::numbers::pi / 4.0 * diameter * diameter * length;
}

double expected_particle_count(const GrainSizeCurve& curve, double total_volume, double porosity) {
  if (!(std::isfinite(total_volume) && total_volume > 0.0))
    throw std::invalid_argument("expected_particle_count: volume must be finite and > 0 m^3");
  if (!(porosity >= 0.0 && porosity < 1.0))
    throw std::invalid_argument("expected_particle_count: porosity must be in [0, 1), got " +
                                num(porosity));
  return total_volume * (1.0 - porosity) / mean_grain_volume(curve);
}

}  // namespace kolsky::psd
