#include "scene/scene_change.hpp"

#include <cstdint>
#include <cstdio>

#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "core/hash.hpp"

namespace kolsky::scene {

namespace {

void flatten(const nlohmann::json& patch, const std::string& prefix, std::vector<SceneChange>& out) {
  for (const auto& [k, v] : patch.items()) {
    if (k.empty() || k.find('.') != std::string::npos)
      throw InputError("", prefix + k, "a merge patch key that is empty or holds a '.' cannot be a change");
    if (v.is_object() && !v.empty()) flatten(v, prefix + k + ".", out);
    else out.push_back({prefix + k, v});
  }
}

}  // namespace

SceneChange parse_change(const std::string& item, const std::string& origin) {
  const auto eq = item.find('=');
  if (eq == std::string::npos) throw InputError(origin, item, "a change is written dotted.key=JSON; this has no '='");
  SceneChange ch{item.substr(0, eq), nullptr};
  if (ch.key.empty()) throw InputError(origin, item, "a change needs a key before '='");
  try {
    ch.value = nlohmann::json::parse(item.substr(eq + 1));
  } catch (const nlohmann::json::parse_error&) {
    throw InputError(origin, ch.key, "the value '" + item.substr(eq + 1) + "' is not JSON (a string needs its quotes)");
  }
  return ch;
}

// Each part of the path names a member of an object (a null on the way becomes an object, as
// nlohmann's operator[] makes it). A removal creates nothing: a key that is not there is
// already removed.
void apply_change(nlohmann::json& scene, const SceneChange& ch, const std::string& file) {
  const bool removal = ch.value.is_null();
  nlohmann::json* at = &scene;
  std::string rest = ch.key;
  for (;;) {
    const auto dot = rest.find('.');
    const std::string part = rest.substr(0, dot);
    if (part.empty()) throw InputError(file, ch.key, "a change's dotted key has an empty part");
    if (!at->is_object() && !at->is_null())
      throw InputError(file, ch.key, "a change's path goes through a " + std::string(at->type_name()) +
                                         ", not an object");
    if (dot == std::string::npos) {
      if (!removal) (*at)[part] = ch.value;
      else if (at->is_object()) at->erase(part);
      return;
    }
    if (removal && !(at->is_object() && at->contains(part))) return;
    at = &(*at)[part];
    rest = rest.substr(dot + 1);
  }
}

std::vector<SceneChange> changes_from_patch(const nlohmann::json& patch) {
  if (!patch.is_object()) throw InputError("", "", "a merge patch must be a JSON object");
  std::vector<SceneChange> out;
  flatten(patch, "", out);
  return out;
}

std::string binary_version() {
  return std::string("kolsky ") + build_info::version() + " " + build_info::git_commit();
}

std::string content_key(const nlohmann::json& scene, std::string_view context) {
  nlohmann::json j = scene;
  if (j.contains("specimen") && j["specimen"].is_object()) j["specimen"].erase("packing_cache");
  std::uint64_t h = fnv1a_64(binary_version() + "\n");
  // No context hashes as the reproduction sets' keys always have: they stay what they were.
  if (!context.empty()) h = fnv1a_64("\n", fnv1a_64(context, h));
  h = fnv1a_64(j.dump(), h);
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(h));
  return hex;
}

}  // namespace kolsky::scene
