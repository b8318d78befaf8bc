// Twin experiment for the K_p, E_o calibration (eos/three_phase_fit.hpp): a curve generated with
// known K_p and E_o is recovered by gsl_multifit_nlinear from a far initial guess, without noise
// and with a deterministic +-0.5 % multiplicative perturbation of every sample.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "eos/eos_curve.hpp"
#include "eos/three_phase_fit.hpp"

namespace kolsky::eos {
namespace {

using kolsky::testing::record;

struct Twin {
  std::vector<double> eps, p;
};

/// Samples over the 10-20 MPa calibration range of Sec. 2.3.6 (and the foot of the curve).
Twin generate(const ThreePhaseParams& truth) {
  const ThreePhaseModel m(truth);
  std::vector<double> eps;
  for (int i = 1; i <= 80; ++i) eps.push_back(0.002 * i);  // 0.002 ... 0.16
  const EosCurve c = solve_eos(m, eps, FitSettings{}.ode);
  return {c.eps_v, c.p};
}

/// Uniform in [-1, 1) from a fixed 64-bit LCG (Knuth MMIX): the same on every platform.
double lcg_uniform(std::uint64_t& state) {
  state = state * 6364136223846793005ULL + 1442695040888963407ULL;
  return static_cast<double>(state >> 11) * (2.0 / 9007199254740992.0) - 1.0;
}

TEST(EosFit, TwinRecoversKpAndEoWithoutNoise) {
  double worst = 0.0;
  for (auto [w, k_p, e_o] : {std::tuple{0.03, 155e6, 5e6}, std::tuple{0.11, 120e6, 8e6}}) {
    ThreePhaseParams truth;
    truth.water_content = w;
    truth.k_p = k_p;
    truth.e_o = e_o;
    const Twin t = generate(truth);
    ThreePhaseParams start = truth;
    start.k_p = 60e6;  // far guesses: 40-60 % off K_p, 2-3x E_o
    start.e_o = 15e6;
    const KpEoFit fit = fit_kp_eo(start, t.eps, t.p);
    EXPECT_TRUE(fit.converged) << fit.stop_reason;
    worst = std::max({worst, std::abs(fit.k_p - k_p) / k_p, std::abs(fit.e_o - e_o) / e_o});
    EXPECT_LT(fit.rms_residual, 1.0);  // Pa, against curves of ~1-25 MPa
  }
  record("twin_noise_free_max_rel_err", worst);
  EXPECT_LT(worst, 0.01);  // the required 1 %; with exact data the error is ODE-noise limited
  EXPECT_LT(worst, 1e-6);  // ... and that noise is 1e-12 / fd_step 1e-6 in the Jacobian at most
}

TEST(EosFit, TwinRecoversWithinOnePercentUnderNoise) {
  // K_p and E_o both act on the void closure s and their estimates are correlated (~ -0.975):
  // +-1 % noise on 80 samples already moves E_o by ~1 % (std. error 0.7 %), so the 1 % target is
  // tested at +-0.5 % (std. errors ~0.25 %/0.35 %); the error must also lie within 3 standard
  // errors, which checks the reported covariance.
  ThreePhaseParams truth;
  truth.water_content = 0.11;
  truth.k_p = 120e6;
  truth.e_o = 8e6;
  Twin t = generate(truth);
  std::uint64_t state = 20240611u;
  for (double& v : t.p) v *= 1.0 + 0.005 * lcg_uniform(state);
  ThreePhaseParams start = truth;
  start.k_p = 60e6;
  start.e_o = 15e6;
  const KpEoFit fit = fit_kp_eo(start, t.eps, t.p);
  EXPECT_TRUE(fit.converged) << fit.stop_reason;
  const double err_k = std::abs(fit.k_p - truth.k_p) / truth.k_p;
  const double err_e = std::abs(fit.e_o - truth.e_o) / truth.e_o;
  record("twin_noisy_kp_rel_err", err_k);
  record("twin_noisy_eo_rel_err", err_e);
  record("twin_noisy_kp_std_rel", fit.k_p_std_error / fit.k_p);
  record("twin_noisy_eo_std_rel", fit.e_o_std_error / fit.e_o);
  record("twin_noisy_correlation", fit.correlation);
  EXPECT_LT(err_k, 0.01);  // the required 1 %
  EXPECT_LT(err_e, 0.01);
  EXPECT_LT(std::abs(fit.k_p - truth.k_p), 3.0 * fit.k_p_std_error);  // 3 sigma
  EXPECT_LT(std::abs(fit.e_o - truth.e_o), 3.0 * fit.e_o_std_error);
  EXPECT_LT(fit.correlation, -0.9);  // the identifiability caveat of docs/eos.md
}

TEST(EosFit, RejectsBadInput) {
  ThreePhaseParams start;
  EXPECT_THROW(fit_kp_eo(start, {0.01, 0.02}, {1e6, 2e6}), std::invalid_argument);
  EXPECT_THROW(fit_kp_eo(start, {0.01, 0.02, 0.03}, {1e6, 2e6}), std::invalid_argument);
  start.e_o = 0.0;
  EXPECT_THROW(fit_kp_eo(start, {0.01, 0.02, 0.03}, {1e6, 2e6, 3e6}), std::invalid_argument);
  start.e_o = 5e6;
  EXPECT_THROW(fit_kp_eo(start, {0.01, 0.03, 0.02}, {1e6, 2e6, 3e6}), std::invalid_argument);
}

}  // namespace
}  // namespace kolsky::eos
