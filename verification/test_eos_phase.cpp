// Phase EOSs of the three-phase model (eos/phase_eos.hpp, Eqs. 2.3-2.5) against hand-computed
// closed-form values, their inverses, their tangent bulk moduli (finite differences and the
// reference values rho0 c0^2 and k_a P_ao), and the initial phase volumes of Eq. 2.2.
// Measured errors are written as test properties (--gtest_output=json shows them).
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>

#include "eos/phase_eos.hpp"
#include "eos/three_phase_params.hpp"

namespace kolsky::eos {
namespace {

using kolsky::testing::record;

double rel(double a, double b) { return std::abs(a - b) / std::abs(b); }

TEST(EosPhase, WaterEq23HandValue) {
  // (1000 * 1500^2 / 7) * (1.01^7 - 1) = 321.428571 MPa * 0.0721353521 (computed by hand).
  const double dp = pressure(kWaterEos, 1010.0) - kWaterEos.p0;
  const double err = rel(dp, 23186363.17725);
  record("water_rel_err", err);
  EXPECT_LT(err, 1e-11);  // the hand value carries 13 digits; pow is good to ~1 ulp
}

TEST(EosPhase, SolidEq24HandValue) {
  // (2650 * 4500^2 / 3) * (1.02^3 - 1) = 17.8875 GPa * 0.061208 exactly.
  const double dp = pressure(kQuartzEos, 2650.0 * 1.02) - kQuartzEos.p0;
  const double err = rel(dp, 1094858100.0);
  record("solid_rel_err", err);
  EXPECT_LT(err, 1e-12);  // exact decimal product; a few roundings of a cubic
}

TEST(EosPhase, AirEq25HandValue) {
  // Doubling the pressure isentropically: rho = 1.225 * 2^(1/1.4) = 2.0098216222 kg/m^3.
  const double err_rho = rel(density(kAirEos, 200e3), 2.009821622219);
  const double err_p = rel(pressure(kAirEos, 2.009821622219), 200e3);
  record("air_rho_rel_err", err_rho);
  record("air_p_rel_err", err_p);
  EXPECT_LT(err_rho, 1e-11);  // 13-digit hand value
  EXPECT_LT(err_p, 1e-11);    // same number the other way; k = 1.4 amplifies by 1.4 only
}

TEST(EosPhase, InverseRoundTrip) {
  double worst = 0.0;
  for (double ratio : {0.99, 1.0, 1.001, 1.05, 1.2}) {
    for (const TaitEos& e : {kWaterEos, kQuartzEos}) {
      const double rho = e.rho0 * ratio;
      worst = std::max(worst, rel(density(e, pressure(e, rho)), rho));
    }
    const double rho_a = kAirEos.rho0 * ratio * 3.0;
    worst = std::max(worst, rel(density(kAirEos, pressure(kAirEos, rho_a)), rho_a));
  }
  record("round_trip_rel_err", worst);
  EXPECT_LT(worst, 1e-12);  // pow and its inverse: a few ulp, times k <= 7 from cancellation
}

TEST(EosPhase, BulkModulusMatchesFiniteDifference) {
  // K = rho dp/drho, central difference with relative step 1e-5: truncation ~1e-10 relative.
  double worst = 0.0;
  for (double ratio : {1.0, 1.01, 1.1}) {
    for (const TaitEos& e : {kWaterEos, kQuartzEos}) {
      const double rho = e.rho0 * ratio, h = 1e-5 * rho;
      const double fd = rho * (pressure(e, rho + h) - pressure(e, rho - h)) / (2.0 * h);
      worst = std::max(worst, rel(bulk_modulus(e, pressure(e, rho)), fd));
    }
    const double rho = kAirEos.rho0 * ratio, h = 1e-5 * rho;
    const double fd = rho * (pressure(kAirEos, rho + h) - pressure(kAirEos, rho - h)) / (2.0 * h);
    worst = std::max(worst, rel(bulk_modulus(kAirEos, pressure(kAirEos, rho)), fd));
  }
  record("bulk_modulus_fd_rel_err", worst);
  EXPECT_LT(worst, 1e-8);  // truncation (h^2 ~ 1e-10) plus roundoff eps/h (~1e-11) with margin
}

TEST(EosPhase, ReferenceModuliAndSoundSpeeds) {
  // rho0 c0^2: 2.25 GPa (water), 53.6625 GPa (quartz); air k_a P_ao = 140 kPa (targets.md 2a).
  EXPECT_NEAR(bulk_modulus(kWaterEos, kWaterEos.p0), 2.25e9, 1e-6);     // exact in binary to 1 ulp
  EXPECT_NEAR(bulk_modulus(kQuartzEos, kQuartzEos.p0), 53.6625e9, 1e-4);  // idem
  EXPECT_NEAR(bulk_modulus(kAirEos, kAirEos.p0), 140e3, 1e-9);          // idem
  EXPECT_NEAR(sound_speed(kWaterEos, kWaterEos.p0), 1500.0, 1e-9);      // sqrt of an exact square
  EXPECT_NEAR(sound_speed(kQuartzEos, kQuartzEos.p0), 4500.0, 1e-9);    // idem
  // sqrt(1.4e5 / 1.225) = 338.0617019 m/s, hand value to 10 digits.
  EXPECT_NEAR(sound_speed(kAirEos, kAirEos.p0), 338.0617019, 1e-6);
}

TEST(EosPhase, DomainErrors) {
  // The Tait form has no density below p0 - rho0 c0^2 / k (water: -321 MPa gauge).
  EXPECT_THROW(density(kWaterEos, kWaterEos.p0 - 400e6), std::domain_error);
  EXPECT_THROW(density(kAirEos, 0.0), std::domain_error);
  EXPECT_NO_THROW(density(kWaterEos, kWaterEos.p0 - 300e6));
}

TEST(EosPhase, InitialVolumesFromPorosityAndWaterContent) {
  // n = 0.45, w = 3 %: V_s = 0.55, V_w = 0.03 * 2.65 * 0.55 = 0.043725, V_a = 0.406275.
  const PhaseVolumes v = initial_volumes(0.45, 0.03, 2650.0, 1000.0);
  EXPECT_NEAR(v.solid, 0.55, 1e-15);     // one subtraction
  EXPECT_NEAR(v.water, 0.043725, 1e-15);  // two products
  EXPECT_NEAR(v.air, 0.406275, 1e-15);
  EXPECT_NEAR(v.total(), 1.0, 1e-15);
  // S_r = 1 at w = 0.45 / (0.55 * 2.65) = 30.875 %; above it the voids overflow.
  EXPECT_NEAR(saturation_water_content(0.45, 2650.0, 1000.0), 0.3087478559, 1e-10);
  EXPECT_THROW(initial_volumes(0.45, 0.31, 2650.0, 1000.0), std::invalid_argument);
  EXPECT_THROW(initial_volumes(1.0, 0.0, 2650.0, 1000.0), std::invalid_argument);
  EXPECT_THROW(initial_volumes(0.45, -0.01, 2650.0, 1000.0), std::invalid_argument);
  ThreePhaseParams p;
  p.b = NAN;
  EXPECT_THROW(validate(p), std::invalid_argument);
}

}  // namespace
}  // namespace kolsky::eos
