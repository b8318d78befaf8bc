// Packing cache: generate_packing once, reuse the result on later runs (docs/dem.md, "Packing
// cache"). A packing is stored as <dir>/packing_<key>.bin, key = 64-bit FNV-1a hash of every
// PackingParams member (the grain-size curve's rows included; the pre-stress members only when
// initial_stress > 0, so unstressed keys are unchanged), the seed and kPackingAlgorithmVersion.
// A pre-stressed packing reuses the cached unstressed one and adds the pre-stress. The file holds the PackingResult scalars and every particle field
// (positions, velocities, forces, radii, masses, material indices) in native binary, so a
// cached packing is bitwise the generated one. Written to a temporary name and renamed, so an
// interrupted or concurrent run never leaves a half file under the final name; a file that
// does not parse (wrong magic, key or size) is regenerated and overwritten.
// Stale entries: bump kPackingAlgorithmVersion whenever generate_packing's output changes.
#pragma once
#include <cstdint>
#include <string>

#include "dem/packing.hpp"

namespace kolsky::dem {

/// Bump when generate_packing's output for the same parameters changes (invalidates caches).
inline constexpr std::uint64_t kPackingAlgorithmVersion = 1;

struct CachedPacking {
  PackingResult result;
  bool from_cache = false;  ///< read from the cache (false: generated now)
  std::string file;         ///< the cache file ("" without a cache directory)
};

/// Hash key of the parameters (hex, 16 digits).
std::string packing_cache_key(const PackingParams& params);

/// generate_packing(params), through the cache directory `dir` ("" = no cache; created if
/// missing). Cache I/O failures fall back to generating (a failed write is not an error).
CachedPacking cached_packing(const PackingParams& params, const std::string& dir);

}  // namespace kolsky::dem
