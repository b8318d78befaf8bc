// The one table of scene and BARS.json parameters (scene/schema.cpp): for every key its dotted
// path, value type, default, unit, range rule and the variant that uses it. The parsers read
// defaults and ranges only from here, parameters()/format_defaults() render it, and
// docs/scene.md is checked against it by verification/test_scene.cpp.
#pragma once
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <string_view>
#include <vector>

#include "scene/scene.hpp"

namespace kolsky::scene {

enum class ValueType { number, integer, boolean, string, choice, path, number_list };

/// Allowed interval for a number (each element, for lists). `or_zero` admits 0 as a sentinel
/// ("automatic") outside the interval, as n_spheres = 0 does.
struct Range {
  double lo = -std::numeric_limits<double>::infinity();
  double hi = std::numeric_limits<double>::infinity();
  bool lo_open = false, hi_open = false;
  bool or_zero = false;

  bool contains(double v) const;
  /// Short form for listings: "> 0", "(0, 0.5)", "0 or >= 4"; "" when any finite value goes.
  std::string text() const;
  /// The rule as a user reads it: "must be > 0", "must be in (0, 0.5)", "must be 0 or >= 4".
  std::string describe() const;
};

struct ParamSpec {
  ParamDoc doc;
  ValueType type = ValueType::number;
  /// Null when the key is required, or when its default depends on other keys (doc says how).
  nlohmann::json default_value;
  bool required = false;
  Range range;
  std::vector<std::string> choices;  ///< ValueType::choice only
};

const std::vector<ParamSpec>& schema_table();
/// The entry for (schema, dotted path), or nullptr.
const ParamSpec* find_param(std::string_view schema, std::string_view path);
/// "pulse.kind=trapezoid|half_sine" -> "pulse.kind = trapezoid or half_sine".
std::string describe_applies_to(const std::string& applies_to);
/// Default values printed the way docs/scene.md writes them: 200e9, 50e-6, 0.0191, true.
std::string format_number(double v);

}  // namespace kolsky::scene
