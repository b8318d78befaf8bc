// Breakage criteria (breakage_criterion.hpp).
#include "dem/breakage_criterion.hpp"

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "core/errors.hpp"
#include "dem/breakage_model.hpp"
#include "dem/hertz.hpp"

namespace kolsky::dem {

namespace {
bool positive(double v) { return std::isfinite(v) && v > 0; }
}  // namespace

BreakageCriterion default_criterion(std::string_view name) {
  if (name == kBreakageCriterionNames[0]) return HertzianContactCriterion{};
  if (name == kBreakageCriterionNames[1]) return ConstantStressCriterion{};
  throw std::invalid_argument("unknown breakage criterion '" + std::string(name) + "'");
}

void validate(const HertzianContactCriterion& c, const std::string& path) {
  const auto fail = [&](const char* key, const std::string& rule) {
    throw InputError("", path + "." + key, rule);
  };
  if (!positive(c.sigma_lim0)) fail("sigma_lim0", "must be finite and > 0 Pa");
  if (!positive(c.d0)) fail("d0", "must be finite and > 0 m");
  if (!positive(c.m1)) fail("m1", "must be finite and > 0");
  if (!(std::isfinite(c.var_a) && c.var_a != 0)) fail("var_a", "must be finite and non-zero");
  if (!std::isfinite(c.var_b)) fail("var_b", "must be finite");
  // Eq. 5.15 is linear in U, so its extremes over [0, 1] are the two ends.
  const double at0 = -c.var_b / c.var_a, at1 = (1 - c.var_b) / c.var_a;
  if (!(at0 > 0 && at1 > 0))
    fail("var_b", "var = (U - var_b)/var_a must stay > 0 for U in [0, 1]; its ends are " +
                      std::to_string(at0) + " (U = 0) and " + std::to_string(at1) + " (U = 1)");
}

void validate(const ConstantStressCriterion& c, const std::string& path) {
  if (!positive(c.characteristic_stress))
    throw InputError("", path + ".characteristic_stress", "must be finite and > 0 Pa");
}

double strength_limit(const HertzianContactCriterion& c, double diameter, double var) {
  return c.sigma_lim0 * std::pow(diameter / c.d0, -3.0 / c.m1) * var;
}

double strength_variability(const HertzianContactCriterion& c, std::uint64_t seed,
                            std::uint64_t grain_id) {
  return (strength_uniform(seed, grain_id) - c.var_b) / c.var_a;
}

double grain_strength(const HertzianContactCriterion& c, double diameter, std::uint64_t seed,
                      std::uint64_t grain_id) {
  return strength_limit(c, diameter, strength_variability(c, seed, grain_id));
}

double pair_constant(const HertzianContactCriterion&, double e_eff) {
  return std::pow(4.0 * e_eff / (3.0 * std::numbers::pi), 2);
}

double grain_constant(const HertzianContactCriterion&, double strength, double) {
  return 1.0 / (strength * strength);
}

double wall_ratio(const HertzianContactCriterion&, double force, double radius, double e_wall,
                  double strength) {
  return force / critical_force(strength, radius, e_wall);
}

double grain_strength(const ConstantStressCriterion& c, double, std::uint64_t, std::uint64_t) {
  return c.characteristic_stress;
}

double pair_constant(const ConstantStressCriterion&, double e_eff) { return e_eff; }

double grain_constant(const ConstantStressCriterion&, double strength, double diameter) {
  return 1.0 / (strength * diameter * diameter);
}

double pair_ratio(const ConstantStressCriterion&, double overlap, double inv_r_eff, double pair_c,
                  double grain_c) {
  return hertz_normal_force(pair_c, 1.0 / inv_r_eff, overlap) * grain_c;
}

double wall_ratio(const ConstantStressCriterion&, double force, double radius, double,
                  double strength) {
  return force / (strength * 4.0 * radius * radius);
}

}  // namespace kolsky::dem
