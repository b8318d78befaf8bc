// K_p, E_o least-squares fit with gsl_multifit_nlinear (see three_phase_fit.hpp).
#include "eos/three_phase_fit.hpp"

#include <gsl/gsl_blas.h>
#include <gsl/gsl_errno.h>
#include <gsl/gsl_multifit_nlinear.h>

#include <cmath>
#include <exception>
#include <memory>
#include <stdexcept>

#include "eos/eos_curve.hpp"
#include "eos/three_phase.hpp"

namespace kolsky::eos {
namespace {

constexpr double kPressureUnit = 1e6;  // residuals in MPa and parameters as log(value / 1 MPa)

struct Problem {
  ThreePhaseParams base;
  const std::vector<double>* eps;
  const std::vector<double>* p;
  OdeSettings ode;
  std::exception_ptr error;  // C callbacks must not throw; rethrown after the driver returns
};

ThreePhaseParams with_log_params(ThreePhaseParams base, const gsl_vector* x) {
  base.k_p = kPressureUnit * std::exp(gsl_vector_get(x, 0));
  base.e_o = kPressureUnit * std::exp(gsl_vector_get(x, 1));
  return base;
}

int residuals(const gsl_vector* x, void* data, gsl_vector* f) {
  auto* pr = static_cast<Problem*>(data);
  try {
    const ThreePhaseModel m(with_log_params(pr->base, x));
    const EosCurve c = solve_eos(m, *pr->eps, pr->ode);
    for (std::size_t i = 0; i < c.size(); ++i)
      gsl_vector_set(f, i, (c.p[i] - (*pr->p)[i]) / kPressureUnit);
    return GSL_SUCCESS;
  } catch (...) {
    pr->error = std::current_exception();
    return GSL_EFAILED;
  }
}

/// GSL's default handler aborts the process; errors come back as status codes instead.
struct GslHandlerOff {
  gsl_error_handler_t* previous = gsl_set_error_handler_off();
  ~GslHandlerOff() { gsl_set_error_handler(previous); }
};

struct WorkspaceFree {
  void operator()(gsl_multifit_nlinear_workspace* w) const { gsl_multifit_nlinear_free(w); }
};

}  // namespace

KpEoFit fit_kp_eo(const ThreePhaseParams& start, const std::vector<double>& eps_v,
                  const std::vector<double>& p, const FitSettings& settings) {
  if (eps_v.size() != p.size()) throw std::invalid_argument("fit: eps_v and p differ in length");
  if (eps_v.size() < 3) throw std::invalid_argument("fit: needs at least 3 samples for 2 parameters");
  if (!(start.k_p > 0.0) || !(start.e_o > 0.0))
    throw std::invalid_argument("fit: initial K_p and E_o must be > 0 (fitted as logarithms)");
  for (double v : p)
    if (!std::isfinite(v)) throw std::invalid_argument("fit: non-finite pressure sample");
  validate(start);  // the held fields, before the driver starts

  const GslHandlerOff handler_off;
  Problem pr{start, &eps_v, &p, settings.ode, nullptr};
  const std::size_t n = eps_v.size();
  constexpr std::size_t n_par = 2;

  gsl_multifit_nlinear_fdf fdf{};
  fdf.f = residuals;
  fdf.df = nullptr;  // central differences (settings.fd_step): no closed-form sensitivity of P
  fdf.fvv = nullptr;
  fdf.n = n;
  fdf.p = n_par;
  fdf.params = &pr;

  gsl_multifit_nlinear_parameters par = gsl_multifit_nlinear_default_parameters();
  par.trs = gsl_multifit_nlinear_trs_lm;
  par.scale = gsl_multifit_nlinear_scale_more;
  par.fdtype = GSL_MULTIFIT_NLINEAR_CTRDIFF;
  par.h_df = settings.fd_step;
  std::unique_ptr<gsl_multifit_nlinear_workspace, WorkspaceFree> w(
      gsl_multifit_nlinear_alloc(gsl_multifit_nlinear_trust, &par, n, n_par));
  if (!w) throw std::runtime_error("fit: GSL workspace allocation failed");

  double x0[n_par] = {std::log(start.k_p / kPressureUnit), std::log(start.e_o / kPressureUnit)};
  gsl_vector_view xv = gsl_vector_view_array(x0, n_par);
  int status = gsl_multifit_nlinear_init(&xv.vector, &fdf, w.get());
  int info = 0;
  if (status == GSL_SUCCESS)
    status = gsl_multifit_nlinear_driver(static_cast<std::size_t>(settings.max_iterations),
                                         settings.xtol, settings.gtol, settings.ftol, nullptr,
                                         nullptr, &info, w.get());
  if (pr.error) std::rethrow_exception(pr.error);

  KpEoFit out;
  const ThreePhaseParams best = with_log_params(start, gsl_multifit_nlinear_position(w.get()));
  out.k_p = best.k_p;
  out.e_o = best.e_o;
  out.n_iterations = gsl_multifit_nlinear_niter(w.get());
  out.converged = status == GSL_SUCCESS;
  out.stop_reason = !out.converged ? std::string(gsl_strerror(status))
                    : info == 1    ? "small step"
                    : info == 2    ? "small gradient"
                                   : "small cost reduction";
  double chi2 = 0.0;
  gsl_blas_ddot(gsl_multifit_nlinear_residual(w.get()), gsl_multifit_nlinear_residual(w.get()),
                &chi2);
  out.rms_residual = kPressureUnit * std::sqrt(chi2 / static_cast<double>(n));

  // Covariance of the log-parameters, scaled by the residual variance; d(value) = value d(log).
  gsl_matrix* covar = gsl_matrix_alloc(n_par, n_par);
  if (covar && gsl_multifit_nlinear_covar(gsl_multifit_nlinear_jac(w.get()), 0.0, covar) ==
                   GSL_SUCCESS) {
    const double dof = static_cast<double>(n - n_par);
    const double s2 = chi2 / dof;
    out.k_p_std_error = out.k_p * std::sqrt(s2 * gsl_matrix_get(covar, 0, 0));
    out.e_o_std_error = out.e_o * std::sqrt(s2 * gsl_matrix_get(covar, 1, 1));
    out.correlation = gsl_matrix_get(covar, 0, 1) /
                      std::sqrt(gsl_matrix_get(covar, 0, 0) * gsl_matrix_get(covar, 1, 1));
  }
  gsl_matrix_free(covar);
  return out;
}

}  // namespace kolsky::eos
