// One scene override "dotted.key=JSON" (the studies' --set, the Chapter 4 driver's
// KOLSKY_CH4_SET): the value parsed as JSON replaces the key, creating the objects on its path;
// the value null removes the key (a key another override makes unused, e.g. the tube_* keys
// of an FE tube set to rigid).
#pragma once
#include <string>

#include <nlohmann/json.hpp>

namespace kolsky::repro {

/// Applies `item` to `scene`; false (scene unchanged) when `item` has no '='. Throws
/// nlohmann::json::parse_error for a value that is not JSON.
inline bool set_scene_key(nlohmann::json& scene, const std::string& item) {
  const auto eq = item.find('=');
  if (eq == std::string::npos) return false;
  const nlohmann::json value = nlohmann::json::parse(item.substr(eq + 1));
  nlohmann::json* at = &scene;
  std::string key = item.substr(0, eq);
  for (auto dot = key.find('.'); dot != std::string::npos; dot = key.find('.')) {
    at = &(*at)[key.substr(0, dot)];
    key = key.substr(dot + 1);
  }
  if (value.is_null()) at->erase(key);
  else (*at)[key] = value;
  return true;
}

}  // namespace kolsky::repro
