// The replacement side of the breakage scheme (dem/apollonian, dem/breakage_ledger;
// docs/breakage.md): Table 5.3 geometry (inside the parent, overlaps, retained volume) and its
// placement in the force frame; volume and momentum bookkeeping of one replacement; the fines
// ledger against the Eq. 5.16 closed form, its counts and order independence; Hardin's B_r of
// a hand-made curve pair.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "core/rng.hpp"
#include "dem/apollonian.hpp"
#include "dem/breakage_ledger.hpp"
#include "dem/breakage_model.hpp"
#include "psd/fractal_fines.hpp"
#include "test_support.hpp"

namespace kolsky::dem {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double kInf = std::numeric_limits<double>::infinity();

double ball_volume(double r) { return 4.0 / 3.0 * kPi * r * r * r; }

TEST(Apollonian, Table53Geometry) {
  double inside = 0, overlap = -1;
  for (std::size_t i = 0; i < kApollonianCount; ++i) {
    const auto& a = kApollonianTable[i];
    inside = std::max(inside, norm(a.centre) + a.radius);
    for (std::size_t j = i + 1; j < kApollonianCount; ++j) {
      const auto& b = kApollonianTable[j];
      overlap = std::max(overlap, a.radius + b.radius - norm(a.centre - b.centre));
    }
  }
  EXPECT_LE(inside, 1.0 + 1e-4);  // internally tangent to the table's 4-decimal rounding
  EXPECT_LE(overlap, 6e-5);       // targets.md 5a: 5.8e-5 R, from the rounding
  EXPECT_GT(overlap, 0.0);        // ... and the set is tangent, not loose
  // 0.5338 as printed (4 decimals): half a unit of the last digit.
  EXPECT_NEAR(retained_volume_fraction(), 0.5338, 5e-5);
  EXPECT_EQ(lost_volume_fraction(), 1.0 - retained_volume_fraction());
  EXPECT_EQ(smallest_daughter_ratio(), 0.2240);
  // The rounded table's centroid: each coordinate rounded to 5e-5, so well below 1e-4 R.
  EXPECT_LT(norm(retained_centroid()), 1e-4);
  kolsky::testing::record("max_extent_R", inside);
  kolsky::testing::record("max_overlap_R", overlap);
  kolsky::testing::record("retained_volume_fraction", retained_volume_fraction());
  kolsky::testing::record("centroid_offset_R", norm(retained_centroid()));
}

TEST(Apollonian, PlacementFollowsTheForceAxis) {
  const Vec3 c{3e-3, -2e-3, 5e-3};  // specimen-sized coordinates: ulp ~ 1e-18 m
  const double r = 0.3e-3;
  std::vector<Vec3> axes{{1, 0, 0}, {0, 1, 0}, {0, 0, 1}, {0, 0, -1}, {-1, 0, 0},
                         {0, 0, 1e-200}, {1e200, 1e200, 0}, {1, 1, 1}};
  Xoshiro256ss rng(5);
  for (int i = 0; i < 20; ++i)
    axes.push_back({rng.uniform_open() - 0.5, rng.uniform_open() - 0.5, rng.uniform_open() - 0.5});
  for (const Vec3& axis : axes)
    for (double spin : {0.0, 1.234, 6.2, 2 * kPi * rng.uniform_open()}) {
      const auto e = force_frame(axis, spin);
      // Orthonormal and right-handed to round-off (a few ulp of 1).
      EXPECT_NEAR(dot(cross(e[0], e[1]), e[2]), 1.0, 1e-15);
      EXPECT_NEAR(dot(e[0], e[1]), 0.0, 1e-15);
      const Vec3 n = e[2];
      const auto d = place_daughters(c, r, axis, spin);
      // 1e-12 R: coordinates of 5e-3 m carry ~1e-18 m of rounding, ~1e-14 R.
      for (int k = 0; k < 3; ++k) EXPECT_NEAR(dot(d[k].centre - c, n), 0.0, 1e-12 * r);
      for (int k = 6; k < 8; ++k) {  // #7, #8 on the axis, 0.6339 R either side
        EXPECT_NEAR(norm(cross(d[k].centre - c, n)), 0.0, 1e-12 * r);
        EXPECT_NEAR(std::abs(dot(d[k].centre - c, n)), 0.6339 * r, 1e-12 * r);
      }
      for (std::size_t i = 0; i < kApollonianCount; ++i) {
        EXPECT_EQ(d[i].radius, r * kApollonianTable[i].radius);
        for (std::size_t j = i + 1; j < kApollonianCount; ++j)
          EXPECT_NEAR(norm(d[i].centre - d[j].centre),
                      r * norm(kApollonianTable[i].centre - kApollonianTable[j].centre),
                      1e-12 * r);
      }
      // The spin turns #1 (along y') by exactly `spin` about the axis.
      const auto d0 = place_daughters(c, r, axis, 0.0);
      const Vec3 u0 = d0[0].centre - c, u = d[0].centre - c;
      const double turned = std::atan2(dot(cross(u0, u), n), dot(u0, u));
      EXPECT_NEAR(std::remainder(turned - spin, 2 * kPi), 0.0, 1e-12);
    }
  EXPECT_THROW(place_daughters(c, r, {0, 0, 0}, 0), std::invalid_argument);
  EXPECT_THROW(place_daughters(c, r, {std::nan(""), 0, 1}, 0), std::invalid_argument);
  EXPECT_THROW(place_daughters(c, r, {0, 0, 1}, kInf), std::invalid_argument);
  EXPECT_THROW(place_daughters(c, 0.0, {0, 0, 1}, 0), std::invalid_argument);
}

TEST(Apollonian, VolumeAndMomentumBookkeeping) {
  const double r = 0.25e-3, rho = 2650;
  const Vec3 v{1.5, -0.3, 2.0};
  const auto d = place_daughters({0, 0, 0}, r, {0.3, 0.4, 0.5}, 0.7);
  BreakageLedger ledger;
  const double lost = record_break(ledger, BreakageParams{}, r, 0);
  double vd = 0;
  Vec3 momentum{};
  for (const auto& k : d) {
    vd += ball_volume(k.radius);
    momentum += (rho * ball_volume(k.radius)) * daughter_velocity(v);
  }
  // Sums of 15 volumes: a few ulp each, 1e-14 relative.
  EXPECT_NEAR(vd + lost, ball_volume(r), 1e-14 * ball_volume(r));
  EXPECT_NEAR(vd, retained_volume_fraction() * ball_volume(r), 1e-14 * vd);
  const double m_ret = rho * vd;
  for (double Vec3::*c : {&Vec3::x, &Vec3::y, &Vec3::z}) {
    // Momentum per unit retained mass equals the parent's velocity (14 products and sums).
    EXPECT_NEAR(momentum.*c / m_ret, v.*c, 1e-14 * norm(v));
    EXPECT_NEAR(momentum.*c, retained_volume_fraction() * rho * ball_volume(r) * v.*c,
                1e-14 * m_ret * norm(v));
  }
}

TEST(BreakageLedger, FinesFollowEq516AndCountsSplit) {
  const BreakageParams p;
  const double r = 0.3e-3, d_max = 2 * 0.2240 * r;
  const int n = 1000;
  BreakageLedger l;
  std::vector<double> grains;
  for (int i = 0; i < n; ++i) {
    record_break(l, p, r, i < 990 ? 0 : 1 + i % 3);
    for (const auto& k : place_daughters({0, 0, 0}, r, {0, 0, 1}, 0))
      grains.push_back(2 * k.radius);
  }
  EXPECT_EQ(l.n_primary, 990u);
  EXPECT_EQ(l.n_secondary, 10u);
  EXPECT_EQ(primary_daughters(l), 13860u);
  ASSERT_EQ(l.fines.size(), 1u);  // one parent size: one aggregated entry
  EXPECT_EQ(l.fines[0].d_max, d_max);
  // 1000 equal additions: at most ~1000 half-ulp roundings, 1e-12 relative.
  const double v_lost = n * lost_volume_fraction() * ball_volume(r);
  EXPECT_NEAR(l.lost_volume, v_lost, 1e-12 * v_lost);
  EXPECT_NEAR(l.fines[0].volume, v_lost, 1e-12 * v_lost);

  std::vector<double> sizes;
  for (int k = 0; k <= 40; ++k) sizes.push_back(5e-6 * std::pow(2.0, k / 5.0));  // 5 um-1.3 mm
  const auto fines_only = current_curve(l, {}, sizes);
  const auto all = current_curve(l, grains, sizes);
  const double total = n * ball_volume(r);
  for (std::size_t k = 0; k < sizes.size(); ++k) {
    const double eq516 =
        psd::fractal_passing_fraction(sizes[k], p.fines_d_min, d_max, p.fines_fractal_dimension);
    // Same formula, summed volumes: 1e-10 percentage points is round-off of the sums.
    EXPECT_NEAR(fines_only.percent_passing[k], 100 * eq516, 1e-10);
    double v_grains = 0;
    for (const auto& t : kApollonianTable)
      if (2 * t.radius * r <= sizes[k]) v_grains += n * ball_volume(t.radius * r);
    EXPECT_NEAR(all.percent_passing[k], 100 * (v_grains + v_lost * eq516) / total, 1e-10);
  }
  // Parents of several sizes and generations, recorded in two orders: the same entries, bitwise.
  BreakageLedger a, b;
  const std::vector<double> radii{0.3e-3, 0.2e-3, 0.3e-3, 0.1e-3, 0.2e-3};
  for (std::size_t i = 0; i < radii.size(); ++i) record_break(a, p, radii[i], i % 2);
  for (std::size_t i = radii.size(); i-- > 0;) record_break(b, p, radii[i], i % 2);
  ASSERT_EQ(a.fines.size(), 3u);
  for (std::size_t i = 0; i < 3; ++i) {
    EXPECT_EQ(a.fines[i].d_max, b.fines[i].d_max);
    EXPECT_EQ(a.fines[i].volume, b.fines[i].volume);
  }
  EXPECT_LT(a.fines[0].d_max, a.fines[2].d_max);
  EXPECT_EQ(a.n_primary, 3u);
  EXPECT_EQ(a.n_secondary, 2u);
  // Sizes that stop short get the largest size appended, at 100 %.
  const auto cut = current_curve(l, grains, std::vector<double>{10e-6, 100e-6});
  EXPECT_EQ(cut.diameter.back(), 2 * 0.4641 * r);
  EXPECT_NO_THROW(cut.validate());
  EXPECT_THROW(record_break(l, p, 1e-6, 0), std::invalid_argument);  // d_max < d_min
  EXPECT_THROW(record_break(l, p, 0.0, 0), std::invalid_argument);
  EXPECT_THROW(current_curve(l, grains, std::vector<double>{2e-5, 1e-5}), std::invalid_argument);
}

TEST(BreakageLedger, HardinBrOfAHandMadePair) {
  // x = log10(d / 0.1 mm). Initial: P0 = 100 x on [0, 1]. Current: 0.01-0.1-1 mm at 0-50-100 %,
  // i.e. P = 50 + 50 x on [-1, 1]. Threshold 75 um: x_t = log10(0.75) < 0, where P0 = 0.
  // B_p = int_{x_t}^1 (1 - P0/100) dx = -x_t + 1/2;
  // B_t = int_{x_t}^1 (P - P0)/100 dx = -(x_t/2 + x_t^2/4) + 1/4.
  const psd::GrainSizeCurve initial{{0.1e-3, 1e-3}, {0, 100}};
  const psd::GrainSizeCurve current{{0.01e-3, 0.1e-3, 1e-3}, {0, 50, 100}};
  const double xt = std::log10(0.75);
  const double br = (0.25 - xt / 2 - xt * xt / 4) / (0.5 - xt);
  EXPECT_NEAR(hardin_br(initial, current), br, 1e-13);  // exact areas, a few log10 roundings
  EXPECT_EQ(hardin_br(initial, initial), 0.0);
  kolsky::testing::record("hardin_br_hand", br);
}

}  // namespace
}  // namespace kolsky::dem
