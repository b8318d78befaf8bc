// Scene files: JSON (SI units) parsed once into the typed ExperimentSpec. Unknown keys are
// rejected (with a "did you mean"), defaults live in one table (scene_parameters()), and the
// resolved scene (every parameter, defaults filled in) is kept for the outputs.
// The schema is documented in docs/scene.md; a test checks docs and table agree.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "shpb/analysis.hpp"
#include "shpb/experiment.hpp"
#include "shpb/gauge_processing.hpp"

namespace kolsky::scene {

struct Scene {
  shpb::ExperimentSpec spec;
  nlohmann::json resolved;  ///< the scene with every default filled in
  std::string file;         ///< where it came from ("" if parsed from memory)
};

/// Reads and validates a scene file. Throws InputError(file, json.path, rule).
Scene load_scene(const std::string& path);
/// Validates an in-memory scene; relative CSV paths are resolved against base_dir.
Scene parse_scene(const nlohmann::json& j, const std::string& file, const std::string& base_dir);

/// The BARS.json of `kolsky analyze`: bars, gauge distances, specimen size, processing options.
struct BarsFile {
  shpb::AnalysisSetup setup;
  shpb::GaugeOptions gauge;
  shpb::AnalysisOptions analysis;
  nlohmann::json resolved;
};
BarsFile load_bars_file(const std::string& path);
BarsFile parse_bars_file(const nlohmann::json& j, const std::string& file);

/// One documented parameter. `schema` is "scene" or "bars"; `applies_to` names the variant
/// that uses the key (e.g. "pulse.kind=tabulated"), empty when it always applies.
struct ParamDoc {
  std::string schema, path, type, default_value, unit, description, applies_to;
};
const std::vector<ParamDoc>& parameters();
/// The `kolsky defaults` listing.
std::string format_defaults();

}  // namespace kolsky::scene
