// measurements.json and baseline_<scale>.json (formats in baseline.hpp and
// docs/reproductions.md), and the tolerance rule of `make rebaseline`.
#include "harness/baseline.hpp"

#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "core/hash.hpp"
#include "core/build_info.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <limits>
#include <set>

namespace kolsky::harness {
namespace {

using Json = nlohmann::ordered_json;
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kEps = std::numeric_limits<double>::epsilon();

// JSON has no NaN/Inf: they are written as null and read back as NaN (the gate compares
// "not finite" with "not finite", which is all a driver can mean by them).
Json number(double v) { return std::isfinite(v) ? Json(v) : Json(nullptr); }

std::string fmt(const char* f, double v) {
  char b[64];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

/// Strict reader: every access names the JSON path, unknown keys are refused.
struct Reader {
  std::string file;

  [[noreturn]] void fail(const std::string& path, const std::string& rule) const {
    throw InputError(file, path, rule);
  }
  void keys(const nlohmann::json& j, const std::string& path,
            std::initializer_list<const char*> allowed) const {
    if (!j.is_object()) fail(path, "must be an object");
    const std::set<std::string> ok(allowed.begin(), allowed.end());
    for (auto it = j.begin(); it != j.end(); ++it)
      if (!ok.count(it.key())) fail(path + "." + it.key(), "unknown key");
  }
  const nlohmann::json& at(const nlohmann::json& j, const std::string& path, const char* k) const {
    if (!j.contains(k)) fail(path + "." + k, "missing");
    return j.at(k);
  }
  std::string text(const nlohmann::json& j, const std::string& path, const char* k) const {
    const auto& v = at(j, path, k);
    if (!v.is_string()) fail(path + "." + k, "must be a string");
    return v.get<std::string>();
  }
  double num(const nlohmann::json& v, const std::string& path) const {
    if (v.is_null()) return kNaN;
    if (!v.is_number()) fail(path, "must be a number or null");
    return v.get<double>();
  }
  double num(const nlohmann::json& j, const std::string& path, const char* k) const {
    return num(at(j, path, k), path + "." + k);
  }
  bool flag(const nlohmann::json& j, const std::string& path, const char* k) const {
    const auto& v = at(j, path, k);
    if (!v.is_boolean()) fail(path + "." + k, "must be true or false");
    return v.get<bool>();
  }
  std::vector<double> list(const nlohmann::json& j, const std::string& path, const char* k) const {
    const auto& v = at(j, path, k);
    if (!v.is_array()) fail(path + "." + k, "must be an array");
    std::vector<double> out;
    out.reserve(v.size());
    for (size_t i = 0; i < v.size(); ++i) out.push_back(num(v[i], path + "." + k + "[" + std::to_string(i) + "]"));
    return out;
  }
  Kind kind(const nlohmann::json& j, const std::string& path) const {
    const std::string k = text(j, path, "kind");
    if (k == "scalar") return Kind::scalar;
    if (k == "trend") return Kind::trend;
    if (k == "curve") return Kind::curve;
    fail(path + ".kind", "must be scalar, trend or curve (is '" + k + "')");
  }
  GateTolerance tolerance(const nlohmann::json& j, const std::string& path, const char* k) const {
    const auto& t = at(j, path, k);
    const std::string p = path + "." + k;
    keys(t, p, {"rtol", "atol"});
    GateTolerance g{num(t, p, "rtol"), num(t, p, "atol")};
    if (!(g.rtol >= 0) || !(g.atol >= 0)) fail(p, "rtol and atol must be finite and >= 0");
    return g;
  }
  nlohmann::json document() const {
    std::ifstream f(file);
    if (!f) fail("", "cannot be read");
    try {
      return nlohmann::json::parse(f);
    } catch (const nlohmann::json::exception& e) {
      fail("", std::string("not valid JSON: ") + e.what());
    }
  }
};

Json tolerance_json(const GateTolerance& t) { return Json{{"rtol", t.rtol}, {"atol", t.atol}}; }

Json list_json(const std::vector<double>& v) {
  Json a = Json::array();
  for (double x : v) a.push_back(number(x));
  return a;
}

/// Largest |a_i - b_i|; NaN when one side is finite and the other not.
double max_change(const std::vector<double>& a, const std::vector<double>& b) {
  double s = 0.0;
  for (size_t i = 0; i < a.size(); ++i) {
    if (same_number(a[i], b[i])) continue;
    const double d = std::fabs(a[i] - b[i]);
    if (!std::isfinite(d)) return kNaN;
    s = std::max(s, d);
  }
  return s;
}

}  // namespace

bool same_number(double a, double b) { return a == b || (std::isnan(a) && std::isnan(b)); }

double GateTolerance::allowed(double baseline) const {
  return atol + rtol * (std::isfinite(baseline) ? std::fabs(baseline) : 0.0);
}

const BaselineValue* Baseline::find(const std::string& id) const {
  for (const auto& v : values)
    if (v.id == id) return &v;
  return nullptr;
}

std::string baseline_path(const std::string& repo_root, const std::string& set,
                          const std::string& scale) {
  return repo_root + "/reproductions/" + set + "/baseline_" + scale + ".json";
}

Json measurements_json(const std::string& set, const std::string& scale, const Measurements& m) {
  Json j{{"set", set}, {"scale", scale}, {"git_commit", build_info::git_commit()}, {"values", Json::array()}};
  for (const auto& [id, v] : m.all()) {
    Json e{{"id", id}, {"kind", to_string(v.kind)}};
    switch (v.kind) {
      case Kind::scalar: e["value"] = number(v.value); break;
      case Kind::trend: e["holds"] = v.holds; e["what"] = v.what; break;
      case Kind::curve: e["x"] = list_json(v.curve.x); e["y"] = list_json(v.curve.y); break;
    }
    j["values"].push_back(std::move(e));
  }
  return j;
}

void write_measurements(const std::string& out_dir, const std::string& set,
                        const std::string& scale, const Measurements& m) {
  std::filesystem::create_directories(out_dir);
  write_file_atomic(out_dir + "/measurements.json", measurements_json(set, scale, m).dump(1) + "\n");
}

MeasurementsFile read_measurements(const std::string& path) {
  const Reader r{path};
  const nlohmann::json j = r.document();
  r.keys(j, "", {"set", "scale", "git_commit", "values"});
  MeasurementsFile out{r.text(j, "", "set"), r.text(j, "", "scale"), r.text(j, "", "git_commit"), {}};
  const auto& values = r.at(j, "", "values");
  if (!values.is_array()) r.fail("values", "must be an array");
  for (size_t i = 0; i < values.size(); ++i) {
    const auto& e = values[i];
    const std::string p = "values[" + std::to_string(i) + "]";
    const Kind k = r.kind(e, p);
    const std::string id = r.text(e, p, "id");
    if (out.m.find(id)) r.fail(p + ".id", "duplicate id '" + id + "'");
    if (k == Kind::scalar) {
      r.keys(e, p, {"id", "kind", "value"});
      out.m.scalar(id, r.num(e, p, "value"));
    } else if (k == Kind::trend) {
      r.keys(e, p, {"id", "kind", "holds", "what"});
      out.m.trend(id, r.flag(e, p, "holds"), r.text(e, p, "what"));
    } else {
      r.keys(e, p, {"id", "kind", "x", "y"});
      Curve c{r.list(e, p, "x"), r.list(e, p, "y")};
      if (c.x.size() != c.y.size()) r.fail(p + ".y", "must have as many points as x");
      out.m.curve(id, std::move(c));
    }
  }
  return out;
}

Baseline make_baseline(const MeasurementsFile& base, const std::vector<MeasurementsFile>& perturbed,
                       const RebaselineRule& rule, const std::string& build,
                       const std::string& created) {
  Baseline b;
  b.set = base.set;
  b.scale = base.scale;
  b.git_commit = base.git_commit;
  b.build = build;
  b.created = created;
  b.perturbed_runs = static_cast<int>(perturbed.size());
  b.method = perturbed.empty()
                 ? "one run, no perturbed reruns: every change beyond the ulp floor is reported"
                 : "one run and " + std::to_string(perturbed.size()) +
                       " reruns with every non-zero float of the scenes moved by one ulp "
                       "(reproduce_<set> --perturb-ulp 1.." + std::to_string(perturbed.size()) + ")";
  const std::string runs = std::to_string(perturbed.size()) + " perturbed run" +
                           (perturbed.size() == 1 ? "" : "s");
  const GateTolerance floor{rule.floor_ulps * kEps, rule.atol_floor};
  const std::string floor_why = fmt("%g", rule.floor_ulps) + " ulp floor (libm differences between CPUs)";
  for (const auto& [id, m0] : base.m.all()) {
    for (const auto& p : perturbed) {
      const Measurement* mk = p.m.find(id);
      if (!mk || mk->kind != m0.kind)
        throw std::runtime_error("rebaseline " + base.set + ": '" + id +
                                 "' is not measured the same way in every perturbed run");
    }
    BaselineValue v;
    v.id = id;
    v.kind = m0.kind;
    v.tol = v.tol_x = floor;
    if (m0.kind == Kind::trend) {
      v.holds = m0.holds;
      int flips = 0;
      for (const auto& p : perturbed) flips += p.m.find(id)->holds != m0.holds ? 1 : 0;
      v.gated = flips == 0;
      v.why = perturbed.empty() ? std::string("must not flip (no perturbed reruns)")
              : v.gated         ? "must not flip (it did not in " + runs + ")"
                      : "flips in " + std::to_string(flips) + " of " + runs +
                            ": round-off decides it, shown but not gated";
    } else if (m0.kind == Kind::scalar) {
      v.value = m0.value;
      double s = 0.0;
      for (const auto& p : perturbed) {
        const double d = max_change({p.m.find(id)->value}, {m0.value});
        s = std::isnan(d) || std::isnan(s) ? kNaN : std::max(s, d);  // std::max drops a NaN
      }
      v.spread = s;
      if (std::isnan(s)) {
        v.gated = false;
        v.why = "finite in some of the " + runs + " and not in others: not gated";
      } else {
        v.tol.atol = std::max(rule.factor * s, rule.atol_floor);
        v.why = perturbed.empty() ? "no perturbed reruns; " + floor_why
                : s == 0.0        ? "unchanged in " + runs + "; " + floor_why
                         : fmt("%g", rule.factor) + " x the largest change in " + runs + " (" +
                               fmt("%.3g", s) + (m0.value != 0 ? ", " + fmt("%.2g", s / std::fabs(m0.value)) + " relative" : "") +
                               "), plus the " + floor_why;
      }
    } else {
      v.curve = m0.curve;
      double sx = 0.0, sy = 0.0;
      bool same_size = true;
      for (const auto& p : perturbed) {
        const Curve& c = p.m.find(id)->curve;
        if (c.x.size() != m0.curve.x.size()) {
          same_size = false;
          continue;
        }
        const double dx = max_change(c.x, m0.curve.x), dy = max_change(c.y, m0.curve.y);
        sx = std::isnan(dx) || std::isnan(sx) ? kNaN : std::max(sx, dx);
        sy = std::isnan(dy) || std::isnan(sy) ? kNaN : std::max(sy, dy);
      }
      v.spread = sy;
      v.spread_x = sx;
      if (!same_size || std::isnan(sx) || std::isnan(sy)) {
        v.gated = false;
        v.why = same_size ? "points finite in some perturbed runs and not in others: not gated"
                          : "its number of points changes under round-off: not gated point by point";
      } else {
        v.tol.atol = std::max(rule.factor * sy, rule.atol_floor);
        v.tol_x.atol = std::max(rule.factor * sx, rule.atol_floor);
        v.why = perturbed.empty() ? "no perturbed reruns; " + floor_why
                : sx == 0.0 && sy == 0.0
                    ? "every point unchanged in " + runs + "; " + floor_why
                    : fmt("%g", rule.factor) + " x the largest pointwise change in " + runs +
                          " (x " + fmt("%.3g", sx) + ", y " + fmt("%.3g", sy) + "), plus the " + floor_why;
      }
    }
    b.values.push_back(std::move(v));
  }
  return b;
}

Json baseline_json(const Baseline& b) {
  Json j{{"set", b.set}, {"scale", b.scale}, {"git_commit", b.git_commit}, {"build", b.build},
         {"created", b.created}, {"method", b.method}, {"perturbed_runs", b.perturbed_runs},
         {"values", Json::array()}};
  for (const auto& v : b.values) {
    Json e{{"id", v.id}, {"kind", to_string(v.kind)}};
    if (v.kind == Kind::scalar) e["value"] = number(v.value);
    if (v.kind == Kind::trend) e["holds"] = v.holds;
    if (v.kind == Kind::curve) {
      e["x"] = list_json(v.curve.x);
      e["y"] = list_json(v.curve.y);
      e["spread_x"] = v.spread_x;
      e["tol_x"] = tolerance_json(v.tol_x);
    }
    if (v.kind != Kind::trend) {
      e["spread"] = number(v.spread);
      e["tol"] = tolerance_json(v.tol);
    }
    e["gated"] = v.gated;
    e["why"] = v.why;
    j["values"].push_back(std::move(e));
  }
  return j;
}

Baseline load_baseline(const std::string& path) {
  const Reader r{path};
  const nlohmann::json j = r.document();
  r.keys(j, "", {"set", "scale", "git_commit", "build", "created", "method", "perturbed_runs", "values"});
  Baseline b;
  b.set = r.text(j, "", "set");
  b.scale = r.text(j, "", "scale");
  b.git_commit = r.text(j, "", "git_commit");
  b.build = r.text(j, "", "build");
  b.created = r.text(j, "", "created");
  b.method = r.text(j, "", "method");
  const auto& n = r.at(j, "", "perturbed_runs");
  if (!n.is_number_integer() || n.get<int>() < 0) r.fail("perturbed_runs", "must be an integer >= 0");
  b.perturbed_runs = n.get<int>();
  const auto& values = r.at(j, "", "values");
  if (!values.is_array()) r.fail("values", "must be an array");
  std::set<std::string> ids;
  for (size_t i = 0; i < values.size(); ++i) {
    const auto& e = values[i];
    const std::string p = "values[" + std::to_string(i) + "]";
    BaselineValue v;
    v.kind = r.kind(e, p);
    v.id = r.text(e, p, "id");
    if (!ids.insert(v.id).second) r.fail(p + ".id", "duplicate id '" + v.id + "'");
    v.gated = r.flag(e, p, "gated");
    v.why = r.text(e, p, "why");
    if (v.why.empty()) r.fail(p + ".why", "must say why the tolerance is what it is");
    if (v.kind == Kind::trend) {
      r.keys(e, p, {"id", "kind", "holds", "gated", "why"});
      v.holds = r.flag(e, p, "holds");
    } else {
      v.spread = r.num(e, p, "spread");
      v.tol = r.tolerance(e, p, "tol");
    }
    if (v.kind == Kind::scalar) {
      r.keys(e, p, {"id", "kind", "value", "spread", "tol", "gated", "why"});
      v.value = r.num(e, p, "value");
    } else if (v.kind == Kind::curve) {
      r.keys(e, p, {"id", "kind", "x", "y", "spread", "spread_x", "tol", "tol_x", "gated", "why"});
      v.curve = {r.list(e, p, "x"), r.list(e, p, "y")};
      if (v.curve.x.size() != v.curve.y.size()) r.fail(p + ".y", "must have as many points as x");
      v.spread_x = r.num(e, p, "spread_x");
      v.tol_x = r.tolerance(e, p, "tol_x");
    }
    b.values.push_back(std::move(v));
  }
  return b;
}

std::string baseline_digest(const Baseline& b) {
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx",
                static_cast<unsigned long long>(fnv1a_64(baseline_json(b)["values"].dump(), kLegacyIdentityOffset)));
  return hex;
}

}  // namespace kolsky::harness
