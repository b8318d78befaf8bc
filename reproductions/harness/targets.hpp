// Reproduction targets: the parsed, validated form of reproductions/<set>/targets.json.
// Reference numbers and tolerances live only in that file (with their dissertation source and a
// reason for the band), and so do the numbers of a trend's pass rule (its "threshold", read by
// the driver through threshold() below); drivers never hard-code them. Entry format:
// docs/reproductions.md.
#pragma once
#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace kolsky::harness {

enum class Kind { scalar, curve, trend };
enum class Status { expected_pass, known_deviation };

/// "scalar" | "curve" | "trend", and the status names as written in targets.json.
std::string to_string(Kind k);
std::string to_string(Status s);

/// A sampled curve y(x). x need not be monotonic (stress-strain curves unload).
struct Curve {
  std::vector<double> x, y;
};

/// Accepted interval for a scalar.
struct Band {
  double lo = 0.0, hi = 0.0;
};

/// |measured - reference| <= atol + rtol*|reference|, at some x within +-xtol (curves only).
struct Tolerance {
  double rtol = 0.0, atol = 0.0, xtol = 0.0;
};

/// What the dissertation says. Exactly the members matching `kind` and the JSON form are set.
struct Reference {
  std::optional<double> value;                    // scalar {"value": v}
  std::optional<Band> range;                      // scalar {"range": [lo, hi]}
  Curve points;                                   // curve, inline or loaded from `file`
  std::string file, x_column, y_column;           // curve {"file", "x", "y"}; file as written
  std::string statement;                          // trend, optional {"statement": text}
  std::string source;                             // section / table / equation
  nlohmann::json raw;                             // the object as written, minus "source"
};

struct Target {
  std::string id;
  Kind kind = Kind::scalar;
  std::string unit;
  Reference reference;
  std::optional<Band> band;            // scalar only, exclusive with tolerance
  std::optional<Tolerance> tolerance;  // scalar or curve (required for curves)
  std::map<std::string, double> threshold;  // trend only, optional: named numbers of its rule
  std::string why_band;
  Status status = Status::expected_pass;
  std::string reason;                  // non-empty iff known_deviation
  /// known_deviation only: expected_pass targets of the same set that test the reason's
  /// explanation and can fail (CONTRIBUTING: a deviation is accepted only with one).
  std::vector<std::string> companions;
  std::string description;
};

struct TargetSet {
  std::string set;
  std::string path;  // the targets.json it came from, for messages
  std::vector<Target> targets;

  /// nullptr when no target has this id.
  const Target* find(const std::string& id) const;
};

/// Reads and validates a targets.json. Curve references given as {"file": ...} are loaded from
/// repo_root/file (relative to the working directory when repo_root is empty).
/// Throws kolsky::InputError(path, "targets[3].band", rule) for the first broken rule, including
/// unknown keys (they are usually typos), duplicate ids and unreadable reference files.
TargetSet load_targets(const std::string& path, const std::string& repo_root);

/// Same checks for an already parsed document; `path` is only used in messages.
TargetSet parse_targets(const nlohmann::json& doc, const std::string& path,
                        const std::string& repo_root);

/// The number `key` of trend `id`'s "threshold" object, which the driver's comparison uses (e.g.
/// threshold(targets, "ch5.wang.pair_coincide_low", "max_rms_pa") for `rms <= 2e6`). Throws
/// kolsky::InputError naming the targets file, the target and the key when either is missing.
double threshold(const TargetSet& s, const std::string& id, const std::string& key);

}  // namespace kolsky::harness
