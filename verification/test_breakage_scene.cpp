// Breakage from the scene file (specimen.breakage) through a whole simulated test: a short
// SHPB run whose grains break completes (the energy check, which now books the energy of each
// replacement, does not fire), its probes count the breaks, and bad breakage input is refused
// naming the key; a fixed time.dt above the daughters' stable step is refused up front.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "scene/scene.hpp"
#include "shpb/simulation.hpp"

namespace kolsky {
namespace {

using nlohmann::json;

// Short bars, a strong pulse, coarse grains (N = 5) and a low strength: breaks within 150 us.
json breaking_scene(const json& breakage) {
  json specimen = {{"model", "dem"},
                   {"grain_size_curve", "data/digitized/chapter4/song2009_psd_reconstructed.csv"},
                   {"upscale", 5.0}, {"seed", 7}, {"length", 0.006}, {"diameter", 0.008}};
  if (!breakage.is_null()) specimen["breakage"] = breakage;
  return {{"bars", {{"incident", {{"length", 0.3}, {"gauges", {0.15}}}}, {"transmission", {{"length", 0.2}, {"gauges", {0.1}}}}}},
          {"pulse", {{"kind", "trapezoid"}, {"amplitude", 150e6}, {"rise_time", 10e-6}, {"duration", 60e-6},
                     {"fall_time", 10e-6}}},
          {"specimen", specimen},
          {"time", {{"end", 140e-6}}},
          {"output", {{"interval", 2e-6}}}};
}

shpb::ExperimentSpec spec_of(const json& j) { return scene::parse_scene(j, "breaking.json", KOLSKY_SOURCE_DIR).spec; }

std::string path_of_error(const json& breakage, const json& extra_specimen = json::object()) {
  json j = breaking_scene(breakage);
  j["specimen"].update(extra_specimen);
  try {
    shpb::SimulatedShpb sim(spec_of(j));
  } catch (const InputError& e) {
    return e.path();
  }
  return "";
}

TEST(BreakageScene, GrainsBreakDuringARunThatCompletes) {
  const json breakage = {{"sigma_lim0", 2.0e9}, {"coordination_limit", 0}};
  shpb::SimulatedShpb sim(spec_of(breaking_scene(breakage)));
  shpb::RunControl control;  // the grain-size curve at the snapshot steps (kolsky run's CSV)
  std::vector<psd::GrainSizeCurve> curves;
  control.snapshot_every = 4000;
  control.snapshot = [](long, double, const dem::Particles&) {};
  control.grain_size_curve = [&](long, double, const psd::GrainSizeCurve& c) { curves.push_back(c); };
  const shpb::RunResult r = sim.run(nullptr, control);
  ASSERT_TRUE(r.complete) << r.failure;
  const auto& primary = r.probe("broken_primary").value;
  const auto& count = r.probe("grain_count").value;
  const double breaks = primary.back() + r.probe("broken_secondary").value.back();
  RecordProperty("breaks", std::to_string(breaks));
  RecordProperty("grains", std::to_string(count.front()) + " -> " + std::to_string(count.back()));
  RecordProperty("relative_breakage", std::to_string(r.probe("relative_breakage").value.back()));
  EXPECT_GT(breaks, 0.0);
  const double before_loading = primary.front();  // the packing's residual forces alone
  EXPECT_EQ(count.back(), count.front() + 13.0 * (breaks - before_loading));  // each: -1 + 14 grains
  EXPECT_GT(r.probe("relative_breakage").value.back(), 0.0);
  EXPECT_GT(r.probe("lost_volume").value.back(), 0.0);
  ASSERT_GE(curves.size(), 3u);
  EXPECT_NO_THROW(curves.back().validate());  // ends at 100 %, non-decreasing
  // Fines appear below the smallest grain: passing at 2 x d_min of the fines grows from 0.
  EXPECT_EQ(psd::passing_at(curves.front(), 15e-6), 0.0);
  EXPECT_GT(psd::passing_at(curves.back(), 15e-6), 0.0);
  EXPECT_EQ(before_loading, 0.0) << "grains break under the packing's residual forces alone";
  // The ledger closes with the replacements booked: specimen + faces hold what entered through
  // the faces, within the 1 % of the incident wave's energy that the run's own check allows
  // (time.energy_tolerance x injected). Measured: 1.6e-5 of the incident energy; 0.99 % of the
  // (small) delivered energy with breakage, 0.50 % without (docs/breakage.md, "Energy").
  const double held = r.probe("energy_held").value.back(), delivered = r.probe("energy_delivered").value.back();
  const double incident = r.probe("w_incident").value.back();
  RecordProperty("energy_mismatch_over_delivered", std::to_string((held - delivered) / delivered));
  RecordProperty("energy_mismatch_over_incident", std::to_string((held - delivered) / incident));
  RecordProperty("insertion_over_delivered", std::to_string(r.probe("breakage_insertion_energy").value.back() / delivered));
  EXPECT_LT(std::fabs(held - delivered), 0.01 * incident);
  // Without the block: the same run has no breakage probes.
  shpb::SimulatedShpb plain(spec_of(breaking_scene(nullptr)));
  const shpb::RunResult q = plain.run();
  EXPECT_FALSE(q.has_probe("broken_primary"));
  const double q_held = q.probe("energy_held").value.back(), q_delivered = q.probe("energy_delivered").value.back();
  RecordProperty("plain_energy_mismatch_over_delivered", std::to_string((q_held - q_delivered) / q_delivered));
}

TEST(BreakageScene, BadBreakageInputNamesTheKey) {
  EXPECT_EQ(path_of_error({{"sigma_lim0", 0.0}}), "specimen.breakage.sigma_lim0");
  EXPECT_EQ(path_of_error({{"m1", -3.0}}), "specimen.breakage.m1");
  EXPECT_EQ(path_of_error({{"var_a", 0.0}}), "specimen.breakage.var_a");
  EXPECT_EQ(path_of_error({{"var_b", 0.5}}), "specimen.breakage.var_b");  // var(U=0) = -0.5/-1.22 > 0, var(U=1) < 0
  EXPECT_EQ(path_of_error({{"comminution_factor", 1.0}}), "specimen.breakage.comminution_factor");
  EXPECT_EQ(path_of_error({{"check_interval", 0}}), "specimen.breakage.check_interval");
  EXPECT_EQ(path_of_error({{"sigma_lim", 1e9}}), "specimen.breakage.sigma_lim");  // unknown key
  EXPECT_EQ(path_of_error(json::object(), {{"contact_law", "linear"}}), "specimen.breakage");
}

// The second criterion through the scene: the key selects it, its parameter reaches the
// engine (grains break in a run), and the other criterion's keys are refused under it.
TEST(BreakageScene, ConstantStressCriterionIsAScenesChoice) {
  const json breakage = {{"criterion", "constant_stress"}, {"characteristic_stress", 20e6}, {"coordination_limit", 0}};
  shpb::SimulatedShpb sim(spec_of(breaking_scene(breakage)));
  const shpb::RunResult r = sim.run();
  ASSERT_TRUE(r.complete) << r.failure;
  const double breaks = r.probe("broken_primary").value.back() + r.probe("broken_secondary").value.back();
  RecordProperty("breaks", std::to_string(breaks));
  EXPECT_GT(breaks, 0.0);
  EXPECT_EQ(path_of_error({{"criterion", "constant_stress"}, {"sigma_lim0", 1e9}}), "specimen.breakage.sigma_lim0");
  EXPECT_EQ(path_of_error({{"criterion", "constant_stress"}, {"characteristic_stress", 0.0}}),
            "specimen.breakage.characteristic_stress");
  EXPECT_EQ(path_of_error({{"characteristic_stress", 20e6}}), "specimen.breakage.characteristic_stress");
  EXPECT_EQ(path_of_error({{"criterion", "hertzian"}}), "specimen.breakage.criterion");
}

TEST(BreakageScene, FixedStepAboveTheDaughtersLimitIsRefused) {
  // The packed grains alone would allow this dt; their smallest possible daughter does not.
  json j = breaking_scene(nullptr);
  shpb::SimulatedShpb plain(spec_of(j));
  const double grains_only = plain.schedule().stable_dt;
  j["specimen"]["breakage"] = json::object();
  const double with_daughters = shpb::SimulatedShpb(spec_of(j)).schedule().stable_dt;
  ASSERT_LT(with_daughters, 0.5 * grains_only);
  j["time"]["dt"] = 0.9 * grains_only;
  try {
    shpb::SimulatedShpb sim(spec_of(j));
    ADD_FAILURE() << "unstable fixed dt accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "time.dt");
  }
}

}  // namespace
}  // namespace kolsky
