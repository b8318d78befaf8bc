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
  // The first bracket [guess / factor, guess x factor] written as this set always computed it.
  const double ln_lo = std::log(s.guess / s.factor), ln_mid = std::log(s.guess), ln_hi = std::log(s.guess * s.factor);
  const harness::LogSearchResult q =
      harness::log_brent_search(objective, {ln_lo, ln_mid, ln_hi, std::log(s.factor), s.rel_tol, s.max_evaluations});
  r.bracket_lo = q.bracket_lo;
  r.bracket_hi = q.bracket_hi;
  r.converged = q.converged;
  r.note = q.note;
  return r;
}

}  // namespace kolsky::ch5
