// The packing cache's file store (dem/packing_cache.hpp): one file per key,
// <dir>/packing_<key>.bin, holding the PackingResult scalars and every particle field
// (positions, velocities, forces, radii, masses, material indices) in native binary, so a
// stored packing is bitwise the generated one. Written to a temporary name and renamed
// (core/atomic_file.hpp), so an interrupted or concurrent run never leaves a half file under the
// final name; a file that does not parse (wrong magic, key or size) reads as absent, and the
// packing is regenerated and the file overwritten. Format 002 adds the pre-stress results after
// the scalars; 001 files (no pre-stress) are still read.
#pragma once
#include <string>

#include "dem/packing_cache.hpp"

namespace kolsky::io {

/// The store in folder `dir` (created at the first save; "" gives the empty store: no cache).
dem::PackingStore packing_files(const std::string& dir);

}  // namespace kolsky::io
