// Packing cache: generate_packing once, reuse the result on later runs (docs/dem.md, "Packing
// cache"). A packing is stored under a key, the 64-bit FNV-1a hash of every PackingParams member
// (the grain-size curve's rows included; the pre-stress members only when initial_stress > 0, so
// unstressed keys are unchanged), the seed and kPackingAlgorithmVersion. A pre-stressed packing
// reuses the stored unstressed one and adds the pre-stress. Where and how a packing is stored is
// the store's business (PackingStore: io/packing_files.hpp keeps one file per key in a folder);
// this module only decides what is looked up and what is generated, so that the physics does
// no file I/O. Stale entries: bump kPackingAlgorithmVersion whenever generate_packing's output
// changes.
#pragma once
#include <cstdint>
#include <functional>
#include <string>

#include "dem/packing.hpp"

namespace kolsky::dem {

/// Bump when generate_packing's output for the same parameters changes (invalidates caches).
inline constexpr std::uint64_t kPackingAlgorithmVersion = 1;

/// Where packings are kept. Empty functions: no store (every packing is generated).
/// load(key, out): true and `out` set when a packing of that key is stored and readable (a
/// damaged entry reads as absent); save(key, r): keeps r (a failed save is not an error);
/// name(key): where that key lives, for messages.
struct PackingStore {
  std::function<bool(const std::string& key, PackingResult& out)> load;
  std::function<void(const std::string& key, const PackingResult& r)> save;
  std::function<std::string(const std::string& key)> name;
  explicit operator bool() const { return static_cast<bool>(load); }
};

struct CachedPacking {
  PackingResult result;
  bool from_cache = false;  ///< read from the store (false: generated now)
  std::string file;         ///< the store's name for the key ("" without a store)
};

/// Hash key of the parameters (hex, 16 digits).
std::string packing_cache_key(const PackingParams& params);

/// generate_packing(params), through the store (none: generated). A stored result is returned
/// bitwise as generated, with target_porosity taken from params.
CachedPacking cached_packing(const PackingParams& params, const PackingStore& store);

}  // namespace kolsky::dem
