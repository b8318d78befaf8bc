// What `kolsky sweep` runs (issue 33): a scene, the keys it varies (each over a list or a
// range of values) and the packing seeds; the members are the product of every key's values
// and the seeds, the first key varying slowest and the seed fastest. Each member is the scene
// with its changes applied (scene/scene_change.hpp) and must pass the scene reader before any
// member runs: a bad key, value or range is refused up front (InputError, exit 2).
//
// A key's values (--set KEY=SPEC):
//   [v1, v2, ...]          a JSON list (any JSON values: numbers, strings, objects)
//   lo:hi:count            count values from lo to hi, evenly spaced (both ends included)
//   log:lo:hi:count        count values from lo to hi, evenly spaced in log (lo, hi > 0)
//   v                      one JSON value: a change every member gets
// A range of integers (lo and hi written without '.', 'e') whose values are all whole gives
// JSON integers, so that integer keys (specimen.n_elements) take it.
#pragma once
#include <cstddef>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace kolsky::sweep {

struct SweepAxis {
  std::string key;                     ///< a dotted scene key ("specimen.breakage.sigma_lim0")
  std::vector<nlohmann::json> values;  ///< in the order written (a range: lo to hi)
  bool log_spaced = false;             ///< from log:lo:hi:count (the figures use a log axis)
};

/// "KEY=SPEC" as an axis. Throws InputError("--set", key, rule) for an item without '=', an
/// empty key, a malformed range (not three numbers lo:hi:count, a count that is not a whole
/// number >= 1, one value from lo != hi, a log range with lo or hi <= 0), an empty list, or a
/// value that is not JSON.
SweepAxis parse_axis(const std::string& item);

/// The values of a range SPEC (without the "log:" prefix when `log` is set); InputError as
/// parse_axis, naming `key`.
std::vector<nlohmann::json> range_values(const std::string& spec, bool log, const std::string& key);

struct SweepPlan {
  std::string scene_file;          ///< as given: named in every message
  nlohmann::json scene;            ///< the file's JSON as read
  std::vector<SweepAxis> axes;     ///< the keys varied, in the order given
  int seeds = 0;                   ///< K > 0: specimen.seed = 1..K for every point; 0: the scene's
};

/// One member: a value of each axis (axes order) and the seed (0: the scene's own).
struct SweepPoint {
  std::vector<nlohmann::json> values;
  int seed = 0;
  std::string label;               ///< "key=value key2=value2 seed=s"
};

/// The key --seeds varies.
inline constexpr const char* kSeedKey = "specimen.seed";

/// Reads the scene and checks the plan's shape: InputError(scene, ...) for an unreadable scene;
/// InputError("--set", key, ...) for a key given twice, or specimen.seed beside --seeds.
SweepPlan make_plan(const std::string& scene_file, std::vector<SweepAxis> axes, int seeds);

/// The most members a sweep may have (each is at least one run; more is a typo, e.g. a count of
/// 1e6 in two ranges).
inline constexpr double kMostMembers = 1e6;

/// Every member, first axis slowest, seed fastest. InputError("--set", key, ...) when the
/// product is empty or has more than kMostMembers members.
std::vector<SweepPoint> sweep_points(const SweepPlan& plan);

/// The member's scene: the plan's scene with each axis' value (and the seed) applied.
/// InputError(scene_file, key, ...) for a key whose path cannot be followed.
nlohmann::json member_scene(const SweepPlan& plan, const SweepPoint& point);

/// The folder the scene's relative paths resolve against (absolute).
std::string scene_folder(const SweepPlan& plan);

/// Every member's scene through the scene reader and the end-time check `kolsky run` makes
/// before building: the first refusal as InputError(scene_file, key, rule + the member's label).
/// Nothing is built or run.
void validate_points(const SweepPlan& plan, const std::vector<SweepPoint>& points);

/// A value as the labels and the table write it: numbers shortest round-trip ("2e+09",
/// "0.25"), strings without quotes, anything else as compact JSON.
std::string value_text(const nlohmann::json& v);

}  // namespace kolsky::sweep
