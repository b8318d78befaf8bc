// Walks a parsed JSON document against one schema of the parameter table (scene/schema.hpp):
// unknown keys are rejected up front with a "did you mean" (so a typo is reported instead of
// the missing key it causes), typed reads apply the table's default and range and record the
// resolved value, and finish() rejects keys that the selected variant does not use.
// Every error is InputError(file, dotted.path, rule).
#pragma once
#include <nlohmann/json.hpp>
#include <set>
#include <string>
#include <string_view>
#include <vector>

#include "scene/schema.hpp"

namespace kolsky::scene {

/// Deepest nesting of arrays and objects a parsed document may have; deeper is refused.
inline constexpr int kMaxJsonDepth = 64;

/// Reads and parses a JSON file. Throws InputError(path, "", rule) if it cannot be opened, on
/// a syntax error ("JSON syntax error at line L, column C: ...") or when nested deeper than
/// kMaxJsonDepth.
nlohmann::json read_json_file(const std::string& path);
/// The same for a document already in memory (the fuzz targets); `path` names it in errors.
nlohmann::json parse_json_text(std::string_view text, const std::string& path);

/// 1-based line and column of the character at 1-based byte offset `byte` (as reported by
/// nlohmann::json::parse_error::byte); offsets past the end point just after the last byte.
struct TextPosition {
  size_t line = 1, column = 1;
};
TextPosition text_position(std::string_view text, size_t byte);

/// Levenshtein distance (insertions, deletions, substitutions).
size_t edit_distance(std::string_view a, std::string_view b);
/// The candidate a misspelt `word` most likely meant: the nearest within edit distance 2
/// (and shorter than the word itself), else the one sharing the longest prefix of at least
/// 3 characters; "" when nothing is close.
std::string closest_name(std::string_view word, const std::vector<std::string>& candidates);

class JsonReader {
 public:
  /// `schema` is "scene" or "bars". Throws on a non-object root, on keys the schema does not
  /// know anywhere in the tree, and on a non-object where the schema expects an object.
  JsonReader(const nlohmann::json& root, std::string file, std::string schema);

  bool has(const std::string& path) const;
  /// Typed reads: the value, or the table default when absent (InputError if required).
  /// Each checks the JSON type and the table's range and records the value as resolved.
  double number(const std::string& path);
  int integer(const std::string& path);
  bool boolean(const std::string& path);
  /// string, choice (checked against the table's choices) or path (non-empty) keys.
  std::string text(const std::string& path);
  /// A non-empty array of numbers, each within the table's range.
  std::vector<double> numbers(const std::string& path);

  /// Overrides the resolved value of a key (a derived default, an absolute CSV path).
  void resolve(const std::string& path, nlohmann::json value);
  [[noreturn]] void fail(const std::string& path, const std::string& rule) const;
  /// Rejects present keys that no read consumed; for table keys this means the key belongs
  /// to a variant that is not selected ("'file' is used only when pulse.kind = tabulated").
  void finish() const;

  const nlohmann::json& resolved() const { return resolved_; }
  const std::string& file() const { return file_; }

 private:
  const ParamSpec& spec(const std::string& path) const;
  const nlohmann::json* find(const std::string& path) const;
  /// The value to read: present, or the table default (InputError when required).
  const nlohmann::json* value_or_default(const std::string& path, const ParamSpec& p);
  void check_range(const std::string& path, const ParamSpec& p, double v) const;
  void check_keys(const nlohmann::json& object, const std::string& prefix) const;
  void check_consumed(const nlohmann::json& object, const std::string& prefix) const;

  const nlohmann::json& root_;
  std::string file_, schema_;
  nlohmann::json resolved_ = nlohmann::json::object();
  std::set<std::string> read_;
};

}  // namespace kolsky::scene
