// The strain-rate loading in scene files (docs/scene.md, "Strain-rate-controlled walls"):
// `"loading": {"kind": "strain_rate", "file": ...}` parses into ExperimentSpec::strain_rate,
// its resolved scene is a fixed point, and each class of bad input is an InputError naming the
// file and the path: the CSV (empty, non-finite, time not strictly increasing, missing
// columns, a wrong header, a negative start) by its own name and line; the scene (an unknown
// loading.kind, bars or pulse given with the walls, no file, a file under loading.kind = bars,
// a non-DEM specimen, a preload on supports that do not exist) by the JSON path.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>

#include "core/errors.hpp"
#include "scene/scene.hpp"
#include "shpb/simulation.hpp"
#include "test_support.hpp"

namespace kolsky {
namespace {

using nlohmann::json;

struct StrainRateScene : ::testing::Test {
  testing::TempDir dir{"kolsky_test_strain_rate_scene"};
  StrainRateScene() {
    write("rate.csv", "# illustrative\ntime_s,strain_rate\n0,0\n1e-5,1200\n5e-5,1200\n");
    write("psd.csv", "diameter_m,percent_passing\n1e-4,0\n3e-4,50\n6e-4,100\n");
  }
  std::string write(const std::string& name, const std::string& text) {
    std::ofstream(dir.file(name)) << text;
    return dir.file(name);
  }
  static json base() {
    return {{"loading", {{"kind", "strain_rate"}, {"file", "rate.csv"}}},
            {"specimen", {{"model", "dem"}, {"grain_size_curve", "psd.csv"}}},
            {"time", {{"end", 5e-5}}}};
  }
  scene::Scene parse(const json& j) { return scene::parse_scene(j, "walls.json", dir.str()); }
  InputError error_of(const json& j) {
    try {
      parse(j);
    } catch (const InputError& e) {
      return e;
    }
    ADD_FAILURE() << "expected an InputError for " << j.dump();
    return InputError("", "", "");
  }
  void expect(const json& j, const std::string& file, const std::string& path, const std::string& rule) {
    const InputError e = error_of(j);
    EXPECT_EQ(e.file(), file) << e.what();
    EXPECT_EQ(e.path(), path) << e.what();
    EXPECT_NE(e.rule().find(rule), std::string::npos) << e.what() << "\n  expected: " << rule;
  }
  // The base scene reading `name` as its strain-rate table.
  json with_table(const std::string& name, const std::string& text) {
    write(name, text);
    json j = base();
    j["loading"]["file"] = name;
    return j;
  }
};

TEST_F(StrainRateScene, ParsesAndRoundTripsThroughTheResolvedScene) {
  const std::string path = dir.file("walls.json");
  std::ofstream(path) << base().dump(2);
  const scene::Scene s = scene::load_scene(path);
  ASSERT_TRUE(s.spec.strain_rate.has_value());
  EXPECT_EQ(s.spec.strain_rate->rates(), std::vector<double>({0, 1200, 1200}));
  EXPECT_EQ(s.resolved["loading"]["kind"], "strain_rate");
  EXPECT_EQ(s.resolved["loading"]["file"], std::filesystem::path(dir.file("rate.csv")).lexically_normal().string());
  EXPECT_FALSE(s.resolved.contains("bars"));   // nothing of the bars is resolved ...
  EXPECT_FALSE(s.resolved.contains("pulse"));  // ... or of the pulse
  EXPECT_EQ(s.resolved["time"]["safety_factor"], 0.15);  // the DEM default
  EXPECT_EQ(s.resolved["time"]["energy_tolerance"], 0.05);  // the walls' default
  EXPECT_EQ(parse(s.resolved).resolved, s.resolved);      // a fixed point
  // Without a loading block, or with kind = bars, nothing changes: bars and pulse load it.
  json bars = {{"bars", {{"incident", {{"length", 1.0}}}, {"transmission", {{"length", 1.0}}}}},
               {"pulse", {{"kind", "trapezoid"}, {"amplitude", 1e8}, {"duration", 3e-4}}},
               {"specimen", {{"model", "elastic"}, {"constrained_modulus", 230e6}}},
               {"time", {{"end", 1e-3}}}};
  const scene::Scene plain = parse(bars);
  EXPECT_FALSE(plain.spec.strain_rate.has_value());
  EXPECT_EQ(plain.resolved["time"]["energy_tolerance"], 0.01);  // as before the walls existed
  EXPECT_EQ(plain.resolved["loading"]["kind"], "bars");
  bars["loading"] = {{"kind", "bars"}};
  EXPECT_EQ(parse(bars).resolved, plain.resolved);
}

TEST_F(StrainRateScene, BadTablesNameTheCsvAndTheLine) {
  const std::string dirs = dir.str() + "/";
  expect(with_table("empty.csv", ""), dirs + "empty.csv", "", "");
  expect(with_table("header_only.csv", "time_s,strain_rate\n"), dirs + "header_only.csv", "", "");
  expect(with_table("one_row.csv", "0,100\n"), dirs + "one_row.csv", "", "at least 2 data rows");
  expect(with_table("nan.csv", "0,100\n1e-5,nan\n"), dirs + "nan.csv", "line 2", "not a finite number");
  expect(with_table("inf.csv", "0,inf\n1e-5,100\n"), dirs + "inf.csv", "line 1", "not a finite number");
  expect(with_table("order.csv", "time_s,strain_rate\n0,1\n2e-5,1\n1e-5,1\n"), dirs + "order.csv",
         "line 4", "time_s must be strictly increasing");
  expect(with_table("same.csv", "0,1\n1e-5,1\n1e-5,2\n"), dirs + "same.csv", "line 3",
         "strictly increasing");
  expect(with_table("one_col.csv", "0\n1e-5\n"), dirs + "one_col.csv", "line 1",
         "expected 2 columns (time_s, strain_rate), found 1");
  expect(with_table("three_col.csv", "0,1,2\n1e-5,1,2\n"), dirs + "three_col.csv", "line 1",
         "expected 2 columns");
  expect(with_table("pulse.csv", "time_s,stress_pa\n0,0\n1e-4,1e8\n"), dirs + "pulse.csv", "",
         "the header must read time_s,strain_rate");
  expect(with_table("early.csv", "-1e-6,0\n1e-5,100\n"), dirs + "early.csv", "line 1",
         "must start at >= 0");
  // A file that is not there is the scene's error, at the key.
  json missing = base();
  missing["loading"]["file"] = "nowhere.csv";
  expect(missing, "walls.json", "loading.file", "no such file");
}

TEST_F(StrainRateScene, BadSceneKeysNameTheJsonPath) {
  json j = base();
  j["loading"]["kind"] = "strain_rat";
  expect(j, "walls.json", "loading.kind", "did you mean 'strain_rate'");
  j = base();
  j["loading"].erase("file");
  expect(j, "walls.json", "loading.file", "required when loading.kind = strain_rate");
  // The walls replace bars and pulse: either given is unused, and named.
  j = base();
  j["bars"] = {{"incident", {{"length", 1.0}}}, {"transmission", {{"length", 1.0}}}};
  expect(j, "walls.json", "bars", "'bars' is unused with loading.kind = strain_rate");
  j = base();
  j["pulse"] = {{"kind", "trapezoid"}, {"amplitude", 1e8}, {"duration", 3e-4}};
  expect(j, "walls.json", "pulse", "'pulse' is unused with loading.kind = strain_rate");
  // A table under the bars is unused too.
  j = {{"loading", {{"kind", "bars"}, {"file", "rate.csv"}}},
       {"bars", {{"incident", {{"length", 1.0}}}, {"transmission", {{"length", 1.0}}}}},
       {"pulse", {{"kind", "trapezoid"}, {"amplitude", 1e8}, {"duration", 3e-4}}},
       {"specimen", {{"model", "elastic"}, {"constrained_modulus", 230e6}}},
       {"time", {{"end", 1e-3}}}};
  expect(j, "walls.json", "loading.file", "'file' is used only when loading.kind = strain_rate");
  j["loading"].erase("file");
  j["loading"]["end_at_back_stress"] = 72e6;
  expect(j, "walls.json", "loading.end_at_back_stress",
         "'end_at_back_stress' is used only when loading.kind = strain_rate");
  j = base();
  j["loading"]["end_at_back_stress"] = -1.0;
  expect(j, "walls.json", "loading.end_at_back_stress", ">= 0");
  j = base();
  j["specimen"] = {{"model", "elastic"}, {"constrained_modulus", 230e6}};
  expect(j, "walls.json", "specimen.model", "needs specimen.model = dem");
  j = base();
  j["specimen"]["preload_on_supports"] = true;
  expect(j, "walls.json", "specimen.preload_on_supports", "no bar supports");
  j = base();
  j["loading"]["rate"] = 1200;
  expect(j, "walls.json", "loading.rate", "unknown key 'rate'");
}

TEST(StrainRateHistory, TheAssemblyRefusesWhatTheSceneRefuses) {
  // Built by hand, without the scene: a column specimen, or a preload on the supports.
  shpb::ExperimentSpec spec;
  spec.strain_rate = shpb::StrainRateHistory({0, 1e-4}, {100, 100});
  auto path_of = [](const shpb::ExperimentSpec& s) {
    try {
      shpb::SimulatedShpb sim(s);
    } catch (const InputError& e) {
      return e.path();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(path_of(spec), "specimen.model");  // the default specimen is a 1-D column
  dem::DemSpecimenParams d;
  d.walls.preload_on_supports = true;
  spec.specimen = d;
  EXPECT_EQ(path_of(spec), "specimen.preload_on_supports");  // refused before packing
}

TEST(StrainRateHistory, RefusesWhatTheSceneRefuses) {
  // A library user without a scene gets the same rules, under loading.file.
  auto path_of = [](std::vector<double> t, std::vector<double> r) {
    try {
      shpb::StrainRateHistory h(std::move(t), std::move(r));
    } catch (const InputError& e) {
      return e.path();
    }
    return std::string("(accepted)");
  };
  EXPECT_EQ(path_of({0}, {1}), "loading.file");
  EXPECT_EQ(path_of({0, 1}, {1}), "loading.file");
  EXPECT_EQ(path_of({0, 0}, {1, 1}), "loading.file");
  EXPECT_EQ(path_of({-1, 0}, {1, 1}), "loading.file");
  EXPECT_EQ(path_of({0, 1}, {1, std::nan("")}), "loading.file");
  EXPECT_EQ(path_of({0, 1}, {1, 1}), "(accepted)");
}

}  // namespace
}  // namespace kolsky
