// A tabulated strain-rate history and its strain, Eq. 5.1 (Sec. 5.2.1, methodology 1: the
// reported strain rate of the Wang et al. 2018 and Huang et al. 2013 tests drives the
// incident-side wall of a DEM specimen).
//   Rate: linear in time between the rows (t_k, r_k); 0 before the first row and after the
//   last one (the wall stands still there). Compression positive, 1/s.
//   Strain: eps(t) = integral_0^t rate dt (Eq. 5.1), in closed form: the cumulative trapezoid
//   at the rows (exact for a linear segment) plus the exact partial segment
//   s (r_k + slope s / 2), s = t - t_k. So eps does not depend on the time step, and a constant
//   rate r from t = 0 gives eps = r t to round-off.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

namespace kolsky::shpb {

class StrainRateHistory {
 public:
  StrainRateHistory() = default;
  /// Throws InputError("", "loading.file", rule): fewer than 2 rows, sizes differ, a
  /// non-finite value, time not strictly increasing, or a first time below 0 (the run starts
  /// at t = 0).
  StrainRateHistory(std::vector<double> time, std::vector<double> rate);

  double rate(double t) const;    ///< 1/s
  double strain(double t) const;  ///< Eq. 5.1, engineering strain (compression +)
  /// Time of the last row, s: beyond it the rate is 0 and the strain stays strain(end_time()).
  double end_time() const { return t_.empty() ? 0.0 : t_.back(); }
  const std::vector<double>& times() const { return t_; }
  const std::vector<double>& rates() const { return r_; }

 private:
  /// Index k of the segment [t_k, t_{k+1}) holding t; requires t_0 <= t < t_n.
  std::size_t segment(double t) const;
  std::vector<double> t_, r_;
  std::vector<double> cum_;  // eps at each row
};

}  // namespace kolsky::shpb
