// Chapter 5's cases on the one case pipeline (reproductions/chapter5/ch5.hpp, make_case): what a
// driver says about a case (ch5::CaseSpec) becomes the pipeline's changes of the set's scene
// file, by the rules the set has always run its scenes with (fines_d_min scaled by N, breakage
// off at safety factor 0.3, the loading and seed overrides, --set items last), and every
// scene of the set so changed is one the reader accepts. The runs themselves are the chapter5
// smoke set, whose values the regression gate holds.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <string>

#include "chapter5/ch5.hpp"
#include "core/errors.hpp"

namespace kolsky::ch5 {
namespace {

const std::string kDir = std::string(KOLSKY_SOURCE_DIR) + "/reproductions/chapter5";

nlohmann::json file(const std::string& name) {
  std::ifstream f(kDir + "/" + name);
  EXPECT_TRUE(f) << name;
  return nlohmann::json::parse(f);
}

CaseSpec wang(double n) {
  CaseSpec s;
  s.label = "Wang N = " + std::to_string(n);
  s.scene = "scene_wang.json";
  s.upscale = n;
  s.sigma_lim0 = 3e9;
  s.end_time = 1e-4;
  s.fines_d_min = 7.5e-6;
  return s;
}

TEST(Chapter5Case, ASpecBecomesTheSetsChangesOfItsScene) {
  CaseSpec s = wang(2);
  s.coordination_limit = 0;
  s.loading_file = "../../data/digitized/chapter5/wang2018_strain_rate_held.csv";
  s.end_at_back_stress = 72e6;
  s.seed = 3;
  s.sets = {"specimen.breakage.sigma_lim0=4e9"};  // last: it wins over the spec's own
  const harness::Case c = make_case(s, kDir, "cache");
  EXPECT_EQ(c.label, s.label);
  EXPECT_EQ(c.scene, file("scene_wang.json"));  // the file as read, unperturbed
  EXPECT_EQ(harness::scene_dir(c), kDir);
  EXPECT_EQ(c.grain_size_curve_every, 1e-6);
  EXPECT_EQ(c.progress_lines, 10);
  nlohmann::json want = file("scene_wang.json");
  auto& sp = want["specimen"];
  sp["upscale"] = 2.0;
  sp["packing_cache"] = std::filesystem::absolute("cache").string();
  sp["breakage"]["coordination_limit"] = 0;
  sp["breakage"]["fines_d_min"] = 7.5e-6 * 2.0;  // the original sand's d_min, upscaled
  sp["breakage"]["sigma_lim0"] = 4e9;
  sp["seed"] = 3;
  want["time"]["end"] = 1e-4;
  want["loading"]["file"] = s.loading_file;
  want["loading"]["end_at_back_stress"] = 72e6;
  EXPECT_EQ(harness::final_scene(c), want);
  EXPECT_NO_THROW(harness::validate(c));
}

TEST(Chapter5Case, WithoutBreakageTheBlockGoesAndTheStepFactorIsChapter4s) {
  CaseSpec s = wang(1.5);
  s.breakage = false;
  s.coordination_limit = 0;  // a breakage key: not applied without breakage
  const nlohmann::json j = harness::final_scene(make_case(s, kDir, "cache"));
  EXPECT_FALSE(j["specimen"].contains("breakage"));
  EXPECT_EQ(j["time"]["safety_factor"].get<double>(), 0.3);
  EXPECT_NO_THROW(harness::validate(make_case(s, kDir, "cache")));
}

TEST(Chapter5Case, TheScenesOwnFactorScalesTheFinesWhenTheSpecKeepsIt) {
  CaseSpec s = wang(-1);  // keep the scene's N
  const double n = file("scene_wang.json")["specimen"]["upscale"].get<double>();
  const nlohmann::json j = harness::final_scene(make_case(s, kDir, "cache"));
  EXPECT_EQ(j["specimen"]["upscale"].get<double>(), n);
  EXPECT_EQ(j["specimen"]["breakage"]["fines_d_min"].get<double>(), 7.5e-6 * n);
}

TEST(Chapter5Case, EverySceneOfTheSetIsAcceptedAsChanged) {
  for (const char* scene : {"scene_wang.json", "scene_huang.json", "scene_song.json"})
    for (bool breakage : {true, false}) {
      CaseSpec s = wang(3);
      s.scene = scene;
      s.breakage = breakage;
      EXPECT_NO_THROW(harness::validate(make_case(s, kDir, "cache"))) << scene << " " << breakage;
      // perturbed by one ulp (make rebaseline): another scene, still one the reader accepts
      const harness::Case moved = make_case(s, kDir, "cache", 3);
      EXPECT_NE(moved.scene, file(scene));
      EXPECT_NO_THROW(harness::validate(moved)) << scene;
    }
}

// The ensemble makes each packing once (chapter5/set.hpp, run_packings): cases whose packing
// is the same must share its key, and only those.
TEST(Chapter5Case, CasesShareAPackingKeyExactlyWhenTheyShareThePacking) {
  const auto key = [](const CaseSpec& s) { return harness::packing_key(make_case(s, kDir, "cache")); };
  CaseSpec base = wang(3), nobreak = wang(3), clim0 = wang(3), other_sigma = wang(3), seed2 = wang(3);
  nobreak.breakage = false;
  clim0.coordination_limit = 0;
  other_sigma.sigma_lim0 = 5e9;
  seed2.seed = 2;
  const std::string k = key(base);
  EXPECT_EQ(k.size(), 16u);
  EXPECT_EQ(key(nobreak), k);
  EXPECT_EQ(key(clim0), k);
  EXPECT_EQ(key(other_sigma), k);
  EXPECT_NE(key(seed2), k);
  EXPECT_NE(key(wang(2.5)), k);
  harness::Case elastic;
  elastic.scene_path = std::string(KOLSKY_SOURCE_DIR) + "/data/examples/song2009_elastic.json";
  std::ifstream f(elastic.scene_path);
  elastic.scene = nlohmann::json::parse(f);
  EXPECT_EQ(harness::packing_key(elastic), "");  // not a DEM specimen: nothing to pack
}

TEST(Chapter5Case, ACaseThatCannotBeReadIsAFailureNotAThrow) {
  CaseSpec s = wang(3);
  s.scene = "no_such_scene.json";
  CaseResult r;
  EXPECT_NO_THROW(r = run_case(s, kDir, "cache"));
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.failure.find("no_such_scene.json"), std::string::npos) << r.failure;
  s = wang(3);
  s.sets = {"specimen.no_such_key=1"};  // the reader refuses it: a failure naming the key
  r = run_case(s, kDir, "cache");
  EXPECT_FALSE(r.ok);
  EXPECT_NE(r.failure.find("no_such_key"), std::string::npos) << r.failure;
}

}  // namespace
}  // namespace kolsky::ch5
