// Pool-adjacent-violators (see isotonic.hpp).
#include "harness/isotonic.hpp"

#include <cstddef>

namespace kolsky::harness {

std::vector<double> nearest_non_decreasing(const std::vector<double>& v) {
  std::vector<double> mean, weight;
  for (double x : v) {
    mean.push_back(x), weight.push_back(1);
    while (mean.size() > 1 && mean[mean.size() - 2] > mean.back()) {
      const std::size_t j = mean.size() - 2;
      mean[j] = (mean[j] * weight[j] + mean.back() * weight.back()) / (weight[j] + weight.back());
      weight[j] += weight.back();
      mean.pop_back(), weight.pop_back();
    }
  }
  std::vector<double> out;
  for (std::size_t j = 0; j < mean.size(); ++j) out.insert(out.end(), static_cast<std::size_t>(weight[j]), mean[j]);
  return out;
}

}  // namespace kolsky::harness
