// Classic SHPB analysis (shpb/analysis.hpp) against hand-computed cases: Eq. 1.1/1.3 for a
// constant reflected wave, Eqs. 2.11-2.13 for a constant stress, Eq. 2.15 limits, Eq. 1.4 ideal
// equilibrium, Eq. 5.1 for a constant rate, the least-squares slope of an exact line, and the
// DynaMat-Platform FBC/SEQI on hand-checkable inputs.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "shpb/analysis.hpp"

namespace kolsky::shpb {
namespace {

constexpr double eps = 1e-12;  // relative: sums of <= 1e3 terms in double precision (~1e-13)

void record(const std::string& key, double value) {  // measured errors, in --gtest_output
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4e", value);
  ::testing::Test::RecordProperty(key, buf);
}

AnalysisSetup steel_setup() {
  AnalysisSetup s;
  s.incident = {200e9, 7850.0, 0.29, 0.0191, 1.0};
  s.transmission = s.incident;
  s.specimen_length = 0.0093;
  s.specimen_diameter = 0.0191;
  return s;
}

FaceWaves constant_waves(std::size_t n, double dt, double e_i, double e_r, double e_t) {
  FaceWaves w;
  for (std::size_t k = 0; k < n; ++k) {
    w.t.push_back(static_cast<double>(k) * dt);
    w.eps_i.push_back(e_i);
    w.eps_r.push_back(e_r);
    w.eps_t.push_back(e_t);
  }
  return w;
}

TEST(ShpbAnalysis, ConstantReflectedGivesLinearStrain) {
  const AnalysisSetup s = steel_setup();
  const double dt = 1e-7, e_r = -1e-3, c = s.incident.wave_speed(), l = s.specimen_length;
  const FaceWaves w = constant_waves(1001, dt, 1e-3, e_r, 0.0);
  const SpecimenHistory h = analyze(w, s);
  const double rate = -2.0 * c * e_r / l;  // Eq. 1.3 by hand
  double worst = 0;
  for (std::size_t k = 0; k < w.t.size(); ++k) {
    worst = std::max(worst, std::abs(h.strain[k] - rate * w.t[k]) / (rate * w.t.back()));
    EXPECT_NEAR(h.strain_rate[k], rate, eps * rate);  // a product of constants: roundoff only
  }
  record("strain_rel_err", worst);
  EXPECT_LT(worst, eps);  // trapezoid rule is exact for a constant integrand; 1e3-term sum
  // The OLS slope of an exactly linear strain is the rate itself, up to roundoff.
  EXPECT_NEAR(fitted_slope(w.t, h.strain, 0, 1001), rate, 1e-10 * rate);
}

TEST(ShpbAnalysis, EnergyOfConstantStress) {
  const double dt = 1e-7, sigma = 150e6, area = 2.865e-4, rho = 7850, c = 5047.5;
  const std::vector<double> s(501, sigma);
  const std::vector<double> w = wave_energy(s, dt, area, rho, c);
  const double exact = area * sigma * sigma * (500 * dt) / (rho * c);  // A sigma^2 T / (rho c)
  record("energy_rel_err", std::abs(w.back() / exact - 1));
  EXPECT_NEAR(w.back(), exact, eps * exact);  // trapezoid exact for a constant; 500-term sum
  EXPECT_EQ(w.front(), 0.0);                  // the integral starts at zero by definition

  // Through analyze(): e_i only -> W_i = A E^2 e^2 T / (rho c), W_loss = W_i, 100 % dissipated.
  const AnalysisSetup st = steel_setup();
  const FaceWaves fw = constant_waves(501, dt, 7.5e-4, 0.0, 0.0);
  const SpecimenHistory h = analyze(fw, st);
  const double e_sigma = st.incident.youngs_modulus * 7.5e-4;
  const double w_i = st.incident.area() * e_sigma * e_sigma * (500 * dt) /
                     (st.incident.density * st.incident.wave_speed());
  EXPECT_NEAR(h.w_incident.back(), w_i, eps * w_i);         // same closed form, via E e
  EXPECT_NEAR(h.dissipation_percent.back(), 100.0, 1e-10);  // W_r = W_t = 0 exactly
  EXPECT_TRUE(std::isnan(h.dissipation_percent.front()));   // W_i = 0 at t = 0: undefined
}

TEST(ShpbAnalysis, AlphaLimits) {
  EXPECT_EQ(stress_nonuniformity(5e6, 5e6, 0.0), 0.0);  // equal faces: exactly 0 (Eq. 2.15)
  EXPECT_EQ(stress_nonuniformity(5e6, 0.0, 0.0), 2.0);  // back = 0: |f| / (f/2) = 2 exactly
  EXPECT_EQ(stress_nonuniformity(3e6, 1e6, 0.0), 1.0);  // 2e6 / 2e6, exact in binary
  EXPECT_TRUE(std::isnan(stress_nonuniformity(1e3, 1e3, 1e4)));  // below the floor: NaN
  EXPECT_TRUE(std::isnan(stress_nonuniformity(0.0, 0.0, 0.0)));  // 0/0 is reported as NaN
}

TEST(ShpbAnalysis, IdealEquilibriumGivesEqualFaces) {
  // e_i a half-sine, e_t any smooth response, e_r = e_t - e_i (Eq. 1.4 exactly), same bars.
  const AnalysisSetup s = steel_setup();
  const std::size_t n = 2001;
  const double dt = 1e-7, big_t = 150e-6;
  FaceWaves w;
  for (std::size_t k = 0; k < n; ++k) {
    const double t = static_cast<double>(k) * dt;
    const double e_i = t < big_t ? 1e-3 * std::sin(std::numbers::pi * t / big_t) : 0.0;
    const double e_t = 2e-4 * (1 - std::exp(-t / 40e-6));
    w.t.push_back(t);
    w.eps_i.push_back(e_i);
    w.eps_t.push_back(e_t);
    w.eps_r.push_back(e_t - e_i);
  }
  const SpecimenHistory h = analyze(w, s);
  double worst_stress = 0, worst_alpha = 0, worst_strain = 0, peak = 0;
  for (std::size_t k = 0; k < n; ++k) {
    peak = std::max(peak, std::abs(h.stress_back[k]));
    worst_stress = std::max(worst_stress, std::abs(h.stress_front[k] - h.stress_back[k]));
    if (std::isfinite(h.alpha[k])) worst_alpha = std::max(worst_alpha, h.alpha[k]);
    worst_strain = std::max(worst_strain, std::abs(h.strain[k] - h.strain_three_wave[k]));
  }
  record("stress_rel_diff", worst_stress / peak);
  record("max_alpha", worst_alpha);
  record("strain_3w_rel_diff", worst_strain / h.strain.back());
  EXPECT_LT(worst_stress, eps * peak);  // e_i + (e_t - e_i) = e_t up to one rounding
  EXPECT_LT(worst_alpha, eps);          // alpha is that rounding over the mean stress
  EXPECT_LT(worst_strain, eps * h.strain.back());  // 3-wave = Eq. 1.1 when Eq. 1.4 holds
  EXPECT_TRUE(std::isnan(h.alpha[0]));  // stress_avg = 0 at t = 0 is below the 2 % floor

  const EquilibriumIndices q = equilibrium_indices(w, h, 0, static_cast<long>(n));
  EXPECT_NEAR(q.force_balance, 1.0, eps);       // |F_f - F_b| is rounding only
  EXPECT_NEAR(q.stress_equilibrium, 1.0, eps);  // exp(-0) up to rounding
  EXPECT_LT(q.mean_alpha, eps);                 // mean of rounding-level alphas
  EXPECT_LT(q.max_strain_difference, 1e-18);    // e_i + e_r - e_t: one rounding of 1e-3
  // alpha < 0.05 from the first sample above the floor on: that is the equilibrium index.
  long first_finite = 0;
  while (std::isnan(h.alpha[first_finite])) ++first_finite;
  EXPECT_EQ(first_equilibrium_index(h.alpha, 0.05, 10), first_finite);  // exact index logic
}

TEST(ShpbAnalysis, AreaRatiosAndThreeWaveRate) {
  AnalysisSetup s = steel_setup();
  s.transmission = {70e9, 2700.0, 0.33, 0.0254, 0.5};  // aluminium, larger bar
  s.specimen_diameter = 0.0127;
  const FaceWaves w = constant_waves(11, 1e-7, 1e-3, -6e-4, 2e-4);
  const SpecimenHistory h = analyze(w, s);
  const double a_s = s.specimen_area();
  const double front = 200e9 * s.incident.area() / a_s * (1e-3 - 6e-4);  // E_I A_I/A_s (e_i+e_r)
  const double back = 70e9 * s.transmission.area() / a_s * 2e-4;        // Eq. 1.2, E_T A_T/A_s
  const double rate3 = (s.incident.wave_speed() * (1e-3 + 6e-4) -
                        s.transmission.wave_speed() * 2e-4) / s.specimen_length;
  EXPECT_NEAR(h.stress_front[5], front, eps * front);  // hand formula, a few roundings
  EXPECT_NEAR(h.stress_back[5], back, eps * back);
  EXPECT_NEAR(h.stress_avg[5], 0.5 * (front + back), eps * front);  // Eq. 4.16
  EXPECT_NEAR(h.strain_rate_three_wave[5], rate3, eps * rate3);
  // Transmitted energy uses the transmission bar's A, rho, c: A sigma^2 T / (rho c).
  const double st = 70e9 * 2e-4;
  const double w_t = s.transmission.area() * st * st * 10e-7 /
                     (s.transmission.density * s.transmission.wave_speed());
  EXPECT_NEAR(h.w_transmitted.back(), w_t, eps * w_t);
}

TEST(ShpbAnalysis, StrainFromConstantRateIsLinear) {
  const double rate = 1234.5, dt = 2e-8;
  const std::vector<double> e = strain_from_strain_rate(std::vector<double>(4001, rate), dt);
  double worst = 0;
  for (std::size_t k = 0; k < e.size(); ++k)
    worst = std::max(worst, std::abs(e[k] - rate * dt * static_cast<double>(k)));
  record("strain_rel_err", worst / e.back());
  EXPECT_LT(worst, eps * e.back());  // Eq. 5.1 trapezoid exact for a constant; 4e3-term sum
}

TEST(ShpbAnalysis, FittedSlopeRecoversLine) {
  std::vector<double> x, y;
  for (int k = 0; k < 200; ++k) {
    x.push_back(1e-3 * k);
    y.push_back(228e6 * x.back() + 1.5e6);
  }
  record("slope_rel_err", std::abs(fitted_slope(x, y, 20, 180) / 228e6 - 1));
  EXPECT_NEAR(fitted_slope(x, y, 20, 180), 228e6, 1e-9 * 228e6);  // exact line: roundoff only
  EXPECT_THROW(fitted_slope(x, y, 5, 6), std::invalid_argument);   // one point has no slope
  EXPECT_THROW(fitted_slope(x, y, -1, 6), std::invalid_argument);  // outside the series
  const std::vector<double> flat(10, 1.0);
  EXPECT_THROW(fitted_slope(flat, flat, 0, 10), std::invalid_argument);  // constant x
}

TEST(ShpbAnalysis, FirstEquilibriumIndexRuns) {
  const double nan = std::nan("");
  const std::vector<double> a{nan, 0.1, 0.01, 0.02, nan, 0.01, 0.01, 0.01, 0.3};
  EXPECT_EQ(first_equilibrium_index(a, 0.05, 2), 2);   // run {2,3} is long enough
  EXPECT_EQ(first_equilibrium_index(a, 0.05, 3), 5);   // NaN at 4 breaks the first run
  EXPECT_EQ(first_equilibrium_index(a, 0.05, 4), -1);  // no run of 4
  EXPECT_EQ(first_equilibrium_index(a, 0.005, 1), -1); // never below the threshold
}

TEST(ShpbAnalysis, EquilibriumIndicesHandCase) {
  // Front 2, back 1 (arbitrary units via e_t) everywhere: FBC = 1 - 1/2, RMSE = 1, and the
  // front-stress range is zero -> SEQI defined as 0 (faces disagree, no scale to normalise by).
  AnalysisSetup s = steel_setup();
  const FaceWaves w = constant_waves(20, 1e-7, 2e-4, 0.0, 1e-4);
  const SpecimenHistory h = analyze(w, s);
  const EquilibriumIndices q = equilibrium_indices(w, h, 0, 20);
  EXPECT_NEAR(q.force_balance, 0.5, eps);        // |2 - 1| / max(2, 1) = 1/2 at each sample
  EXPECT_EQ(q.stress_equilibrium, 0.0);          // documented zero-range rule
  EXPECT_NEAR(q.mean_alpha, 2.0 / 3.0, eps);     // |2 - 1| / 1.5
  EXPECT_NEAR(q.max_strain_difference, 1e-4, 1e-18);  // 2e-4 - 1e-4, one rounding
  EXPECT_THROW(equilibrium_indices(w, h, 5, 5), std::invalid_argument);  // empty range

  // Ramp: front e_i from 1e-4 to 2e-4, back 1e-5 lower everywhere -> RMSE / range = 0.1.
  FaceWaves r = constant_waves(101, 1e-7, 0.0, 0.0, 0.0);
  for (std::size_t k = 0; k < 101; ++k) {
    r.eps_i[k] = 1e-4 * (1.0 + 0.01 * static_cast<double>(k));
    r.eps_t[k] = r.eps_i[k] - 1e-5;
  }
  const SpecimenHistory hr = analyze(r, s);
  const EquilibriumIndices qr = equilibrium_indices(r, hr, 0, 101);
  EXPECT_NEAR(qr.stress_equilibrium, std::exp(-0.1), 1e-10);  // exp(-NRMSE), range-normalised
}

}  // namespace
}  // namespace kolsky::shpb
