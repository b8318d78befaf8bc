#include "chapter4/calibration.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_roots.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/format.hpp"

namespace kolsky::ch4 {

using repro::fmt;

double x_of_k(double k) { return k >= 1 ? -std::numeric_limits<double>::infinity() : std::log10(1 - k); }
double k_of_x(double x) { return 1 - std::pow(10.0, x); }

CalSettings cal_settings(const nlohmann::json& studies) {
  const auto& c = studies.at("rotational_calibration");
  CalSettings s;
  s.start_ks = c.at("start_ks").get<std::vector<double>>();
  s.resolution_rtol = c.at("resolution_rtol").get<double>();
  s.x_tolerance = c.at("x_tolerance").get<double>();
  s.max_evaluations = c.at("max_evaluations").get<int>();
  return s;
}

const CalPoint* Calibration::root() const {
  if (!std::isfinite(x)) return nullptr;
  for (const auto& p : points)
    if (p.x == x) return &p;
  return nullptr;
}

CalPoint cal_point(const CaseResult& c, const Measures& m, bool reused) {
  CalPoint p;
  p.k = c.rolling_factor;
  p.x = x_of_k(c.rolling_factor);
  p.value = m.modulus_initial;
  p.m = m;
  p.wall_s = reused ? 0 : c.wall_s;
  p.reused = reused;
  p.label = c.label;
  if (c.ok) {
    const long end = m.i_end > 0 ? m.i_end : static_cast<long>(c.history.t.size());
    p.strain.assign(c.history.strain.begin(), c.history.strain.begin() + end);
    p.stress.assign(c.history.stress_back.begin(), c.history.stress_back.begin() + end);
  }
  return p;
}

namespace {

// GSL's default handler aborts on a non-finite function value; the finder's own status
// codes are checked instead (as in eos/three_phase_fit.cpp).
struct GslHandlerOff {
  gsl_error_handler_t* previous = gsl_set_error_handler_off();
  ~GslHandlerOff() { gsl_set_error_handler(previous); }
};

struct Context {
  const std::function<CalPoint(double)>* evaluate = nullptr;
  Calibration* cal = nullptr;
  int budget = 0;
  std::string error;
  /// f(x) = value(x) - target, from an earlier point when x was evaluated before.
  double f(double x) {
    for (const auto& p : cal->points)
      if (p.x == x) return p.value - cal->target;
    if (!error.empty()) return NAN;
    if (cal->evaluations >= budget) {
      error = "evaluation budget (" + std::to_string(budget) + ") spent";
      return NAN;
    }
    CalPoint p = (*evaluate)(k_of_x(x));
    p.x = x;  // the finder's x exactly (k_of_x/x_of_k round trip is not exact)
    if (!p.reused) ++cal->evaluations;
    cal->points.push_back(p);
    if (!std::isfinite(p.value)) error = "no initial modulus at k = " + fmt("%.10g", p.k) + " (" + p.label + ")";
    return p.value - cal->target;
  }
};

double trampoline(double x, void* params) { return static_cast<Context*>(params)->f(x); }

}  // namespace

Calibration calibrate(const std::function<CalPoint(double k)>& evaluate, double target,
                      const CalSettings& s) {
  Calibration cal;
  cal.target = target;
  Context ctx{&evaluate, &cal, s.max_evaluations, ""};
  // Start points (reused where the set already ran them), sorted by x.
  for (double k : s.start_ks) {
    if (ctx.cal->evaluations >= s.max_evaluations) break;
    CalPoint p = evaluate(k);
    p.x = x_of_k(k);
    if (!p.reused) ++cal.evaluations;
    cal.points.push_back(p);
  }
  std::vector<const CalPoint*> sorted;
  for (const auto& p : cal.points)
    if (std::isfinite(p.x) && std::isfinite(p.value)) sorted.push_back(&p);
  std::sort(sorted.begin(), sorted.end(), [](auto* a, auto* b) { return a->x < b->x; });
  for (size_t i = 0; i + 1 < sorted.size(); ++i) {
    const double fa = sorted[i]->value - target, fb = sorted[i + 1]->value - target;
    if (fa * fb <= 0 && (!cal.bracketed || sorted[i + 1]->x - sorted[i]->x < cal.x_hi - cal.x_lo)) {
      cal.bracketed = true;
      cal.x_lo = sorted[i]->x;
      cal.x_hi = sorted[i + 1]->x;
      cal.slope = (sorted[i + 1]->value - sorted[i]->value) / (cal.x_hi - cal.x_lo);
    }
  }
  if (!cal.bracketed) {
    std::string vals;
    for (const auto* p : sorted) vals += (vals.empty() ? "" : ", ") + fmt("%.1f MPa at k = ", p->value / 1e6) + fmt("%.8g", p->k);
    cal.status = "no root: the target " + fmt("%.1f MPa", target / 1e6) + " is not bracketed by the start points (" + vals + ")";
    return cal;
  }
  cal.dx = s.resolution_rtol * std::abs(target) / std::abs(cal.slope);
  const double tol_f = s.resolution_rtol * std::abs(target);

  GslHandlerOff quiet;
  gsl_function F{&trampoline, &ctx};
  gsl_root_fsolver* solver = gsl_root_fsolver_alloc(gsl_root_fsolver_brent);
  gsl_root_fsolver_set(solver, &F, cal.x_lo, cal.x_hi);  // both ends are earlier points
  for (;;) {
    const int rc = gsl_root_fsolver_iterate(solver);
    ++cal.iterations;
    const double x = gsl_root_fsolver_root(solver);
    if (!ctx.error.empty() || rc != GSL_SUCCESS) {
      cal.status = !ctx.error.empty() ? ctx.error : std::string("GSL: ") + gsl_strerror(rc);
      // Keep the best point evaluated inside the bracket as the estimate.
      double best = INFINITY;
      for (const auto& p : cal.points)
        if (p.x >= cal.x_lo && p.x <= cal.x_hi && std::abs(p.value - target) < best)
          best = std::abs(p.value - target), cal.x = p.x, cal.k = p.k;
      break;
    }
    const double fx = ctx.f(x);  // already evaluated by the iteration
    const double lo = gsl_root_fsolver_x_lower(solver), hi = gsl_root_fsolver_x_upper(solver);
    cal.x = x;
    cal.k = k_of_x(x);
    if (std::abs(fx) <= tol_f) {
      cal.converged = true;
      cal.status = "converged: |M - target| = " + fmt("%.1f MPa", std::abs(fx) / 1e6) + " <= resolution " +
                   fmt("%.1f MPa", tol_f / 1e6) + " after " + std::to_string(cal.iterations) + " Brent iteration(s)";
      break;
    }
    if (gsl_root_test_interval(lo, hi, s.x_tolerance, 0) == GSL_SUCCESS) {
      cal.converged = true;
      cal.status = "converged: bracket [" + fmt("%.3f", lo) + ", " + fmt("%.3f", hi) + "] narrower than " +
                   fmt("%g decades", s.x_tolerance) + " after " + std::to_string(cal.iterations) + " Brent iteration(s)";
      break;
    }
  }
  gsl_root_fsolver_free(solver);
  return cal;
}

std::string calibration_table(const Calibration& c) {
  std::string t =
      "| # | k per 1 ns | x = log10(1 - k) | M 1-3 MPa | M 7-10 MPa | M 1-10 MPa | case wall (s) | |\n"
      "|---|---|---|---|---|---|---|---|\n";
  int i = 0;
  for (const auto& p : c.points) {
    t += "| " + std::to_string(++i) + " | " + fmt("%.8g", p.k) + " | " + fmt("%.3f", p.x) + " | " +
         fmt("%.1f MPa", p.value / 1e6) + " | " + fmt("%.1f MPa", p.m.modulus_late / 1e6) + " | " +
         fmt("%.1f MPa", p.m.modulus_back / 1e6) + " | " + (p.reused ? "(reused)" : fmt("%.1f", p.wall_s)) + " | " +
         (p.x == c.x ? "**root**" : "") + " |\n";
  }
  return t;
}

}  // namespace kolsky::ch4
