// BARS.json of `kolsky analyze` -> BarsFile (analysis setup, gauge-processing and analysis
// options). Defaults and ranges come from the "bars" rows of the parameter table
// (scene/schema.cpp); only the cross-key geometry rule lives here.
#include <algorithm>

#include "scene/json_reader.hpp"
#include "scene/scene.hpp"

namespace kolsky::scene {

namespace {

shpb::AnalysisBar read_bar(JsonReader& r, const std::string& side) {
  const std::string p = side + ".";
  shpb::AnalysisBar b;
  b.youngs_modulus = r.number(p + "youngs_modulus");
  b.density = r.number(p + "density");
  b.poisson_ratio = r.number(p + "poisson_ratio");
  b.diameter = r.number(p + "diameter");
  b.gauge_distance = r.number(p + "gauge_distance");
  return b;
}

}  // namespace

BarsFile parse_bars_file(const nlohmann::json& j, const std::string& file) {
  JsonReader r(j, file, "bars");
  BarsFile f;
  f.setup.incident = read_bar(r, "incident");
  f.setup.transmission = read_bar(r, "transmission");
  f.setup.specimen_length = r.number("specimen.length");
  f.setup.specimen_diameter = r.number("specimen.diameter");
  // Same consistency rule as the scene: a specimen wider than 4 bar diameters is a unit slip.
  const double bar_d = std::min(f.setup.incident.diameter, f.setup.transmission.diameter);
  if (f.setup.specimen_diameter > 4.0 * bar_d)
    r.fail("specimen.diameter",
           "inconsistent geometry: specimen diameter " + format_number(f.setup.specimen_diameter) +
               " m exceeds 4 x the bar diameter (" + format_number(bar_d) + " m)");
  f.gauge.threshold_fraction = r.number("processing.threshold_fraction");
  f.gauge.noise_sigmas = r.number("processing.noise_sigmas");
  f.gauge.pretrigger_fraction = r.number("processing.pretrigger_fraction");
  f.gauge.dispersion_correction = r.boolean("processing.dispersion_correction");
  f.gauge.duration = r.number("processing.duration");
  f.analysis.alpha_floor_fraction = r.number("processing.alpha_floor_fraction");
  r.finish();
  f.resolved = r.resolved();
  return f;
}

BarsFile load_bars_file(const std::string& path) {
  return parse_bars_file(read_json_file(path), path);
}

}  // namespace kolsky::scene
