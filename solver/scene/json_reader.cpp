#include "scene/json_reader.hpp"

#include <algorithm>
#include <cerrno>
#include <climits>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <functional>
#include <sstream>
#include <stdexcept>

#include "core/errors.hpp"

namespace kolsky::scene {

namespace {

using nlohmann::json;

/// "a string", "an array", ... for "expected X, got <this>".
std::string a_type(const json& v) {
  if (v.is_null()) return "null";
  if (v.is_array() || v.is_object()) return std::string("an ") + v.type_name();
  return std::string("a ") + v.type_name();
}

std::string join(const std::vector<std::string>& items) {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s;
}

std::string last_segment(const std::string& path) {
  const auto dot = path.rfind('.');
  return dot == std::string::npos ? path : path.substr(dot + 1);
}

std::string join_path(const std::string& prefix, const std::string& key) {
  return prefix.empty() ? key : prefix + "." + key;
}

json::json_pointer pointer(const std::string& path) {
  std::string p = "/" + path;
  std::replace(p.begin(), p.end(), '.', '/');
  return json::json_pointer(p);
}

/// The keys the schema allows directly under `prefix`, and which of them are objects.
struct Children {
  std::vector<std::string> names;
  std::set<std::string> objects;
};

Children children_of(const std::string& schema, const std::string& prefix) {
  Children c;
  const std::string head = prefix.empty() ? "" : prefix + ".";
  for (const ParamSpec& p : schema_table()) {
    if (p.doc.schema != schema || p.doc.path.compare(0, head.size(), head) != 0) continue;
    const std::string rest = p.doc.path.substr(head.size());
    const auto dot = rest.find('.');
    const std::string name = rest.substr(0, dot);
    if (std::find(c.names.begin(), c.names.end(), name) == c.names.end()) c.names.push_back(name);
    if (dot != std::string::npos) c.objects.insert(name);
  }
  return c;
}

}  // namespace

TextPosition text_position(std::string_view text, size_t byte) {
  // parse_error::byte counts from 1 and points at the last character read.
  const size_t index = std::min(byte == 0 ? 0 : byte - 1, text.size());
  TextPosition pos;
  size_t line_start = 0;
  for (size_t i = 0; i < index; ++i)
    if (text[i] == '\n') ++pos.line, line_start = i + 1;
  pos.column = index - line_start + 1;
  return pos;
}

namespace {

/// The dotted path of the value being parsed, kept from nlohmann's parser events, so that an
/// error the parser itself raises (a duplicate key, a number outside the double range) names
/// the key like every other scene error. Each open object remembers its keys: nlohmann keeps
/// the last of two equal keys without a word, and a scene that says a thing twice is refused.
class PathTracker {
 public:
  bool operator()(int depth, json::parse_event_t event, json& parsed) {
    using E = json::parse_event_t;
    // Refused before the frames' paths grow: at 100,000 levels they took every byte of memory
    // (std::bad_alloc); a scene is 3-4 levels deep.
    if ((event == E::object_start || event == E::array_start) && depth >= kMaxJsonDepth)
      throw TooDeep{};
    switch (event) {
      case E::object_start: stack_.push_back({false, child(), {}, {}, 0}); break;
      case E::array_start: stack_.push_back({true, child(), {}, {}, 0}); break;
      case E::key: {
        Frame& f = stack_.back();
        f.key = parsed.get<std::string>();
        if (!f.keys.insert(f.key).second) duplicate_ = child();
        break;
      }
      case E::object_end:
      case E::array_end:
        stack_.pop_back();
        element_done();
        break;
      case E::value: element_done(); break;
    }
    // Stopping here keeps the path of the duplicate; the caller turns it into the error.
    if (!duplicate_.empty()) throw DuplicateKey{};
    return true;
  }
  /// Path of the value the parser is at (the last key read, or the next array element).
  std::string child() const {
    if (stack_.empty()) return "";
    const Frame& f = stack_.back();
    return f.array ? f.path + "[" + std::to_string(f.index) + "]" : join_path(f.path, f.key);
  }
  const std::string& duplicate() const { return duplicate_; }
  struct DuplicateKey {};
  struct TooDeep {};

 private:
  struct Frame {
    bool array;
    std::string path;
    std::set<std::string> keys;
    std::string key;
    size_t index;
  };
  void element_done() {
    if (!stack_.empty() && stack_.back().array) ++stack_.back().index;
  }
  std::vector<Frame> stack_;
  std::string duplicate_;
};

}  // namespace

json read_json_file(const std::string& path) {
  std::error_code ec;
  if (std::filesystem::is_directory(path, ec))
    throw InputError(path, "", "is a directory, not a JSON file");
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError(path, "", std::string("cannot open the file: ") + std::strerror(errno));
  std::ostringstream buf;
  buf << in.rdbuf();
  return parse_json_text(buf.str(), path);
}

json parse_json_text(std::string_view text, const std::string& path) {
  PathTracker tracker;
  try {
    return json::parse(text, std::ref(tracker));
  } catch (const PathTracker::DuplicateKey&) {
    const std::string& key = tracker.duplicate();
    throw InputError(path, key, "duplicate key '" + last_segment(key) +
                                    "': an object holds each key once; remove one of them");
  } catch (const PathTracker::TooDeep&) {
    throw InputError(path, "", "arrays and objects nested more than " + std::to_string(kMaxJsonDepth) +
                                   " levels deep (a scene needs 3 or 4)");
  } catch (const json::out_of_range& e) {  // 406: a number beyond the double range (1e400)
    const std::string what = e.what();
    const auto quote = what.find('\'');
    const std::string number = quote == std::string::npos ? "" : " " + what.substr(quote);
    throw InputError(path, tracker.child(), "the number" + number +
                         " is outside the range of a double (magnitude up to 1.8e308)");
  } catch (const json::parse_error& e) {
    // nlohmann's message is "[json.exception...] parse error at line L, column C: detail";
    // keep the detail and state the position ourselves, computed from the byte offset.
    const std::string what = e.what();
    std::string detail = what;
    const auto at = what.find("parse error");
    const auto colon = at == std::string::npos ? at : what.find(": ", at);
    if (colon != std::string::npos) detail = what.substr(colon + 2);
    const TextPosition pos = text_position(text, e.byte);
    throw InputError(path, "",
                     "JSON syntax error at line " + std::to_string(pos.line) + ", column " +
                         std::to_string(pos.column) + ": " + detail);
  }
}

size_t edit_distance(std::string_view a, std::string_view b) {
  std::vector<size_t> row(b.size() + 1);
  for (size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (size_t i = 1; i <= a.size(); ++i) {
    size_t diagonal = row[0];
    row[0] = i;
    for (size_t j = 1; j <= b.size(); ++j) {
      const size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

std::string closest_name(std::string_view word, const std::vector<std::string>& candidates) {
  std::string best;
  size_t best_distance = 3;
  for (const auto& c : candidates) {
    const size_t d = edit_distance(word, c);
    // d < |word|: a 2-letter key is not "close" to every other 2-letter key.
    if (d < best_distance && d < word.size()) best = c, best_distance = d;
  }
  if (!best.empty()) return best;
  size_t best_prefix = 2;
  for (const auto& c : candidates) {
    size_t n = 0;
    while (n < word.size() && n < c.size() && word[n] == c[n]) ++n;
    if (n > best_prefix) best = c, best_prefix = n;
  }
  return best;
}

JsonReader::JsonReader(const json& root, std::string file, std::string schema)
    : root_(root), file_(std::move(file)), schema_(std::move(schema)) {
  if (!root_.is_object())
    throw InputError(file_, "", "the top level must be a JSON object, got " + a_type(root_));
  check_keys(root_, "");
}

void JsonReader::check_keys(const json& object, const std::string& prefix) const {
  const Children allowed = children_of(schema_, prefix);
  for (const auto& [key, value] : object.items()) {
    const std::string path = join_path(prefix, key);
    if (std::find(allowed.names.begin(), allowed.names.end(), key) == allowed.names.end()) {
      const std::string near = closest_name(key, allowed.names);
      fail(path, "unknown key '" + key + "'; " +
                     (near.empty() ? "valid keys here: " + join(allowed.names)
                                   : "did you mean '" + near + "'?"));
    }
    if (allowed.objects.count(key)) {
      if (!value.is_object()) fail(path, "expected an object, got " + a_type(value));
      check_keys(value, path);
    }
  }
}

void JsonReader::fail(const std::string& path, const std::string& rule) const {
  throw InputError(file_, path, rule);
}

const ParamSpec& JsonReader::spec(const std::string& path) const {
  const ParamSpec* p = find_param(schema_, path);
  if (!p) throw std::logic_error("parameter '" + path + "' is not in the " + schema_ + " table");
  return *p;
}

const json* JsonReader::find(const std::string& path) const {
  const json* node = &root_;
  size_t start = 0;
  while (true) {
    const auto dot = path.find('.', start);
    const std::string key = path.substr(start, dot == std::string::npos ? dot : dot - start);
    if (!node->is_object()) return nullptr;
    const auto it = node->find(key);
    if (it == node->end()) return nullptr;
    node = &*it;
    if (dot == std::string::npos) return node;
    start = dot + 1;
  }
}

bool JsonReader::has(const std::string& path) const { return find(path) != nullptr; }

const json* JsonReader::value_or_default(const std::string& path, const ParamSpec& p) {
  read_.insert(path);
  if (const json* v = find(path)) return v;
  if (p.required) {
    std::string rule = "required key is missing";
    if (!p.doc.applies_to.empty())
      rule += " (required when " + describe_applies_to(p.doc.applies_to) + ")";
    fail(path, rule);
  }
  // A derived default (gauges: [length/2]) is the parser's job; it must ask has() first.
  if (p.default_value.is_null())
    throw std::logic_error("'" + path + "' has a derived default; check has() first");
  return &p.default_value;
}

void JsonReader::check_range(const std::string& path, const ParamSpec& p, double v) const {
  if (!p.range.contains(v)) fail(path, p.range.describe() + ", got " + format_number(v));
}

double JsonReader::number(const std::string& path) {
  const ParamSpec& p = spec(path);
  const json* v = value_or_default(path, p);
  if (!v->is_number()) fail(path, "expected a number, got " + a_type(*v));
  const double x = v->get<double>();
  check_range(path, p, x);
  resolve(path, x);
  return x;
}

int JsonReader::integer(const std::string& path) {
  const ParamSpec& p = spec(path);
  const json* v = value_or_default(path, p);
  if (!v->is_number()) fail(path, "expected an integer, got " + a_type(*v));
  const double x = v->get<double>();
  if (std::floor(x) != x) fail(path, "expected an integer, got " + format_number(x));
  check_range(path, p, x);
  if (std::fabs(x) > INT_MAX) fail(path, "must be at most " + std::to_string(INT_MAX));
  const int n = static_cast<int>(x);
  resolve(path, n);
  return n;
}

bool JsonReader::boolean(const std::string& path) {
  const json* v = value_or_default(path, spec(path));
  if (!v->is_boolean()) fail(path, "expected a boolean (true or false), got " + a_type(*v));
  resolve(path, *v);
  return v->get<bool>();
}

std::string JsonReader::text(const std::string& path) {
  const ParamSpec& p = spec(path);
  const json* v = value_or_default(path, p);
  if (!v->is_string()) fail(path, "expected a string, got " + a_type(*v));
  const std::string s = v->get<std::string>();
  if (p.type == ValueType::path && s.empty()) fail(path, "the file name must not be empty");
  if (p.type == ValueType::choice &&
      std::find(p.choices.begin(), p.choices.end(), s) == p.choices.end()) {
    const std::string near = closest_name(s, p.choices);
    fail(path, "unknown value '" + s + "'" +
                   (near.empty() ? "" : "; did you mean '" + near + "'?") +
                   " (valid: " + join(p.choices) + ")");
  }
  resolve(path, s);
  return s;
}

std::vector<double> JsonReader::numbers(const std::string& path) {
  const ParamSpec& p = spec(path);
  const json* v = value_or_default(path, p);
  if (!v->is_array()) fail(path, "expected an array of numbers, got " + a_type(*v));
  if (v->empty()) fail(path, "must hold at least one value");
  std::vector<double> out;
  for (size_t i = 0; i < v->size(); ++i) {
    const std::string item = path + "[" + std::to_string(i) + "]";
    if (!(*v)[i].is_number()) fail(item, "expected a number, got " + a_type((*v)[i]));
    out.push_back((*v)[i].get<double>());
    check_range(item, p, out.back());
  }
  resolve(path, out);
  return out;
}

void JsonReader::resolve(const std::string& path, json value) {
  resolved_[pointer(path)] = std::move(value);
}

void JsonReader::check_consumed(const json& object, const std::string& prefix) const {
  for (const auto& [key, value] : object.items()) {
    const std::string path = join_path(prefix, key);
    const ParamSpec* p = find_param(schema_, path);
    if (!p) {  // an object node; check_keys has vetted the names already
      check_consumed(value, path);
      continue;
    }
    if (read_.count(path)) continue;
    if (p->doc.applies_to.empty())
      throw std::logic_error("the " + schema_ + " parser did not read '" + path + "'");
    // A selector that is itself a variant key (specimen.contact_law, DEM only) says so too.
    std::string when = describe_applies_to(p->doc.applies_to);
    const std::string selector = p->doc.applies_to.substr(0, p->doc.applies_to.find('='));
    if (const ParamSpec* s = find_param(schema_, selector); s && !s->doc.applies_to.empty())
      when += ", with " + describe_applies_to(s->doc.applies_to);
    fail(path, "'" + last_segment(path) + "' is used only when " + when);
  }
}

void JsonReader::finish() const { check_consumed(root_, ""); }

}  // namespace kolsky::scene
