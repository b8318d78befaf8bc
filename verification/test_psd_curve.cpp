// Grain-size curves (psd/grain_size_curve.hpp): validation rules and their messages, log-linear
// interpolation, D_x and C_u of a hand-computable curve, up/downscaling round trips, the mean
// grain volume of single-size, one-bin and two-size curves against closed forms, and the
// expected particle count of a cylinder.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "psd/grain_size_curve.hpp"
#include "test_support.hpp"

namespace kolsky::psd {
namespace {

constexpr double kPi = std::numbers::pi;
constexpr double eps = 1e-13;  // relative: a handful of pow/log/exp calls (~1e-15 each)

double sphere(double d) { return kPi / 6.0 * d * d * d; }

// One decade, linear in log d: D_x = 0.1 mm * 10^(x/100).
GrainSizeCurve decade() { return {{0.1e-3, 1e-3}, {0.0, 100.0}}; }

std::string message_of(const GrainSizeCurve& c) {
  try {
    c.validate();
  } catch (const InvalidCurve& e) {
    return e.what();
  }
  return "";
}

TEST(PsdCurve, ValidationNamesRowAndRule) {
  EXPECT_NO_THROW(decade().validate());
  EXPECT_NO_THROW((GrainSizeCurve{{0.3e-3}, {100.0}}).validate());  // monodisperse
  EXPECT_NE(message_of({{}, {}}).find("no rows"), std::string::npos);
  EXPECT_NE(message_of({{1e-4, 2e-4}, {0.0}}).find("differ in length"), std::string::npos);
  const std::string order = message_of({{1e-4, 3e-4, 2e-4}, {0.0, 50.0, 100.0}});
  EXPECT_NE(order.find("row 3"), std::string::npos) << order;
  EXPECT_NE(order.find("strictly increase"), std::string::npos) << order;
  const std::string down = message_of({{1e-4, 2e-4, 3e-4}, {0.0, 60.0, 50.0}});
  EXPECT_NE(down.find("must not decrease"), std::string::npos) << down;
  EXPECT_NE(message_of({{-1e-4, 2e-4}, {0.0, 100.0}}).find("> 0"), std::string::npos);
  EXPECT_NE(message_of({{1e-4, 2e-4}, {0.0, 101.0}}).find("[0, 100]"), std::string::npos);
  EXPECT_NE(message_of({{1e-4, 2e-4}, {0.0, NAN}}).find("finite"), std::string::npos);
  EXPECT_NE(message_of({{1e-4, 2e-4}, {0.0, 90.0}}).find("100 %"), std::string::npos);
  try {
    GrainSizeCurve{{1e-4, 3e-4, 2e-4}, {0.0, 50.0, 100.0}}.validate();
    FAIL() << "no throw";
  } catch (const InvalidCurve& e) {
    EXPECT_EQ(e.row(), 2u);  // 0-based index for the scene layer's line mapping
  }
  // InvalidCurve is a std::invalid_argument, as the scene layer expects.
  EXPECT_THROW((GrainSizeCurve{{1e-4}, {50.0}}).validate(), std::invalid_argument);
}

TEST(PsdCurve, PassingIsLinearInLogD) {
  const auto c = decade();
  EXPECT_EQ(passing_at(c, 0.05e-3), 0.0);
  EXPECT_EQ(passing_at(c, 2e-3), 100.0);
  EXPECT_NEAR(passing_at(c, std::sqrt(0.1e-3 * 1e-3)), 50.0, 100 * eps);
  EXPECT_NEAR(passing_at(c, 0.2e-3), 100.0 * std::log10(2.0), 100 * eps);
  // A first row above 0 % is a lump at the smallest size.
  const GrainSizeCurve lump{{0.1e-3, 1e-3}, {20.0, 100.0}};
  EXPECT_EQ(passing_at(lump, 0.0999e-3), 0.0);
  EXPECT_EQ(passing_at(lump, 0.1e-3), 20.0);
}

TEST(PsdCurve, PercentilesOfAKnownCurve) {
  const auto c = decade();
  EXPECT_NEAR(d50(c), std::sqrt(0.1e-3 * 1e-3), eps * 1e-3);
  EXPECT_NEAR(d10(c), 0.1e-3 * std::pow(10.0, 0.1), eps * 1e-3);
  EXPECT_NEAR(d60(c), 0.1e-3 * std::pow(10.0, 0.6), eps * 1e-3);
  EXPECT_NEAR(uniformity_coefficient(c), std::pow(10.0, 0.5), eps);
  EXPECT_NEAR(curvature_coefficient(c), std::pow(10.0, 0.6 - 0.7), eps);
  EXPECT_EQ(percentile_diameter(c, 100.0), 1e-3);
  // Flat segment: D_x is the smallest size reaching x.
  const GrainSizeCurve flat{{1e-4, 2e-4, 3e-4, 4e-4}, {0.0, 50.0, 50.0, 100.0}};
  EXPECT_NEAR(d50(flat), 2e-4, 1e-18);
  EXPECT_EQ(d50(GrainSizeCurve{{0.3e-3}, {100.0}}), 0.3e-3);
  EXPECT_THROW(percentile_diameter(c, 0.0), std::invalid_argument);
  EXPECT_THROW(percentile_diameter(c, 100.5), std::invalid_argument);
}

TEST(PsdCurve, UpscaleThenDownscaleReturnsTheCurve) {
  const GrainSizeCurve c{{75e-6, 0.2e-3, 0.3e-3, 0.6e-3}, {0.0, 20.0, 55.0, 100.0}};
  for (double n : {1.5, 2.0, 2.5, 3.7}) {
    const auto up = upscale(c, n);
    const auto back = downscale(up, n);
    for (std::size_t i = 0; i < c.size(); ++i) {
      // x*n/n is within 1 ulp of x (two correctly rounded operations).
      EXPECT_NEAR(back.diameter[i], c.diameter[i], 2.3e-16 * c.diameter[i]);
      EXPECT_EQ(back.percent_passing[i], c.percent_passing[i]);
    }
    EXPECT_NEAR(d50(up), n * d50(c), eps * d50(up));
    EXPECT_NEAR(mean_grain_volume(up), n * n * n * mean_grain_volume(c),
                eps * mean_grain_volume(up));
    EXPECT_NEAR(uniformity_coefficient(up), uniformity_coefficient(c), eps);
  }
  EXPECT_THROW(upscale(c, 0.0), std::invalid_argument);
  EXPECT_THROW(downscale(c, -2.0), std::invalid_argument);
}

TEST(PsdCurve, MeanGrainVolumeOfASingleSize) {
  const double d = 0.3e-3;
  const GrainSizeCurve mono{{d}, {100.0}};
  EXPECT_NEAR(mean_grain_volume(mono), sphere(d), eps * sphere(d));
  EXPECT_NEAR(mean_volume_diameter(mono), d, eps * d);
  // A vanishing bin tends to the same size: the bin integral's narrow-bin limit is a^-3.
  const GrainSizeCurve narrow{{d, d * (1 + 1e-12)}, {0.0, 100.0}};
  EXPECT_NEAR(mean_volume_diameter(narrow), d, 1e-11 * d);  // bin width 1e-12 relative
}

TEST(PsdCurve, MeanGrainVolumeOfOneBinClosedForm) {
  // Mass uniform in log d on [a, b]: grains per unit solid volume (6/pi) (a^-3 - b^-3)/(3 ln(b/a)).
  const double a = 0.1e-3, b = 0.4e-3;
  const double expected = kPi / 6.0 * 3.0 * std::log(b / a) / (std::pow(a, -3) - std::pow(b, -3));
  const GrainSizeCurve bin{{a, b}, {0.0, 100.0}};
  EXPECT_NEAR(mean_grain_volume(bin), expected, eps * expected);
  kolsky::testing::record("one_bin_d_v_over_a", mean_volume_diameter(bin) / a);
}

TEST(PsdCurve, MeanGrainVolumeOfTwoSizesClosedForm) {
  // Half the mass at d, half at 2d (the second as a bin 1e-7 wide): per unit solid volume
  // 0.5/v(d) + 0.5/v(2d) = 0.5625/v(d) grains, so the mean grain volume is v(d)/0.5625.
  const double d = 0.2e-3;
  const GrainSizeCurve two{{d, 2 * d * (1 - 1e-7), 2 * d}, {50.0, 50.0, 100.0}};
  const double expected = sphere(d) / 0.5625;
  EXPECT_NEAR(mean_grain_volume(two), expected, 1e-6 * expected);  // the 1e-7 bin: ~2e-7 shift
  // Same masses, the coarse half spread over [d, 2d] uniformly in log d (lump + bin):
  const GrainSizeCurve lump_bin{{d, 2 * d}, {50.0, 100.0}};
  const double per_volume = 0.5 / sphere(d) +
                            0.5 * 6.0 / kPi * (std::pow(d, -3) - std::pow(2 * d, -3)) /
                                (3.0 * std::log(2.0));
  EXPECT_NEAR(mean_grain_volume(lump_bin), 1.0 / per_volume, eps / per_volume);
}

TEST(PsdCurve, ExpectedCountOfACylinder) {
  const double d = 0.3e-3, porosity = 0.465;
  const double v = cylinder_volume(19.1e-3, 9.3e-3);
  EXPECT_NEAR(v, kPi * 9.55e-3 * 9.55e-3 * 9.3e-3, eps * v);
  const double n = expected_particle_count(GrainSizeCurve{{d}, {100.0}}, v, porosity);
  EXPECT_NEAR(n, v * (1 - porosity) / sphere(d), eps * n);
  EXPECT_THROW(expected_particle_count(decade(), v, 1.0), std::invalid_argument);
  EXPECT_THROW(expected_particle_count(decade(), -v, 0.4), std::invalid_argument);
}

}  // namespace
}  // namespace kolsky::psd
