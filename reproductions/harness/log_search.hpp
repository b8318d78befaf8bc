// The calibration search the reproduction sets share (issue 32): the parameter p > 0 that
// minimises a costly deterministic objective f(p), each evaluation one simulation (Chapter 3's
// NORMK against a slope, Chapter 5's sigma_lim0 against a reference curve). A bracketing walk
// by a constant step in ln p from a guess until the middle of three points is lowest, then
// GSL's Brent minimiser on ln p until the bracket is narrower than rel_tol (its relative
// width). Evaluations are cached (a simulation never runs twice) and capped; a probe within
// 0.1 % of a point already run ends the search there (Brent probes right next to its best
// point once its own tolerance is met, far below the bracket tolerance and the objectives'
// noise), keeping the bracket from before that probe.
#pragma once
#include <cmath>
#include <functional>
#include <map>
#include <string>

namespace kolsky::harness {

struct LogSearchSettings {
  /// The first three points, ln p: below, the guess, above; the walk moves by `step`. Given
  /// as logarithms so that each set keeps the arithmetic its results were made with
  /// (ln(g / f) and ln g - ln f differ in the last bit, and so would every run after).
  double ln_lo = 0, ln_mid = 0, ln_hi = 0, step = 0;
  double rel_tol = 0.03;   ///< stop when ln(hi / lo) is below this
  int max_evaluations = 8; ///< distinct evaluations at most
};

struct LogSearchResult {
  double best = NAN;        ///< the evaluated p with the lowest f (the first one on a tie)
  double best_value = NAN;  ///< f there
  double bracket_lo = NAN, bracket_hi = NAN;  ///< the final bracket
  bool converged = false;   ///< the bracket reached rel_tol (or the search ended on a repeat)
  std::map<double, double> evaluated;  ///< p -> f, every evaluation
  std::string note;         ///< why it stopped, when not plainly converged
};

/// `objective(p)` runs one evaluation; it is never called twice for one p, nor for a p within
/// 0.1 % of one already evaluated. The first three evaluations are the middle point, then
/// the lower and the upper one. A non-finite f counts as worse than any finite one.
LogSearchResult log_brent_search(const std::function<double(double)>& objective, const LogSearchSettings& s);

}  // namespace kolsky::harness
