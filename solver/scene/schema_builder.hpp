// Internal to scene/: the builder of the parameter table and the range rules its rows share,
// used by schema.cpp (bars, pulse, column, FE, time, output, BARS.json) and schema_dem.cpp
// (the DEM specimen: packing, grains, contact laws, walls).
#pragma once
#include <limits>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "scene/schema.hpp"

namespace kolsky::scene::table {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline const Range kNoRange{};
inline const Range kPositive{0.0, kInf, true, false};
inline const Range kNonNegative{0.0, kInf, false, false};
inline const Range kPoisson{0.0, 0.5, true, true};
inline const Range kOpenUnit{0.0, 1.0, true, true};
inline const Range kHalfOpenUnitUpper{0.0, 1.0, true, false};  // (0, 1]
inline const Range kHalfOpenUnitLower{0.0, 1.0, false, true};  // [0, 1)
// Below 2 elements the column has no interior node; above 1e5 a 1-D column is only slow.
inline const Range kElementCount{2.0, 100000.0, false, false};
inline const Range kMeshCount{1.0, 1000.0, false, false};
inline const Range kFrictionAngle{0.0, 90.0, false, true};  // [0, 90) degrees
inline const Range kUnitClosed{0.0, 1.0, false, false};     // [0, 1]
// Below 4 balls a chain is no longer a wave guide: incident and reflected waves overlap at
// every ball, so there is nothing for a gauge to separate.
inline const Range kSphereCount{4.0, kInf, false, false, true};

inline std::string type_name(ValueType t) {
  switch (t) {
    case ValueType::number: return "number";
    case ValueType::integer: return "integer";
    case ValueType::boolean: return "boolean";
    case ValueType::string: return "string";
    case ValueType::choice: return "choice";
    case ValueType::path: return "path";
    case ValueType::number_list: return "number[]";
  }
  return "?";
}

inline std::string default_text(ValueType t, const nlohmann::json& v) {
  switch (t) {
    case ValueType::number: return format_number(v.get<double>());
    case ValueType::boolean: return v.get<bool>() ? "true" : "false";
    case ValueType::integer: return std::to_string(v.get<long long>());
    case ValueType::choice: return v.get<std::string>();
    default: return v.dump();
  }
}

/// Collects rows for one schema; `def` null marks a required key.
class TableBuilder {
 public:
  TableBuilder(std::vector<ParamSpec>& rows, std::string schema)
      : rows_(rows), schema_(std::move(schema)) {}

  void add(ValueType type, const std::string& path, nlohmann::json def, const std::string& unit,
           const Range& range, const std::string& description, const std::string& applies = "",
           std::vector<std::string> choices = {}) {
    ParamSpec p;
    p.type = type;
    p.required = def.is_null();
    p.default_value = std::move(def);
    p.range = range;
    p.choices = std::move(choices);
    p.doc = {schema_,
             path,
             type_name(type),
             p.required ? "required" : default_text(type, p.default_value),
             unit,
             description,
             applies};
    rows_.push_back(std::move(p));
  }
  /// A key whose default is derived from other keys by the parser; `text` documents how.
  void add_derived(ValueType type, const std::string& path, const std::string& text,
                   const std::string& unit, const Range& range, const std::string& description) {
    add(type, path, nullptr, unit, range, description);
    rows_.back().required = false;
    rows_.back().doc.default_value = text;
  }

 private:
  std::vector<ParamSpec>& rows_;
  std::string schema_;
};

inline const nlohmann::json kRequired = nullptr;
using VT = ValueType;

/// The DEM specimen's rows (schema_dem.cpp), appended in the order kolsky defaults prints them.
void add_dem_rows(TableBuilder& s);
/// The specimen.breakage rows (schema_dem.cpp), used when `applies` holds.
void add_breakage_rows(TableBuilder& s, const std::string& applies);

}  // namespace kolsky::scene::table
