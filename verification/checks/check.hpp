// A verification check: a closed form, what the code produced, and a tolerance with its reason.
// The same functions feed the GoogleTest suite (make check) and reports/verification/.
#pragma once
#include <cmath>
#include <ostream>
#include <string>
#include <vector>

namespace kolsky::verify {

struct CheckResult {
  std::string id;            ///< e.g. "bar.wave_speed"
  std::string description;   ///< what is checked
  std::string closed_form;   ///< the formula the expected value comes from
  std::string unit;
  double expected = 0, got = 0;
  double error = 0;          ///< |got - expected| (relative when `relative`)
  double tolerance = 0;
  bool relative = true;
  std::string why_tolerance;
  std::string note;          ///< extra measured facts (e.g. transits to equilibrium)
  bool pass() const { return std::isfinite(error) && error <= tolerance; }
};

/// Fills error from expected/got and returns the result.
inline CheckResult finish(CheckResult r) {
  const double d = std::fabs(r.got - r.expected);
  r.error = r.relative ? d / std::fabs(r.expected) : d;
  return r;
}

inline std::ostream& operator<<(std::ostream& os, const CheckResult& r) {
  return os << r.id << ": expected " << r.expected << " got " << r.got << " error " << r.error
            << (r.relative ? " (relative)" : "") << " tolerance " << r.tolerance << " ["
            << r.why_tolerance << "] " << r.note;
}

/// Linear-interpolated time at which |y| first reaches `level` (NaN if never).
double crossing_time(const std::vector<double>& t, const std::vector<double>& y, double level);

std::vector<CheckResult> bar_checks();       // checks_bars.cpp
std::vector<CheckResult> specimen_checks();  // checks_specimen.cpp
std::vector<CheckResult> analysis_checks();  // checks_analysis.cpp
std::vector<CheckResult> fe_coupling_checks();  // checks_fe_coupling.cpp
std::vector<CheckResult> dem_coupling_checks();  // checks_dem_coupling.cpp

}  // namespace kolsky::verify
