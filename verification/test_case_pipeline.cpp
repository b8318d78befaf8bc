// The reproduction sets' one case pipeline (reproductions/harness/case_pipeline.hpp): changes
// are applied in order and as written, a change that cannot be applied is an InputError naming
// its key, the content key follows the final scene and nothing else, the Chapter 3 studies'
// merge patches give, as changes, the scenes merge_patch gives (so the port kept every value),
// and a short run hands back its outputs by name (probes on the history's clock, gauge
// stresses, progress lines).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <string>

#include "core/errors.hpp"
#include "harness/case_pipeline.hpp"
#include "scene/scene.hpp"
#include "test_support.hpp"

namespace kolsky::harness {
namespace {

using kolsky::testing::input_error;

const std::string kSource = KOLSKY_SOURCE_DIR;

nlohmann::json read(const std::string& path) {
  std::ifstream f(path);
  EXPECT_TRUE(f) << path;
  return nlohmann::json::parse(f);
}

Case elastic_case() {
  Case c;
  c.label = "elastic";
  c.scene_path = kSource + "/data/examples/song2009_elastic.json";
  c.scene = read(c.scene_path);
  return c;
}

TEST(HarnessCasePipeline, ChangesAreAppliedInOrder) {
  Case c = elastic_case();
  c.changes = {{"specimen.constrained_modulus", 100e6},
               {"specimen.constrained_modulus", 120e6},    // the later change wins
               {"output.nested.made", true},               // objects on the path are created
               {"title", nullptr},                         // null removes the key
               {"no_such.parent", nullptr}};               // removing what is not there: nothing
  c.packing_cache = "cache_dir";
  const nlohmann::json j = final_scene(c);
  EXPECT_EQ(j["specimen"]["constrained_modulus"].get<double>(), 120e6);
  EXPECT_TRUE(j["output"]["nested"]["made"].get<bool>());
  EXPECT_FALSE(j.contains("title"));
  EXPECT_FALSE(j.contains("no_such"));
  EXPECT_TRUE(std::filesystem::path(j["specimen"]["packing_cache"].get<std::string>()).is_absolute());
  EXPECT_EQ(j["specimen"]["length"], c.scene["specimen"]["length"]);  // the rest as written
  EXPECT_EQ(scene_dir(c), kSource + "/data/examples");

  const Case w = c.with("time.end", 1e-3, "shorter");
  EXPECT_EQ(w.label, "shorter");
  EXPECT_EQ(final_scene(w)["time"]["end"].get<double>(), 1e-3);
  EXPECT_EQ(c.changes.size() + 1, w.changes.size());

  const SceneChange p = parse_change("specimen.model=\"dem\"", "KOLSKY_CH4_SET");
  EXPECT_EQ(p.key, "specimen.model");
  EXPECT_EQ(p.value, "dem");
}

TEST(HarnessCasePipeline, ABadChangeIsAnInputErrorNamingItsKey) {
  Case c = elastic_case();
  c.changes = {{"specimen..length", 0.01}};
  InputError e = input_error([&] { final_scene(c); });
  EXPECT_EQ(e.path(), "specimen..length");
  EXPECT_EQ(e.file(), c.scene_path);
  EXPECT_NE(std::string(e.what()).find("empty part"), std::string::npos) << e.what();

  c.changes = {{"title.sub", 1}};  // title is a string
  e = input_error([&] { final_scene(c); });
  EXPECT_EQ(e.path(), "title.sub");
  EXPECT_NE(std::string(e.what()).find("string"), std::string::npos) << e.what();

  e = input_error([] { parse_change("specimen.length", "KOLSKY_CH4_SET"); });
  EXPECT_EQ(e.file(), "KOLSKY_CH4_SET");
  EXPECT_EQ(e.path(), "specimen.length");
  e = input_error([] { parse_change("specimen.model=dem", "--set"); });  // a string without quotes
  EXPECT_EQ(e.path(), "specimen.model");
  EXPECT_NE(std::string(e.what()).find("not JSON"), std::string::npos) << e.what();

  // A key the scene reader does not know: refused by validate, named by the reader.
  c.changes = {{"specimen.no_such_key", 1}};
  e = input_error([&] { validate(c); });
  EXPECT_NE(std::string(e.what()).find("no_such_key"), std::string::npos) << e.what();
  // ... and by run_case, which never throws: the refusal comes back with the failure.
  const CaseOutputs out = run_case(c);
  EXPECT_FALSE(out.ok);
  EXPECT_TRUE(out.refusal);
  EXPECT_NE(out.failure.find("no_such_key"), std::string::npos) << out.failure;
}

TEST(HarnessCasePipeline, TheContentKeyFollowsTheFinalSceneOnly) {
  const Case c = elastic_case();
  const std::string k0 = content_key(c);
  EXPECT_EQ(k0.size(), 16u);
  EXPECT_EQ(k0, content_key(c));
  // A change that changes the scene changes the key; one that writes the value already there,
  // a label, a packing cache folder or the same change written as a merge patch do not.
  EXPECT_NE(content_key(c.with("specimen.constrained_modulus", 231e6, "x")), k0);
  EXPECT_NE(content_key(c.with("time.end", 1e-3, "x")), content_key(c.with("time.end", 1.5e-3, "x")));
  EXPECT_EQ(content_key(c.with("specimen.constrained_modulus", c.scene["specimen"]["constrained_modulus"], "x")), k0);
  Case relabelled = c;
  relabelled.label = "another label";
  relabelled.packing_cache = "/tmp/somewhere_else";
  EXPECT_EQ(content_key(relabelled), k0);
  Case patched = c;
  patched.changes = changes_from_patch(nlohmann::json::parse(R"({"time": {"end": 1e-3}})"));
  EXPECT_EQ(content_key(patched), content_key(c.with("time.end", 1e-3, "x")));
  EXPECT_NE(binary_version().find("kolsky "), std::string::npos);
}

// Every merge patch of the Chapter 3 studies files, as changes, gives the scene merge_patch
// gives: the set's port to the pipeline runs the scenes it ran.
TEST(HarnessCasePipeline, Chapter3PatchesAsChangesGiveTheMergedScenes) {
  for (const std::string scale : {"smoke", "full"}) {
    Case c;
    c.scene_path = kSource + "/reproductions/chapter3/scene_" + scale + ".json";
    c.scene = read(c.scene_path);
    const nlohmann::json studies = read(kSource + "/reproductions/chapter3/studies_" + scale + ".json");
    std::vector<nlohmann::json> patches;
    for (const auto& cs : studies.at("cases")) patches.push_back(cs.at("patch"));
    for (const auto& lv : studies.at("levels").at("reduced")) patches.push_back(lv.at("patch"));
    nlohmann::json printed = studies.at("backcalc").at("level_patch");
    printed.merge_patch(studies.at("backcalc").at("printed_modulus_patch"));
    patches.push_back(printed);
    if (studies.contains("companions")) {
      nlohmann::json p6 = studies.at("backcalc").at("level_patch");
      p6.merge_patch(studies.at("companions").at("n_dependence").at("patch"));
      patches.push_back(p6);
    }
    ASSERT_GE(patches.size(), 5u);
    for (const auto& p : patches) {
      nlohmann::json merged = c.scene;
      merged.merge_patch(p);
      c.changes = changes_from_patch(p);
      EXPECT_EQ(final_scene(c), merged) << scale << ": " << p.dump();
    }
  }
  EXPECT_THROW(changes_from_patch(nlohmann::json::parse(R"({"a.b": 1})")), InputError);
}

TEST(HarnessCasePipeline, ARunHandsBackItsOutputsByName) {
  const Case c = elastic_case().with("time.end", 1.2e-3, "short elastic");
  const CaseOutputs out = run_case(c);
  ASSERT_TRUE(out.ok) << out.failure;
  EXPECT_EQ(out.label, "short elastic");
  EXPECT_EQ(out.content_key, content_key(c));
  EXPECT_FALSE(out.refusal);
  EXPECT_TRUE(out.analysis_failure.empty()) << out.analysis_failure;
  EXPECT_FALSE(out.history.t.empty());
  ASSERT_FALSE(out.faces.t.empty());
  EXPECT_EQ(out.faces.t.size(), out.faces.back.size());
  EXPECT_EQ(out.faces.t.size(), out.faces.front.size());
  EXPECT_EQ(out.faces.t.size(), out.faces.strain.size());
  EXPECT_GE(out.faces.t.front(), -1e-12);  // from the incident arrival on
  EXPECT_EQ(from_arrival(out.run, "stress_back"), out.faces.back);
  EXPECT_GT(out.run.steps, 0);
  EXPECT_EQ(out.dem.grains, 0u);  // not a DEM specimen
  EXPECT_GE(out.wall_s, out.run_s);
  EXPECT_GE(out.wall_s, out.build_s);
  EXPECT_THROW(pack(c), InputError);  // nothing to pack

  // The gauge stresses: -strain x E of each bar, on the run's clock.
  ASSERT_EQ(out.gauges.t, out.run.t);
  const auto spec = scene::parse_scene(final_scene(c), c.scene_path, scene_dir(c)).spec;
  const auto& strain_i = out.run.probe("incident_gauge_strain").value;
  const auto& strain_t = out.run.probe("transmission_gauge_strain").value;
  ASSERT_EQ(out.gauges.transmission.size(), out.run.t.size());
  for (std::size_t k = 0; k < out.run.t.size(); k += 50) {
    EXPECT_EQ(out.gauges.incident[k], -strain_i[k] * spec.incident.material.youngs_modulus);
    EXPECT_EQ(out.gauges.transmission[k], -strain_t[k] * spec.transmission.material.youngs_modulus);
  }
  EXPECT_GT(*std::max_element(out.gauges.incident.begin(), out.gauges.incident.end()), 0);  // compression positive
  // A probe on the history's samples (t = 0 at the arrival): the run's own sample there, up to
  // the round-off of shifting the clock by the arrival time and back.
  const std::vector<double> back = on_history(out, "stress_back");
  const auto& probe = out.run.probe("stress_back").value;
  ASSERT_EQ(back.size(), out.history.t.size());
  const double peak = std::abs(*std::max_element(probe.begin(), probe.end()));
  for (std::size_t k = 0; k < back.size(); k += 25) {
    const double at = out.history.t[k] + out.run.arrival_time;
    const auto j = std::min_element(out.run.t.begin(), out.run.t.end(),
                                    [at](double a, double b) { return std::abs(a - at) < std::abs(b - at); }) -
                   out.run.t.begin();
    EXPECT_NEAR(back[k], probe[j], 1e-9 * peak) << k;
  }

  // Progress lines: one per part of the run, headed by the label.
  ::testing::internal::CaptureStdout();
  Case talking = c;
  talking.progress_lines = 4;
  EXPECT_TRUE(run_case(talking).ok);
  const std::string said = ::testing::internal::GetCapturedStdout();
  EXPECT_NE(said.find("  short elastic: 25 % (t = "), std::string::npos) << said;
  EXPECT_NE(said.find("  short elastic: 75 % (t = "), std::string::npos) << said;

  // A time.end before the arrival: the solver refuses the scene; the case says so.
  const CaseOutputs early = run_case(c.with("time.end", 1e-5, "too short"));
  EXPECT_FALSE(early.ok);
  EXPECT_TRUE(early.refusal);
  EXPECT_NE(early.failure.find("time.end"), std::string::npos) << early.failure;
}

}  // namespace
}  // namespace kolsky::harness
