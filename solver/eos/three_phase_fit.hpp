// Calibration of the three-phase model: K_p and E_o fitted to a pressure-volumetric strain curve
// by nonlinear least squares (GSL gsl_multifit_nlinear, Levenberg-Marquardt trust region with
// More scaling and central-difference Jacobian), each residual an Eq. 2.9 solve. This is the step
// of Sec. 2.3.6 in which K_p and E_o were calibrated to the back-calculated EOS at 0, 5, 7, 20 %.
// The parameters are fitted as logarithms, so both stay positive. Units: Pa.
#pragma once
#include <cstddef>
#include <string>
#include <vector>

#include "eos/ode_integrate.hpp"
#include "eos/three_phase_params.hpp"

namespace kolsky::eos {

struct FitSettings {
  int max_iterations = 200;  ///< trust-region iterations
  double xtol = 1e-10;       ///< GSL step test (relative change of the log-parameters)
  double gtol = 1e-14;       ///< GSL gradient test
  double ftol = 1e-14;       ///< GSL cost-reduction test
  double fd_step = 1e-6;     ///< relative central-difference step; the ODE noise (rel_tol) must
                             ///< be far below it, hence the tight OdeSettings below
  OdeSettings ode{Stepper::dopri5, 1e-12, 1e-12, 1e-4, 1000000};
};

struct KpEoFit {
  double k_p = 0.0;            ///< Pa
  double e_o = 0.0;            ///< Pa
  double k_p_std_error = 0.0;  ///< Pa, from the Gauss-Newton covariance times the residual variance
  double e_o_std_error = 0.0;  ///< Pa
  double correlation = 0.0;    ///< correlation of the K_p and E_o estimates (both act on s)
  double rms_residual = 0.0;   ///< Pa
  std::size_t n_iterations = 0;
  bool converged = false;      ///< the driver met a convergence test
  std::string stop_reason;     ///< which test (or GSL's error text)
};

/// Fits K_p and E_o of `start` (its k_p, e_o are the initial guess, both > 0; every other field is
/// held) to the samples (eps_v[i], p[i]), Pa, eps_v strictly increasing in [0, V_p0). Throws
/// std::invalid_argument for bad samples or guesses.
KpEoFit fit_kp_eo(const ThreePhaseParams& start, const std::vector<double>& eps_v,
                  const std::vector<double>& p, const FitSettings& settings = FitSettings{});

}  // namespace kolsky::eos
