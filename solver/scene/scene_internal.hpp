// Internal to scene/: what the scene parser's files share (scene.cpp, scene_dem.cpp).
#pragma once
#include <string>

#include "dem/dem_specimen_params.hpp"
#include "scene/json_reader.hpp"

namespace kolsky::scene {

/// Reads the CSV path `key`, resolved against base_dir (relative paths are relative to the
/// scene file's folder); records the absolute path as resolved. InputError if no such file.
std::string resolve_csv(JsonReader& r, const std::string& key, const std::string& base_dir);

/// The DEM specimen (specimen.model = dem; scene_dem.cpp).
dem::DemSpecimenParams read_dem_specimen(JsonReader& r, const std::string& base_dir);

}  // namespace kolsky::scene
