// Eq. 2.9 solved with the Odeint wrapper (eos/eos_curve.hpp) against:
//   - the closed-form air-water-solid series mixture when branches D and E are off:
//       eps_v(P) = 1 - V_s0 (1 + k_s P/(rho_so c_so^2))^(-1/k_s)
//                    - V_w0 (1 + k_w P/(rho_wo c_wo^2))^(-1/k_w) - V_a0 (1 + P/P_ao)^(-1/k_a),
//     with initial tangent 1/K = V_s0/(rho_so c_so^2) + V_w0/(rho_wo c_wo^2) + V_a0/(k_a P_ao);
//   - its own invariants (Eq. 2.1 sum of branches, Eq. 2.2 volume balance);
//   - convergence as the tolerance shrinks, agreement of three steppers, and the tangent
//     dP/deps_v against central differences of the solved path.
#include <gtest/gtest.h>

#include "test_support.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "eos/eos_curve.hpp"
#include "eos/moisture_law.hpp"

namespace kolsky::eos {
namespace {

using kolsky::testing::record;

ThreePhaseParams at_water(double w) {
  return params_at_water_content(dissertation_moisture_law(), ThreePhaseParams{}, w);
}

OdeSettings tol(double t, Stepper s = Stepper::dopri5) { return {s, t, t, 1e-4, 1000000}; }

/// Written out here rather than taken from phase_eos.hpp, so the check is independent.
double series_strain(const ThreePhaseParams& p, const PhaseVolumes& v0, double pressure) {
  const double ks = p.solid.rho0 * p.solid.c0 * p.solid.c0;
  const double kw = p.water.rho0 * p.water.c0 * p.water.c0;
  return 1.0 - v0.solid * std::pow(1.0 + p.solid.k * pressure / ks, -1.0 / p.solid.k) -
         v0.water * std::pow(1.0 + p.water.k * pressure / kw, -1.0 / p.water.k) -
         v0.air * std::pow(1.0 + pressure / p.air.p0, -1.0 / p.air.k);
}

TEST(EosSolve, SeriesMixtureWithBranchesDAndEOff) {
  // w = 25 %: air (V_a0 = 0.0856) is expelled before eps_v = 0.15, so the path crosses into
  // water lock-up (P ~ 1 GPa) and tests the water and solid laws as well as the air.
  double worst_eps = 0.0, worst_split = 0.0, worst_k0 = 0.0;
  for (double w : {0.0, 0.03, 0.11, 0.25}) {
    ThreePhaseParams p;
    p.water_content = w;
    p.k_p = 0.0;
    p.e_o = 0.0;
    const ThreePhaseModel m(p);
    const EosCurve c = solve_eos(m, uniform_strains(0.15, 61), tol(1e-12));
    for (std::size_t i = 0; i < c.size(); ++i) {
      worst_eps = std::max(worst_eps, std::abs(series_strain(p, m.initial(), c.p[i]) - c.eps_v[i]));
      worst_split = std::max(worst_split, std::abs(c.p[i] - c.p_bc[i]) / std::max(c.p[i], 1.0));
      EXPECT_EQ(c.p_d[i], 0.0);
      EXPECT_EQ(c.p_e[i], 0.0);
    }
    const PhaseVolumes& v = m.initial();
    const double k0 = 1.0 / (v.solid / (p.solid.rho0 * p.solid.c0 * p.solid.c0) +
                             v.water / (p.water.rho0 * p.water.c0 * p.water.c0) +
                             v.air / (p.air.k * p.air.p0));
    worst_k0 = std::max(worst_k0, std::abs(c.tangent[0] - k0) / k0);
  }
  record("series_strain_abs_err", worst_eps);
  record("series_p_minus_pbc_rel", worst_split);
  record("series_k0_rel_err", worst_k0);
  EXPECT_LT(worst_eps, 1e-9);    // local bound ~1e-12 on s, summed over <= ~1e3 steps
  EXPECT_LT(worst_split, 1e-9);  // P and P_BC integrate the same increments (same tolerance)
  EXPECT_LT(worst_k0, 1e-14);    // closed form vs closed form: rounding only
}

TEST(EosSolve, InvariantsEq21AndEq22) {
  // P is integrated from Eq. 2.9; P_D and P_E are closed forms of s; V_s, V_w, V_a come from
  // P and P_BC. Eq. 2.1 and Eq. 2.2 therefore hold only to the integration tolerance.
  double worst_sum = 0.0, worst_vol = 0.0;
  for (double w : {0.0, 0.03, 0.11, 0.20}) {
    const ThreePhaseModel m(at_water(w));
    const EosCurve c = solve_eos(m, uniform_strains(0.15, 61), tol(1e-10));
    for (std::size_t i = 0; i < c.size(); ++i) {
      worst_sum = std::max(worst_sum, std::abs(pressure_sum_residual(c, i)) / std::max(c.p[i], 1.0));
      const PhaseVolumes v = phase_volumes(m, {c.p[i], c.closure[i], c.p_bc[i]});
      worst_vol = std::max(worst_vol, std::abs(v.total() - (1.0 - c.eps_v[i])));
    }
  }
  record("eq21_rel_residual", worst_sum);
  record("eq22_abs_residual", worst_vol);
  // RK steps preserve the linear part (P_BC, P_D) exactly; only the nonlinear P_E part drifts,
  // by at most the local error each step, i.e. of the order of rel_tol = 1e-10.
  EXPECT_LT(worst_sum, 1e-10);
  EXPECT_LT(worst_vol, 1e-9);  // abs_tol 1e-10 on s and on P/1 MPa, accumulated
}

TEST(EosSolve, ConvergesAsToleranceShrinks) {
  // Reference: the 7(8) pair at 1e-13. Outputs only every 0.05 in strain, so the tolerance and
  // not the output grid sets the steps. Two steppers, three water contents (w = 20 % nears
  // air expulsion, the hardest path). The global error of this non-stiff problem must stay
  // below the sum of the local tolerances (n_steps * tol), and fall at least 10x per 100x
  // tolerance step (dopri5 and Cash-Karp are 5th/4th order: ~40-100x is observed).
  const auto grid = uniform_strains(0.15, 4);
  for (double w : {0.03, 0.11, 0.20}) {
    const ThreePhaseModel m(at_water(w));
    const EosCurve ref = solve_eos(m, grid, tol(1e-13, Stepper::fehlberg78));
    for (Stepper st : {Stepper::dopri5, Stepper::cash_karp54}) {
      double previous = 1.0;
      for (double t : {1e-6, 1e-8, 1e-10, 1e-12}) {
        const EosCurve c = solve_eos(m, grid, tol(t, st));
        double err = 0.0;
        for (std::size_t i = 0; i < c.size(); ++i)
          err = std::max(err, std::abs(c.p[i] - ref.p[i]) / (ref.p[i] + 1e6));
        record(stepper_name(st) + "_w" + std::to_string(static_cast<int>(100 * w + 0.5)) +
                   "_tol1e-" + std::to_string(static_cast<int>(-std::log10(t) + 0.5)),
               err);
        EXPECT_LT(err, static_cast<double>(c.stats.n_steps) * t) << stepper_name(st) << " " << t;
        EXPECT_LT(err, previous / 10.0) << stepper_name(st) << " w " << w << " tol " << t;
        previous = err;
      }
    }
  }
}

TEST(EosSolve, ThreeSteppersAgree) {
  const ThreePhaseModel m(at_water(0.03));
  const auto grid = uniform_strains(0.15, 31);
  const EosCurve a = solve_eos(m, grid, tol(1e-10, Stepper::dopri5));
  const EosCurve b = solve_eos(m, grid, tol(1e-10, Stepper::cash_karp54));
  const EosCurve c = solve_eos(m, grid, tol(1e-10, Stepper::fehlberg78));
  double worst = 0.0;
  for (std::size_t i = 1; i < a.size(); ++i) {
    worst = std::max(worst, std::abs(a.p[i] - b.p[i]) / a.p[i]);
    worst = std::max(worst, std::abs(a.p[i] - c.p[i]) / a.p[i]);
    worst = std::max(worst, std::abs(a.p_bc[i] - c.p_bc[i]) / a.p_bc[i]);
  }
  record("stepper_max_rel_diff", worst);
  EXPECT_LT(worst, 2e-9);  // each within ~10x tol (1e-10) of the truth, so within 2e-9 of another
  EXPECT_EQ(a.ode.stepper, Stepper::dopri5);  // the settings travel with the curve
  EXPECT_EQ(a.ode.rel_tol, 1e-10);
  EXPECT_GT(a.stats.n_steps, 0u);
  EXPECT_GE(a.stats.n_rhs, 6 * a.stats.n_steps);  // dopri5: >= 6 new evaluations per step (FSAL)
}

TEST(EosSolve, TangentMatchesFiniteDifferenceOfPath) {
  // Central differences D(h) of the solved P converge to the Eq. 2.9 tangent as h^2 (ratio
  // D-error(h) / D-error(h/2) = 4), and the Richardson value (4 D(h/2) - D(h)) / 3 as h^4.
  const double h = 1e-4;
  double worst_plain = 0.0, worst_richardson = 0.0, worst_order = 0.0;
  for (double w : {0.0, 0.03, 0.11, 0.20}) {
    const ThreePhaseModel m(at_water(w));
    for (double e : {0.01, 0.05, 0.10, 0.14}) {
      const EosCurve c = solve_eos(m, {e - h, e - h / 2, e, e + h / 2, e + h},
                                   tol(1e-13, Stepper::fehlberg78));
      const double k = c.tangent[2];
      const double d_h = (c.p[4] - c.p[0]) / (2.0 * h), d_h2 = (c.p[3] - c.p[1]) / h;
      const double rich = (4.0 * d_h2 - d_h) / 3.0;
      worst_plain = std::max(worst_plain, std::abs(d_h - k) / k);
      worst_richardson = std::max(worst_richardson, std::abs(rich - k) / k);
      if (std::abs(d_h - k) > 1e-6 * k)  // the ratio is meaningful only above the noise
        worst_order = std::max(worst_order, std::abs((d_h - k) / (d_h2 - k) - 4.0));
    }
  }
  record("tangent_fd_rel_err_h1e-4", worst_plain);
  record("tangent_richardson_rel_err", worst_richardson);
  record("tangent_fd_order_ratio_dev", worst_order);
  EXPECT_LT(worst_plain, 2e-5);       // (d3P/de3) h^2/6 / K: largest near air expulsion (w 20 %)
  EXPECT_LT(worst_richardson, 1e-8);  // h^4 term, plus solve noise 1e-13 / h ~ 1e-9
  EXPECT_LT(worst_order, 0.05);       // second order: the error ratio is 4 to within ~1 %
}

TEST(EosSolve, RejectsBadGridsAndSettings) {
  const ThreePhaseModel m(at_water(0.03));
  EXPECT_THROW(solve_eos(m, {}, tol(1e-8)), std::invalid_argument);
  EXPECT_THROW(solve_eos(m, {0.0, 0.1, 0.1}, tol(1e-8)), std::invalid_argument);
  EXPECT_THROW(solve_eos(m, {-0.01, 0.1}, tol(1e-8)), std::invalid_argument);
  EXPECT_THROW(solve_eos(m, {0.0, 0.45}, tol(1e-8)), std::invalid_argument);  // voids all closed
  EXPECT_THROW(solve_eos(m, {0.0, 0.1}, tol(0.0)), std::invalid_argument);
  EXPECT_THROW(uniform_strains(0.1, 1), std::invalid_argument);
  // A grid not starting at 0 is integrated from the initial state all the same.
  const EosCurve a = solve_eos(m, {0.0, 0.05, 0.1}, tol(1e-10));
  const EosCurve b = solve_eos(m, {0.05, 0.1}, tol(1e-10));
  ASSERT_EQ(b.size(), 2u);
  EXPECT_NEAR(b.p[1], a.p[2], 1e-8 * a.p[2]);  // same path, different step sequence
  EXPECT_EQ(stepper_from_name("cash_karp54"), Stepper::cash_karp54);
  EXPECT_EQ(stepper_from_name("runge_kutta_fehlberg78"), Stepper::fehlberg78);
  EXPECT_THROW(stepper_from_name("rk4"), std::invalid_argument);
}

}  // namespace
}  // namespace kolsky::eos
