// Contact laws and walls from the scene (docs/scene.md, docs/dem.md "Contact laws"): each law of
// kContactLawNames is selectable by specimen.contact_law and its parameters reach the law (the
// two-grain stiffness and stable step equal the law's closed form: Hertz, Sec. 4.3; linear;
// LS-DYNA Eqs. 3.1-3.2 with Table 3.2, K_n = 612.5 N/m for r = 0.15 mm, targets 3a); an
// unknown name is refused with exit 2; `kolsky defaults` lists every law parameter with its
// struct's default; an error from inside the physics names the scene key; the wall slot rule.
#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <numbers>
#include <random>
#include <string>

#include "core/errors.hpp"
#include "dem/dem_specimen_params.hpp"
#include "dem/dem_system.hpp"
#include "scene/json_reader.hpp"
#include "scene/scene.hpp"
#include "scene/schema.hpp"

namespace {

namespace fs = std::filesystem;
using kolsky::InputError;
using nlohmann::json;
using namespace kolsky::dem;
using namespace kolsky::scene;

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

class SceneLaws : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = fs::temp_directory_path() / ("kolsky_test_laws_" + std::to_string(std::random_device{}()));
    fs::create_directories(dir_);
    std::ofstream(dir_ / "psd.csv") << "diameter_m,percent_passing\n1e-4,0\n3e-4,50\n6e-4,100\n";
  }
  void TearDown() override { fs::remove_all(dir_); }

  /// A small DEM scene (~70 grains: the curve x 3 in a 6 x 4 mm cylinder) with extra keys.
  static json dem_scene(const json& specimen_keys) {
    json j = json::parse(R"({
      "bars": {"incident": {"length": 0.6, "gauges": [0.3]}, "transmission": {"length": 0.4}},
      "pulse": {"kind": "trapezoid", "amplitude": 20e6, "duration": 200e-6},
      "specimen": {"model": "dem", "grain_size_curve": "psd.csv", "upscale": 3,
                   "length": 0.004, "diameter": 0.006},
      "time": {"end": 2e-4}})");
    if (specimen_keys.is_object()) j["specimen"].update(specimen_keys);
    return j;
  }
  DemSpecimenParams dem_params(const json& j) {
    return std::get<DemSpecimenParams>(parse_scene(j, "scene.json", dir_.string()).spec.specimen);
  }
  /// Runs the kolsky program on scene j; returns its exit status, stderr in `err`. Skips the
  /// test when the program has not been built.
  int run_kolsky(const std::string& args, const json& j, std::string& err) {
    const std::string kolsky = std::string(KOLSKY_BINARY_DIR) + "/kolsky";
    if (!fs::exists(kolsky)) return -1;
    std::ofstream(dir_ / "scene.json") << j.dump();
    const std::string cmd = "cd '" + dir_.string() + "' && '" + kolsky + "' " + args +
                            " > out.txt 2> err.txt";
    const int status = std::system(cmd.c_str());
    std::ifstream in(dir_ / "err.txt");
    err.assign(std::istreambuf_iterator<char>(in), {});
    return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  }
  fs::path dir_;
};

// Two equal grains of radius r overlapping by delta along z, at rest, under `law`.
struct TwoGrains {
  static constexpr double r = 0.15e-3, delta = 1e-7;
  std::vector<Material> materials;
  Particles p;
  explicit TwoGrains(const Material& m) : materials{m} {
    p.add({0, 0, 0}, r, 0, materials);
    p.add({0, 0, 2 * r - delta}, r, 0, materials);
  }
  double mass() const { return p.mass[0]; }
  /// Normal force on grain 0 (compression +) and the system's stable dt (the raw limit: no
  /// safety factor inside, the stepping loop applies it).
  std::pair<double, double> force_and_dt(const ContactLaw& law) const {
    DemSystem sys(p, materials, law);
    sys.compute_forces();
    return {-sys.particles().f[0].z, sys.stable_dt()};
  }
};

// sqrt(m/k)(sqrt(1 + z^2) - z): the stable step of one damped linear spring.
double spring_step(double m, double k, double zeta) {
  return std::sqrt(m / k) * (std::sqrt(1 + zeta * zeta) - zeta);
}

TEST_F(SceneLaws, WithoutTheKeyTheLawIsHertzMindlinAsBefore) {
  const DemSpecimenParams d = dem_params(dem_scene({{"grain_friction", 0.4}}));
  ASSERT_TRUE(std::holds_alternative<HertzMindlinParams>(d.contact));
  EXPECT_EQ(std::get<HertzMindlinParams>(d.contact).friction, 0.4);
  EXPECT_EQ(std::get<HertzMindlinParams>(d.contact).restitution, HertzMindlinParams{}.restitution);
  EXPECT_EQ(d.packing.prestress_friction, 0.4);
  const Scene s = parse_scene(dem_scene({}), "scene.json", dir_.string());
  EXPECT_EQ(s.resolved["specimen"]["contact_law"], "hertz_mindlin");
  EXPECT_EQ(name_of(make_contact_law({Material{}}, DemSpecimenParams{}.contact)), "hertz_mindlin");
}

TEST_F(SceneLaws, PackingFrictionReachesTheJammingStageOnly) {
  // mu_pack of the jamming stage (docs/dem.md, Packing): the default is the one every scene
  // packed with before the key existed; the run's own law keeps the scene's grain friction.
  EXPECT_EQ(dem_params(dem_scene({})).packing.jam_friction, PackingParams{}.jam_friction);
  const DemSpecimenParams d = dem_params(dem_scene({{"packing_friction", 0.1}, {"grain_friction", 0.5}}));
  EXPECT_EQ(d.packing.jam_friction, 0.1);
  EXPECT_EQ(std::get<HertzMindlinParams>(d.contact).friction, 0.5);
  try {
    dem_params(dem_scene({{"packing_friction", -0.1}}));
    ADD_FAILURE() << "a negative packing friction accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "specimen.packing_friction");
  }
}

// The preparation procedures (docs/dem.md, Packing): servo_walls and the rotation lock reach
// PackingParams; a porosity the servo walls cannot reach is refused up front, naming the key.
TEST_F(SceneLaws, PackingProceduresAndTheRotationLockReachThePacking) {
  const DemSpecimenParams jammed = dem_params(dem_scene({{"packing", "jammed"}}));
  EXPECT_TRUE(jammed.packing.jam);
  EXPECT_FALSE(jammed.packing.servo_walls);
  EXPECT_FALSE(jammed.packing.packing_lock_rotation);
  const DemSpecimenParams servo =
      dem_params(dem_scene({{"packing", "servo_walls"}, {"packing_lock_rotation", true},
                            {"packing_density_scaling", true}}));
  EXPECT_TRUE(servo.packing.servo_walls);
  EXPECT_FALSE(servo.packing.jam);
  EXPECT_TRUE(servo.packing.packing_lock_rotation);
  EXPECT_TRUE(servo.packing.jam_mass_scaling);
  EXPECT_EQ(servo.packing.jam_steps_per_stage, kJamScaledStepsPerStage);
  try {
    dem_params(dem_scene({{"packing", "servo_walls"}, {"porosity", 0.3}}));
    ADD_FAILURE() << "an unreachable porosity accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "specimen.porosity");
  }
}

TEST_F(SceneLaws, DemSpecimenDefaultsToTheFractionItsRunsAlwaysUsed) {
  // The raw limit has no safety factor in it, so the scene's one factor defaults to 0.5 x 0.3
  // for a DEM specimen: the 0.5 of the loop times the 0.3 DemSystem applied inside before.
  const Scene s = parse_scene(dem_scene({}), "scene.json", dir_.string());
  EXPECT_EQ(s.spec.time.safety_factor, 0.15);
  EXPECT_EQ(s.resolved["time"]["safety_factor"], 0.15);
  json explicit_factor = dem_scene({});
  explicit_factor["time"]["safety_factor"] = 0.3;
  EXPECT_EQ(parse_scene(explicit_factor, "scene.json", dir_.string()).spec.time.safety_factor, 0.3);
  // The same bits as before: 0.5 x (0.3 x dt) == 0.15 x dt for every normal dt (halving is exact
  // and 0.15 is the double nearest to 0.3 / 2), so DEM results are unchanged.
  std::mt19937_64 gen(7);
  std::uniform_real_distribution<double> u(1e-10, 1e-6);
  for (int k = 0; k < 100000; ++k) {
    const double dt = u(gen);
    ASSERT_EQ(0.5 * (kDemStepFraction * dt), 0.15 * dt) << dt;
  }
}

TEST_F(SceneLaws, HertzMindlinParametersReachTheLaw) {
  const DemSpecimenParams d = dem_params(
      dem_scene({{"contact_law", "hertz_mindlin"}, {"grain_friction", 0.4}, {"restitution", 0.8}}));
  const Material m = d.packing.material;  // G = 30 GPa, nu = 0.3 (Table 4.1)
  const ContactLaw law = make_contact_law({m}, d.contact);
  const auto& hm = std::get<HertzMindlin>(law);
  EXPECT_EQ(hm.params().friction, 0.4);
  EXPECT_EQ(hm.params().restitution, 0.8);
  const TwoGrains g(m);
  const auto [force, dt] = g.force_and_dt(law);
  // Hertz: F = 4/3 E* sqrt(R*) delta^{3/2}, E* = E / (2(1 - nu^2)), R* = r/2 (Sec. 4.3).
  const double e_star = m.youngs_modulus / (2 * (1 - m.poisson_ratio * m.poisson_ratio));
  EXPECT_NEAR(force, 4.0 / 3.0 * e_star * std::sqrt(g.r / 2) * std::pow(g.delta, 1.5),
              1e-12 * force);
  // The Rayleigh step pi r sqrt(rho/G) / (0.1631 nu + 0.8766) (Li et al. 2005).
  const double rayleigh = std::numbers::pi * g.r * std::sqrt(m.density / 30e9) /
                          (0.1631 * 0.3 + 0.8766);
  EXPECT_NEAR(hm.stable_dt({g.mass(), g.r, rayleigh_time_step(g.r, m)}), rayleigh, 1e-12 * rayleigh);
  EXPECT_NEAR(dt, rayleigh, 1e-12 * dt);
}

TEST_F(SceneLaws, LinearParametersReachTheLaw) {
  const DemSpecimenParams d = dem_params(dem_scene(
      {{"contact_law", "linear"}, {"linear_normal_stiffness", 5e5}, {"linear_shear_stiffness", 2e5},
       {"linear_friction", 0.4}, {"linear_damping_ratio", 0.2}}));
  const ContactLaw law = make_contact_law({d.packing.material}, d.contact);
  const auto& s = std::get<LinearSpring>(law);
  EXPECT_EQ(s.tangential.friction, 0.4);
  EXPECT_EQ(s.damping_normal.ratio, 0.2);
  EXPECT_EQ(s.damping_tangential.ratio, 0.2);
  const TwoGrains g(d.packing.material);
  const auto [force, dt] = g.force_and_dt(law);
  EXPECT_NEAR(force, 5e5 * g.delta, 1e-12 * force);  // F = k_n delta (at rest: no dashpot)
  // The normal spring, and 3.5 k_s for the tangential one (a sphere's contact point moves
  // with mass m / 3.5 once it rolls): here 3.5 x 2e5 = 7e5 > k_n sets the step.
  const double expected = std::min(spring_step(g.mass(), 5e5, 0.2), spring_step(g.mass(), 7e5, 0.2));
  EXPECT_NEAR(dt, expected, 1e-12 * dt);
}

TEST_F(SceneLaws, LsDynaParametersReachTheLaw) {
  // Table 3.2's grains: E = 70 MPa, nu = 0.2, i.e. G = E / (2 (1 + nu)).
  const DemSpecimenParams d = dem_params(dem_scene(
      {{"contact_law", "ls_dyna_linear"}, {"grain_shear_modulus", 70e6 / 2.4},
       {"grain_poisson_ratio", 0.2}, {"sheark", 0.5}, {"fric", 0.4}, {"fricr", 0.2},
       {"ndamp", 0.05}, {"tdamp", 0.15}}));
  const Material m = d.packing.material;
  EXPECT_NEAR(m.youngs_modulus, 70e6, 1e-6);
  const ContactLaw law = make_contact_law({m}, d.contact);
  const LsDynaPair& pair = std::get<LsDynaLinear>(law).pair(0, 0);
  EXPECT_EQ(pair.p.normk, LsDynaParams{}.normk);  // 0.07, Table 3.2
  EXPECT_EQ(pair.p.sheark, 0.5);
  EXPECT_EQ(pair.p.fric, 0.4);
  EXPECT_EQ(pair.p.fricr, 0.2);
  const TwoGrains g(m);
  // Eq. 3.1 for equal grains: K_n = NORMK k r / 2, k = E / (1 - 2 nu): 612.5 N/m (targets 3a).
  const double kn = 0.07 * (70e6 / 0.6) * g.r / 2;
  EXPECT_NEAR(kn, 612.5, 1e-9);
  EXPECT_NEAR(pair.normal_stiffness(g.r, g.r), kn, 1e-9);
  const auto [force, dt] = g.force_and_dt(law);
  EXPECT_NEAR(force, kn * g.delta, 1e-9 * force);
  // K_s = SHEARK K_n (Eq. 3.2); NDAMP and TDAMP as fractions of critical damping.
  const double expected = std::min(spring_step(g.mass(), kn, 0.05),
                                   spring_step(g.mass(), 3.5 * 0.5 * kn, 0.15));
  EXPECT_NEAR(dt, expected, 1e-9 * dt);
}

TEST_F(SceneLaws, EachLawReachesTheSpecimenBuiltFromTheScene) {
  // The whole path scene -> make_dem_specimen, with walls soft enough that the grain law alone
  // sets the step: the specimen's stable dt is the chosen law's limit on the packed grains.
  for (const std::string_view name : kContactLawNames) {
    const DemSpecimenParams d = dem_params(dem_scene(
        {{"contact_law", name}, {"wall_normal_stiffness", 1.0}, {"wall_shear_stiffness", 1.0}}));
    const DemSpecimen specimen = make_dem_specimen(d);
    const Particles& p = specimen.system().particles();
    ASSERT_GT(p.size(), 20u) << name;
    LawLimits lim{1e300, 0, 1e300};
    for (std::size_t i = 0; i < p.size(); ++i) {
      lim.lightest_mass = std::min(lim.lightest_mass, p.mass[i]);
      lim.largest_radius = std::max(lim.largest_radius, p.radius[i]);
      lim.rayleigh_step = std::min(lim.rayleigh_step, rayleigh_time_step(p.radius[i], d.packing.material));
    }
    const ContactLaw law = make_contact_law({d.packing.material}, d.contact);
    EXPECT_EQ(name_of(law), name);
    const double limit = std::visit([&](const auto& l) { return l.stable_dt(lim); }, law);
    EXPECT_EQ(specimen.stable_dt(), limit) << name;
  }
}

TEST_F(SceneLaws, UnknownLawIsRefusedNamingTheKey) {
  json j = dem_scene({{"contact_law", "linear_sprng"}});
  try {
    dem_params(j);
    ADD_FAILURE() << "unknown law accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "specimen.contact_law");
    EXPECT_TRUE(contains(e.rule(), "unknown value 'linear_sprng'")) << e.what();
    EXPECT_TRUE(contains(e.rule(), "hertz_mindlin, linear, ls_dyna_linear")) << e.what();
  }
  std::string err;
  const int rc = run_kolsky("run scene.json -o o.h5 --quiet", j, err);
  if (rc == -1) GTEST_SKIP() << "kolsky not built";
  EXPECT_EQ(rc, 2) << err;
  EXPECT_TRUE(contains(err, "scene.json: specimen.contact_law: unknown value")) << err;
  EXPECT_FALSE(fs::exists(dir_ / "o.h5"));
}

TEST_F(SceneLaws, AnotherLawsKeysAndPrestressAreRefused) {
  try {
    dem_params(dem_scene({{"normk", 0.1}}));  // hertz_mindlin by default
    ADD_FAILURE() << "normk accepted under hertz_mindlin";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "specimen.normk");
    EXPECT_EQ(e.rule(), "'normk' is used only when specimen.contact_law = ls_dyna_linear, with "
                        "specimen.model = dem");
  }
  try {
    dem_params(dem_scene({{"contact_law", "linear"}, {"initial_stress", 1e4}}));
    ADD_FAILURE() << "pre-stress accepted with a linear grain law";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "specimen.initial_stress");
    EXPECT_TRUE(contains(e.rule(), "hertz_mindlin")) << e.what();
  }
}

TEST_F(SceneLaws, DefaultsListEveryLawParameterWithItsStructDefault) {
  const LinearParams lin;
  const LsDynaParams ls;
  const HertzMindlinParams hm;
  // key, the struct initialiser it must show, a source its description must cite
  const std::vector<std::tuple<std::string, double, std::string>> keys = {
      {"grain_friction", hm.friction, "Table 4.1"}, {"restitution", hm.restitution, "Tsuji"},
      {"linear_normal_stiffness", lin.normal_stiffness, "Table 4.1"},
      {"linear_shear_stiffness", lin.shear_stiffness, "Table 4.1"},
      {"linear_friction", lin.friction, "Table 4.1"}, {"linear_damping_ratio", lin.damping_ratio, "critical"},
      {"normk", ls.normk, "Eq. 3.1"}, {"sheark", ls.sheark, "Eq. 3.2"}, {"fric", ls.fric, "Eq. 3.3"},
      {"fricr", ls.fricr, "Eq. 3.4"}, {"ndamp", ls.ndamp, "Table 3.2"}, {"tdamp", ls.tdamp, "Table 3.2"},
      {"wall_normal_stiffness", lin.normal_stiffness, "Table 4.1"},
      {"wall_shear_stiffness", lin.shear_stiffness, "Table 4.1"},
      {"wall_friction", lin.friction, "Table 4.1"}};
  const std::string listing = format_defaults();
  for (const auto& [key, value, source] : keys) {
    const ParamSpec* p = find_param("scene", "specimen." + key);
    ASSERT_NE(p, nullptr) << key;
    EXPECT_EQ(p->doc.default_value, format_number(value)) << key;
    EXPECT_FALSE(p->doc.unit.empty()) << key;
    EXPECT_TRUE(contains(p->doc.description, source)) << key << ": " << p->doc.description;
    EXPECT_TRUE(contains(listing, "specimen." + key + " ")) << key;
  }
  // The law names are the choices, the first (the default-constructed variant) the default.
  const ParamSpec* law = find_param("scene", "specimen.contact_law");
  ASSERT_NE(law, nullptr);
  EXPECT_EQ(law->choices, std::vector<std::string>(kContactLawNames.begin(), kContactLawNames.end()));
  EXPECT_EQ(law->doc.default_value, "hertz_mindlin");
  // Every parameter of the table is in the listing (moved here from test_scene.cpp).
  for (const ParamDoc& d : parameters()) EXPECT_TRUE(contains(listing, d.path + " ")) << d.path;
  EXPECT_EQ(edit_distance("kitten", "sitting"), 3u);
  const std::vector<std::string> names = {"length", "diameter", "density", "youngs_modulus"};
  EXPECT_EQ(closest_name("lenght", names), "length");
  EXPECT_EQ(closest_name("densty", names), "density");
  EXPECT_EQ(closest_name("young", names), "youngs_modulus");
  EXPECT_EQ(closest_name("colour", names), "");
  std::string err;
  const int rc = run_kolsky("defaults", json::object(), err);
  if (rc == -1) GTEST_SKIP() << "kolsky not built";
  EXPECT_EQ(rc, 0) << err;
  std::ifstream in(dir_ / "out.txt");
  const std::string out(std::istreambuf_iterator<char>(in), {});
  for (const auto& [key, value, source] : keys) EXPECT_TRUE(contains(out, "specimen." + key)) << key;
}

TEST_F(SceneLaws, ErrorsFromInsideThePhysicsNameTheSceneKey) {
  // The packing refuses grains too large for the cylinder (dem.packing.curve): x 10, the
  // largest grain is 6 mm across a 4 mm specimen.
  const json j = dem_scene({{"upscale", 10}});
  const DemSpecimenParams d = dem_params(j);
  try {
    make_dem_specimen(d);
    ADD_FAILURE() << "oversized grains accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "specimen.upscale");
    EXPECT_TRUE(contains(e.rule(), "largest grain does not fit")) << e.what();
  }
  // A law the physics refuses (the schema would stop -1 earlier): NORMK <= 0 in LsDynaLinear.
  DemSpecimenParams bad = dem_params(dem_scene({{"contact_law", "ls_dyna_linear"}}));
  std::get<LsDynaParams>(bad.contact).normk = -1;
  try {
    make_dem_specimen(bad);
    ADD_FAILURE() << "NORMK < 0 accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "specimen.normk");
  }
  // The renaming itself: longest match at a segment boundary; other paths unchanged.
  const auto& names = d.input_names;
  const auto renamed = [&](const std::string& path) {
    return rename_input_error(InputError("", path, "r"), names).path();
  };
  EXPECT_EQ(renamed("dem.contact_law"), "specimen.contact_law");
  EXPECT_EQ(renamed("dem.contact_law.friction"), "specimen.grain_friction");
  EXPECT_EQ(renamed("dem.walls.plane.law.normal_stiffness"), "specimen.wall_normal_stiffness");
  EXPECT_EQ(renamed("dem.walls.cylinder.law.friction"), "specimen.wall_friction");
  EXPECT_EQ(renamed("dem.walls.plane.normal"), "specimen");
  EXPECT_EQ(renamed("dem.materials[0].density"), "specimen.grain_density");
  EXPECT_EQ(renamed("dem.owner_block"), "specimen");
  EXPECT_EQ(renamed("dem.packing.curvex"), "specimen.packing");  // not under dem.packing.curve
  EXPECT_EQ(renamed("time.dt"), "time.dt");
  EXPECT_EQ(rename_input_error(InputError("f.json", "dem.packing.porosity", "rule"), names).what(),
            std::string("f.json: specimen.porosity: rule"));
  // End to end: exit 2 and the scene key in the one-line error.
  std::string err;
  const int rc = run_kolsky("run scene.json -o o.h5 --quiet", j, err);
  if (rc == -1) GTEST_SKIP() << "kolsky not built";
  EXPECT_EQ(rc, 2) << err;
  EXPECT_TRUE(contains(err, "scene.json: specimen.upscale: largest grain does not fit")) << err;
}

}  // namespace
