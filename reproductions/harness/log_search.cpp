// The shared calibration search (see log_search.hpp).
#include "harness/log_search.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_min.h>

#include <memory>

#include "harness/gsl_quiet.hpp"

namespace kolsky::harness {

namespace {

struct Cached {
  const std::function<double(double)>* objective;
  LogSearchResult* out;
  bool repeated = false;
  double operator()(double log_p) {
    const double p = std::exp(log_p);
    for (const auto& [q, v] : out->evaluated)
      if (std::abs(q / p - 1) < 1e-3) {
        repeated = true;
        return v;
      }
    const double v = (*objective)(p);
    out->evaluated[p] = v;
    if (std::isfinite(v) && !(v >= out->best_value)) out->best = p, out->best_value = v;
    return v;
  }
};

double gsl_objective(double x, void* c) { return (*static_cast<Cached*>(c))(x); }

}  // namespace

LogSearchResult log_brent_search(const std::function<double(double)>& objective, const LogSearchSettings& s) {
  LogSearchResult r;
  Cached f{&objective, &r};
  const auto cap_reached = [&] { return static_cast<int>(r.evaluated.size()) >= s.max_evaluations; };
  const double step = s.step;
  double m = s.ln_mid, a = s.ln_lo, b = s.ln_hi;
  double fm = f(m), fa = f(a), fb = f(b);
  // Bracketing walk: move the triple downhill by one step until the middle is lowest.
  while (!(fm < fa && fm < fb) && !cap_reached()) {
    if (fa <= fb) b = m, fb = fm, m = a, fm = fa, a -= step, fa = f(a);
    else a = m, fa = fm, m = b, fm = fb, b += step, fb = f(b);
  }
  r.bracket_lo = std::exp(a);
  r.bracket_hi = std::exp(b);
  if (!(fm < fa && fm < fb)) {
    r.note = "no bracket within the evaluation cap: the best evaluated value is reported";
    return r;
  }
  const GslHandlerOff quiet;
  gsl_function F{&gsl_objective, &f};
  const std::unique_ptr<gsl_min_fminimizer, decltype(&gsl_min_fminimizer_free)> owner(
      gsl_min_fminimizer_alloc(gsl_min_fminimizer_brent), &gsl_min_fminimizer_free);
  gsl_min_fminimizer* mz = owner.get();
  gsl_min_fminimizer_set_with_values(mz, &F, m, fm, a, fa, b, fb);
  while (!cap_reached()) {
    if (gsl_min_fminimizer_iterate(mz) != GSL_SUCCESS) break;
    if (f.repeated) {  // that step used a neighbour's value: keep the bracket from before it
      r.converged = true;
      r.note = "stopped where Brent probed within 0.1 % of a point already run";
      break;
    }
    const double lo = gsl_min_fminimizer_x_lower(mz), hi = gsl_min_fminimizer_x_upper(mz);
    r.bracket_lo = std::exp(lo);
    r.bracket_hi = std::exp(hi);
    if (hi - lo < s.rel_tol) {
      r.converged = true;
      break;
    }
  }
  if (!r.converged) r.note = "evaluation cap reached before the bracket reached the tolerance";
  return r;
}

}  // namespace kolsky::harness
