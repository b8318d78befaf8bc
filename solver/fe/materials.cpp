#include "fe/materials.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"

namespace kolsky::fe {

namespace {
[[noreturn]] void bad(const char* path, const std::string& field, const std::string& rule) {
  throw InputError("", std::string(path) + "." + field, rule);
}
double sin_phi(const PseudoTensorModeI& m) {
  return std::sin(m.friction_angle_deg * std::numbers::pi / 180.0);
}
}  // namespace

void LinearElastic::validate(const char* path) const {
  if (!(youngs_modulus > 0.0)) bad(path, "youngs_modulus", "must be > 0");
  if (!(density > 0.0)) bad(path, "density", "must be > 0");
  if (!(poisson_ratio > -1.0 && poisson_ratio < 0.5)) bad(path, "poisson_ratio", "must lie in (-1, 0.5)");
}

void CompactionEos::validate(const char* path) const {
  try {
    loading.validate();
  } catch (const std::invalid_argument& e) {
    bad(path, "loading", e.what());
  }
  if (loading.x.front() != 0.0 || loading.y.front() != 0.0)
    bad(path, "loading", "must start at (0, 0): no pressure in the undeformed specimen");
  for (std::size_t i = 1; i < loading.y.size(); ++i)
    if (!(loading.y[i] > loading.y[i - 1])) bad(path, "loading", "pressure must rise with eps_v");
  double steepest = 0.0;
  for (std::size_t i = 0; i + 1 < loading.x.size(); ++i)
    steepest = std::max(steepest, (loading.y[i + 1] - loading.y[i]) / (loading.x[i + 1] - loading.x[i]));
  if (!(unloading_bulk_modulus >= steepest))
    bad(path, "unloading_bulk_modulus",
        "must be >= the steepest loading slope (" + std::to_string(steepest) + " Pa)");
}

double CompactionEos::loading_pressure(double eps_v) const {
  const auto& x = loading.x;
  const auto& y = loading.y;
  if (eps_v <= x.back()) return loading(eps_v);
  const std::size_t n = x.size();
  return y[n - 1] + (y[n - 1] - y[n - 2]) / (x[n - 1] - x[n - 2]) * (eps_v - x[n - 1]);
}

double CompactionEos::pressure(double eps_v, double eps_max) const {
  const double top = std::max(eps_max, eps_v);
  if (top <= 0.0) return 0.0;  // never compressed: dilation carries no pressure
  // Sand takes no tension: the unloading line stops at P = 0.
  return std::max(0.0, loading_pressure(top) - unloading_bulk_modulus * (top - eps_v));
}

double CompactionEos::max_tangent() const {
  double k = unloading_bulk_modulus;
  for (std::size_t i = 0; i + 1 < loading.x.size(); ++i)
    k = std::max(k, (loading.y[i + 1] - loading.y[i]) / (loading.x[i + 1] - loading.x[i]));
  return k;
}

double PseudoTensorModeI::yield_slope() const {
  const double s = sin_phi(*this);
  return 6.0 * s / (3.0 - s);
}

double PseudoTensorModeI::yield_intercept() const {
  const double s = sin_phi(*this);
  return 6.0 * cohesion * std::cos(friction_angle_deg * std::numbers::pi / 180.0) / (3.0 - s);
}

double PseudoTensorModeI::yield_stress(double pressure) const {
  return std::max(0.0, yield_intercept() + yield_slope() * pressure);
}

void PseudoTensorModeI::validate(const char* path) const {
  if (!(density > 0.0)) bad(path, "density", "must be > 0");
  if (!(shear_modulus > 0.0)) bad(path, "shear_modulus", "must be > 0");
  if (!(friction_angle_deg >= 0.0 && friction_angle_deg < 90.0))
    bad(path, "friction_angle_deg", "must lie in [0, 90)");
  if (!(cohesion >= 0.0)) bad(path, "cohesion", "must be >= 0");
  eos.validate((std::string(path) + ".eos").c_str());
}

double update_pressure(const LinearElastic& m, double eps_v, double&) {
  return m.bulk_modulus() * eps_v;
}

double update_pressure(const PseudoTensorModeI& m, double eps_v, double& eps_max) {
  const double p = m.eos.pressure(eps_v, eps_max);
  eps_max = std::max(eps_max, eps_v);
  return p;
}

double mises(const Deviator& s) {
  return std::sqrt(1.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2.0 * s[3] * s[3]));
}

void limit_deviator(Deviator& s, double yield_stress) {
  const double q2 = 1.5 * (s[0] * s[0] + s[1] * s[1] + s[2] * s[2] + 2.0 * s[3] * s[3]);
  if (q2 > yield_stress * yield_stress) {  // squares: no square root on the elastic path
    const double f = yield_stress / std::sqrt(q2);
    for (double& c : s) c *= f;
  }
}

double max_constrained_modulus(const Material& m) {
  return std::visit([](const auto& x) { return max_bulk_tangent(x) + 4.0 / 3.0 * shear_modulus(x); }, m);
}

double max_wave_speed(const Material& m) {
  const double rho = std::visit([](const auto& x) { return density(x); }, m);
  return std::sqrt(max_constrained_modulus(m) / rho);
}

double lame_wall_stiffness(const LinearElastic& m, double a, double t) {
  const double b = a + t;
  const double nu = m.poisson_ratio;
  return m.youngs_modulus * (b * b - a * a) / (a * ((1.0 - nu) * a * a + (1.0 + nu) * b * b));
}

}  // namespace kolsky::fe
