// Scene and BARS.json parsing (solver/scene): docs/scene.md and the parameter table agree,
// every documented key is accepted, every rule names the file, the dotted path and the rule.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <random>
#include <sstream>
#include <variant>

#include "core/errors.hpp"
#include "scene/json_reader.hpp"
#include "scene/scene.hpp"
#include "test_support.hpp"

namespace {

namespace fs = std::filesystem;
using kolsky::InputError;
using nlohmann::json;
using namespace kolsky::scene;

json minimal_scene() {
  return json::parse(R"({
    "bars": {"incident": {"length": 1.0}, "transmission": {"length": 1.0}},
    "pulse": {"kind": "trapezoid", "amplitude": 100e6, "duration": 300e-6},
    "specimen": {"model": "elastic", "constrained_modulus": 230e6},
    "time": {"end": 1e-3}})");
}

json minimal_bars() {
  return json::parse(R"({"incident": {"gauge_distance": 0.5},
    "transmission": {"gauge_distance": 0.5}, "specimen": {"length": 0.0093}})");
}

json::json_pointer pointer(std::string dotted) {
  std::replace(dotted.begin(), dotted.end(), '.', '/');
  return json::json_pointer("/" + dotted);
}

using kolsky::testing::input_error;

bool contains(const std::string& s, const std::string& part) {
  return s.find(part) != std::string::npos;
}

class SceneTest : public ::testing::Test {
 protected:
  void SetUp() override {
    std::random_device rd;
    dir_ = fs::temp_directory_path() / ("kolsky_test_scene_" + std::to_string(rd()));
    fs::create_directories(dir_);
    write("pulse.csv", "# reconstructed pulse\ntime_s,stress_pa\n0 0\n1e-4 1e8\n2e-4 0\n");
    write("curve.csv", "strain,stress_pa\n0,0\n0.05,20e6\n0.1,100e6\n");
    write("psd.csv", "diameter_m,percent_passing\n1e-4,0\n3e-4,50\n6e-4,100\n");
    write("rate.csv", "time_s,strain_rate\n0,0\n1e-5,1200\n");
  }
  void TearDown() override { fs::remove_all(dir_); }

  std::string write(const std::string& name, const std::string& text) {
    const fs::path p = dir_ / name;
    fs::create_directories(p.parent_path());
    std::ofstream(p) << text;
    return p.string();
  }
  Scene parse(const json& j) { return parse_scene(j, "scene.json", dir_.string()); }
  InputError scene_error(const json& j) {
    return input_error([&] { parse(j); });
  }
  void expect_error(const json& j, const std::string& path, const std::string& rule) {
    const InputError e = scene_error(j);
    EXPECT_EQ(e.path(), path) << e.what();
    EXPECT_TRUE(contains(e.rule(), rule)) << e.what() << "\n  expected: " << rule;
  }
  static json with(json j, const std::string& dotted, const json& value) {
    j[pointer(dotted)] = value;
    return j;
  }
  /// The minimal scene with `selector` (e.g. "pulse.kind") switched to `value`.
  static json scene_for(const std::string& selector, const std::string& value) {
    json j = minimal_scene();
    if (selector == "bars.kind") j["bars"]["kind"] = value;
    if (selector == "pulse.kind" && value == "half_sine") j["pulse"]["kind"] = value;
    if (selector == "pulse.kind" && value == "tabulated")
      j["pulse"] = {{"kind", "tabulated"}, {"file", "pulse.csv"}};
    if (selector == "specimen.model" && value == "compaction")
      j["specimen"] = {
          {"model", "compaction"}, {"loading_curve", "curve.csv"}, {"unloading_modulus", 1e9}};
    if (selector == "specimen.model" && value == "dem")
      j["specimen"] = {{"model", "dem"}, {"grain_size_curve", "psd.csv"}};
    if (selector == "specimen.contact_law")  // a DEM specimen with that grain law
      j["specimen"] = {{"model", "dem"}, {"grain_size_curve", "psd.csv"}, {"contact_law", value}};
    if (selector == "specimen.breakage.criterion")  // a DEM specimen breaking by that criterion
      j["specimen"] = {{"model", "dem"}, {"grain_size_curve", "psd.csv"}, {"breakage", {{"criterion", value}}}};
    if (selector == "loading.kind" && value == "strain_rate")  // no bars, no pulse; DEM only
      j = {{"loading", {{"kind", "strain_rate"}, {"file", "rate.csv"}}},
           {"specimen", {{"model", "dem"}, {"grain_size_curve", "psd.csv"}}},
           {"time", {{"end", 1e-3}}}};
    if (selector == "specimen.model" && value == "fe")  // K_u >= the curve's steepest slope
      j["specimen"] = {{"model", "fe"}, {"loading_curve", "curve.csv"}, {"unloading_modulus", 2e9}};
    return j;
  }
  fs::path dir_;
};

TEST(SceneDocs, DocsAndParameterTableAgree) {
  std::ifstream in(std::string(KOLSKY_SOURCE_DIR) + "/docs/scene.md");
  ASSERT_TRUE(in) << "docs/scene.md not found under KOLSKY_SOURCE_DIR";
  std::map<std::pair<std::string, std::string>, std::vector<std::string>> rows;
  std::string schema, line;
  while (std::getline(in, line)) {
    if (line.rfind("## ", 0) == 0) schema = contains(line, "BARS") ? "bars" : "scene";
    if (line.rfind("| `", 0) != 0) continue;
    std::vector<std::string> cells;
    std::stringstream ss(line.substr(1));
    for (std::string cell; std::getline(ss, cell, '|');) {
      const auto b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
      cells.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
    }
    ASSERT_EQ(cells.size(), 5u) << line;
    const std::string key = cells[0].substr(1, cells[0].size() - 2);
    EXPECT_TRUE(rows.emplace(std::make_pair(schema, key), cells).second) << "duplicate " << key;
  }
  for (const ParamDoc& d : parameters()) {
    const auto it = rows.find({d.schema, d.path});
    if (it == rows.end()) {
      ADD_FAILURE() << d.schema << " key " << d.path << " is not documented in docs/scene.md";
      continue;
    }
    EXPECT_EQ(it->second[1], d.type) << d.path;
    EXPECT_EQ(it->second[2], d.default_value) << d.path;
    EXPECT_EQ(it->second[3], d.unit) << d.path;
    if (!d.applies_to.empty()) {  // "pulse.kind=trapezoid|half_sine" as the docs write it
      std::string variant = d.applies_to;
      variant.replace(variant.find('='), 1, " = ");
      for (auto bar = variant.find('|'); bar != std::string::npos; bar = variant.find('|'))
        variant.replace(bar, 1, " or ");
      EXPECT_TRUE(contains(it->second[4], "(" + variant + ")")) << d.path;
    }
    rows.erase(it);
  }
  for (const auto& [key, cells] : rows)
    ADD_FAILURE() << key.first << " key " << key.second << " is documented but not a parameter";
}

TEST_F(SceneTest, EveryParameterIsAccepted) {
  // Values for keys without a literal default: required keys and the derived defaults (gauges,
  // the safety factor that depends on the specimen model, the energy tolerance on the loading).
  const std::map<std::string, json> example = {
      {"bars.incident.length", 1.0}, {"bars.transmission.length", 1.0},
      {"bars.incident.gauges", {0.25, 0.5}}, {"bars.transmission.gauges", {0.5}},
      {"pulse.kind", "trapezoid"}, {"pulse.amplitude", 100e6}, {"pulse.duration", 300e-6},
      {"pulse.file", "pulse.csv"}, {"loading.file", "rate.csv"}, {"specimen.model", "elastic"},
      {"specimen.constrained_modulus", 230e6}, {"specimen.loading_curve", "curve.csv"},
      {"specimen.grain_size_curve", "psd.csv"}, {"specimen.unloading_modulus", 2e9},
      {"time.end", 1e-3}, {"time.safety_factor", 0.5}, {"time.energy_tolerance", 0.01},
      {"incident.gauge_distance", 0.5}, {"transmission.gauge_distance", 0.5},
      {"specimen.length", 0.0093}};
  for (const ParamDoc& d : parameters()) {
    json value;
    if (d.default_value == "required" || d.default_value.front() == '[' || example.count(d.path))
      value = example.at(d.path);
    else if (d.type == "choice")
      value = d.default_value;
    else  // numbers, booleans and the quoted string default are JSON literals as printed
      value = json::parse(d.default_value);
    if (d.schema == "bars") {
      json j = minimal_bars();
      j[pointer(d.path)] = value;
      EXPECT_NO_THROW(parse_bars_file(j, "BARS.json")) << d.path;
      continue;
    }
    std::string selector, options = "-";
    if (!d.applies_to.empty()) {
      selector = d.applies_to.substr(0, d.applies_to.find('='));
      options = d.applies_to.substr(d.applies_to.find('=') + 1);
    }
    std::stringstream variants(options);
    for (std::string variant; std::getline(variants, variant, '|');) {
      json j = scene_for(selector, variant);
      j[pointer(d.path)] = value;
      try {
        const Scene s = parse(j);
        if (d.type != "path") {
          EXPECT_EQ(s.resolved.at(pointer(d.path)), value) << d.path;
        }
      } catch (const std::exception& e) {
        ADD_FAILURE() << d.path << " (" << d.applies_to << "): " << e.what();
      }
    }
  }
}

TEST_F(SceneTest, UnknownKeyIsRejectedWithSuggestion) {
  const InputError e = scene_error(with(minimal_scene(), "bars.incident.lenght", 1.0));
  EXPECT_EQ(e.file(), "scene.json");
  EXPECT_EQ(e.path(), "bars.incident.lenght");
  EXPECT_TRUE(contains(e.rule(), "unknown key")) << e.what();
  EXPECT_TRUE(contains(e.rule(), "did you mean 'length'")) << e.what();
  // A shared prefix suggests where the edit distance is too large.
  expect_error(with(minimal_scene(), "bars.incident.youngs", 1.0), "bars.incident.youngs",
               "did you mean 'youngs_modulus'");
  expect_error(with(minimal_scene(), "colour", "red"), "colour", "valid keys here: title, bars");
}

TEST_F(SceneTest, MissingRequiredKeyNamesPath) {
  json j = minimal_scene();
  j["bars"]["incident"].erase("length");
  expect_error(j, "bars.incident.length", "required key is missing");
  j = minimal_scene();
  j.erase("time");
  expect_error(j, "time.end", "required key is missing");
  j = scene_for("pulse.kind", "tabulated");
  j["pulse"].erase("file");
  expect_error(j, "pulse.file", "required when pulse.kind = tabulated");
}

TEST_F(SceneTest, OutOfRangeValueNamesPathAndRule) {
  const std::vector<std::tuple<std::string, json, std::string>> cases = {
      {"bars.incident.poisson_ratio", 0.6, "must be in (0, 0.5), got 0.6"},
      {"bars.transmission.density", -1.0, "must be > 0"},
      {"specimen.n_elements", 1, "must be in [2, 100000]"},
      {"time.safety_factor", 0.0, "must be in (0, 1]"},
      {"time.end", 0.0, "must be > 0"},
      {"time.dt", -1e-9, "must be >= 0"},
      {"output.interval", -1.0, "must be >= 0"}};
  for (const auto& [path, value, rule] : cases)
    expect_error(with(minimal_scene(), path, value), path, rule);
  expect_error(with(scene_for("bars.kind", "sphere_chain"), "bars.incident.n_spheres", 3),
               "bars.incident.n_spheres", "must be 0 or >= 4");
}

TEST_F(SceneTest, WrongJsonTypeIsRejected) {
  const json m = minimal_scene();
  EXPECT_EQ(scene_error(with(m, "time.end", "1 ms")).rule(), "expected a number, got a string");
  EXPECT_EQ(scene_error(with(m, "bars", 5)).rule(), "expected an object, got a number");
  expect_error(with(m, "specimen.n_elements", 2.5), "specimen.n_elements", "expected an integer");
  expect_error(with(m, "time.check_stability", "yes"), "time.check_stability",
               "expected a boolean");
  expect_error(with(m, "bars.incident.gauges", {0.5, "x"}), "bars.incident.gauges[1]",
               "expected a number, got a string");
  expect_error(with(m, "pulse.kind", "trapezoidal"), "pulse.kind", "did you mean 'trapezoid'");
}

TEST_F(SceneTest, GaugeOutsideTheBarIsRejected) {
  expect_error(with(minimal_scene(), "bars.incident.gauges", {0.5, 1.2}), "bars.incident.gauges[1]",
               "outside the bar");
  expect_error(with(minimal_scene(), "bars.incident.gauges", {0.0}), "bars.incident.gauges[0]",
               "must be > 0");
  // Sphere chains: a gauge needs a contact on each side, so one ball diameter from each end.
  const json chain = scene_for("bars.kind", "sphere_chain");
  expect_error(with(chain, "bars.transmission.gauges", {0.01}), "bars.transmission.gauges[0]",
               "at least one ball diameter");
  expect_error(with(chain, "bars.incident", {{"length", 0.05}, {"gauges", {0.025}}}),
               "bars.incident.length", "at least 4 balls");  // L/d = 2.6: 3 balls
}

TEST_F(SceneTest, VariantKeyUnderAnotherVariantIsRejected) {
  const InputError e = scene_error(with(minimal_scene(), "pulse.file", "pulse.csv"));
  EXPECT_EQ(e.path(), "pulse.file");
  EXPECT_EQ(e.rule(), "'file' is used only when pulse.kind = tabulated");
  EXPECT_EQ(scene_error(with(minimal_scene(), "bars.incident.n_spheres", 10)).rule(),
            "'n_spheres' is used only when bars.kind = sphere_chain");
  EXPECT_EQ(scene_error(with(scene_for("pulse.kind", "half_sine"), "pulse.rise_time", 1e-5)).rule(),
            "'rise_time' is used only when pulse.kind = trapezoid");
  expect_error(with(scene_for("specimen.model", "compaction"), "specimen.constrained_modulus", 1e9),
               "specimen.constrained_modulus", "used only when specimen.model = elastic");
}

TEST_F(SceneTest, CrossKeyRules) {
  json j = with(minimal_scene(), "pulse.rise_time", 200e-6);
  expect_error(with(j, "pulse.fall_time", 150e-6), "pulse.duration", "must not exceed duration");
  expect_error(with(minimal_scene(), "specimen.diameter", 0.1), "specimen.diameter",
               "inconsistent geometry");  // > 4 x 0.0191
}

TEST_F(SceneTest, JsonSyntaxErrorReportsLineAndColumn) {
  const std::string path = write("broken.json", "{\n  \"title\": \"x\",\n  \"bars\": }\n");
  InputError e = input_error([&] { load_scene(path); });
  EXPECT_EQ(e.file(), path);
  EXPECT_EQ(e.path(), "");
  EXPECT_EQ(e.rule().rfind("JSON syntax error at line 3, column 11: ", 0), 0u) << e.what();
  const std::string array = write("array.json", "[1, 2]");
  e = input_error([&] { load_scene(array); });
  EXPECT_EQ(e.path(), "");
  EXPECT_TRUE(contains(e.rule(), "must be a JSON object, got an array")) << e.what();
  EXPECT_EQ(text_position("ab\ncd", 5).line, 2u);
  EXPECT_EQ(text_position("ab\ncd", 5).column, 2u);
}

TEST_F(SceneTest, DefaultsAreFilledInResolved) {
  const Scene s = parse(minimal_scene());
  const json& r = s.resolved;
  EXPECT_EQ(r["title"], "");
  EXPECT_EQ(r["bars"]["kind"], "characteristic");
  EXPECT_EQ(r["bars"]["incident"]["diameter"], 0.0191);
  EXPECT_EQ(r["bars"]["incident"]["youngs_modulus"], 200e9);
  EXPECT_EQ(r["bars"]["transmission"]["gauges"], json({0.5}));
  EXPECT_FALSE(r["bars"]["incident"].contains("n_spheres"));  // not a sphere chain
  EXPECT_EQ(r["pulse"]["rise_time"], 50e-6);
  EXPECT_EQ(r["pulse"]["delay"], 0.0);
  EXPECT_EQ(r["specimen"]["n_elements"], 100);
  EXPECT_EQ(r["time"]["safety_factor"], 0.5);
  EXPECT_EQ(r["time"]["check_stability"], true);
  EXPECT_EQ(r["output"]["interval"], 0.0);
  EXPECT_EQ(s.spec.incident.gauges, std::vector<double>({0.5}));
  EXPECT_EQ(std::get<kolsky::bar::ColumnParams>(s.spec.specimen).n_elements, 100);
  EXPECT_EQ(std::get<kolsky::bar::LinearElastic>(std::get<kolsky::bar::ColumnParams>(s.spec.specimen).material).constrained_modulus,
            230e6);
  EXPECT_EQ(std::get<kolsky::bar::TrapezoidPulse>(s.spec.pulse).fall_time, 50e-6);
  EXPECT_EQ(parse(r).resolved, r);  // the resolved scene is itself a valid, fixed-point scene
}

TEST_F(SceneTest, CsvPathsResolveAgainstTheSceneFolder) {
  write("case/data/pulse.csv", "# t, s\n\n0, 0\n5e-5, 2e8\r\n1e-4, 0\n");
  write("case/data/curve.csv", "0 0\n0.1 1e8\n");
  json j = minimal_scene();
  j["pulse"] = {{"kind", "tabulated"}, {"file", "data/pulse.csv"}, {"scale", 0.5}};
  j["specimen"] = {
      {"model", "compaction"}, {"loading_curve", "data/curve.csv"}, {"unloading_modulus", 2e9}};
  const std::string path = write("case/scene.json", j.dump());
  const Scene s = load_scene(path);
  const auto& pulse = std::get<kolsky::bar::TabulatedPulse>(s.spec.pulse);
  EXPECT_EQ(pulse.table.x, std::vector<double>({0.0, 5e-5, 1e-4}));
  EXPECT_EQ(pulse.table.y[1], 2e8);
  EXPECT_EQ(pulse.scale, 0.5);
  const std::string abs = (dir_ / "case/data/pulse.csv").lexically_normal().string();
  EXPECT_EQ(s.resolved["pulse"]["file"], abs);
  const auto& curve = std::get<kolsky::bar::TabulatedCompaction>(std::get<kolsky::bar::ColumnParams>(s.spec.specimen).material);
  EXPECT_EQ(curve.loading.y.back(), 1e8);
  j["pulse"]["file"] = "missing.csv";
  const InputError e = scene_error(j);
  EXPECT_EQ(e.path(), "pulse.file");
  EXPECT_TRUE(contains(e.rule(), "no such file")) << e.what();
}

TEST_F(SceneTest, BadCsvIsRejectedNamingFileAndLine) {
  const std::string bad =
      write("bad_pulse.csv", "# pulse\ntime_s,stress_pa\n0,0\n2e-4,1e8\n1e-4,0\n");
  json j = scene_for("pulse.kind", "tabulated");
  j["pulse"]["file"] = "bad_pulse.csv";
  InputError e = scene_error(j);
  EXPECT_EQ(e.file(), fs::path(bad).lexically_normal().string());
  EXPECT_EQ(e.path(), "line 5");
  EXPECT_TRUE(contains(e.rule(), "time_s must be strictly increasing")) << e.what();

  const std::vector<std::tuple<std::string, std::string, std::string>> cases = {
      {"0,0\n1,2,3\n", "line 2", "row has 3 cells but the table has 2 columns"},
      {"0,1,2\n1,2,3\n", "line 1", "expected 2 columns"},
      {"0,0\n1,abc\n", "line 2", "'abc' is not a number"},
      {"0,0\n1,nan\n", "line 2", "'nan' is not a finite number"},
      {"# only\n0,0\n", "", "needs at least 2 data rows"},
      {"0.01,0\n0.1,1e8\n", "line 1", "must start at (0, 0)"},
      {"0,0\n0.1,1e8\n0.2,5e7\n", "line 3", "stress_pa must be strictly increasing"}};
  for (const auto& [text, where, rule] : cases) {
    write("curve_case.csv", text);
    j = scene_for("specimen.model", "compaction");
    j["specimen"]["loading_curve"] = "curve_case.csv";
    e = scene_error(j);
    EXPECT_EQ(e.path(), where) << text;
    EXPECT_TRUE(contains(e.rule(), rule)) << e.what();
  }
}

TEST_F(SceneTest, BarsFileFillsTheAnalysisStructs) {
  json j = minimal_bars();
  j["transmission"]["diameter"] = 0.02;
  j["processing"] = {{"dispersion_correction", true}, {"duration", 4e-4}};
  const BarsFile f = load_bars_file(write("BARS.json", j.dump()));
  EXPECT_EQ(f.setup.incident.gauge_distance, 0.5);
  EXPECT_EQ(f.setup.transmission.diameter, 0.02);
  EXPECT_EQ(f.setup.specimen_length, 0.0093);
  EXPECT_EQ(f.setup.specimen_diameter, 0.0191);
  EXPECT_TRUE(f.gauge.dispersion_correction);
  EXPECT_EQ(f.gauge.duration, 4e-4);
  EXPECT_EQ(f.gauge.threshold_fraction, 0.05);
  EXPECT_EQ(f.analysis.alpha_floor_fraction, 0.02);
  EXPECT_EQ(f.resolved["processing"]["noise_sigmas"], 5.0);
  j = minimal_bars();
  j["incident"].erase("gauge_distance");
  EXPECT_EQ(input_error([&] { parse_bars_file(j, "B"); }).path(), "incident.gauge_distance");
  j = minimal_bars();
  j["processing"] = {{"treshold_fraction", 0.1}};
  EXPECT_TRUE(contains(input_error([&] { parse_bars_file(j, "B"); }).rule(),
                       "did you mean 'threshold_fraction'"));
}

}  // namespace
