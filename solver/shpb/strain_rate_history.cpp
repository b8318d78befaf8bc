#include "shpb/strain_rate_history.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace kolsky::shpb {

namespace {
[[noreturn]] void bad(const std::string& rule) { throw InputError("", "loading.file", rule); }
}  // namespace

StrainRateHistory::StrainRateHistory(std::vector<double> time, std::vector<double> rate)
    : t_(std::move(time)), r_(std::move(rate)) {
  if (t_.size() != r_.size()) bad("time and strain-rate columns differ in length");
  if (t_.size() < 2) bad("a strain-rate history needs at least 2 rows");
  for (std::size_t k = 0; k < t_.size(); ++k) {
    if (!std::isfinite(t_[k]) || !std::isfinite(r_[k]))
      bad("row " + std::to_string(k) + " is not finite");
    if (k > 0 && !(t_[k] > t_[k - 1])) bad("time must be strictly increasing (row " + std::to_string(k) + ")");
  }
  if (t_.front() < 0) bad("the first time must be >= 0: the run starts at t = 0");
  // Eq. 5.1 at the rows: the trapezoid of a linear segment is its exact integral.
  cum_.assign(t_.size(), 0.0);
  for (std::size_t k = 1; k < t_.size(); ++k)
    cum_[k] = cum_[k - 1] + 0.5 * (r_[k - 1] + r_[k]) * (t_[k] - t_[k - 1]);
}

std::size_t StrainRateHistory::segment(double t) const {
  // upper_bound: the first row after t; t_0 <= t < t_n puts it in [1, n - 1].
  const auto it = std::upper_bound(t_.begin(), t_.end(), t);
  return static_cast<std::size_t>(it - t_.begin()) - 1;
}

double StrainRateHistory::rate(double t) const {
  if (t_.empty() || t < t_.front() || t > t_.back()) return 0.0;
  if (t == t_.back()) return r_.back();
  const std::size_t k = segment(t);
  const double slope = (r_[k + 1] - r_[k]) / (t_[k + 1] - t_[k]);
  return r_[k] + slope * (t - t_[k]);
}

double StrainRateHistory::strain(double t) const {
  if (t_.empty() || t <= t_.front()) return 0.0;
  if (t >= t_.back()) return cum_.back();
  const std::size_t k = segment(t);
  const double s = t - t_[k];
  const double slope = (r_[k + 1] - r_[k]) / (t_[k + 1] - t_[k]);
  return cum_[k] + s * (r_[k] + 0.5 * slope * s);
}

}  // namespace kolsky::shpb
