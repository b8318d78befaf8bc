#include "chapter2/calibrate.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_multimin.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>

#include "harness/isotonic.hpp"

namespace kolsky::ch2 {

Table1D table_from_params(const std::vector<double>& strains, const std::vector<double>& x,
                          bool never_soften) {
  Table1D t;
  t.x = {0.0};
  t.y = {0.0};
  double p = 0, inc = 0;
  for (size_t k = 0; k < strains.size(); ++k) {
    inc = never_soften ? inc + 1e6 * std::exp(x[k]) : 1e6 * std::exp(x[k]);
    p += inc;
    t.x.push_back(strains[k]);
    t.y.push_back(p);
  }
  t.extrapolate = true;
  return t;
}

namespace {

struct Problem {
  const BaseScene* base;
  const std::vector<CalibrationTest>* tests;
  const CalibrationOptions* opts;
  int evaluations = 0;
  std::vector<double> last_slopes;
  double best_f = HUGE_VAL;
  std::vector<double> best_slopes;  ///< slopes at the lowest objective seen
};

double evaluate(Problem& pb, const std::vector<double>& x, std::vector<double>& slopes) {
  ++pb.evaluations;
  const auto table = table_from_params(pb.opts->strains, x, pb.opts->never_soften);
  double f = 0;
  slopes.clear();
  for (const auto& test : *pb.tests) {
    auto spec = test.spec;
    spec.eos = table;
    const auto r = run_case(*pb.base, spec);
    const double s = r.ok ? loading_slope(r.h, test.strain_lo, test.strain_hi, test.t_end)
                          : std::nan("");
    slopes.push_back(s);
    f += std::isfinite(s) ? std::pow(s / test.reference - 1.0, 2) : 1e3;
  }
  if (!pb.opts->never_soften)
    for (size_t k = 2; k < x.size(); ++k) f += pb.opts->smoothness * std::pow(x[k] - x[k - 1], 2);
  return f;
}

double gsl_objective(const gsl_vector* v, void* params) {
  auto& pb = *static_cast<Problem*>(params);
  std::vector<double> x(v->size);
  for (size_t k = 0; k < v->size; ++k) x[k] = gsl_vector_get(v, k);
  const double f = evaluate(pb, x, pb.last_slopes);
  if (f < pb.best_f) pb.best_f = f, pb.best_slopes = pb.last_slopes;
  return f;
}

}  // namespace

CalibrationResult calibrate_dry_eos(const BaseScene& base, const std::vector<CalibrationTest>& tests,
                                    const Table1D& start, const CalibrationOptions& opts) {
  const size_t n = opts.strains.size();
  Problem pb{&base, &tests, &opts, 0, {}, HUGE_VAL, {}};
  gsl_vector* x = gsl_vector_alloc(n);
  gsl_vector* step = gsl_vector_alloc(n);
  Table1D s0 = start;
  s0.extrapolate = true;
  double prev = 0;
  std::vector<double> inc(n);
  for (size_t k = 0; k < n; ++k) {
    const double p = s0(opts.strains[k]);
    if (!(p > prev)) throw std::runtime_error("calibration start table must rise strictly");
    inc[k] = p - prev;
    prev = p;
  }
  if (opts.never_soften) inc = harness::nearest_non_decreasing(inc);
  for (size_t k = 0; k < n; ++k) {
    // A never-softening start's growth of the increment may be zero; 1 % of the first keeps ln finite.
    const double v = !opts.never_soften || k == 0 ? inc[k] : std::max(inc[k] - inc[k - 1], 0.01 * inc[0]);
    gsl_vector_set(x, k, std::log(v / 1e6));
  }
  gsl_vector_set_all(step, opts.initial_step);
  gsl_multimin_function fn{&gsl_objective, n, &pb};
  gsl_multimin_fminimizer* m = gsl_multimin_fminimizer_alloc(gsl_multimin_fminimizer_nmsimplex2, n);
  gsl_multimin_fminimizer_set(m, &fn, x, step);

  CalibrationResult res;
  int status = GSL_CONTINUE;
  int it = 0;
  while (status == GSL_CONTINUE && it < opts.max_iterations) {
    ++it;
    if (gsl_multimin_fminimizer_iterate(m) != GSL_SUCCESS) break;
    const double size = gsl_multimin_fminimizer_size(m);
    status = gsl_multimin_test_size(size, opts.size_tolerance);
    CalibrationStep st;
    st.iteration = it;
    st.objective = m->fval;
    st.simplex_size = size;
    st.slopes = pb.best_slopes;
    res.history.push_back(st);
  }
  res.converged = status == GSL_SUCCESS;
  res.iterations = it;
  std::vector<double> best(n);
  for (size_t k = 0; k < n; ++k) best[k] = gsl_vector_get(m->x, k);
  res.table = table_from_params(opts.strains, best, opts.never_soften);
  res.objective = evaluate(pb, best, res.slopes);
  res.evaluations = pb.evaluations;
  gsl_multimin_fminimizer_free(m);
  gsl_vector_free(x);
  gsl_vector_free(step);
  return res;
}

}  // namespace kolsky::ch2
