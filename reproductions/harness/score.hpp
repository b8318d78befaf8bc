// What a driver measured, and how each measurement is scored against its target.
//   scalar: pass if lo <= value <= hi; with a tolerance [lo, hi] = ref -+ (atol + rtol*|ref|)
//           (a range reference widens each end by its own tolerance).
//   trend:  pass if the driver's boolean holds; value 1/0, lo = hi = 1.
//   curve:  every reference point (x_r, y_r) must come within atol + rtol*|y_r| of the measured
//           polyline somewhere in x_r -+ xtol; value = relative error at the worst point.
// The curve check is exact on the polyline (each segment clipped to the x window), not sampled.
#pragma once
#include "harness/targets.hpp"

#include <map>
#include <optional>
#include <string>

namespace kolsky::harness {

/// One recorded measurement; which members matter follows `kind`.
struct Measurement {
  Kind kind = Kind::scalar;
  double value = 0.0;  // scalar
  bool holds = false;  // trend
  std::string what;    // trend: what was compared, e.g. "peak 41 MPa at 7% > 33 MPa at 3%"
  Curve curve;         // curve
};

/// Everything one driver run measured, keyed by target id.
class Measurements {
 public:
  /// Each throws std::invalid_argument if `id` was already recorded (a driver bug).
  void scalar(const std::string& id, double value);
  void trend(const std::string& id, bool holds, std::string what);
  /// x and y must have equal length (checked when scored, so the report can say why).
  void curve(const std::string& id, Curve measured);
  /// Free text shown with the target in results.json and report.md; repeated calls append.
  void note(const std::string& id, std::string text);
  /// Adds every value and note of `other` (a part of the set measured apart, e.g. on another
  /// thread); throws std::invalid_argument as above if an id is in both.
  void merge(const Measurements& other);

  const Measurement* find(const std::string& id) const;
  std::string note_for(const std::string& id) const;
  const std::map<std::string, Measurement>& all() const { return values_; }

 private:
  void add(const std::string& id, Measurement m);
  std::map<std::string, Measurement> values_;
  std::map<std::string, std::string> notes_;
};

/// The reference point that came closest to failing (or failed worst).
struct WorstPoint {
  double x_ref = 0.0, y_ref = 0.0;
  double x_nearest = 0.0, y_nearest = 0.0;  // where on the measured curve the error is smallest
  double error = 0.0;                       // |y_nearest - y_ref|, in the target unit
  double allowed = 0.0;                     // atol + rtol*|y_ref|
  bool outside = false;                     // x window misses the measured x range entirely
};

/// Curve comparison result. pass iff every point has error <= allowed.
struct CurveCheck {
  bool pass = false;
  size_t n_failed = 0;
  std::optional<WorstPoint> worst;  // largest error/allowed; empty only without reference points
  std::string problem;              // why the measured curve could not be compared at all
};

CurveCheck compare_curve(const Curve& measured, const Curve& reference, const Tolerance& tol);

/// A scored target, ready for results.json and report.md.
struct Score {
  const Target* target = nullptr;
  bool measured = false;
  std::optional<double> value;  // empty when not measured or not finite
  std::optional<double> lo, hi;
  bool pass = false;
  bool unexpected_pass = false;  // known_deviation that passed: its note should be removed
  std::optional<WorstPoint> worst;
  std::string note;  // scoring explanation, then the driver's note

  /// True when the set fails because of this target.
  bool fails_set() const;
};

/// Scores t against m (missing id: fails with "not measured"; kind mismatch: fails).
Score score_target(const Target& t, const Measurements& m);

}  // namespace kolsky::harness
