// The DEM specimen's rows of the parameter table (specimen.model = dem): packing, grains, the
// grain contact law and its parameters, rotational resistance, walls. Every default comes from
// a struct initialiser in solver/dem/ (the laws' through dem_keys.cpp).
#include <string>
#include <type_traits>
#include <variant>

#include "dem/dem_specimen_params.hpp"
#include "scene/dem_keys.hpp"
#include "scene/schema_builder.hpp"

namespace kolsky::scene::table {

namespace {

// A law's keys, each used only when `applies` selects it.
template <class P>
void add_keys(TableBuilder& s, const std::vector<LawKey<P>>& keys, const std::string& applies) {
  const P defaults{};
  for (const LawKey<P>& k : keys)
    s.add(VT::number, "specimen." + k.key, defaults.*k.field, k.unit, k.range, k.description,
          applies);
}

// Breakage keys (dem_keys.hpp), each row typed by its field.
template <class P>
void add_breakage_keys(TableBuilder& s, const std::vector<BreakageKey<P>>& keys, const std::string& applies) {
  static const P defaults{};  // static: GCC 12 misreads a local one as uninitialised through the member pointers
  for (const BreakageKey<P>& k : keys) {
    const std::string path = "specimen.breakage." + k.key;
    std::visit(
        [&](auto field) {
          using T = std::remove_cvref_t<decltype(defaults.*field)>;
          const VT type = std::is_same_v<T, bool> ? VT::boolean : std::is_same_v<T, int> ? VT::integer : VT::number;
          s.add(type, path, defaults.*field, k.unit, k.range, k.description, applies);
        },
        k.field);
  }
}

}  // namespace

void add_dem_rows(TableBuilder& s) {
  const dem::PackingParams pack;
  const dem::Material grain;
  const std::string dem = "specimen.model=dem";
  s.add(VT::path, "specimen.grain_size_curve", kRequired, "path", kNoRange,
        "CSV table diameter_m,percent_passing (by mass), before upscaling", dem);
  s.add(VT::number, "specimen.upscale", 1.0, "-", kPositive,
        "Upscaling factor N: every grain size times N (Sec. 4.3, Ch. 5)", dem);
  // The packing places the grains shrunk to a solid fraction (initial_solid_fraction, 0.25)
  // and grows them to size, so 1 - porosity must exceed that fraction (dem/packing.cpp).
  const Range packable{0.0, 1.0 - pack.initial_solid_fraction, true, true};
  s.add(VT::number, "specimen.porosity", pack.porosity, "-", packable,
        "Target porosity of the packing (Sec. 4.3: 0.44); the packing places the grains shrunk "
        "to a solid fraction of " + format_number(pack.initial_solid_fraction) +
            " before growing them to size, hence the upper bound (docs/dem.md, Packing)",
        dem);
  s.add(VT::integer, "specimen.seed", static_cast<int>(pack.seed), "-", kNonNegative,
        "Seed of the grain sampling and placement", dem);
  s.add(VT::choice, "specimen.packing", pack.jam ? "jammed" : "loose", "-", kNoRange,
        "Packing procedure: loose (frictionless growth), jammed (frictional growth: a contact "
        "network at the target porosity) or servo_walls (grains placed loose in a longer "
        "cylinder, the end walls closing on the specimen length under the frictional law; "
        "docs/dem.md, Packing)",
        dem, {"loose", "jammed", "servo_walls"});
  s.add(VT::boolean, "specimen.packing_density_scaling", pack.jam_mass_scaling, "-", kNoRange,
        "Jammed packing with density scaling: no grain lighter than the mean grain while "
        "jamming, " + std::to_string(dem::kJamScaledStepsPerStage) +
            " steps per stage; about 3-4x faster, same porosity, coordination and rattlers "
            "(docs/dem.md, Packing); a loose packing ignores it",
        dem);
  s.add(VT::boolean, "specimen.packing_lock_rotation", pack.packing_lock_rotation, "-", kNoRange,
        "Grains do not rotate while a jammed packing grows or the servo walls compact it (the "
        "pre-stress locks rotation anyway; the run uses specimen.rolling_factor); a loose "
        "packing ignores it (docs/dem.md, Packing)",
        dem);
  s.add(VT::number, "specimen.packing_friction", pack.jam_friction, "-", kNonNegative,
        "Grain-grain friction while a jammed packing grows or the servo walls compact it "
        "(mu_pack; the grains' own: specimen.grain_friction's value): it sets how loose a "
        "contact network the grains lock into; the run uses the contact law's own friction "
        "(docs/dem.md, Packing); a loose packing ignores it",
        dem);
  s.add(VT::string, "specimen.packing_cache", std::string(), "-", kNoRange,
        "Folder (relative to the scene file) where packings are stored by a hash of all packing "
        "parameters and reused; empty = no cache (docs/dem.md, Packing cache)",
        dem);
  s.add(VT::boolean, "specimen.hold_until_loaded", dem::SpecimenWalls{}.hold_until_loaded, "-",
        kNoRange,
        "Hold the grains as packed (no DEM step) until a face moves into the specimen (docs/dem.md)",
        dem);
  s.add(VT::boolean, "specimen.relax_to_rest", false, "-", kNoRange,
        "End the preparation with the grains relaxed to rest between the fixed walls under the "
        "run's own grain law, rolling and wall laws (kinetic damping), and start the run from "
        "that state with its contacts' tangential histories; off: the run starts from the "
        "packing's positions with no tangential history, and a frictional network may fall "
        "apart at rest (docs/dem.md, A specimen at rest)",
        dem);
  s.add(VT::number, "specimen.initial_stress", pack.initial_stress, "Pa", kNonNegative,
        "Isotropic mean stress the packed grains are pre-stressed to before the test (0: none; "
        "hertz_mindlin grains only; docs/dem.md, Pre-stress)",
        dem);
  s.add(VT::boolean, "specimen.preload_on_supports", dem::SpecimenWalls{}.preload_on_supports,
        "-", kNoRange,
        "The bar supports hold the initial wall forces and the gauges are zeroed with them: the "
        "bars carry only the change (docs/dem.md, Pre-stressed specimens)",
        dem);
  s.add(VT::number, "specimen.grain_shear_modulus", grain.shear_modulus(), "Pa", kPositive,
        "Grain shear modulus G (Table 4.1: 30 GPa); E = 2 G (1 + nu)", dem);
  s.add(VT::number, "specimen.grain_poisson_ratio", grain.poisson_ratio, "-", kPoisson,
        "Grain Poisson ratio (Table 4.1: 0.3)", dem);
  s.add(VT::number, "specimen.grain_density", grain.density, "kg/m^3", kPositive,
        "Grain density (G_s = 2.65)", dem);

  // The grain law: its name is the index of the default-constructed parameter variant, so the
  // default law, like every default, is a struct initialiser (dem_specimen_params.hpp).
  std::vector<std::string> laws(dem::kContactLawNames.begin(), dem::kContactLawNames.end());
  s.add(VT::choice, "specimen.contact_law",
        std::string(dem::kContactLawNames[dem::DemSpecimenParams{}.contact.index()]), "-",
        kNoRange,
        "Grain-grain contact law: hertz_mindlin (Sec. 4.3, Eqs. 4.10-4.11, Table 4.1), linear "
        "(PFC-style springs) or ls_dyna_linear (LS-DYNA DES, Sec. 3.3, Eqs. 3.1-3.4, Table 3.2; "
        "its grains there: E = 70 MPa, nu = 0.2)",
        dem, laws);
  for (const std::string& law : laws)  // each law's keys, in the order of the names
    std::visit([&](const auto& p) { add_keys(s, law_keys(p), "specimen.contact_law=" + law); },
               dem::default_law_params(law));

  s.add(VT::number, "specimen.rolling_factor",
        dem::RollingRetardation{}.factor_per_reference_step, "-", kUnitClosed,
        "Rolling retardation k per 1e-9 s step (Eqs. 4.12-4.14; Sec. 4.3: 0.99999975; 1 = none)",
        dem);
  add_keys(s, wall_keys(), dem);
  add_breakage_rows(s, dem);
}

void add_breakage_rows(TableBuilder& s, const std::string& dem) {
  // Particle breakage (Sec. 5.2.3; docs/breakage.md): used only when the specimen.breakage
  // object is present; without it no grain breaks. The criterion's keys apply only to it.
  std::vector<std::string> names(dem::kBreakageCriterionNames.begin(), dem::kBreakageCriterionNames.end());
  s.add(VT::choice, "specimen.breakage.criterion",
        std::string(dem::kBreakageCriterionNames[dem::BreakageParams{}.criterion.index()]), "-", kNoRange,
        "Which grains are loaded past their strength: hertzian_contact (Eq. 5.13, the text's) or "
        "constant_stress (F >= sigma_c d^2, McDowell and Bolton 1998; no chapter uses it; "
        "docs/breakage.md)",
        dem, names);
  for (const std::string& name : names)
    std::visit([&](const auto& c) { add_breakage_keys(s, breakage_keys(c), "specimen.breakage.criterion=" + name); },
               dem::default_criterion(name));
  add_breakage_keys(s, breakage_limit_keys(), dem);
  add_breakage_keys(s, breakage_cadence_keys(), dem);
}

}  // namespace kolsky::scene::table
