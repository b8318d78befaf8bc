// Round-off perturbation of a scene, for measuring how far round-off can move a reproduced
// number (the regression gate's tolerances, docs/reproductions.md "Regression gate").
// Every non-zero floating-point number of the scene JSON moves by one ulp, up or down as a hash
// of (seed, JSON path) decides; integers (counts, seeds, element numbers) and zeros stay as
// written. This is the size of difference a reordered sum or another libm makes, fed in at the
// inputs: a deterministic computation answers with its condition number, a chaotic one (DEM)
// with the spread that round-off alone can reach.
#pragma once
#include "core/errors.hpp"
#include "core/hash.hpp"
#include "scene/scene.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <stdexcept>
#include <string>

namespace kolsky::repro {

namespace detail {

/// FNV-1a over the path, mixed with the seed (splitmix64 finaliser): stable across builds.
inline std::uint64_t path_hash(unsigned seed, const std::string& path) {
  std::uint64_t h = fnv1a_64(path, kLegacyIdentityOffset);
  h ^= 0x9e3779b97f4a7c15ull * (seed + 1ull);
  h = (h ^ (h >> 30)) * 0xbf58476d1ce4e5b9ull;
  h = (h ^ (h >> 27)) * 0x94d049bb133111ebull;
  return h ^ (h >> 31);
}

/// The value one ulp from v, up or down.
inline double ulp_step(double v, bool up) {
  return std::nextafter(v, up ? std::numeric_limits<double>::infinity()
                              : -std::numeric_limits<double>::infinity());
}

// Paths as the scene reader writes them in its errors: "time.end", "bars.gauges[1]".
inline std::string child(const std::string& path, const std::string& key) {
  return path.empty() ? key : path + "." + key;
}

inline void perturb_at(nlohmann::json& j, unsigned seed, const std::string& path,
                       std::map<std::string, std::pair<double, bool>>* moved) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) perturb_at(it.value(), seed, child(path, it.key()), moved);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i)
      perturb_at(j[i], seed, path + "[" + std::to_string(i) + "]", moved);
  } else if (j.is_number_float()) {
    const double v = j.get<double>();
    if (v == 0.0 || !std::isfinite(v)) return;
    const bool up = (path_hash(seed, path) & 1u) != 0;
    j = ulp_step(v, up);
    if (moved) (*moved)[path] = {v, up};
  }
}

inline nlohmann::json& at_path(nlohmann::json& j, const std::string& path) {
  nlohmann::json* node = &j;
  std::size_t i = 0;
  while (i < path.size()) {
    if (path[i] == '.') ++i;
    if (path[i] == '[') {
      const std::size_t end = path.find(']', i);
      node = &(*node)[std::stoul(path.substr(i + 1, end - i - 1))];
      i = end + 1;
    } else {
      const std::size_t end = std::min(path.find('.', i), path.find('[', i));
      node = &(*node)[path.substr(i, end - i)];
      i = end == std::string::npos ? path.size() : end;
    }
  }
  return *node;
}

}  // namespace detail

/// Moves every non-zero float of j by one ulp (seed 0: j unchanged). Deterministic in seed.
inline void perturb_floats(nlohmann::json& j, unsigned seed) {
  if (seed != 0) detail::perturb_at(j, seed, "", nullptr);
}

/// Reads a scene JSON and applies perturb_floats(seed). A value written at the edge of its range
/// (a safety factor of exactly 1 in (0, 1]) that the step pushed outside is stepped the other
/// way instead: the scene is validated by the scene reader and each value the reader refuses is
/// moved inward. Throws what the reader throws for a scene that is invalid as written.
inline nlohmann::json read_scene_json(const std::string& path, unsigned seed) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error(path + ": cannot be read");
  const nlohmann::json written = nlohmann::json::parse(f);
  if (seed == 0) return written;
  nlohmann::json j = written;
  std::map<std::string, std::pair<double, bool>> moved;
  detail::perturb_at(j, seed, "", &moved);
  const std::string dir = std::filesystem::absolute(path).parent_path().string();
  for (std::size_t tries = 0; tries <= moved.size(); ++tries) {
    try {
      scene::parse_scene(j, path, dir);
      return j;
    } catch (const InputError& e) {
      auto it = moved.find(e.path());
      if (it == moved.end()) throw;  // not a perturbed value: the scene itself is refused
      auto& [was, up] = it->second;
      up = !up;
      detail::at_path(j, it->first) = detail::ulp_step(was, up);
      moved.erase(it);  // flipped once; a second refusal is the scene's own problem
    }
  }
  return j;
}

}  // namespace kolsky::repro
