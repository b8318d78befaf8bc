// First Pochhammer-Chree mode (shpb/dispersion.hpp) against its known limits and a published
// fit, and the dispersive pulse shift against its own inverse and the pure delay:
//   low a/Lambda: Rayleigh-Love c/c0 = 1 - nu^2 pi^2 (a/Lambda)^2 + O((a/Lambda)^4)
//   high a/Lambda: the Rayleigh surface wave speed (exact root and Viktorov's approximation)
//   SurePulse steel fit (relinc/SurePulse staticClasses/PochammerChreeDispersion.java, nu = 0.29)
// Measured errors are written as test properties (--gtest_output=json shows them).
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

#include "shpb/dispersion.hpp"

namespace kolsky::shpb {
namespace {

constexpr double pi = std::numbers::pi;

using kolsky::testing::record;

/// Exact Rayleigh speed ratio c_R/c_S: root of (2 - e^2)^2 = 4 sqrt(1 - e^2 k^2) sqrt(1 - e^2),
/// k^2 = (c_S/c_L)^2 = (1 - 2 nu) / (2 (1 - nu)), by bisection on (0.5, 1).
double rayleigh_ratio(double nu) {
  const double k2 = (1 - 2 * nu) / (2 * (1 - nu));
  auto f = [&](double e) {
    const double e2 = e * e;
    return (2 - e2) * (2 - e2) - 4 * std::sqrt(1 - e2 * k2) * std::sqrt(1 - e2);
  };
  double lo = 0.5, hi = 1.0 - 1e-12;
  for (int i = 0; i < 200; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f(mid) < 0) == (f(lo) < 0) ? lo : hi) = mid;
  }
  return 0.5 * (lo + hi);
}

/// sin^2 pulse of length `len` starting at t0 on a uniform grid: smooth (C1), compact support.
std::vector<double> sin2_pulse(std::size_t n, double dt, double t0, double len) {
  std::vector<double> s(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    const double u = (static_cast<double>(i) * dt - t0) / len;
    if (u > 0 && u < 1) s[i] = std::pow(std::sin(pi * u), 2);
  }
  return s;
}

double max_abs_diff(const std::vector<double>& a, const std::vector<double>& b) {
  double m = 0;
  for (std::size_t i = 0; i < a.size(); ++i) m = std::max(m, std::abs(a[i] - b[i]));
  return m;
}

TEST(Dispersion, LowFrequencyMatchesRayleighLove) {
  const double nu = 0.29;
  double ratio_max = 0;
  std::vector<double> err;
  for (double x : {0.005, 0.01, 0.02, 0.04}) {
    const double rl = 1 - nu * nu * pi * pi * x * x;
    const double e = std::abs(pochhammer_chree_phase_ratio(x, nu) - rl);
    err.push_back(e);
    ratio_max = std::max(ratio_max, e / std::pow(x, 4));
  }
  record("max_err_over_x4", ratio_max);
  // The neglected term is O((a/Lambda)^4); its coefficient is 5.44 at x -> 0 for nu = 0.29
  // (measured here) and 5.48 at x = 0.04: a bound of 6 x^4 leaves 10 % for that growth.
  EXPECT_LT(ratio_max, 6.0);
  const double order = std::log(err[2] / err[1]) / std::log(2.0);
  record("observed_order", order);
  EXPECT_NEAR(order, 4.0, 0.05);  // between x = 0.01 and 0.02 the x^6 term shifts it by ~0.01
  EXPECT_EQ(pochhammer_chree_phase_ratio(0.0, nu), 1.0);  // the long-wave limit is exactly c0
}

TEST(Dispersion, HighFrequencyTendsToRayleighSpeed) {
  double worst_approx = 0, worst_exact = 0;
  for (double nu : {0.2, 0.25, 0.29, 0.33, 0.4, 0.45}) {
    const double cs = 1 / std::sqrt(2 * (1 + nu));  // c_S / c0
    const std::vector<double> xi = pochhammer_chree_phase_ratios({20.0, 50.0}, nu);
    const double approx = (0.862 + 1.14 * nu) / (1 + nu);  // Viktorov's c_R/c_S
    worst_approx = std::max(worst_approx, std::abs(xi[0] / cs - approx) / approx);
    const double exact = rayleigh_ratio(nu);
    worst_exact = std::max(worst_exact, std::abs(xi[1] / cs - exact) / exact);
  }
  record("worst_vs_viktorov_x20", worst_approx);
  record("worst_vs_exact_rayleigh_x50", worst_exact);
  // Viktorov's closed form is good to ~0.5 % for nu >= 0.2 (1.3 % at nu = 0.01, checked
  // against the exact root); at a/Lambda = 20 the mode is within 0.12 % of c_R.
  EXPECT_LT(worst_approx, 5e-3);
  // The remaining gap to the exact c_R is the curvature correction ~ 0.018 / (a/Lambda)
  // (measured: 8.9e-4 at 20, 3.65e-4 at 50 for nu = 0.29); 1e-3 bounds it at a/Lambda = 50.
  EXPECT_LT(worst_exact, 1e-3);
}

TEST(Dispersion, MatchesSurePulseSteelFit) {
  const double nu = 0.29;
  std::vector<double> xs;
  for (int i = 0; i <= 60; ++i) xs.push_back(0.01 * i);
  const std::vector<double> xi = pochhammer_chree_phase_ratios(xs, nu);
  double worst = 0;
  for (std::size_t i = 0; i < xs.size(); ++i) {
    const double x = xs[i];
    const double fit = 0.57594 + 0.42555 / (21.3260 * std::pow(x, 4) + 19.2240 * std::pow(x, 3) -
                                            7.3258 * x * x + 2.4713 * std::pow(x, 1.5) + 1);
    worst = std::max(worst, std::abs(xi[i] - fit) / fit);
  }
  record("worst_rel_vs_fit", worst);
  // The fit itself misses the exact x = 0 value (1) by 0.149 % and wanders +-0.3 % about the
  // exact curve; 0.5 % is that residual with margin, far below the 36 % drop over the range.
  EXPECT_LT(worst, 5e-3);
}

TEST(Dispersion, RejectsBadArguments) {
  EXPECT_THROW(pochhammer_chree_phase_ratio(0.1, 0.5), std::invalid_argument);   // nu < 0.5
  EXPECT_THROW(pochhammer_chree_phase_ratio(-0.1, 0.3), std::invalid_argument);  // x >= 0
  EXPECT_THROW(pochhammer_chree_phase_ratios({0.2, 0.1}, 0.3), std::invalid_argument);
  // nu = 0 decouples lateral motion: the 1-D bar wave is exact, no dispersion at all.
  EXPECT_EQ(pochhammer_chree_phase_ratio(1.0, 0.0), 1.0);
}

TEST(Dispersion, ForwardThenBackwardReturnsOriginal) {
  // The record must hold the slowest part of the dispersed pulse: the first mode's group
  // velocity bottoms out at 0.379 c0 (nu = 0.29), so 1 m delays it by up to 523 us; 819 us do.
  const std::size_t n = 8192;
  const double dt = 1e-7, c0 = 5047.5, a = 0.00955, nu = 0.29, d = 1.0;
  const std::vector<double> s = sin2_pulse(n, dt, 20e-6, 60e-6);
  const auto fwd = propagate_dispersive(s, dt, d, c0, a, nu);
  const auto back = propagate_dispersive(fwd, dt, -d, c0, a, nu);
  const double err = max_abs_diff(s, back);
  record("round_trip_max_err", err);
  // Per component the two phases cancel exactly; what remains is the rounding of four
  // 16384-point FFTs (~ log2(m) eps ~ 1e-14 of the unit peak); 1e-12 allows 100x that.
  EXPECT_LT(err, 1e-12);
  EXPECT_GT(max_abs_diff(s, fwd), 0.5);  // the forward pass really moved the pulse
}

TEST(Dispersion, LowFrequencyPulseShiftMatchesPureDelay) {
  // Gaussian pulse, 60 us wide (spectrum below ~20 kHz, a/Lambda < 0.04), moved 1 m.
  const std::size_t n = 16384;
  const double dt = 1e-7, c0 = 5047.5, a = 0.00955, nu = 0.29, d = 1.0, width = 60e-6;
  std::vector<double> g(n);
  double max_d3 = 0;  // max |third derivative| on the grid
  for (std::size_t i = 0; i < n; ++i) {
    const double u = (static_cast<double>(i) * dt - 400e-6) / width;
    g[i] = std::exp(-u * u);
    max_d3 = std::max(max_d3, std::abs((12 * u - 8 * u * u * u) * g[i]) / std::pow(width, 3));
  }
  const double diff = max_abs_diff(propagate_dispersive(g, dt, d, c0, a, nu),
                                   propagate_nondispersive(g, dt, d, c0));
  // Rayleigh-Love: component f is delayed by an extra d nu^2 pi^2 a^2 f^2 / c0^3, which to first
  // order is the operator (d nu^2 a^2 / (4 c0^3)) d^3/dt^3 applied to the delayed pulse.
  const double predicted = d * nu * nu * a * a / (4 * std::pow(c0, 3)) * max_d3;
  record("dispersive_vs_delay_max_diff", diff);
  record("rayleigh_love_prediction", predicted);
  EXPECT_LT(diff, 5e-4);  // the two shifts agree closely: 0.03 % of the unit peak
  // ...and their difference is the Rayleigh-Love term: the neglected O((a/Lambda)^4) part is
  // ~1 % at a/Lambda = 0.04 and the pure delay's interpolation error 0.3 %; 5 % bounds both.
  EXPECT_NEAR(diff / predicted, 1.0, 0.05);
}

TEST(Dispersion, HighFrequenciesTrailThePulse) {
  // A sharp pulse (4 us sin^2, content to ~500 kHz) after 2 m: the high frequencies travel
  // slower than c0, so the ringing trails the c0 arrival. Ahead of it there is only the Airy
  // precursor of the cubic (Rayleigh-Love) phase, of time scale (3 d nu^2 a^2 / (4 c0^3))^(1/3)
  // = 4.5 us, negligible 20 us (4.4 scales) before the arrival.
  const std::size_t n = 16384;  // holds the slowest group (2 m / 0.379 c0 = 1.05 ms)
  const double dt = 1e-7, c0 = 5047.5, a = 0.00955, nu = 0.29, d = 2.0, t0 = 20e-6;
  const std::vector<double> s = sin2_pulse(n, dt, t0, 4e-6);
  const auto out = propagate_dispersive(s, dt, d, c0, a, nu);
  const double arrival = (t0 + d / c0) / dt;
  double before = 0, after = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const double k = static_cast<double>(i);
    if (k < arrival - 200) before = std::max(before, std::abs(out[i]));
    if (k > arrival + 300) after = std::max(after, std::abs(out[i]));
  }
  record("max_20us_before_arrival", before);
  record("max_30us_after_arrival", after);
  EXPECT_LT(before, 1e-3);  // Airy tail exp(-(2/3) 4.4^1.5) ~ 2e-3 of a ~0.1 precursor
  EXPECT_GT(after, 2e-2);   // the dispersed ringing is there, behind the pulse
}

TEST(Dispersion, PureDelayIsExactOnWholeSamples) {
  const std::size_t n = 1000;
  const double dt = 1e-7, c0 = 5000.0;
  const std::vector<double> s = sin2_pulse(n, dt, 10e-6, 30e-6);
  const auto out = propagate_nondispersive(s, dt, 37 * c0 * dt, c0);
  double err = 0;
  for (std::size_t i = 0; i < n; ++i)
    err = std::max(err, std::abs(out[i] - (i >= 37 ? s[i - 37] : 0.0)));
  EXPECT_LT(err, 1e-12);  // 37 samples to rounding; zero-filled at the start
}

}  // namespace
}  // namespace kolsky::shpb
