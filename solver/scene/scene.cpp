// Scene file -> shpb::ExperimentSpec. Each key is read through JsonReader, which takes its
// default and range from the parameter table (scene/schema.cpp); this file adds only the rules
// that involve several keys (gauges inside the bar, rise + fall <= duration, geometry) and
// loads the referenced CSV tables.
#include "scene/scene.hpp"

#include <algorithm>
#include <cstdint>
#include <filesystem>
#include <stdexcept>

#include "bar/material.hpp"
#include "core/errors.hpp"
#include "scene/csv_load.hpp"
#include "scene/json_reader.hpp"
#include "scene/scene_internal.hpp"

namespace kolsky::scene {

namespace fs = std::filesystem;

/// Relative CSV paths are relative to the scene file's folder, so a scene can be run from
/// anywhere; the absolute path is what the resolved scene records.
std::string resolve_csv(JsonReader& r, const std::string& key, const std::string& base_dir) {
  fs::path p(r.text(key));
  if (p.is_relative()) p = fs::path(base_dir.empty() ? "." : base_dir) / p;
  const std::string abs = fs::absolute(p).lexically_normal().string();
  std::error_code ec;
  if (!fs::is_regular_file(abs, ec)) r.fail(key, "no such file: " + abs);
  r.resolve(key, abs);
  return abs;
}

namespace {

std::string show(double v) { return format_number(v); }

constexpr std::size_t kMaxGaugesPerBar = 1000;

void check_gauges(JsonReader& r, const std::string& prefix, const shpb::BarSpec& b,
                  shpb::BarKind kind) {
  const double length = b.geometry.length, d = b.geometry.diameter;
  for (size_t i = 0; i < b.gauges.size(); ++i) {
    const std::string key = prefix + "gauges[" + std::to_string(i) + "]";
    const double g = b.gauges[i];
    if (!(g > 0.0 && g < length))
      r.fail(key, "gauge at " + show(g) +
                      " m lies outside the bar: the distance from the "
                      "specimen face must be strictly between 0 and the bar length " +
                      show(length) + " m");
    if (kind != shpb::BarKind::sphere_chain) continue;
    // A chain gauge interpolates between contacts; within one ball of an end there is no
    // contact pair on both sides of it.
    const int n = b.n_spheres > 0 ? b.n_spheres : bar::sphere_count(length, d);
    const double chain = std::min(length, n * d);
    if (g < d || g > chain - d)
      r.fail(key, "sphere-chain gauges must be at least one ball diameter (" + show(d) +
                      " m) from either end of the chain, i.e. in [" + show(d) + ", " +
                      show(chain - d) + "] m; got " + show(g));
  }
}

shpb::BarSpec read_bar(JsonReader& r, const std::string& side, shpb::BarKind kind) {
  const std::string p = "bars." + side + ".";
  shpb::BarSpec b;
  b.geometry.length = r.number(p + "length");
  b.geometry.diameter = r.number(p + "diameter");
  b.material.youngs_modulus = r.number(p + "youngs_modulus");
  b.material.density = r.number(p + "density");
  b.material.poisson_ratio = r.number(p + "poisson_ratio");
  if (r.has(p + "gauges")) {
    b.gauges = r.numbers(p + "gauges");
    // Each gauge is a probe sampled at every output step, in memory and in the run file:
    // 200,000 gauges wrote 1.7 GB. A bar study needs tens; the limit leaves room for a gauge
    // every 5 mm along a 5 m bar.
    if (b.gauges.size() > kMaxGaugesPerBar)
      r.fail(p + "gauges", "at most " + std::to_string(kMaxGaugesPerBar) +
                               " gauges per bar (each is a probe of the run file), got " +
                               std::to_string(b.gauges.size()));
  } else {
    b.gauges = {0.5 * b.geometry.length};  // the table documents this as [length/2]
    r.resolve(p + "gauges", b.gauges);
  }
  if (kind == shpb::BarKind::sphere_chain) {
    b.n_spheres = r.integer(p + "n_spheres");
    const int automatic = bar::sphere_count(b.geometry.length, b.geometry.diameter);
    if (b.n_spheres == 0 && automatic < 4)
      r.fail(p + "length", "a sphere-chain bar needs at least 4 balls; length/diameter = " +
                               show(b.geometry.length / b.geometry.diameter) + " gives " +
                               std::to_string(automatic));
  }
  check_gauges(r, p, b, kind);
  return b;
}

bar::Pulse read_pulse(JsonReader& r, const std::string& base_dir) {
  const std::string kind = r.text("pulse.kind");
  const double delay = r.number("pulse.delay");
  if (kind == "trapezoid") {
    bar::TrapezoidPulse t;
    t.amplitude = r.number("pulse.amplitude");
    t.rise_time = r.number("pulse.rise_time");
    t.fall_time = r.number("pulse.fall_time");
    t.duration = r.number("pulse.duration");
    t.delay = delay;
    // Relative slack of 1e-12: 0.1e-3 + 0.2e-3 exceeds 0.3e-3 by one rounding error.
    if (t.rise_time + t.fall_time > t.duration * (1.0 + 1e-12))
      r.fail("pulse.duration", "rise_time + fall_time (" + show(t.rise_time + t.fall_time) +
                                   " s) must not exceed duration (" + show(t.duration) + " s)");
    return t;
  }
  if (kind == "half_sine") {
    bar::HalfSinePulse h;
    h.amplitude = r.number("pulse.amplitude");
    h.duration = r.number("pulse.duration");
    h.delay = delay;
    return h;
  }
  bar::TabulatedPulse tab;
  tab.table = load_pulse_table(resolve_csv(r, "pulse.file", base_dir));
  tab.scale = r.number("pulse.scale");
  tab.delay = delay;
  return tab;
}

fe::FeSpecimenParams read_fe_specimen(JsonReader& r, const std::string& base_dir) {
  fe::FeSpecimenParams f;
  f.length = r.number("specimen.length");
  f.radius = 0.5 * r.number("specimen.diameter");
  f.n_r = r.integer("specimen.n_radial");
  f.n_z = r.integer("specimen.n_axial");
  fe::PseudoTensorModeI m;
  m.density = r.number("specimen.density");
  m.shear_modulus = r.number("specimen.shear_modulus");
  m.friction_angle_deg = r.number("specimen.friction_angle");
  m.cohesion = r.number("specimen.cohesion");
  m.eos.loading = load_loading_curve(resolve_csv(r, "specimen.loading_curve", base_dir));
  m.eos.unloading_bulk_modulus = r.number("specimen.unloading_modulus");
  try {  // the EOS rules (e.g. unloading modulus >= every loading slope) at parse time
    m.validate("specimen");
  } catch (const kolsky::InputError& e) {
    const bool unloading = e.path().find("unloading") != std::string::npos;
    r.fail(unloading ? "specimen.unloading_modulus" : "specimen.loading_curve", e.rule());
  }
  f.material = m;
  const fe::LinearElastic tube{r.number("specimen.tube_youngs_modulus"),
                               r.number("specimen.tube_poisson_ratio"),
                               r.number("specimen.tube_density")};
  const std::string tube_kind = r.text("specimen.tube");
  const double thickness = r.number("specimen.tube_thickness");
  const double tube_length = r.number("specimen.tube_length");
  if (tube_kind == "none") f.tube = fe::NoTube{};
  else if (tube_kind == "rigid") f.tube = fe::RigidTube{};
  else if (tube_kind == "spring") f.tube = fe::SpringTube{tube, thickness};
  else {
    if (tube_length < f.length)
      r.fail("specimen.tube_length", "the meshed tube must be at least as long as the specimen");
    fe::MeshedTube t;
    t.material = tube;
    t.thickness = thickness;
    t.length = tube_length;
    f.tube = t;
  }
  f.friction_faces = r.number("specimen.friction_faces");
  f.friction_tube = r.number("specimen.friction_tube");
  f.penalty_scale = r.number("specimen.penalty_scale");
  f.contact_damping = r.number("specimen.contact_damping");
  return f;
}

shpb::SpecimenSpec read_specimen(JsonReader& r, const std::string& base_dir) {
  const std::string model = r.text("specimen.model");
  if (model == "fe") return read_fe_specimen(r, base_dir);
  if (model == "dem") return read_dem_specimen(r, base_dir);
  bar::ColumnParams c;
  c.length = r.number("specimen.length");
  c.diameter = r.number("specimen.diameter");
  c.density = r.number("specimen.density");
  c.n_elements = r.integer("specimen.n_elements");
  if (model == "elastic") {
    c.material = bar::LinearElastic{r.number("specimen.constrained_modulus")};
  } else {
    bar::TabulatedCompaction m;
    m.loading = load_loading_curve(resolve_csv(r, "specimen.loading_curve", base_dir));
    m.unloading_modulus = r.number("specimen.unloading_modulus");
    c.material = m;
  }
  return c;
}

// specimen.tube with a dem specimen (docs/coupling.md): rigid, the grains' own cylinder (the
// default; not resolved when absent, so DEM scenes keep their resolved form); spring, the
// cylinder's radial mode with the thick tube's Lame stiffness per wall area and the tube's
// mass over the specimen length (dem::TubeCompliance); or meshed, an FE tube (bars.kind =
// meshed: the FE-DEM coupling; characteristic: coupling::FeTube).
void read_dem_tube(JsonReader& r, shpb::ExperimentSpec& e) {
  if (!r.has("specimen.tube")) return;
  const std::string kind = r.text("specimen.tube");
  if (kind == "rigid") return;
  if (kind != "meshed" && kind != "spring")
    r.fail("specimen.tube", "'" + kind + "' is not a tube of a dem specimen: rigid, spring or meshed");
  const fe::LinearElastic material{r.number("specimen.tube_youngs_modulus"), r.number("specimen.tube_poisson_ratio"),
                                   r.number("specimen.tube_density")};
  const double thickness = r.number("specimen.tube_thickness");
  if (kind == "spring") {
    if (e.bar_kind == shpb::BarKind::meshed && !e.strain_rate)
      r.fail("specimen.tube", "a spring tube around a dem specimen is not supported with bars.kind = meshed "
                              "(the FE-DEM coupling needs a rigid or meshed tube)");
    auto& d = std::get<dem::DemSpecimenParams>(e.specimen);
    const double radius = 0.5 * shpb::specimen_diameter(e.specimen);
    d.walls.tube_compliance = dem::TubeCompliance{material.youngs_modulus, thickness, material.density,
                                                  shpb::specimen_length(e.specimen),
                                                  fe::lame_wall_stiffness(material, radius, thickness)};
    return;
  }
  if (e.strain_rate || e.bar_kind == shpb::BarKind::sphere_chain)
    r.fail("specimen.tube", "a meshed tube around a dem specimen needs bars.kind = meshed (the FE-DEM "
                            "coupling) or characteristic (coupling/fe_tube.hpp), docs/coupling.md");
  fe::MeshedTube t;
  t.material = material;
  t.thickness = thickness;
  t.length = r.number("specimen.tube_length");
  if (t.length < shpb::specimen_length(e.specimen))
    r.fail("specimen.tube_length", "the meshed tube must be at least as long as the specimen");
  e.dem_tube = t;
}

shpb::TimeSpec read_time(JsonReader& r, const shpb::SpecimenSpec& specimen, bool walls) {
  shpb::TimeSpec t;
  t.end_time = r.number("time.end");
  t.dt = r.number("time.dt");
  if (r.has("time.safety_factor")) {
    t.safety_factor = r.number("time.safety_factor");
  } else {
    t.safety_factor = shpb::default_safety_factor(specimen);  // documented in the table
    r.resolve("time.safety_factor", t.safety_factor);
  }
  t.check_stability = r.boolean("time.check_stability");
  t.refine_after_breaks = r.boolean("time.refine_after_breaks");
  if (r.has("time.energy_tolerance")) {
    t.energy_tolerance = r.number("time.energy_tolerance");
  } else {  // documented in the table: the walls judge against their own work (experiment.hpp)
    t.energy_tolerance = walls ? shpb::kWallsEnergyTolerance : t.energy_tolerance;
    r.resolve("time.energy_tolerance", t.energy_tolerance);
  }
  return t;
}

// loading.kind = strain_rate (Sec. 5.2.1, methodology 1): the walls replace the bars and the
// pulse, so their keys would be silently unused; they are refused, naming the key.
shpb::StrainRateHistory read_strain_rate_loading(JsonReader& r, const std::string& base_dir) {
  for (const char* unused : {"bars", "pulse"})
    if (r.has(unused))
      r.fail(unused, std::string("'") + unused + "' is unused with loading.kind = strain_rate "
                     "(the walls replace the bars and the pulse, Sec. 5.2.1); remove it");
  const std::string csv = resolve_csv(r, "loading.file", base_dir);
  const Table1D t = load_strain_rate_table(csv);
  try {
    return shpb::StrainRateHistory(t.x, t.y);
  } catch (const InputError& e) {  // load_strain_rate_table checks the same rules first
    throw InputError(csv, "", e.rule());
  }
}

void read_bars_and_pulse(JsonReader& r, const std::string& base_dir, shpb::ExperimentSpec& e) {
  const std::string kind = r.text("bars.kind");
  e.bar_kind = kind == "sphere_chain" ? shpb::BarKind::sphere_chain
               : kind == "meshed"     ? shpb::BarKind::meshed
                                      : shpb::BarKind::characteristic;
  if (e.bar_kind == shpb::BarKind::meshed) {
    e.bar_mesh.n_radial = r.integer("bars.mesh_radial");
    e.bar_mesh.element_length = r.number("bars.element_length");
  }
  e.incident = read_bar(r, "incident", e.bar_kind);
  e.transmission = read_bar(r, "transmission", e.bar_kind);
  e.pulse = read_pulse(r, base_dir);
}

}  // namespace

Scene parse_scene(const nlohmann::json& j, const std::string& file, const std::string& base_dir) {
  JsonReader r(j, file, "scene");
  Scene s;
  s.file = file;
  shpb::ExperimentSpec& e = s.spec;
  e.title = r.text("title");
  const bool walls = r.text("loading.kind") == "strain_rate";
  if (walls) {
    e.strain_rate = read_strain_rate_loading(r, base_dir);
    e.end_at_back_stress = r.number("loading.end_at_back_stress");
  } else read_bars_and_pulse(r, base_dir, e);
  e.specimen = read_specimen(r, base_dir);
  const auto* dem_specimen = std::get_if<dem::DemSpecimenParams>(&e.specimen);
  if (walls) {
    // The assembly owns a DemSpecimen (shpb/strain_rate_walls.hpp) and there are no supports.
    if (!dem_specimen)
      r.fail("specimen.model", "loading.kind = strain_rate needs specimen.model = dem");
    if (dem_specimen->walls.preload_on_supports)
      r.fail("specimen.preload_on_supports",
             "there are no bar supports with loading.kind = strain_rate: set it to false");
  } else {
    // Beyond 4 bar diameters the 1-D bar/specimen coupling (uniform face stress) is
    // meaningless and such a value is almost always a unit slip (mm typed as m).
    const double bar_d = std::min(e.incident.geometry.diameter, e.transmission.geometry.diameter);
    if (shpb::specimen_diameter(e.specimen) > 4.0 * bar_d)
      r.fail("specimen.diameter", "inconsistent geometry: specimen diameter " +
                                      show(shpb::specimen_diameter(e.specimen)) +
                                      " m exceeds 4 x the bar diameter (" + show(bar_d) + " m)");
  }
  e.time = read_time(r, e.specimen, walls);
  e.output.interval = r.number("output.interval");
  if (dem_specimen) e.output.snapshot_interval = r.number("output.snapshot_interval");
  if (dem_specimen) read_dem_tube(r, e);
  if (dem_specimen && !walls && (e.bar_kind == shpb::BarKind::meshed || e.dem_tube)) {
    try {  // what the FE-DEM coupling or the FE tube refuses, named with the scene file
      if (e.bar_kind == shpb::BarKind::meshed) shpb::check_fe_dem_supported(e);
      else shpb::check_fe_tube_supported(e);
    } catch (const InputError& err) {
      r.fail(err.path(), err.rule());
    }
  }
  r.finish();
  s.resolved = r.resolved();
  return s;
}

Scene load_scene(const std::string& path) {
  const nlohmann::json j = read_json_file(path);
  return parse_scene(j, path, fs::absolute(path).parent_path().string());
}

}  // namespace kolsky::scene
