// harness::nearest_non_decreasing (pool-adjacent-violators), the start of Chapter 2's
// never-softening calibration: hand cases, and against random non-decreasing sequences it is
// never farther from the input (it is the least-squares projection onto that cone).
#include <gtest/gtest.h>

#include <algorithm>
#include <numeric>
#include <random>
#include <vector>

#include "harness/isotonic.hpp"

namespace kolsky::harness {
namespace {

double sse(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0;
  for (std::size_t k = 0; k < a.size(); ++k) s += (a[k] - b[k]) * (a[k] - b[k]);
  return s;
}

TEST(Isotonic, HandCases) {
  EXPECT_EQ(nearest_non_decreasing({1, 2, 3}), (std::vector<double>{1, 2, 3}));  // already monotone
  EXPECT_EQ(nearest_non_decreasing({5, 1}), (std::vector<double>{3, 3}));
  EXPECT_EQ(nearest_non_decreasing({3, 1, 2}), (std::vector<double>{2, 2, 2}));  // a pool absorbs the next
  EXPECT_EQ(nearest_non_decreasing({1, 4, 2, 5}), (std::vector<double>{1, 3, 3, 5}));
  EXPECT_TRUE(nearest_non_decreasing({}).empty());
}

TEST(Isotonic, NoNonDecreasingSequenceIsCloser) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> noise(0.0, 1.0);
  for (int trial = 0; trial < 200; ++trial) {
    std::vector<double> v(1 + trial % 7);
    for (double& x : v) x = noise(rng);
    const std::vector<double> y = nearest_non_decreasing(v);
    ASSERT_EQ(y.size(), v.size());
    EXPECT_TRUE(std::is_sorted(y.begin(), y.end()));
    // Each pooled run is the mean of its inputs, so the sum is kept (to round-off).
    EXPECT_NEAR(std::accumulate(y.begin(), y.end(), 0.0), std::accumulate(v.begin(), v.end(), 0.0), 1e-12);
    for (int c = 0; c < 50; ++c) {  // random non-decreasing candidates, some near y
      std::vector<double> z(v.size());
      for (std::size_t k = 0; k < z.size(); ++k) z[k] = (c % 2 ? y[k] : 0.0) + 0.3 * noise(rng);
      std::sort(z.begin(), z.end());
      EXPECT_LE(sse(y, v), sse(z, v) + 1e-12) << "trial " << trial;
    }
  }
}

}  // namespace
}  // namespace kolsky::harness
