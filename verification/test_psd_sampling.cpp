// Sampling grain diameters from a curve (psd/sampling.hpp): the generator against the reference
// outputs of SplitMix64 and xoshiro256**, reproducibility per seed, the sample's mass curve
// against the stated deterministic bound, the solid volume, the within-bin number density, and
// the sample's count against the expected count V_s / mean grain volume.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <vector>

#include "psd/sampling.hpp"
#include "core/rng.hpp"
#include "test_support.hpp"

namespace kolsky::psd {
namespace {

using kolsky::testing::record;

// A poorly graded sand-like curve with wide bins (the hardest case for the within-bin draws).
GrainSizeCurve test_curve() {
  return {{0.1e-3, 0.2e-3, 0.3e-3, 0.45e-3, 0.6e-3}, {0.0, 15.0, 50.0, 85.0, 100.0}};
}

double sphere(double d) { return std::numbers::pi / 6.0 * d * d * d; }

TEST(PsdSampling, GeneratorsMatchReferenceOutputs) {
  // SplitMix64 from 0 (Vigna's splitmix64.c) and xoshiro256** from state {1, 2, 3, 4}
  // (xoshiro256starstar.c), checked against an independent Python transcription.
  SplitMix64 sm(0);
  EXPECT_EQ(sm.next(), 0xe220a8397b1dcdafULL);
  EXPECT_EQ(sm.next(), 0x6e789e6aa1b965f4ULL);
  Xoshiro256ss x(1, 2, 3, 4);
  EXPECT_EQ(x.next(), 11520ULL);
  EXPECT_EQ(x.next(), 0ULL);
  EXPECT_EQ(x.next(), 1509978240ULL);
  EXPECT_EQ(x.next(), 1215971899390074240ULL);
  Xoshiro256ss seeded(42);
  EXPECT_EQ(seeded.next(), 0x15780b2e0c2ec716ULL);
  Xoshiro256ss u(7);
  for (int i = 0; i < 1000; ++i) {
    const double v = u.uniform_open();
    ASSERT_GT(v, 0.0);
    ASSERT_LT(v, 1.0);
  }
}

TEST(PsdSampling, ReproducibleForASeedAndDifferentAcrossSeeds) {
  const auto c = test_curve();
  const double vs = 2000 * sphere(0.3e-3);
  const auto a = sample_diameters(c, vs, 12345);
  const auto b = sample_diameters(c, vs, 12345);
  const auto other = sample_diameters(c, vs, 12346);
  EXPECT_EQ(a, b);  // bit for bit: integer generator, same operations
  EXPECT_NE(a, other);
  EXPECT_TRUE(std::is_sorted(a.begin(), a.end(), std::greater<double>()));
  EXPECT_GE(a.back(), c.d_min());
  EXPECT_LE(a.front(), c.d_max());
}

TEST(PsdSampling, MassCurveWithinTheStratifiedBound) {
  // Bound (sampling.hpp): |dP| <= 100 v(d_max) / (V_s - v(d_max)/2), i.e. about
  // 100 (v(d_max)/v_mean) / count, falling like 1/count (i.i.d. draws: like 1/sqrt(count)).
  const auto c = test_curve();
  double previous_bound = 1e300;
  for (double grains : {300.0, 3000.0, 30000.0}) {
    const double vs = grains * mean_grain_volume(c);
    const auto s = sample_diameters(c, vs, 2024);
    const double dev = max_passing_deviation(c, s);
    const double bound = max_passing_deviation_bound(c, vs);
    EXPECT_LE(dev, bound) << grains << " grains";
    EXPECT_LT(bound, previous_bound / 9.9);  // x10 grains: bound / 10 (1/count)
    previous_bound = bound;
    // And it sits inside a 1/sqrt(count) envelope 100 sqrt(v(d_max)/v_mean / count).
    EXPECT_LE(dev, 100.0 * std::sqrt(sphere(c.d_max()) / mean_grain_volume(c) /
                                     static_cast<double>(s.size())));
    record("max_dev_pp_" + std::to_string(s.size()), dev);
    record("bound_pp_" + std::to_string(s.size()), bound);
  }
}

TEST(PsdSampling, SolidVolumeReachedWithinOneLargestGrain) {
  const auto c = test_curve();
  for (std::uint64_t seed : {1u, 2u, 3u}) {
    const double vs = 5000 * mean_grain_volume(c);
    const double got = solid_volume(sample_diameters(c, vs, seed));
    // The last bin stops within half its largest grain of the target (sampling.hpp).
    EXPECT_LE(std::abs(got - vs), sphere(c.d_max()) / 2);
    record("volume_error_over_vmax_seed" + std::to_string(seed),
           std::abs(got - vs) / sphere(c.d_max()));
  }
}

TEST(PsdSampling, MonodisperseCurveGivesTheNearestCount) {
  const double d = 0.3e-3;
  const auto s = sample_diameters(GrainSizeCurve{{d}, {100.0}}, 1000.4 * sphere(d), 9);
  EXPECT_EQ(s.size(), 1000u);
  EXPECT_TRUE(std::all_of(s.begin(), s.end(), [d](double x) { return x == d; }));
}

TEST(PsdSampling, WithinBinMassIsUniformInLogD) {
  // One bin [a, 2a]: half the mass lies below sqrt(2) a. Delta-method std of the sample's mass
  // fraction there is 0.19 percentage points at 1e5 grains (per-grain variance 0.354 of v_mean^2);
  // 1.0 point is > 5 sigma.
  const double a = 0.1e-3;
  const GrainSizeCurve bin{{a, 2 * a}, {0.0, 100.0}};
  const auto s = sample_diameters(bin, 1e5 * mean_grain_volume(bin), 77);
  const double mid = std::sqrt(2.0) * a;
  const double p = sample_passing(s, std::vector<double>{mid})[0];
  EXPECT_NEAR(p, 50.0, 1.0);
  record("passing_at_log_midpoint", p);
}

TEST(PsdSampling, CountMatchesExpectedCount) {
  // Each bin's volume is fixed to within half a grain, so the count varies only through the
  // within-bin spread of grain volume: relative std about CV(v)/sqrt(n) < 0.65/sqrt(n) (CV 0.65
  // for a bin with b/a = 2, smaller for these narrower ones), i.e. < 0.4 % at n ~ 3e4;
  // 2 % is a 5-sigma band.
  const auto c = test_curve();
  for (std::uint64_t seed : {11u, 12u}) {
    const double vs = 30000 * mean_grain_volume(c);
    const double expected = vs / mean_grain_volume(c);
    const auto s = sample_diameters(c, vs, seed);
    const double rel = static_cast<double>(s.size()) / expected - 1.0;
    EXPECT_NEAR(rel, 0.0, 0.02);
    EXPECT_NEAR(mean_volume_diameter(s), mean_volume_diameter(c), 0.01 * mean_volume_diameter(c));
    record("count_rel_error_seed" + std::to_string(seed), rel);
  }
}

TEST(PsdSampling, RejectsBadInput) {
  const auto c = test_curve();
  EXPECT_THROW(sample_diameters(c, 0.0, 1), std::invalid_argument);
  EXPECT_THROW(sample_diameters(c, 1.0, 1, 1000), std::invalid_argument);  // 1 m^3: a unit slip
  EXPECT_THROW(sample_diameters(GrainSizeCurve{{1e-4, 2e-4}, {0.0, 90.0}}, 1e-9, 1),
               InvalidCurve);
  EXPECT_THROW(sample_passing(std::vector<double>{}, std::vector<double>{1e-4}),
               std::invalid_argument);
  EXPECT_THROW(holds_a_grain(c, 0.0, 1), std::invalid_argument);
  EXPECT_THROW(holds_a_grain(c, 1.0, 1, 1000), std::invalid_argument);
}

// holds_a_grain is what the scene reader asks of every DEM specimen: the answer of the full
// draw, over volumes from below one smallest grain to many grains, for several seeds.
TEST(PsdSampling, HoldsAGrainAgreesWithTheSample) {
  const auto c = test_curve();
  int empty = 0, full = 0;
  for (double v = sphere(0.05e-3); v < 1e3 * sphere(0.6e-3); v *= 1.7)
    for (std::uint64_t seed : {1, 2, 3}) {
      const bool any = !sample_diameters(c, v, seed).empty();
      EXPECT_EQ(holds_a_grain(c, v, seed), any) << "volume " << v << " seed " << seed;
      (any ? full : empty)++;
    }
  EXPECT_GT(empty, 0);  // both answers occur
  EXPECT_GT(full, 0);
}

// Found by fuzz_scene (fuzz/corpus/scene/regress_dem_sampling_hang.json): the reader drew the
// whole sample to see that it was not empty, seconds and hundreds of MB for a 1 m specimen of
// fine grains. holds_a_grain does not draw the sample: 1e15 grains (beyond any memory) answer
// at once; the old check would never return here.
TEST(PsdSampling, HoldsAGrainCostDoesNotGrowWithTheVolume) {
  const auto c = test_curve();
  EXPECT_TRUE(holds_a_grain(c, 1e15 * sphere(0.3e-3), 1, static_cast<std::size_t>(1e16)));
}

}  // namespace
}  // namespace kolsky::psd
