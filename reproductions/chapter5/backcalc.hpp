// The strength back-calculation of Sec. 5.3.1 as a procedure (the text did it by hand): the
// sigma_lim0 at which an upscaled specimen's stress-strain curve is closest, in RMS at equal
// strain, to the reference specimen's: the sets' shared search (harness/log_search.hpp, GSL's
// Brent minimiser on ln sigma_lim0 after a bracketing walk; runs cached and capped).
#pragma once
#include <array>
#include <functional>
#include <map>
#include <string>

#include "chapter5/ch5.hpp"

namespace kolsky::ch5 {

struct BackCalcSettings {
  double guess = 0;           ///< Pa: the bracket's middle (Eq. 5.17's value)
  double factor = 1.5;        ///< the first bracket is [guess / factor, guess * factor]
  double rel_tol = 0.03;      ///< stop when the bracket is narrower than this (relative)
  int max_evaluations = 8;
  double stress_lo = 1e6, stress_hi = 1e12;  ///< Pa: compared where the reference lies in it
};

struct BackCalcResult {
  double sigma = NAN;         ///< Pa, best evaluated
  double score = NAN;         ///< Pa, RMS stress difference there
  double bracket_lo = NAN, bracket_hi = NAN;  ///< Pa, the final bracket
  bool converged = false;     ///< the bracket reached rel_tol
  std::map<double, double> evaluated;  ///< sigma -> score, every run
  CaseResult best;            ///< the run at sigma
  std::string note;
};

/// The three sigma_lim0 (Pa) every back-calculation evaluates first, in its order: the first
/// bracket's middle, lower and upper point, bit for bit the values back_calculate passes to
/// run(). They do not depend on the reference, so a set may run them beforehand, side by side
/// with the reference (issue 33: a search that uses more than one rank), and let run() hand
/// them back.
std::array<double, 3> first_evaluations(const BackCalcSettings& s);

/// `run(sigma)` runs the candidate specimen; `reference` is the curve to match.
BackCalcResult back_calculate(const std::function<CaseResult(double)>& run, const CaseResult& reference,
                              const BackCalcSettings& s);

/// RMS stress difference of c from the reference at equal strain (Pa; +inf for a failed run).
double curve_score(const CaseResult& c, const CaseResult& reference, double lo, double hi);

}  // namespace kolsky::ch5
