// The regression gate's data (docs/reproductions.md, "Regression gate").
//   measurements.json: every value a driver recorded (scalars, trend booleans, whole curves),
//     written beside results.json by write_report (and by the verification driver).
//   reproductions/<set>/baseline_<scale>.json: those values from one committed build, each with
//     the tolerance it may move by and why, measured by rerunning the set with its scenes moved
//     by one ulp (common/perturb.hpp). `make rebaseline` writes it and logs the change in
//     reproductions/BASELINES.md; the log line carries the baseline's digest, so a baseline edited
//     without a log line is caught.
#pragma once
#include "harness/score.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace kolsky::harness {

/// Everything one driver run measured, as read back from measurements.json.
struct MeasurementsFile {
  std::string set, scale, git_commit;
  Measurements m;
};

nlohmann::ordered_json measurements_json(const std::string& set, const std::string& scale,
                                         const Measurements& m);
/// Writes out_dir/measurements.json atomically (creates out_dir).
void write_measurements(const std::string& out_dir, const std::string& set,
                        const std::string& scale, const Measurements& m);
/// Throws kolsky::InputError naming the file and JSON path of the first broken rule.
MeasurementsFile read_measurements(const std::string& path);

/// Equal, or both NaN (a non-finite value is stored as null and read back as NaN).
bool same_number(double a, double b);

/// A value may move by atol + rtol*|baseline| (curves: at every point, x and y separately).
struct GateTolerance {
  double rtol = 0.0, atol = 0.0;
  double allowed(double baseline) const;
};

struct BaselineValue {
  std::string id;
  Kind kind = Kind::scalar;
  double value = 0.0;   // scalar
  bool holds = false;   // trend
  Curve curve;          // curve
  double spread = 0.0;  // largest |perturbed - unperturbed| (curves: over the points, of y)
  double spread_x = 0.0;
  GateTolerance tol, tol_x;  // tol_x: curves' x only
  bool gated = true;         // false: round-off alone changes it; shown, never fails the gate
  std::string why;
};

struct Baseline {
  std::string set, scale, git_commit, build, created, method;
  int perturbed_runs = 0;
  std::vector<BaselineValue> values;

  const BaselineValue* find(const std::string& id) const;
};

/// How a tolerance follows from the perturbed runs: factor x the spread, never below floor_ulps
/// relative (what a different libm on another CPU may change in a value that does not see the
/// perturbation at all). Reasons in docs/reproductions.md.
struct RebaselineRule {
  double factor = 4.0;
  double floor_ulps = 16.0;
  double atol_floor = 1e-300;  // a value of exactly 0 may stay 0, nothing else
};

/// Baseline from an unperturbed run and its perturbed reruns. Throws std::runtime_error when the
/// runs do not measure the same ids and kinds (a driver whose output depends on round-off).
Baseline make_baseline(const MeasurementsFile& base, const std::vector<MeasurementsFile>& perturbed,
                       const RebaselineRule& rule, const std::string& build,
                       const std::string& created);

nlohmann::ordered_json baseline_json(const Baseline& b);
/// Throws kolsky::InputError (file, JSON path, rule), including unknown keys.
Baseline load_baseline(const std::string& path);
/// 16 hex digits identifying the values and tolerances (not the header): the BASELINES.md key.
std::string baseline_digest(const Baseline& b);

/// "reproductions/<set>/baseline_<scale>.json" under repo_root.
std::string baseline_path(const std::string& repo_root, const std::string& set,
                          const std::string& scale);

}  // namespace kolsky::harness
