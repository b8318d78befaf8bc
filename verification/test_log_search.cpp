// The reproduction sets' shared calibration search (reproductions/harness/log_search.hpp) on an
// analytic objective, f(p) = (ln p - ln p*)^2: it finds p* to its bracket tolerance, never
// evaluates a point twice (nor within 0.1 % of one), respects the cap, and says why it stopped
// when the objective has no interior minimum within the cap.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "harness/log_search.hpp"

namespace kolsky::harness {
namespace {

LogSearchSettings around(double guess, double factor, double rel_tol, int cap) {
  const double step = std::log(factor), mid = std::log(guess);
  return {mid - step, mid, mid + step, step, rel_tol, cap};
}

TEST(LogSearch, FindsTheMinimumToItsToleranceWithoutRepeats) {
  const double target = 2.5;
  std::vector<double> calls;
  auto f = [&](double p) {
    calls.push_back(p);
    return std::pow(std::log(p / target), 2);
  };
  const LogSearchResult r = log_brent_search(f, around(7.0, 1.5, 0.01, 30));  // starts 2.8 x off
  ASSERT_TRUE(r.converged) << r.note;
  // The bracket holds p* and is as narrow as asked (ln width 0.01); the best point lies in it.
  EXPECT_LE(r.bracket_lo, target);
  EXPECT_GE(r.bracket_hi, target);
  // It ends either on the tolerance or, on this exact parabola in ln p, where Brent's next
  // probe falls within 0.1 % of its best point (the bracket then is the one before that probe).
  if (r.note.empty())
    EXPECT_LT(std::log(r.bracket_hi / r.bracket_lo), 0.01 + 1e-12);
  else
    EXPECT_NE(r.note.find("within 0.1 %"), std::string::npos) << r.note;
  EXPECT_NEAR(std::log(r.best / target), 0.0, 0.01);
  EXPECT_EQ(calls.size(), r.evaluated.size());
  for (std::size_t i = 0; i < calls.size(); ++i)
    for (std::size_t j = 0; j < i; ++j) EXPECT_GE(std::abs(calls[i] / calls[j] - 1), 1e-3) << i << " " << j;
  EXPECT_DOUBLE_EQ(calls[0], 7.0);  // the middle first, then the two ends
  EXPECT_NEAR(calls[1], 7.0 / 1.5, 1e-12);
  EXPECT_NEAR(calls[2], 7.0 * 1.5, 1e-12);
}

TEST(LogSearch, CapAndAMissingBracketAreReported) {
  int n = 0;
  auto falling = [&](double p) {  // no minimum: the walk goes up forever
    ++n;
    return -p;
  };
  const LogSearchResult r = log_brent_search(falling, around(1.0, 2.0, 0.01, 6));
  EXPECT_FALSE(r.converged);
  EXPECT_EQ(n, 6);
  EXPECT_NE(r.note.find("no bracket"), std::string::npos) << r.note;
  EXPECT_NEAR(r.best, 16.0, 1e-12);  // the highest p tried: 1, 0.5, 2, 4, 8, 16 (6 runs)
  auto bowl = [](double p) { return std::pow(std::log(p / 3.0), 2); };
  const LogSearchResult c = log_brent_search(bowl, around(3.1, 1.5, 1e-9, 5));
  EXPECT_FALSE(c.converged);
  EXPECT_EQ(c.evaluated.size(), 5u);
  EXPECT_NE(c.note.find("cap"), std::string::npos) << c.note;
}

}  // namespace
}  // namespace kolsky::harness
