// targets.json validation. Every rule reports the JSON path of the offending entry so a data
// author can fix the file without reading this code; the rules themselves are listed in
// docs/reproductions.md.
#include "harness/targets.hpp"

#include "core/errors.hpp"
#include "io/csv.hpp"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <set>

namespace kolsky::harness {
namespace {

using nlohmann::json;

/// Validation context for one JSON object: its path for messages and the file it came from.
class Node {
 public:
  Node(const json& j, std::string path, const std::string& file)
      : j_(j), path_(std::move(path)), file_(file) {}

  [[noreturn]] void fail(const std::string& rule) const { throw InputError(file_, path_, rule); }
  [[noreturn]] void fail_at(const std::string& key, const std::string& rule) const {
    throw InputError(file_, at(key), rule);
  }
  std::string at(const std::string& key) const { return path_.empty() ? key : path_ + "." + key; }
  bool has(const std::string& key) const { return j_.contains(key); }
  const json& get(const std::string& key) const {
    if (!j_.contains(key)) fail_at(key, "required field is missing");
    return j_.at(key);
  }
  Node child(const std::string& key) const {
    const json& c = get(key);
    if (!c.is_object()) fail_at(key, "must be an object");
    return Node(c, at(key), file_);
  }
  std::string text(const std::string& key, bool allow_empty) const {
    const json& v = get(key);
    if (!v.is_string()) fail_at(key, "must be a string");
    if (!allow_empty && v.get<std::string>().empty()) fail_at(key, "must not be empty");
    return v.get<std::string>();
  }
  double number(const std::string& key) const { return finite_number(get(key), at(key)); }
  double finite_number(const json& v, const std::string& where) const {
    if (!v.is_number()) throw InputError(file_, where, "must be a number");
    const double d = v.get<double>();
    if (!std::isfinite(d)) throw InputError(file_, where, "must be finite");
    return d;
  }
  /// Rejects keys outside `allowed`, listing them, so a typo ("tolerence") is not silently ignored.
  void only(std::initializer_list<const char*> allowed) const {
    for (const auto& [key, value] : j_.items()) {
      bool ok = false;
      for (const char* a : allowed) ok = ok || key == a;
      if (ok) continue;
      std::string list;
      for (const char* a : allowed) list += (list.empty() ? "" : ", ") + std::string(a);
      fail_at(key, "unknown field (allowed here: " + list + ")");
    }
  }
  const json& raw() const { return j_; }
  const std::string& file() const { return file_; }
  const std::string& path() const { return path_; }

 private:
  const json& j_;
  std::string path_;
  const std::string& file_;
};

Band parse_pair(const Node& n, const std::string& key) {
  const json& v = n.get(key);
  if (!v.is_array() || v.size() != 2) n.fail_at(key, "must be [lo, hi]");
  Band b{n.finite_number(v[0], n.at(key) + "[0]"), n.finite_number(v[1], n.at(key) + "[1]")};
  if (b.lo > b.hi) n.fail_at(key, "lo must not exceed hi");
  return b;
}

Curve load_curve_file(const Node& ref, const std::string& repo_root) {
  const std::string file = ref.text("file", false);
  const std::string xcol = ref.text("x", false);
  const std::string ycol = ref.text("y", false);
  const std::string full =
      repo_root.empty() ? file : (std::filesystem::path(repo_root) / file).string();
  const io::CsvTable table = io::read_csv(full);  // its InputError names the CSV file and line
  Curve c;
  try {
    c.x = table.column(xcol);
    c.y = table.column(ycol);
  } catch (const std::out_of_range& e) {
    ref.fail(full + ": " + e.what());
  }
  if (c.x.empty()) ref.fail_at("file", full + " has no data rows");
  for (size_t i = 0; i < c.x.size(); ++i)
    if (!std::isfinite(c.x[i]) || !std::isfinite(c.y[i]))
      ref.fail_at("file", full + ": data row " + std::to_string(i + 1) + " is not finite");
  return c;
}

Reference parse_reference(const Node& entry, Kind kind, const std::string& repo_root) {
  const Node ref = entry.child("reference");
  Reference r;
  r.source = ref.text("source", false);
  r.raw = ref.raw();
  r.raw.erase("source");
  switch (kind) {
    case Kind::scalar:
      ref.only({"value", "range", "source"});
      if (ref.has("value") == ref.has("range")) ref.fail("a scalar needs exactly one of value, range");
      if (ref.has("value")) r.value = ref.number("value");
      if (ref.has("range")) r.range = parse_pair(ref, "range");
      break;
    case Kind::curve:
      ref.only({"points", "file", "x", "y", "source"});
      if (ref.has("points") == ref.has("file")) ref.fail("a curve needs exactly one of points, file");
      if (ref.has("file")) {
        r.file = ref.text("file", false);
        r.x_column = ref.text("x", false);
        r.y_column = ref.text("y", false);
        r.points = load_curve_file(ref, repo_root);
      } else {
        if (ref.has("x") || ref.has("y")) ref.fail("x and y name columns of a file; use points or file");
        const json& pts = ref.get("points");
        if (!pts.is_array() || pts.empty()) ref.fail_at("points", "must be a non-empty [[x, y], ...]");
        for (size_t i = 0; i < pts.size(); ++i) {
          const std::string where = ref.at("points") + "[" + std::to_string(i) + "]";
          if (!pts[i].is_array() || pts[i].size() != 2)
            throw InputError(ref.file(), where, "must be [x, y]");
          r.points.x.push_back(ref.finite_number(pts[i][0], where + "[0]"));
          r.points.y.push_back(ref.finite_number(pts[i][1], where + "[1]"));
        }
      }
      break;
    case Kind::trend:
      ref.only({"statement", "source"});
      if (ref.has("statement")) r.statement = ref.text("statement", false);
      break;
  }
  return r;
}

Tolerance parse_tolerance(const Node& n, Kind kind) {
  n.only({"rtol", "atol", "xtol"});
  Tolerance t;
  for (auto [key, field] : {std::pair{"rtol", &t.rtol}, {"atol", &t.atol}, {"xtol", &t.xtol}}) {
    if (!n.has(key)) continue;
    *field = n.number(key);
    if (*field < 0.0) n.fail_at(key, "must be non-negative");
  }
  // A zero tolerance demands bit-exact agreement, which no simulation offers: always a mistake.
  if (t.rtol == 0.0 && t.atol == 0.0) n.fail("needs rtol > 0 or atol > 0");
  if (kind != Kind::curve && t.xtol != 0.0) n.fail_at("xtol", "applies to curves only");
  return t;
}

/// A trend's named numbers, {"max_rms_pa": 2e6}: the driver's comparison reads each by name, so
/// the numbers of a pass rule sit here beside its why_band instead of in the driver (issue 32).
std::map<std::string, double> parse_threshold(const Node& e, Kind kind) {
  if (kind != Kind::trend)
    e.fail_at("threshold", "applies to trends only (scalars and curves use band or tolerance)");
  const Node n = e.child("threshold");
  if (n.raw().empty()) n.fail("must name at least one number");
  std::map<std::string, double> out;
  for (const auto& [key, value] : n.raw().items()) {
    if (key.empty()) n.fail("a name must not be empty");
    out[key] = n.finite_number(value, n.at(key));
  }
  return out;
}

/// The ids a known deviation names as the tests of its explanation; that they exist and are
/// expected to pass is checked once the whole set is read (check_companions).
std::vector<std::string> parse_companions(const Node& e, const Target& t) {
  if (t.status != Status::known_deviation)
    e.fail_at("companions", "only for known_deviation (the targets that test its reason)");
  const json& list = e.get("companions");
  if (!list.is_array() || list.empty()) e.fail_at("companions", "must be a non-empty array of target ids");
  std::vector<std::string> out;
  for (size_t i = 0; i < list.size(); ++i) {
    const std::string where = e.at("companions") + "[" + std::to_string(i) + "]";
    if (!list[i].is_string() || list[i].get<std::string>().empty())
      throw InputError(e.file(), where, "must be a non-empty target id");
    out.push_back(list[i].get<std::string>());
    if (out.back() == t.id) throw InputError(e.file(), where, "a target cannot be its own companion");
  }
  return out;
}

/// A companion must be a target of the same file that is expected to pass: a deviation
/// explained by another deviation is not explained.
void check_companions(const TargetSet& s) {
  for (size_t i = 0; i < s.targets.size(); ++i) {
    const Target& t = s.targets[i];
    for (size_t k = 0; k < t.companions.size(); ++k) {
      const std::string where = "targets[" + std::to_string(i) + "].companions[" + std::to_string(k) + "]";
      const Target* c = s.find(t.companions[k]);
      if (c == nullptr) throw InputError(s.path, where, "no target '" + t.companions[k] + "' in this file");
      if (c->status != Status::expected_pass)
        throw InputError(s.path, where,
                         "'" + c->id + "' is itself a known_deviation; a companion must be expected_pass");
    }
  }
}

Target parse_entry(const Node& e, const std::string& repo_root) {
  e.only({"id", "kind", "unit", "reference", "band", "tolerance", "threshold", "why_band", "status",
          "reason", "companions", "description"});
  Target t;
  t.id = e.text("id", false);
  const std::string kind = e.text("kind", false);
  if (kind == "scalar") t.kind = Kind::scalar;
  else if (kind == "curve") t.kind = Kind::curve;
  else if (kind == "trend") t.kind = Kind::trend;
  else e.fail_at("kind", "unknown kind '" + kind + "' (valid: scalar, curve, trend)");
  t.unit = e.text("unit", true);
  t.reference = parse_reference(e, t.kind, repo_root);

  if (e.has("band") && e.has("tolerance")) e.fail("give band or tolerance, not both");
  if (e.has("band")) {
    if (t.kind != Kind::scalar) e.fail_at("band", "applies to scalars only (curves use tolerance)");
    const Node b = e.child("band");
    b.only({"lo", "hi"});
    t.band = Band{b.number("lo"), b.number("hi")};
    if (t.band->lo > t.band->hi) b.fail("lo must not exceed hi");
  } else if (e.has("tolerance")) {
    if (t.kind == Kind::trend) e.fail_at("tolerance", "a trend passes when it holds; no tolerance");
    t.tolerance = parse_tolerance(e.child("tolerance"), t.kind);
  } else if (t.kind != Kind::trend) {
    e.fail_at(t.kind == Kind::scalar ? "band" : "tolerance",
              t.kind == Kind::scalar ? "a scalar needs band or tolerance" : "a curve needs tolerance");
  }
  if (e.has("threshold")) t.threshold = parse_threshold(e, t.kind);
  t.why_band = e.text("why_band", false);

  const std::string status = e.text("status", false);
  if (status == "expected_pass") t.status = Status::expected_pass;
  else if (status == "known_deviation") t.status = Status::known_deviation;
  else e.fail_at("status", "unknown status '" + status + "' (valid: expected_pass, known_deviation)");
  if (t.status == Status::known_deviation) t.reason = e.text("reason", false);
  else if (e.has("reason"))
    e.fail_at("reason", "only for known_deviation (remove it once the target passes)");
  if (e.has("companions")) t.companions = parse_companions(e, t);
  if (e.has("description")) t.description = e.text("description", true);
  return t;
}

}  // namespace

std::string to_string(Kind k) {
  switch (k) {
    case Kind::scalar: return "scalar";
    case Kind::curve: return "curve";
    case Kind::trend: return "trend";
  }
  return "?";
}

std::string to_string(Status s) {
  return s == Status::expected_pass ? "expected_pass" : "known_deviation";
}

const Target* TargetSet::find(const std::string& id) const {
  for (const Target& t : targets)
    if (t.id == id) return &t;
  return nullptr;
}

TargetSet parse_targets(const json& doc, const std::string& path, const std::string& repo_root) {
  if (!doc.is_object()) throw InputError(path, "", "must be a JSON object {\"set\", \"targets\"}");
  const Node root(doc, "", path);
  root.only({"set", "targets", "description"});
  TargetSet s;
  s.set = root.text("set", false);
  s.path = path;
  const json& entries = root.get("targets");
  if (!entries.is_array()) root.fail_at("targets", "must be an array");
  std::set<std::string> ids;
  for (size_t i = 0; i < entries.size(); ++i) {
    const std::string where = "targets[" + std::to_string(i) + "]";
    if (!entries[i].is_object()) throw InputError(path, where, "must be an object");
    Target t = parse_entry(Node(entries[i], where, path), repo_root);
    if (!ids.insert(t.id).second)
      throw InputError(path, where + ".id", "duplicate id '" + t.id + "'");
    s.targets.push_back(std::move(t));
  }
  check_companions(s);
  return s;
}

double threshold(const TargetSet& s, const std::string& id, const std::string& key) {
  const Target* t = s.find(id);
  if (t == nullptr)
    throw InputError(s.path, "targets",
                     "no target '" + id + "', whose threshold '" + key + "' the driver reads");
  const auto it = t->threshold.find(key);
  if (it == t->threshold.end()) {
    const std::string where =
        "targets[" + std::to_string(t - s.targets.data()) + "].threshold." + key;
    throw InputError(s.path, where,
                     "required field is missing (target '" + id + "': the driver's rule reads it)");
  }
  return it->second;
}

TargetSet load_targets(const std::string& path, const std::string& repo_root) {
  std::ifstream in(path);
  if (!in) throw InputError(path, "", "cannot open");
  json doc;
  try {
    doc = json::parse(in);
  } catch (const json::parse_error& e) {
    throw InputError(path, "", std::string("invalid JSON: ") + e.what());
  }
  return parse_targets(doc, path, repo_root);
}

}  // namespace kolsky::harness
