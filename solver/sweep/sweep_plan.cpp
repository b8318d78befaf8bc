#include "sweep/sweep_plan.hpp"

#include <charconv>
#include <cmath>
#include <filesystem>
#include <set>

#include "core/errors.hpp"
#include "scene/json_reader.hpp"
#include "scene/scene.hpp"
#include "scene/scene_change.hpp"
#include "shpb/simulation.hpp"

namespace kolsky::sweep {

namespace {

constexpr const char* kOrigin = "--set";

// A number written in full (strtod would take "3e9x" as 3e9), and finite.
double range_number(const std::string& text, const std::string& key, const char* which) {
  double v = 0;
  const auto [end, ec] = std::from_chars(text.data(), text.data() + text.size(), v);
  if (text.empty() || ec != std::errc() || end != text.data() + text.size() || !std::isfinite(v))
    throw InputError(kOrigin, key, std::string("a range is lo:hi:count; its ") + which + " '" + text +
                                       "' is not a finite number");
  return v;
}

bool integer_text(const std::string& text) {
  return !text.empty() && text.find_first_not_of("+-0123456789") == std::string::npos;
}

// The text of a --set value: a range when it is three fields apart by ':' (four with log:) and
// not JSON (a JSON string may hold ':').
bool looks_like_range(const std::string& spec) {
  if (spec.rfind("log:", 0) == 0) return true;
  if (spec.empty() || spec.front() == '"' || spec.front() == '[' || spec.front() == '{') return false;
  return spec.find(':') != std::string::npos;
}

}  // namespace

std::vector<nlohmann::json> range_values(const std::string& spec, bool log, const std::string& key) {
  std::vector<std::string> f;
  for (std::size_t at = 0;;) {
    const auto colon = spec.find(':', at);
    f.push_back(spec.substr(at, colon == std::string::npos ? std::string::npos : colon - at));
    if (colon == std::string::npos) break;
    at = colon + 1;
  }
  const std::string form = log ? "log:lo:hi:count" : "lo:hi:count";
  const std::string written = (log ? "log:" : "") + spec;
  if (f.size() != 3) throw InputError(kOrigin, key, "a range is " + form + " (three fields), got '" + written + "'");
  const double lo = range_number(f[0], key, "lo"), hi = range_number(f[1], key, "hi");
  long count = 0;
  const auto [end, ec] = std::from_chars(f[2].data(), f[2].data() + f[2].size(), count);
  if (f[2].empty() || ec != std::errc() || end != f[2].data() + f[2].size() || count < 1 || count > 1000000)
    throw InputError(kOrigin, key, "a range's count must be a whole number from 1 to 1e6, got '" + f[2] + "'");
  if (count == 1 && lo != hi)
    throw InputError(kOrigin, key, "a range of one value needs lo = hi (which end was meant?), got '" + written + "'");
  if (log && !(lo > 0 && hi > 0))
    throw InputError(kOrigin, key, "a log range needs lo > 0 and hi > 0, got '" + written + "'");
  std::vector<double> v(static_cast<std::size_t>(count));
  for (long k = 0; k < count; ++k) {
    const double s = count == 1 ? 0.0 : static_cast<double>(k) / static_cast<double>(count - 1);
    v[static_cast<std::size_t>(k)] = log ? lo * std::pow(hi / lo, s) : lo + (hi - lo) * s;
  }
  v.back() = hi;  // the end as written, not as rounded
  v.front() = lo;
  bool whole = integer_text(f[0]) && integer_text(f[1]);
  for (double x : v) whole = whole && x == std::round(x) && std::abs(x) < 9e15;
  std::vector<nlohmann::json> out;
  for (double x : v) out.push_back(whole ? nlohmann::json(static_cast<long long>(x)) : nlohmann::json(x));
  return out;
}

SweepAxis parse_axis(const std::string& item) {
  const auto eq = item.find('=');
  if (eq == std::string::npos)
    throw InputError(kOrigin, item, "a sweep key is written --set KEY=VALUES; this has no '='");
  SweepAxis a;
  a.key = item.substr(0, eq);
  if (a.key.empty()) throw InputError(kOrigin, item, "a sweep key needs a name before '='");
  const std::string spec = item.substr(eq + 1);
  if (looks_like_range(spec)) {
    a.log_spaced = spec.rfind("log:", 0) == 0;
    a.values = range_values(a.log_spaced ? spec.substr(4) : spec, a.log_spaced, a.key);
    return a;
  }
  const nlohmann::json v = scene::parse_change(item, kOrigin).value;  // its rules and message
  if (v.is_array()) {
    if (v.empty()) throw InputError(kOrigin, a.key, "the list of values is empty: the sweep would have no member");
    a.values.assign(v.begin(), v.end());
  } else {
    a.values = {v};
  }
  return a;
}

SweepPlan make_plan(const std::string& scene_file, std::vector<SweepAxis> axes, int seeds) {
  SweepPlan p;
  p.scene_file = scene_file;
  p.scene = scene::read_json_file(scene_file);
  std::set<std::string> keys;
  for (const SweepAxis& a : axes) {
    if (!keys.insert(a.key).second) throw InputError(kOrigin, a.key, "the key is given twice");
    if (seeds > 0 && a.key == kSeedKey)
      throw InputError(kOrigin, a.key, "--seeds varies specimen.seed already: give one or the other");
  }
  p.axes = std::move(axes);
  p.seeds = seeds;
  return p;
}

std::vector<SweepPoint> sweep_points(const SweepPlan& plan) {
  double members = plan.seeds > 0 ? plan.seeds : 1;
  for (const SweepAxis& a : plan.axes) members *= static_cast<double>(a.values.size());
  if (members > kMostMembers)
    throw InputError(kOrigin, plan.axes.empty() ? std::string(kSeedKey) : plan.axes.front().key,
                     "the sweep would have " + value_text(members) + " members, more than " +
                         value_text(kMostMembers) + ": split it");
  std::vector<SweepPoint> out(1);
  for (const SweepAxis& a : plan.axes) {
    if (a.values.empty()) throw InputError(kOrigin, a.key, "no values: the sweep would have no member");
    std::vector<SweepPoint> next;
    for (const SweepPoint& p : out)
      for (const nlohmann::json& v : a.values) {
        SweepPoint q = p;
        q.values.push_back(v);
        q.label += (q.label.empty() ? "" : " ") + a.key + "=" + value_text(v);
        next.push_back(std::move(q));
      }
    out = std::move(next);
  }
  if (plan.seeds <= 0) return out;
  std::vector<SweepPoint> seeded;
  for (const SweepPoint& p : out)
    for (int s = 1; s <= plan.seeds; ++s) {
      SweepPoint q = p;
      q.seed = s;
      q.label += (q.label.empty() ? "" : " ") + std::string("seed=") + std::to_string(s);
      seeded.push_back(std::move(q));
    }
  return seeded;
}

nlohmann::json member_scene(const SweepPlan& plan, const SweepPoint& point) {
  nlohmann::json j = plan.scene;
  for (std::size_t k = 0; k < plan.axes.size(); ++k)
    scene::apply_change(j, {plan.axes[k].key, point.values.at(k)}, plan.scene_file);
  if (point.seed > 0) scene::apply_change(j, {kSeedKey, point.seed}, plan.scene_file);
  return j;
}

std::string scene_folder(const SweepPlan& plan) {
  return std::filesystem::absolute(plan.scene_file).parent_path().string();
}

void validate_points(const SweepPlan& plan, const std::vector<SweepPoint>& points) {
  const std::string dir = scene_folder(plan);
  for (const SweepPoint& p : points) {
    try {
      const scene::Scene sc = scene::parse_scene(member_scene(plan, p), plan.scene_file, dir);
      shpb::require_reachable_end(sc.spec);
    } catch (const InputError& e) {
      const std::string file = e.file().empty() ? plan.scene_file : e.file();
      throw InputError(file, e.path(), e.rule() + " (sweep member " + p.label + ")");
    }
  }
}

std::string value_text(const nlohmann::json& v) {
  if (v.is_string()) return v.get<std::string>();
  if (v.is_number_float()) {
    char buf[32];
    const auto r = std::to_chars(buf, buf + sizeof buf, v.get<double>());
    return std::string(buf, r.ptr);
  }
  return v.dump();
}

}  // namespace kolsky::sweep
