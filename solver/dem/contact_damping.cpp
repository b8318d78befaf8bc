// Restitution-to-damping maps; see contact_damping.hpp for the equations.
#include "dem/contact_damping.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>

namespace kolsky::dem {

double damping_ratio_from_restitution(double e) {
  if (!(e > 0 && e <= 1)) throw std::invalid_argument("restitution must be in (0, 1]");
  const double l = std::log(e);
  return -l / std::sqrt(l * l + std::numbers::pi * std::numbers::pi);
}

double linear_restitution(double zeta) {
  if (zeta >= 1) return 0;
  return std::exp(-zeta * std::numbers::pi / std::sqrt(1 - zeta * zeta));
}

double hertz_restitution(double beta) {
  // State (x, v) of the nondimensional impact; contact ends when x returns to 0.
  const double c = std::sqrt(5.0) * beta;
  auto acc = [c](double x, double v) {
    if (x <= 0) return 0.0;
    const double s = std::sqrt(x);
    return -x * s - c * std::sqrt(s) * v;
  };
  const double h = 1e-4;   // undamped contact lasts ~3.2 time units: ~32,000 RK4 steps
  const double t_max = 200;  // heavily overdamped impacts creep out; treat as e = 0
  double x = 0, v = 1;
  for (double t = 0; t < t_max; t += h) {
    const double k1x = v, k1v = acc(x, v);
    const double k2x = v + 0.5 * h * k1v, k2v = acc(x + 0.5 * h * k1x, k2x);
    const double k3x = v + 0.5 * h * k2v, k3v = acc(x + 0.5 * h * k2x, k3x);
    const double k4x = v + h * k3v, k4v = acc(x + h * k3x, k4x);
    const double xn = x + h / 6 * (k1x + 2 * k2x + 2 * k3x + k4x);
    const double vn = v + h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
    if (xn <= 0 && t > 0) {
      const double s = x / (x - xn);  // linear interpolation to the crossing
      return std::max(0.0, -(v + s * (vn - v)));
    }
    x = xn;
    v = vn;
  }
  return 0;
}

}  // namespace kolsky::dem
