// Hardin (1985) relative breakage: exact areas between piecewise log-linear curves.
#include "psd/hardin_breakage.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <vector>

namespace kolsky::psd {

HardinBreakage hardin_breakage(const GrainSizeCurve& initial, const GrainSizeCurve& current,
                               double threshold) {
  initial.validate();
  current.validate();
  if (!(std::isfinite(threshold) && threshold > 0.0))
    throw std::invalid_argument("hardin_breakage: threshold must be finite and > 0 m");

  // Breakpoints right of the threshold: both curves' sizes; past the larger d_max both are 100.
  std::vector<double> x{threshold};
  for (const auto* c : {&initial, &current})
    for (double d : c->diameter)
      if (d > threshold) x.push_back(d);
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end()), x.end());

  HardinBreakage out;
  for (std::size_t i = 1; i < x.size(); ++i) {
    const double w = std::log10(x[i] / x[i - 1]);
    const double mid = std::sqrt(x[i] * x[i - 1]);  // midpoint in log d: exact for linear
    const double p0 = passing_at(initial, mid), p = passing_at(current, mid);
    out.potential += w * (1.0 - p0 / 100.0);
    out.total += w * (p - p0) / 100.0;
  }
  if (!(out.potential > 0.0))
    throw std::invalid_argument(
        "hardin_breakage: the initial curve has no mass above the threshold (B_p = 0)");
  out.relative = out.total / out.potential;
  return out;
}

}  // namespace kolsky::psd
