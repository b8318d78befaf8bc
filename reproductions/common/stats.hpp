// Mean and sample standard deviation over the finite entries of a set of runs' measurements
// (packing seeds): the seed scatter the Chapter 4 and Chapter 5 reports give.
#pragma once
#include <cmath>
#include <vector>

namespace kolsky::repro {

struct SampleStat {
  double mean = NAN, sd = NAN;  ///< sd: NaN below two finite entries
  int n = 0;                    ///< finite entries
};

inline SampleStat sample_stat(const std::vector<double>& v) {
  SampleStat s;
  double sum = 0;
  for (double x : v)
    if (std::isfinite(x)) sum += x, ++s.n;
  if (s.n == 0) return s;
  s.mean = sum / s.n;
  double q = 0;
  for (double x : v)
    if (std::isfinite(x)) q += (x - s.mean) * (x - s.mean);
  s.sd = s.n > 1 ? std::sqrt(q / (s.n - 1)) : NAN;
  return s;
}

}  // namespace kolsky::repro
