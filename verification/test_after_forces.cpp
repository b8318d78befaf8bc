// The loop's after-forces hook (shpb/assembly.hpp, time_loop::AfterForces; docs/breakage.md,
// "Time step"): every assembly steps in three calls, compute_forces, after_forces, advance, and
// the hook is the one place where breaks happen and a re-plan of dt may be asked for.
//  - strain-rate walls refining after breaks (time.refine_after_breaks, time.dt = 0): the
//    hook asks for a re-plan at exactly the steps whose check broke grains, and a loop written
//    from the contract alone (refine on a request, then advance with the schedule's dt) ends
//    bitwise where SimulatedShpb::run ends: same grains, same dt, same refinements;
//  - the same walls on the up-front rule: the hook breaks grains but never asks for a re-plan;
//  - an assembly without breakage (1-D bars and an elastic column): the hook is a no-op, and
//    the run keeps its planned dt;
//  - a DemSpecimen breaks only when its caller applies the breaks (apply_due_breaks between
//    forces() and advance()); advance() alone breaks nothing.
#include <gtest/gtest.h>

#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "dem/dem_specimen_params.hpp"
#include "scene/scene.hpp"
#include "shpb/one_dim_bars.hpp"
#include "shpb/simulation.hpp"
#include "shpb/strain_rate_walls.hpp"
#include "test_breaking_walls.hpp"
#include "test_support.hpp"
#include "time/explicit_loop.hpp"

namespace kolsky {
namespace {

using nlohmann::json;

// The breaking walls specimen of test_dt_refine.cpp (~250 grains, N = 5, sigma_lim0 1 GPa, no
// coordination limit) at 1200/s after a 10 us ramp: grains break within the first 20 us.
struct AfterForcesHook : ::testing::Test {
  testing::TempDir dir{"kolsky_test_after_forces"};
  scene::Scene walls(double end, bool refine) {
    std::ofstream(dir.file("rate.csv")) << "time_s,strain_rate\n0,0\n10e-6,1200\n1,1200\n";
    json j = testing::breaking_walls_scene("rate.csv", end);
    if (refine) j["time"]["refine_after_breaks"] = true;
    return scene::parse_scene(j, "walls.json", dir.str());
  }
};

std::uint64_t breaks_of(const shpb::StrainRateWallsAssembly& a) {
  return dem::n_breaks(a.specimen().breakage()->ledger);
}

TEST_F(AfterForcesHook, ReplanRequestsComeWithBreaksAndRefineAsTheRunDoes) {
  const scene::Scene sc = walls(30e-6, true);
  shpb::SimulatedShpb sim(sc.spec);
  const shpb::RunResult r = sim.run();
  ASSERT_TRUE(r.complete) << r.failure;
  ASSERT_GE(r.dt_refinements, 1);
  // The same steps from the contract alone: the hook, then a refinement if it asks.
  shpb::StrainRateWallsAssembly a(sc.spec);
  time_loop::Schedule s = sim.schedule();
  const double safety = shpb::default_safety_factor(sc.spec.specimen);
  long requests = 0, mismatches = 0;
  std::uint64_t before = 0;
  auto step = [&](long n, double t, double) {
    a.compute_forces(s.tick(n), t, shpb::RunControl{});
    const bool replan = a.after_forces().replan_dt;
    const bool broke = breaks_of(a) > before;
    before = breaks_of(a);
    requests += replan;
    mismatches += replan != broke;
    if (replan) time_loop::refine(s, n, a.stable_dt(), safety);
    a.advance(s.dt);
  };
  time_loop::run_loop_from(s, 0, step, [](double) {}, nullptr);
  RecordProperty("replan_requests", std::to_string(requests));
  EXPECT_EQ(mismatches, 0);  // a request at every step that broke grains, and only there
  EXPECT_GE(requests, r.dt_refinements);
  EXPECT_EQ(s.refinements, r.dt_refinements);
  EXPECT_EQ(s.dt, r.dt_final);
  const dem::Particles& run = sim.dem_specimen()->system().particles();
  const dem::Particles& own = a.specimen().system().particles();
  ASSERT_EQ(own.size(), run.size());
  EXPECT_EQ(std::memcmp(own.x.data(), run.x.data(), own.size() * sizeof(dem::Vec3)), 0);
  EXPECT_EQ(std::memcmp(own.v.data(), run.v.data(), own.size() * sizeof(dem::Vec3)), 0);
}

TEST_F(AfterForcesHook, UpFrontRuleBreaksWithoutAReplan) {
  shpb::StrainRateWallsAssembly a(walls(30e-6, false).spec);
  const double dt = 0.15 * a.stable_dt();
  const double limit = a.stable_dt();
  const auto n_steps = static_cast<long>(30e-6 / dt);
  long requests = 0;
  for (long n = 0; n < n_steps; ++n) {
    a.compute_forces(n, static_cast<double>(n) * dt, shpb::RunControl{});
    requests += a.after_forces().replan_dt;
    a.advance(dt);
  }
  RecordProperty("breaks", std::to_string(breaks_of(a)));
  ASSERT_GT(breaks_of(a), 0u);
  EXPECT_EQ(requests, 0);
  EXPECT_EQ(a.stable_dt(), limit);  // planned for the smallest daughter: the limit held
}

TEST(AfterForcesHookNoBreakage, OneDimBarsWithAColumnAreUnaffected) {
  const testing::TempDir dir;
  const json j = {{"bars", {{"kind", "characteristic"},
                            {"incident", {{"length", 2.0}, {"gauges", {1.0}}}},
                            {"transmission", {{"length", 1.0}, {"gauges", {0.5}}}}}},
                  {"pulse", {{"kind", "trapezoid"}, {"amplitude", 50e6}, {"rise_time", 20e-6},
                             {"duration", 100e-6}, {"fall_time", 20e-6}}},
                  {"specimen", {{"model", "elastic"}, {"constrained_modulus", 230e6}, {"n_elements", 10}}},
                  {"time", {{"end", 0.4e-3}}}};
  const shpb::ExperimentSpec spec = scene::parse_scene(j, "bars.json", dir.str()).spec;
  shpb::OneDimBarsAssembly a(spec);
  const double dt = 0.5 * a.stable_dt();
  for (long n = 0; n < 2000; ++n) {
    a.compute_forces(n, static_cast<double>(n) * dt, shpb::RunControl{});
    ASSERT_FALSE(a.after_forces().replan_dt) << n;
    a.advance(dt);
  }
  const shpb::RunResult r = shpb::SimulatedShpb(spec).run();
  ASSERT_TRUE(r.complete) << r.failure;
  EXPECT_EQ(r.dt_refinements, 0);
  EXPECT_EQ(r.dt_final, r.dt);
}

TEST_F(AfterForcesHook, ADemSpecimenBreaksOnlyWhenItsCallerAppliesTheBreaks) {
  const scene::Scene sc = walls(30e-6, false);
  const auto& params = std::get<dem::DemSpecimenParams>(sc.spec.specimen);
  dem::DemSpecimen skipped = dem::make_dem_specimen(params);
  dem::DemSpecimen applied = dem::make_dem_specimen(params);
  const std::size_t grains = skipped.system().particles().size();
  const double dt = 0.15 * applied.stable_dt();
  const double speed = 1200.0 * applied.length();  // the front wall at 1200/s from t = 0
  const auto n_steps = static_cast<long>(30e-6 / dt);
  std::size_t broken = 0;
  for (long n = 0; n < n_steps; ++n) {
    const FaceState faces{speed * static_cast<double>(n) * dt, 0.0, speed, 0.0};
    skipped.forces(faces);
    skipped.advance(dt);
    applied.forces(faces);
    broken += applied.apply_due_breaks();
    applied.advance(dt);
  }
  RecordProperty("breaks", std::to_string(broken));
  ASSERT_GT(broken, 0u);
  EXPECT_EQ(dem::n_breaks(applied.breakage()->ledger), broken);
  EXPECT_EQ(dem::n_breaks(skipped.breakage()->ledger), 0u);
  EXPECT_EQ(skipped.system().particles().size(), grains);
  EXPECT_GT(applied.system().particles().size(), grains);
}

}  // namespace
}  // namespace kolsky
