// The least-squares non-decreasing sequence nearest to a given one (isotonic regression by
// pool-adjacent-violators; Barlow et al. 1972): Chapter 2's never-softening calibration
// starts from the never-softening table nearest to a start table whose increments fall.
#pragma once
#include <vector>

namespace kolsky::harness {

/// argmin over non-decreasing y of sum (y_k - v_k)^2; each run of pooled values is their mean.
std::vector<double> nearest_non_decreasing(const std::vector<double>& v);

}  // namespace kolsky::harness
