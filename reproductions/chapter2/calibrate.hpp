// Automated back-calculation of the dry compaction EOS (Sec. 2.3.4): the text adjusted EOS
// points by hand "until the stress-strain curves matched"; here GSL's Nelder-Mead simplex
// (gsl_multimin_fminimizer_nmsimplex2) moves the table ordinates P(eps_v) at fixed strains.
// Parameters: x0 = ln(P_1 / 1 MPa), xk = ln((P_{k+1} - P_k) / 1 MPa): positive increments, so
// every trial table rises strictly (monotonicity by construction).
// Objective: sum over the calibration tests of (slope / reference - 1)^2, plus a weak smoothness
// prior lambda * sum (x_k - x_{k-1})^2 over the increments (the problem has more ordinates than
// slopes; the prior picks the least-curved table among the matching ones).
#pragma once
#include <string>
#include <vector>

#include "chapter2/ch2.hpp"

namespace kolsky::ch2 {

/// One test the EOS must match: the case and its stress-strain slope window.
struct CalibrationTest {
  CaseSpec spec;         ///< spec.eos is replaced by each trial table
  std::string target_id; ///< targets.json id whose reference slope (MPa) is matched
  double reference = 0;  ///< Pa
  double strain_lo = 0.02, strain_hi = 0.10, t_end = 350e-6;
};

struct CalibrationStep {
  int iteration = 0;
  double objective = 0, simplex_size = 0;
  std::vector<double> slopes;  ///< Pa, one per test, at the simplex's best point
};

struct CalibrationResult {
  Table1D table;
  std::vector<double> slopes;  ///< Pa, at the final table
  std::vector<CalibrationStep> history;
  int iterations = 0, evaluations = 0;
  bool converged = false;
  double objective = 0;
};

struct CalibrationOptions {
  std::vector<double> strains{0.05, 0.10, 0.15, 0.20};  ///< table abscissae (besides 0)
  int max_iterations = 150;
  double size_tolerance = 2e-3;  ///< simplex size (in ln P) at which it stops
  double initial_step = 0.15;    ///< simplex step in ln P
  double smoothness = 1e-3;      ///< lambda
  /// Tables that never soften only (the companion of ch2.trend_eos_stiffening): x0 = ln(first
  /// increment), xk = ln(growth of the increment), so every trial table's increments are
  /// non-decreasing by construction; no smoothness prior (the constraint takes its place).
  bool never_soften = false;
};

/// Starts from `start` (interpolated at opts.strains). Throws std::runtime_error if GSL fails.
CalibrationResult calibrate_dry_eos(const BaseScene& base, const std::vector<CalibrationTest>& tests,
                                    const Table1D& start, const CalibrationOptions& opts);

/// Table (0, 0), (strains[k], P_k) from the parameter vector (CalibrationOptions::never_soften
/// picks its meaning).
Table1D table_from_params(const std::vector<double>& strains, const std::vector<double>& x,
                          bool never_soften = false);

}  // namespace kolsky::ch2
