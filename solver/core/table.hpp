// Tabulated 1-D functions y(x) with linear interpolation (pulses, loading curves, references).
#pragma once
#include <string>
#include <vector>

namespace kolsky {

/// Piecewise-linear table. x strictly increasing; outside [x0, xn] the end values are held
/// unless `extrapolate` is set, then the end segments are extended linearly.
struct Table1D {
  std::vector<double> x, y;
  bool extrapolate = false;

  /// Throws std::invalid_argument naming the first violated rule (size, order, finiteness).
  void validate() const;
  double operator()(double xq) const;
  /// Slope dy/dx of the segment containing xq (end segments outside the range).
  double slope(double xq) const;
  bool empty() const { return x.empty(); }
};

/// Linear interpolation on a uniformly sampled series y[i] = f(t0 + i*dt); held at the ends.
double interp_uniform(const std::vector<double>& y, double t0, double dt, double t);

}  // namespace kolsky
