// Breakage measures (psd/hardin_breakage.hpp, psd/fractal_fines.hpp): Hardin's B_r for identical
// curves, complete crushing and two hand-computed cases; Eq. 5.16 at its end points, at a point
// chosen so the powers are exact, and at its alpha = 3 limit; the tabulated fractal curve; the
// PSD of particles plus redistributed fines.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "psd/fractal_fines.hpp"
#include "psd/hardin_breakage.hpp"
#include "test_support.hpp"

namespace kolsky::psd {
namespace {

constexpr double eps = 1e-13;  // relative: sums of a few log10/pow terms (~1e-15 each)

TEST(PsdHardin, IdenticalCurvesGiveZero) {
  const GrainSizeCurve c{{0.05e-3, 0.2e-3, 0.4e-3, 0.6e-3}, {0.0, 10.0, 60.0, 100.0}};
  const auto b = hardin_breakage(c, c, 75e-6);
  EXPECT_EQ(b.total, 0.0);
  EXPECT_EQ(b.relative, 0.0);
  EXPECT_GT(b.potential, 0.0);
}

TEST(PsdHardin, CompleteCrushingBelowTheThresholdGivesOne) {
  const GrainSizeCurve initial{{0.1e-3, 0.3e-3, 0.6e-3}, {0.0, 50.0, 100.0}};
  const GrainSizeCurve crushed{{1e-6, 60e-6}, {0.0, 100.0}};
  EXPECT_NEAR(hardin_breakage(initial, crushed, 75e-6).relative, 1.0, eps);
}

TEST(PsdHardin, HandComputedIntermediateCases) {
  // Initial: one decade 0.1-1 mm, linear in log d: P0 = x with x = log10(d / 0.1 mm).
  // Current: two decades 0.01-1 mm: P = (1 + x)/2.
  const GrainSizeCurve initial{{0.1e-3, 1e-3}, {0.0, 100.0}};
  const GrainSizeCurve current{{0.01e-3, 1e-3}, {0.0, 100.0}};
  // Threshold 0.1 mm: B_p = int_0^1 (1 - x) dx = 1/2, B_t = int_0^1 ((1+x)/2 - x) dx = 1/4.
  const auto b = hardin_breakage(initial, current, 0.1e-3);
  EXPECT_NEAR(b.potential, 0.5, eps);
  EXPECT_NEAR(b.total, 0.25, eps);
  EXPECT_NEAR(b.relative, 0.5, eps);
  // Threshold 75 um adds w = log10(0.1/0.075) decades where P0 = 0 and P rises linearly (in
  // log d) from log10(7.5)/2 to 1/2: B_p = 1/2 + w, B_t = 1/4 + w (log10(7.5)/2 + 1/2)/2.
  const double w = std::log10(0.1 / 0.075);
  const double bp = 0.5 + w, bt = 0.25 + w * (std::log10(7.5) / 2 + 0.5) / 2;
  const auto b75 = hardin_breakage(initial, current, 75e-6);
  EXPECT_NEAR(b75.potential, bp, eps);
  EXPECT_NEAR(b75.total, bt, eps);
  EXPECT_NEAR(b75.relative, bt / bp, eps);
  kolsky::testing::record("hardin_br_75um", b75.relative);
}

TEST(PsdHardin, RejectsAnInitialCurveWithNothingToBreak) {
  const GrainSizeCurve fine{{10e-6, 50e-6}, {0.0, 100.0}};
  EXPECT_THROW(hardin_breakage(fine, fine, 75e-6), std::invalid_argument);
  EXPECT_THROW(hardin_breakage(fine, fine, 0.0), std::invalid_argument);
}

TEST(PsdFractal, Eq516EndPointsAndMidpoint) {
  const double dmin = 1e-6, dmax = 1024e-6, a = 2.6;
  EXPECT_EQ(fractal_passing_fraction(dmin, dmin, dmax, a), 0.0);
  EXPECT_EQ(fractal_passing_fraction(dmax, dmin, dmax, a), 1.0);
  EXPECT_EQ(fractal_passing_fraction(0.5e-6, dmin, dmax, a), 0.0);
  EXPECT_EQ(fractal_passing_fraction(2e-3, dmin, dmax, a), 1.0);
  // 3 - a = 0.4: (32)^0.4 = 4 and (1024)^0.4 = 16, so (4 - 1)/(16 - 1) = 0.2 exactly.
  EXPECT_NEAR(fractal_passing_fraction(32e-6, dmin, dmax, a), 0.2, eps);
  // Scale-free: the same ratios in other units.
  EXPECT_NEAR(fractal_passing_fraction(32.0, 1.0, 1024.0, a), 0.2, eps);
  // alpha = 3 limit: ln(32)/ln(1024) = 1/2; just off it the power form agrees to O(3 - alpha).
  EXPECT_NEAR(fractal_passing_fraction(32e-6, dmin, dmax, 3.0), 0.5, eps);
  EXPECT_NEAR(fractal_passing_fraction(32e-6, dmin, dmax, 3.0 - 1e-6), 0.5, 1e-5);
  EXPECT_THROW(fractal_passing_fraction(1e-5, dmax, dmin, a), std::invalid_argument);
}

TEST(PsdFractal, TabulatedCurveFollowsEq516) {
  const double dmin = 7.5e-6, dmax = 0.224 * 0.6e-3, a = 2.6;
  const auto c = fractal_curve(dmin, dmax, a, 41);
  ASSERT_NO_THROW(c.validate());
  for (std::size_t i = 0; i < c.size(); ++i)
    EXPECT_NEAR(c.percent_passing[i], 100 * fractal_passing_fraction(c.diameter[i], dmin, dmax, a),
                1e-11);  // same formula at the rows, up to pow/exp rounding
  // Between rows the log-linear table is within h^2 max|F''|/8 of Eq. 5.16, F(x) = (e^(kx) - 1)/
  // (e^(kL) - 1) in x = ln(d/dmin), k = 3 - a, L = ln(dmax/dmin), h = L/40: |F''| <= k^2 e^(kL)/
  // (e^(kL) - 1). That is 0.0152 points here; 5 % margin for the O(h^4) remainder.
  const double k = 3 - a, L = std::log(dmax / dmin), h = L / 40;
  const double bound = 100 * h * h * k * k * std::exp(k * L) / (8 * std::expm1(k * L));
  double worst = 0.0;
  for (std::size_t i = 1; i < c.size(); ++i) {
    const double mid = std::sqrt(c.diameter[i] * c.diameter[i - 1]);
    worst = std::max(worst, std::abs(passing_at(c, mid) -
                                     100 * fractal_passing_fraction(mid, dmin, dmax, a)));
  }
  EXPECT_LT(worst, 1.05 * bound);
  EXPECT_GT(worst, 0.5 * bound);  // the estimate is the actual size, not a loose cap
  kolsky::testing::record("fractal_table_worst_pp", worst);
}

TEST(PsdFractal, PassingOfParticlesPlusFines) {
  // One grain of 2 mm and as much fines volume over [1 um, 1024 um] (alpha 2.6).
  const double d = 2e-3, v = std::numbers::pi / 6 * d * d * d;
  const std::vector<double> grains{d};
  const std::vector<FractalFines> fines{{v, 1e-6, 1024e-6, 2.6}};
  const std::vector<double> sizes{0.5e-6, 32e-6, 1024e-6, 1.5e-3, 2e-3};
  const auto p = passing_with_fines(grains, fines, sizes);
  EXPECT_NEAR(p[0], 0.0, eps);
  EXPECT_NEAR(p[1], 10.0, 1e-11);  // half the mass, of which Eq. 5.16 puts 0.2 below 32 um
  EXPECT_NEAR(p[2], 50.0, 1e-11);
  EXPECT_NEAR(p[3], 50.0, 1e-11);
  EXPECT_NEAR(p[4], 100.0, 1e-11);
  // Fines alone are Eq. 5.16; nothing at all is an error.
  EXPECT_NEAR(passing_with_fines({}, fines, sizes)[1], 20.0, 1e-11);
  EXPECT_THROW(passing_with_fines({}, {}, sizes), std::invalid_argument);
}

}  // namespace
}  // namespace kolsky::psd
