#include "chapter5/backcalc.hpp"

#include <cmath>
#include <cstdio>
#include <limits>

#include "harness/log_search.hpp"

namespace kolsky::ch5 {

double curve_score(const CaseResult& c, const CaseResult& reference, double lo, double hi) {
  if (!c.ok) return std::numeric_limits<double>::infinity();
  const auto d = stress_difference(reference.strain, reference.stress_back, c.strain, c.stress_back, lo, hi);
  return std::isfinite(d.rms) ? d.rms : std::numeric_limits<double>::infinity();
}

namespace {

// The first bracket [guess / factor, guess x factor] in ln sigma_lim0, written as this set always
// computed it (the search's points are exp of these, harness/log_search.cpp).
struct FirstBracket {
  double ln_lo, ln_mid, ln_hi;
};
FirstBracket first_bracket(const BackCalcSettings& s) {
  return {std::log(s.guess / s.factor), std::log(s.guess), std::log(s.guess * s.factor)};
}

}  // namespace

std::array<double, 3> first_evaluations(const BackCalcSettings& s) {
  const FirstBracket b = first_bracket(s);
  return {std::exp(b.ln_mid), std::exp(b.ln_lo), std::exp(b.ln_hi)};
}

BackCalcResult back_calculate(const std::function<CaseResult(double)>& run, const CaseResult& reference,
                              const BackCalcSettings& s) {
  BackCalcResult r;
  r.score = std::numeric_limits<double>::infinity();
  auto objective = [&](double sigma) {
    CaseResult c = run(sigma);
    const double score = curve_score(c, reference, s.stress_lo, s.stress_hi);
    std::printf("  back-calculation N = %g: sigma_lim0 %.4g GPa -> RMS %.3g MPa (%.0f s)\n", c.upscale,
                sigma / 1e9, score / 1e6, c.wall_s);
    r.evaluated[sigma] = score;
    if (!(score >= r.score)) r.score = score, r.sigma = sigma, r.best = std::move(c);
    return score;
  };
  const FirstBracket b = first_bracket(s);
  const harness::LogSearchResult q =
      harness::log_brent_search(objective, {b.ln_lo, b.ln_mid, b.ln_hi, std::log(s.factor), s.rel_tol, s.max_evaluations});
  r.bracket_lo = q.bracket_lo;
  r.bracket_hi = q.bracket_hi;
  r.converged = q.converged;
  r.note = q.note;
  return r;
}

}  // namespace kolsky::ch5
