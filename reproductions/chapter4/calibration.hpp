// Back-calculation of the rotational factor (Sec. 4.3 says its k was calibrated; issue 15):
// the k per 1 ns whose initial confined modulus (sigma_t fit over back stress 1-3 MPa, as
// measure() does) equals a target, found by GSL's Brent root finder on x = log10(1 - k).
// x is the natural variable: the family k = 0, 0.999, 0.99999975 sits at x = 0, -3, -6.6 and
// the modulus changes smoothly between them (README), while k itself crowds against 1.
//
// The response is a chaotic DEM run: a change of the summation order alone moves the initial
// modulus by ~4 % (README, "k = 1 against the calibrated k"). The root is therefore only known
// to resolution * target / |dM/dx|, and the finder stops as soon as |M - target| is within that
// resolution (iterating further chases round-off). Settings and their reasons: studies.json.
#pragma once
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "chapter4/ch4.hpp"

namespace kolsky::ch4 {

/// x = log10(1 - k) and back (k per 1 ns; k = 1 is x = -inf).
double x_of_k(double k);
double k_of_x(double x);

/// One evaluated k.
struct CalPoint {
  double k = NAN, x = NAN;
  double value = NAN;    ///< Pa, the calibrated quantity (initial modulus)
  Measures m;            ///< every Sec. 4.4 measure of the case
  std::vector<double> strain, stress;  ///< sigma_t(strain) to the first 10 MPa sample, Pa
  double wall_s = 0;     ///< 0 when reused from a case the set had already run
  bool reused = false;
  std::string label;
};

struct CalSettings {
  std::vector<double> start_ks;  ///< evaluated first; the tightest sign change brackets the root
  double resolution_rtol = 0.04; ///< run-to-run resolution of the modulus (relative)
  double x_tolerance = 0.05;     ///< decades: stop when the bracket is this narrow
  int max_evaluations = 8;       ///< new evaluations (start points included)
};
CalSettings cal_settings(const nlohmann::json& studies);

struct Calibration {
  double target = NAN;           ///< Pa
  bool bracketed = false, converged = false;
  std::string status;            ///< how it stopped (or why there is no root)
  double x_lo = NAN, x_hi = NAN; ///< the start bracket
  double slope = NAN;            ///< Pa per decade of x, secant over the start bracket
  double x = NAN, k = NAN;       ///< the root (the evaluated point Brent ended on)
  double dx = NAN;               ///< decades: resolution * target / |slope|
  int iterations = 0, evaluations = 0;
  std::vector<CalPoint> points;  ///< in evaluation order
  const CalPoint* root() const;  ///< the point at x (nullptr without a root)
};

/// evaluate(k) runs (or looks up) the case at k and returns its point. Throws nothing: a
/// failed evaluation ends the calibration with its message in `status`.
Calibration calibrate(const std::function<CalPoint(double k)>& evaluate, double target,
                      const CalSettings& s);

/// A CalPoint from a finished case (value = initial modulus).
CalPoint cal_point(const CaseResult& c, const Measures& m, bool reused);

/// Markdown table of the evaluations, with the root marked.
std::string calibration_table(const Calibration& c);

}  // namespace kolsky::ch4
