// The calibration search's root finder (see root_search.hpp).
#include "harness/root_search.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <memory>

#include "harness/gsl_quiet.hpp"

namespace kolsky::harness {

namespace {

struct Cached {
  const std::function<RootEvaluation(double)>* objective;
  RootSearchResult* out;
  int budget;
  bool failed = false;  ///< the cap was hit or an f was non-finite: no more evaluations
  double operator()(double x) {
    for (const auto& [q, v] : out->evaluated)
      if (q == x) return v;
    if (failed) return NAN;
    if (out->evaluations >= budget) {
      failed = true;
      out->end = RootSearchResult::End::budget_spent;
      return NAN;
    }
    const RootEvaluation e = (*objective)(x);
    if (e.fresh) ++out->evaluations;
    out->evaluated.emplace_back(x, e.f);
    if (!std::isfinite(e.f)) failed = true, out->end = RootSearchResult::End::non_finite;
    return e.f;
  }
};

double trampoline(double x, void* c) { return (*static_cast<Cached*>(c))(x); }

// The tightest sign change between neighbouring finite start points (the first on a tie).
void bracket_from_start(RootSearchResult& r) {
  std::vector<std::pair<double, double>> sorted;
  for (const auto& p : r.evaluated)
    if (std::isfinite(p.first) && std::isfinite(p.second)) sorted.push_back(p);
  std::stable_sort(sorted.begin(), sorted.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  for (size_t i = 0; i + 1 < sorted.size(); ++i) {
    const double fa = sorted[i].second, fb = sorted[i + 1].second;
    if (fa * fb <= 0 && (!r.bracketed || sorted[i + 1].first - sorted[i].first < r.x_hi - r.x_lo)) {
      r.bracketed = true;
      r.x_lo = sorted[i].first;
      r.x_hi = sorted[i + 1].first;
      r.slope = (fb - fa) / (r.x_hi - r.x_lo);
    }
  }
}

}  // namespace

RootSearchResult brent_root_search(const std::function<RootEvaluation(double)>& objective,
                                   const RootSearchSettings& s) {
  RootSearchResult r;
  // The start points: not through the cache (they are distinct), each within the cap.
  for (double x : s.start_x) {
    if (r.evaluations >= s.max_evaluations) break;
    const RootEvaluation e = objective(x);
    if (e.fresh) ++r.evaluations;
    r.evaluated.emplace_back(x, e.f);
  }
  bracket_from_start(r);
  if (!r.bracketed) return r;

  Cached f{&objective, &r, s.max_evaluations};
  GslHandlerOff quiet;
  gsl_function F{&trampoline, &f};
  const std::unique_ptr<gsl_root_fsolver, decltype(&gsl_root_fsolver_free)> owner(
      gsl_root_fsolver_alloc(gsl_root_fsolver_brent), &gsl_root_fsolver_free);
  gsl_root_fsolver* solver = owner.get();
  gsl_root_fsolver_set(solver, &F, r.x_lo, r.x_hi);  // both ends are start points
  for (;;) {
    const int rc = gsl_root_fsolver_iterate(solver);
    ++r.iterations;
    const double x = gsl_root_fsolver_root(solver);
    if (f.failed || rc != GSL_SUCCESS) {
      if (!f.failed) r.end = RootSearchResult::End::gsl_error, r.gsl_message = gsl_strerror(rc);
      // The best point evaluated inside the start bracket is the estimate.
      double best = INFINITY;
      for (const auto& [q, v] : r.evaluated)
        if (q >= r.x_lo && q <= r.x_hi && std::abs(v) < best) best = std::abs(v), r.x = q;
      break;
    }
    const double fx = f(x);  // already evaluated by the iteration
    r.final_lo = gsl_root_fsolver_x_lower(solver);
    r.final_hi = gsl_root_fsolver_x_upper(solver);
    r.x = x;
    if (std::abs(fx) <= s.f_tolerance) {
      r.converged = true, r.end = RootSearchResult::End::f_tolerance;
      break;
    }
    if (gsl_root_test_interval(r.final_lo, r.final_hi, s.x_tolerance, 0) == GSL_SUCCESS) {
      r.converged = true, r.end = RootSearchResult::End::x_tolerance;
      break;
    }
  }
  return r;
}

}  // namespace kolsky::harness
