// Bad input named like every other (issue 17, "Bad input that is not named"): each case ends in
// an InputError naming the file, the dotted key (or the file line) and the rule, never in an
// internal error or a silent choice:
//  - JSON: a duplicate key (nlohmann keeps the last), a number beyond the double range, a NUL
//    in a key (the message stays whole), a folder given as the file;
//  - the step count: time.end / dt beyond time_loop::kMaxSteps, blamed on time.dt when the
//    stable step would not need so many;
//  - DEM packings that cannot be made: a porosity above 1 - the initial solid fraction, a
//    specimen too small for one grain (before any packing work);
//  - time.end before the wave can be analysed, found before the assembly is built;
//  - CSV: a decimal-comma export, a NaN in a gauge record (reported by its file line).
#include <gtest/gtest.h>

#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "core/errors.hpp"
#include "io/csv.hpp"
#include "scene/json_reader.hpp"
#include "scene/scene.hpp"
#include "shpb/gauge_processing.hpp"
#include "shpb/simulation.hpp"
#include "test_support.hpp"
#include "time/explicit_loop.hpp"

namespace kolsky {
namespace {

using nlohmann::json;

std::string write(const testing::TempDir& dir, const std::string& name, const std::string& text) {
  const std::string path = dir.file(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

using testing::input_error;

TEST(BadInput, DuplicateKeysAreRefusedNamingTheKey) {
  const testing::TempDir dir;
  const std::string top = write(dir, "top.json", R"({"time": {"end": 1e-3}, "time": {"end": 2e-3}})");
  InputError e = input_error([&] { scene::read_json_file(top); });
  EXPECT_EQ(e.path(), "time");
  EXPECT_NE(e.rule().find("duplicate key 'time'"), std::string::npos) << e.what();
  const std::string nested = write(dir, "nested.json",
                                   R"({"bars": {"incident": {"length": 2, "gauges": [1], "length": 3}}})");
  e = input_error([&] { scene::read_json_file(nested); });
  EXPECT_EQ(e.path(), "bars.incident.length");
  // Objects in arrays count their own keys; equal keys in sibling objects are fine.
  const std::string siblings = write(dir, "siblings.json", R"({"a": [{"k": 1}, {"k": 2}], "b": {"k": 3}})");
  EXPECT_NO_THROW(scene::read_json_file(siblings));
  const std::string in_array = write(dir, "in_array.json", R"({"a": [{"k": 1}, {"k": 2, "k": 3}]})");
  EXPECT_EQ(input_error([&] { scene::read_json_file(in_array); }).path(), "a[1].k");
}

// A scene nested 100,000 arrays deep used to end in "internal error: std::bad_alloc" (exit 1):
// the parser's key paths grew with the depth. Refused at kMaxJsonDepth, naming the file.
TEST(BadInput, DeeplyNestedDocumentsAreRefusedNamingTheFile) {
  const testing::TempDir dir;
  const std::string deep = write(dir, "deep.json", std::string(100000, '[') + std::string(100000, ']'));
  InputError e = input_error([&] { scene::read_json_file(deep); });
  EXPECT_EQ(e.file(), deep);
  EXPECT_NE(e.rule().find("nested more than 64 levels"), std::string::npos) << e.what();
  const std::string objects = write(dir, "objects.json", [] {
    std::string t;
    for (int k = 0; k < 65; ++k) t += "{\"a\": ";
    return t + "1" + std::string(65, '}');
  }());
  EXPECT_NE(input_error([&] { scene::read_json_file(objects); }).rule().find("nested"), std::string::npos);
  // 64 levels are still read.
  const std::string ok = write(dir, "ok.json", std::string(64, '[') + std::string(64, ']'));
  EXPECT_NO_THROW(scene::read_json_file(ok));
}

TEST(BadInput, NumbersBeyondTheDoubleRangeNameTheKey) {
  const testing::TempDir dir;
  const std::string scalar = write(dir, "s.json", R"({"time": {"end": 1e-3, "dt": 1e400}})");
  InputError e = input_error([&] { scene::read_json_file(scalar); });
  EXPECT_EQ(e.file(), scalar);
  EXPECT_EQ(e.path(), "time.dt");
  EXPECT_NE(e.rule().find("'1e400' is outside the range of a double"), std::string::npos) << e.what();
  const std::string item = write(dir, "a.json", R"({"bars": {"incident": {"gauges": [0.5, -1e999]}}})");
  EXPECT_EQ(input_error([&] { scene::read_json_file(item); }).path(), "bars.incident.gauges[1]");
}

TEST(BadInput, ControlCharactersInKeysDoNotCutTheMessage) {
  const testing::TempDir dir;
  const std::string f = write(dir, "nul.json", "{\"time\": {\"e\\u0000nd\": 1e-3}}");
  const json j = scene::read_json_file(f);
  const InputError e = input_error([&] { scene::parse_scene(j, f, dir.str()); });
  const std::string what = e.what();
  EXPECT_EQ(what.find('\0'), std::string::npos);
  EXPECT_NE(what.find("time.e\\u0000nd: unknown key 'e\\u0000nd'; did you mean 'end'?"),
            std::string::npos) << what;
}

TEST(BadInput, AFolderIsNotAFile) {
  const testing::TempDir dir;
  EXPECT_EQ(input_error([&] { scene::read_json_file(dir.str()); }).rule(), "is a directory, not a JSON file");
  EXPECT_EQ(input_error([&] { io::read_csv(dir.str()); }).rule(), "is a directory, not a CSV file");
}

TEST(BadInput, StepCountsBeyondTheLimitNameTheKey) {
  // {end, dt, safety, check, interval} against a stable step of 1 us.
  const double stable = 1e-6;
  InputError e = input_error([&] { time_loop::plan_steps({1e300, 0.0, 0.5, true, 1e-6}, stable); });
  EXPECT_EQ(e.path(), "time.end");
  EXPECT_NE(e.rule().find("more than the 1e+10"), std::string::npos) << e.what();
  EXPECT_EQ(input_error([&] { time_loop::plan_steps({6e-4, 1e-300, 0.5, true, 1e-6}, stable); }).path(),
            "time.dt");
  // A fixed dt at the stable step: the end time is at fault.
  EXPECT_EQ(input_error([&] { time_loop::plan_steps({1e300, 1e-6, 0.5, true, 1e-6}, stable); }).path(),
            "time.end");
  // At the limit itself, and a probe interval far beyond the run, plan without overflow.
  const time_loop::Schedule s = time_loop::plan_steps({1e4 - 2e-6, 1e-6, 0.5, true, 1e300}, stable);
  EXPECT_EQ(s.n_steps, 9'999'999'999L);
  EXPECT_EQ(s.sample_every, s.n_steps);
}

json dem_scene(double porosity, double diameter) {
  return {{"bars", {{"incident", {{"length", 0.6}}}, {"transmission", {{"length", 0.4}}}}},
          {"pulse", {{"kind", "trapezoid"}, {"amplitude", 20e6}, {"duration", 200e-6}}},
          {"specimen", {{"model", "dem"},
                        {"grain_size_curve", "data/digitized/chapter4/song2009_psd_reconstructed.csv"},
                        {"upscale", 5.0}, {"porosity", porosity}, {"length", 0.006}, {"diameter", diameter}}},
          {"time", {{"end", 2e-4}}}};
}

TEST(BadInput, DemPackingsThatCannotBeMadeAreRefusedWhileReading) {
  // Parsing only: both rules are checked before any packing work.
  InputError e = input_error([] { scene::parse_scene(dem_scene(0.8, 0.008), "s.json", KOLSKY_SOURCE_DIR); });
  EXPECT_EQ(e.path(), "specimen.porosity");
  EXPECT_EQ(e.rule(), "must be in (0, 0.75), got 0.8");
  e = input_error([] { scene::parse_scene(dem_scene(0.44, 0.0005), "s.json", KOLSKY_SOURCE_DIR); });
  EXPECT_EQ(e.path(), "specimen.diameter");
  EXPECT_NE(e.rule().find("the specimen holds no grain"), std::string::npos) << e.what();
  EXPECT_NO_THROW(scene::parse_scene(dem_scene(0.74, 0.008), "s.json", KOLSKY_SOURCE_DIR));
}

TEST(BadInput, AnEndBeforeTheWaveIsFoundWithoutBuildingTheAssembly) {
  // The DEM scene is not packed: require_reachable_end reads the bars alone.
  json j = dem_scene(0.44, 0.008);
  j["time"]["end"] = 1e-4;  // the wave reaches the specimen at 0.6 / 4969 = 121 us
  const shpb::ExperimentSpec spec = scene::parse_scene(j, "s.json", KOLSKY_SOURCE_DIR).spec;
  const InputError e = input_error([&] { shpb::require_reachable_end(spec); });
  EXPECT_EQ(e.path(), "time.end");
  EXPECT_NE(e.rule().find("reaches the specimen at L_I / c_I = 0.0001207 s"), std::string::npos) << e.what();
  j["time"]["end"] = 2e-4;
  EXPECT_NO_THROW(shpb::require_reachable_end(scene::parse_scene(j, "s.json", KOLSKY_SOURCE_DIR).spec));
}

TEST(BadInput, CsvMessagesGiveFileLinesAndSayWhatADecimalCommaLooksLike) {
  const testing::TempDir dir;
  const std::string comma = write(dir, "comma.csv", "# exported\n0,0;0,0\n0,5;1,2\n");
  InputError e = input_error([&] { io::read_csv(comma); });
  EXPECT_EQ(e.path(), "line 2");
  EXPECT_NE(e.rule().find("decimal-comma"), std::string::npos) << e.what();
  const std::string after_header = write(dir, "h.csv", "time_s,a\n0,0;1\n");
  EXPECT_NE(input_error([&] { io::read_csv(after_header); }).rule().find("decimal-comma"), std::string::npos);
  // A NaN in a gauge record: the row the processing names is the record's, which the
  // command maps to its file line (CLI case analyze); here the row itself.
  shpb::GaugeRecord rec;
  for (int i = 0; i < 400; ++i) {
    rec.t.push_back(i * 1e-6);
    rec.incident.push_back(i == 123 ? NAN : 0.0);
    rec.transmitted.push_back(0.0);
  }
  shpb::AnalysisSetup setup;
  setup.incident.gauge_distance = setup.transmission.gauge_distance = 1.0;
  try {
    shpb::process_gauges(rec, setup, shpb::GaugeOptions{});
    FAIL() << "no GaugeRowError";
  } catch (const shpb::GaugeRowError& g) {
    EXPECT_EQ(g.row, 123u);
  }
}

}  // namespace
}  // namespace kolsky
