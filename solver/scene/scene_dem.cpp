// Scene keys of a DEM specimen -> dem::DemSpecimenParams: the packing, the grains, the grain
// contact law the scene selects (specimen.contact_law) with its parameters, the walls, and the
// names of all of them for the physics' errors (dem_keys.hpp).
#include <cstdint>
#include <filesystem>
#include <stdexcept>
#include <type_traits>
#include <variant>

#include "core/errors.hpp"
#include "io/packing_files.hpp"
#include "psd/sampling.hpp"
#include "scene/csv_load.hpp"
#include "scene/dem_keys.hpp"
#include "scene/scene_internal.hpp"

namespace kolsky::scene {

namespace {

namespace fs = std::filesystem;

template <class P>
void read_keys(JsonReader& r, const std::vector<LawKey<P>>& keys, P& p) {
  for (const LawKey<P>& k : keys) p.*k.field = r.number("specimen." + k.key);
}

template <class P>
void read_breakage_keys(JsonReader& r, const std::vector<BreakageKey<P>>& keys, P& p) {
  for (const BreakageKey<P>& k : keys) {
    const std::string path = "specimen.breakage." + k.key;
    std::visit(
        [&](auto field) {
          using T = std::remove_cvref_t<decltype(p.*field)>;
          if constexpr (std::is_same_v<T, bool>) p.*field = r.boolean(path);
          else if constexpr (std::is_same_v<T, int>) p.*field = r.integer(path);
          else p.*field = r.number(path);
        },
        k.field);
  }
}

// Whether the packing will draw any grain (psd::holds_a_grain: the draw of
// psd::sample_diameters with its volume and seed, stopped at the first grain, so its cost does
// not grow with the specimen), so that a specimen too small to hold a grain, or one needing
// more grains than the sampler allows, is refused while the scene is read, under the scene's
// key, before any packing work; the packing's own rules (the largest grain fits twice across,
// RSA finds room) follow in dem/packing.cpp.
void check_packable(JsonReader& r, const dem::PackingParams& p) {
  const double solid = psd::cylinder_volume(p.diameter, p.length) * (1 - p.porosity);
  bool any = false;
  try {
    any = psd::holds_a_grain(p.curve, solid, p.seed);
  } catch (const std::invalid_argument& e) {  // the expected count beyond kMaxSampleGrains
    r.fail("specimen.upscale", std::string(e.what()) + "; a larger specimen.upscale or a "
                               "smaller specimen");
  }
  if (any) return;
  const bool thin = p.diameter <= p.length;
  r.fail(thin ? "specimen.diameter" : "specimen.length",
         "the specimen holds no grain: its solid volume, (1 - porosity) x the cylinder, is " +
             format_number(solid) + " m^3, too small for one grain of the curve (" +
             format_number(p.curve.d_min()) + " to " + format_number(p.curve.d_max()) +
             " m after upscaling); a larger specimen or a smaller specimen.upscale");
}

}  // namespace

dem::DemSpecimenParams read_dem_specimen(JsonReader& r, const std::string& base_dir) {
  dem::DemSpecimenParams d;
  const std::string csv = resolve_csv(r, "specimen.grain_size_curve", base_dir);
  const CsvColumns c = read_two_column_csv(csv, "diameter_m", "percent_passing");
  psd::GrainSizeCurve curve{c.x, c.y};
  try {
    curve.validate();
  } catch (const std::invalid_argument& e) {
    throw InputError(csv, "", e.what());
  }
  d.packing.curve = psd::upscale(curve, r.number("specimen.upscale"));
  d.packing.porosity = r.number("specimen.porosity");
  d.packing.diameter = r.number("specimen.diameter");
  d.packing.length = r.number("specimen.length");
  d.packing.seed = static_cast<std::uint64_t>(r.integer("specimen.seed"));
  check_packable(r, d.packing);
  const std::string procedure = r.text("specimen.packing");
  d.packing.jam = procedure == "jammed";
  d.packing.servo_walls = procedure == "servo_walls";
  d.packing.packing_lock_rotation = r.boolean("specimen.packing_lock_rotation");
  if (d.packing.servo_walls && 1 - d.packing.porosity > 0.64)  // as dem/packing.cpp, up front
    r.fail("specimen.porosity", "servo_walls cannot compact spheres beyond random close packing "
                                "(solid fraction 0.64): porosity must be >= 0.36");
  // Read for every dem scene (a loose packing has no jamming stage to scale).
  if (r.boolean("specimen.packing_density_scaling") && (d.packing.jam || d.packing.servo_walls)) {
    d.packing.jam_mass_scaling = true;
    d.packing.jam_steps_per_stage = dem::kJamScaledStepsPerStage;
  }
  d.packing.jam_friction = r.number("specimen.packing_friction");
  if (std::string cache = r.text("specimen.packing_cache"); !cache.empty()) {
    fs::path cp(cache);  // relative to the scene file's folder, like the CSV paths
    if (cp.is_relative()) cp = fs::path(base_dir.empty() ? "." : base_dir) / cp;
    const std::string folder = fs::absolute(cp).lexically_normal().string();
    d.packing_store = io::packing_files(folder);
    r.resolve("specimen.packing_cache", folder);
  }
  d.walls.hold_until_loaded = r.boolean("specimen.hold_until_loaded");
  d.walls.preload_on_supports = r.boolean("specimen.preload_on_supports");
  d.packing.initial_stress = r.number("specimen.initial_stress");
  if (r.boolean("specimen.relax_to_rest")) d.rest = dem::RestRelaxationParams{};
  const double g = r.number("specimen.grain_shear_modulus");
  const double nu = r.number("specimen.grain_poisson_ratio");
  d.packing.material = dem::Material{2.0 * g * (1.0 + nu), nu, r.number("specimen.grain_density")};

  // The grain law: its name selects the parameter struct (defaults: its initialisers), whose
  // keys are then read; another law's keys stay unread, so JsonReader::finish refuses them.
  d.contact = dem::default_law_params(r.text("specimen.contact_law"));
  std::visit([&](auto& p) { read_keys(r, law_keys(p), p); }, d.contact);
  if (const auto* hm = std::get_if<dem::HertzMindlinParams>(&d.contact)) {
    d.packing.prestress_friction = hm->friction;  // pre-stressed under the test's friction
  } else if (d.packing.initial_stress > 0) {
    // The servo of prestress.cpp drives a Hertz-Mindlin network (its gain is the Hertz
    // estimate of the target overlap), and a packing pre-stressed under Hertz contacts is
    // out of equilibrium under another law; docs/dem.md, Pre-stress.
    r.fail("specimen.initial_stress",
           "a pre-stress needs specimen.contact_law = hertz_mindlin (the pre-stress servo "
           "drives Hertz-Mindlin contacts); set it to 0 for " +
               std::string(dem::kContactLawNames[d.contact.index()]));
  }
  d.options.rolling.factor_per_reference_step = r.number("specimen.rolling_factor");

  dem::LinearParams wall;  // Table 4.1 by default; the same spring on both ends and the tube
  read_keys(r, wall_keys(), wall);
  d.walls.end_law = dem::linear_spring(wall);
  d.walls.tube_law = dem::linear_spring(wall);
  // Pre-stressed against the test's wall springs (docs/dem.md, Pre-stress).
  d.packing.prestress_wall_normal_stiffness = wall.normal_stiffness;
  d.packing.prestress_wall_shear_stiffness = wall.shear_stiffness;
  if (r.has("specimen.breakage")) {  // absent: no breakage, and the resolved scene has none
    const std::string p = "specimen.breakage.";
    dem::BreakageParams b;
    b.criterion = dem::default_criterion(r.text(p + "criterion"));
    std::visit([&](auto& c) { read_breakage_keys(r, breakage_keys(c), c); }, b.criterion);
    read_breakage_keys(r, breakage_limit_keys(), b);
    read_breakage_keys(r, breakage_cadence_keys(), b.cadence);
    b.hardin_threshold *= r.number("specimen.upscale");  // 75 um at the original grain scale
    try {
      dem::validate(b);  // the rules between keys (var range, var_a != 0), before any packing
    } catch (const InputError& e) {
      r.fail(e.path(), e.rule());
    }
    if (!std::holds_alternative<dem::HertzMindlinParams>(d.contact))
      r.fail("specimen.breakage", "needs specimen.contact_law = hertz_mindlin (the breakage criteria read the "
                                  "Hertz overlap: docs/breakage.md)");
    d.breakage = b;
  }
  d.input_names = dem_input_names(d.contact);
  return d;
}

}  // namespace kolsky::scene
