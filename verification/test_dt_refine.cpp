// The loop's step refined after a break (time_loop::refine; docs/breakage.md, "Time step"):
//  - the schedule alone: q is the smallest integer >= 2 that fits the new limit, the remaining
//    steps grow by q, every cadence (samples, checkpoints) keeps its times, the end time is
//    kept, a limit that still fits changes nothing, and an unrefined schedule reduces bitwise
//    to t^n = n dt and n % k == 0;
//  - a strain-rate-walls run whose grains break (time.dt = 0): the step is refined, the run
//    completes with its energy check on, its samples stay on the output grid, the final step
//    fits the limit of the grains present, and a checkpoint taken after a refinement restarts
//    bitwise through the checkpoint file; a fixed time.dt (or time.refine_after_breaks =
//    false) keeps the up-front rule (no refinement).
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>

#include "io/checkpoint_hdf5.hpp"
#include "scene/scene.hpp"
#include "shpb/simulation.hpp"
#include "test_breaking_walls.hpp"
#include "test_support.hpp"
#include "time/explicit_loop.hpp"

namespace kolsky {
namespace {

using nlohmann::json;

TEST(DtRefine, ScheduleKeepsEveryCadenceOnItsTimes) {
  // 1000 steps of 1 ns, a sample every 10 steps; refined at step 437 for a limit 3.3x lower.
  time_loop::Schedule s = time_loop::plan_steps({999e-9, 0.0, 0.5, true, 10e-9}, 2e-9);
  ASSERT_EQ(s.dt, 1e-9);
  ASSERT_EQ(s.n_steps, 1000);
  ASSERT_EQ(s.sample_every, 10);
  const time_loop::Schedule plan = s;
  for (long n : {0L, 1L, 437L, 999L}) {
    EXPECT_EQ(s.time_of(n), static_cast<double>(n) * s.dt);  // bitwise the unrefined formula
    EXPECT_EQ(s.due(n, 10), n % 10 == 0);
  }
  EXPECT_FALSE(time_loop::refine(s, 437, 2e-9, 0.5));  // still fits: unchanged
  EXPECT_EQ(s.refinements, 0);
  const double t437 = s.time_of(437);
  ASSERT_TRUE(time_loop::refine(s, 437, 2e-9 / 3.3, 0.5));
  EXPECT_EQ(s.ticks_per_planned_step, 4);  // ceil(3.3) = 4: the smallest integer that fits
  EXPECT_EQ(s.dt, 0.25e-9);
  EXPECT_LE(s.dt, 0.5 * 2e-9 / 3.3);
  EXPECT_EQ(s.time_of(437), t437);  // the step being taken keeps its time
  EXPECT_EQ(s.n_steps, 437 + 563 * 4);
  // Samples and a checkpoint cadence of 100 planned steps fall on the planned times.
  int samples_after = 0;
  for (long n = 437; n < s.n_steps; ++n) {
    if (s.due(n, 10)) {
      const long planned = 437 + (n - 437) / 4;
      EXPECT_EQ((n - 437) % 4, 0) << n;
      EXPECT_NEAR(s.time_of(n), plan.time_of(planned), 1e-21) << n;
      EXPECT_EQ(planned % 10, 0) << n;
      ++samples_after;
    }
    if (s.due(n, 100)) {
      EXPECT_NEAR(std::fmod(s.time_of(n) + 1e-13, 100e-9), 1e-13, 1e-18) << n;
    }
  }
  EXPECT_EQ(samples_after, 56);  // the planned samples at steps 440, 450, ..., 990
  // The end: the last step starts dt before the planned end of the run.
  EXPECT_NEAR(s.time_of(s.n_steps - 1) + s.dt, plan.time_of(plan.n_steps - 1) + plan.dt, 1e-21);
  // A second refinement compounds (q = 2 for a limit 1.5x lower), cadences still planned.
  ASSERT_TRUE(time_loop::refine(s, 1001, 2e-9 / 3.3 / 1.5, 0.5));
  EXPECT_EQ(s.ticks_per_planned_step, 8);
  for (long n = 1001; n < s.n_steps; ++n) {
    if (s.due(n, 10)) {
      EXPECT_NEAR(std::fmod(s.time_of(n) + 1e-13, 10e-9), 1e-13, 1e-18) << n;
    }
  }
  EXPECT_EQ(s.refinements, 2);
  // A limit that is not a positive number is a numerical failure, not a refinement.
  EXPECT_THROW(time_loop::refine(s, 1001, 0.0, 0.5), NumericalError);
  EXPECT_THROW(time_loop::refine(s, 1001, std::nan(""), 0.5), NumericalError);
}

struct DtRefineRun : ::testing::Test {
  testing::TempDir dir{"kolsky_test_dt_refine"};
  scene::Scene parse(double end, double dt = 0.0, bool refine = true) {
    std::ofstream(dir.file("rate.csv")) << "time_s,strain_rate\n0,0\n10e-6,1200\n1,1200\n";
    json j = testing::breaking_walls_scene("rate.csv", end);
    if (dt > 0) j["time"]["dt"] = dt;
    if (refine) j["time"]["refine_after_breaks"] = true;  // the default is the up-front plan
    return scene::parse_scene(j, "walls.json", dir.str());
  }
};

TEST_F(DtRefineRun, BreaksRefineTheStepAndTheRunStaysOnItsGrid) {
  const scene::Scene sc = parse(60e-6);
  shpb::SimulatedShpb sim(sc.spec);
  const shpb::RunResult r = sim.run();
  ASSERT_TRUE(r.complete) << r.failure;  // the energy check (time.check_stability) was on
  const double breaks = r.probe("broken_primary").value.back() + r.probe("broken_secondary").value.back();
  RecordProperty("breaks", std::to_string(breaks));
  RecordProperty("refinements", std::to_string(r.dt_refinements));
  RecordProperty("dt_planned_over_final", std::to_string(r.dt / r.dt_final));
  ASSERT_GT(breaks, 0.0);
  EXPECT_GE(r.dt_refinements, 1);
  EXPECT_LT(r.dt_final, r.dt);
  // The final step fits the limit of the grains present, with the scene's safety factor.
  const auto& walls = std::get<shpb::StrainRateWallsAssembly>(sim.assembly());
  const double safety = shpb::default_safety_factor(sc.spec.specimen);
  EXPECT_LE(r.dt_final, safety * walls.stable_dt() * (1 + 1e-12));
  // The samples stay on the planned output grid, k sample_every dt of the plan (to the
  // rounding of t_base + (n - n_base) dt: a few ulp of 60 us), and there are as many.
  const time_loop::Schedule& plan = sim.schedule();
  const double every = static_cast<double>(plan.sample_every) * plan.dt;
  for (std::size_t k = 0; k < r.t.size(); ++k) EXPECT_NEAR(r.t[k], every * static_cast<double>(k), 1e-18) << k;
  EXPECT_EQ(static_cast<long>(r.t.size()), (plan.n_steps - 1) / plan.sample_every + 1);
}

TEST_F(DtRefineRun, CheckpointAfterARefinementRestartsBitwise) {
  const scene::Scene sc = parse(40e-6);
  const shpb::RunResult full = shpb::SimulatedShpb(sc.spec).run();
  ASSERT_TRUE(full.complete) << full.failure;
  ASSERT_GE(full.dt_refinements, 1);
  // Checkpoints every 1000 planned steps; keep the last one, which follows a refinement.
  shpb::RunControl c;
  c.checkpoint_every = 1000;
  int refined_checkpoints = 0;
  c.checkpoint = [&](const shpb::ShpbState& s) {
    if (s.schedule.refinements == 0) return;
    io::write_checkpoint_hdf5(dir.file("ck.h5"), {{{"scene", sc.resolved}}, s});
    ++refined_checkpoints;
  };
  const shpb::RunResult written = shpb::SimulatedShpb(sc.spec).run(nullptr, c);
  ASSERT_TRUE(written.complete) << written.failure;
  ASSERT_GE(refined_checkpoints, 1);
  const io::Checkpoint ck = io::read_checkpoint_hdf5(dir.file("ck.h5"));
  shpb::RunControl resume;
  resume.resume = &ck.state;
  const shpb::RunResult again = shpb::SimulatedShpb(sc.spec).run(nullptr, resume);
  ASSERT_TRUE(again.complete) << again.failure;
  EXPECT_EQ(again.steps, full.steps);
  EXPECT_EQ(again.dt_final, full.dt_final);
  EXPECT_EQ(again.dt_refinements, full.dt_refinements);
  ASSERT_EQ(again.t, full.t);
  for (std::size_t k = 0; k < full.probes.size(); ++k) {
    const auto& a = full.probes[k].value;
    const auto& b = again.probes[k].value;
    EXPECT_TRUE(a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(double)) == 0)
        << full.probes[k].name;
  }
}

TEST_F(DtRefineRun, FixedStepKeepsTheUpFrontRule) {
  // time.dt given: the specimen plans for the smallest daughter from the start and the loop
  // never refines (the up-front limit is what a fixed dt is checked against).
  const double grains_only = shpb::SimulatedShpb(parse(20e-6).spec).schedule().stable_dt;
  const double daughters = shpb::SimulatedShpb(parse(20e-6, 1e-13).spec).schedule().stable_dt;
  EXPECT_LT(daughters, grains_only);  // the smallest daughter's limit, planned up front
  // time.refine_after_breaks = false (the default) plans the same with dt = 0.
  EXPECT_EQ(shpb::SimulatedShpb(parse(20e-6, 0.0, false).spec).schedule().stable_dt, daughters);
  const double dt = 0.5 * daughters;
  shpb::SimulatedShpb sim(parse(20e-6, dt).spec);
  const shpb::RunResult r = sim.run();
  ASSERT_TRUE(r.complete) << r.failure;
  EXPECT_EQ(r.dt_refinements, 0);
  EXPECT_EQ(r.dt_final, dt);
}

TEST_F(DtRefineRun, CheckPeriodKeepsTheChecksApartInTime) {
  // specimen.breakage.check_period: with the step refined mid-run, the grain count changes only
  // at checks, and checks lie at least the period apart in simulated time. Sampled every step
  // (output.interval below dt rounds to one step).
  std::ofstream(dir.file("rate.csv")) << "time_s,strain_rate\n0,0\n10e-6,1200\n1,1200\n";
  json j = testing::breaking_walls_scene("rate.csv", 40e-6);
  j["time"]["refine_after_breaks"] = true;
  j["output"]["interval"] = 1e-15;
  const double period = 2e-6;
  j["specimen"]["breakage"]["check_period"] = period;
  const shpb::RunResult r = shpb::SimulatedShpb(scene::parse_scene(j, "walls.json", dir.str()).spec).run();
  ASSERT_TRUE(r.complete) << r.failure;
  ASSERT_GE(r.dt_refinements, 1);
  const auto& count = r.probe("grain_count").value;
  std::vector<double> changes;  // t^n of the steps whose check broke grains (sampled after it)
  for (std::size_t k = 1; k < count.size(); ++k)
    if (count[k] != count[k - 1]) changes.push_back(r.t[k]);
  RecordProperty("break_events", std::to_string(changes.size()));
  ASSERT_GE(changes.size(), 3u);
  // Samples fall on planned steps only (the cadence keeps its times through a refinement), so
  // a break is seen up to one planned step after its check: that is the resolution here. The
  // step-counted default (50 steps, 0.1-0.9 us here) would put checks far closer together.
  const double resolution = r.dt * (1 + 1e-9);
  for (std::size_t k = 1; k < changes.size(); ++k)
    EXPECT_GE(changes[k] - changes[k - 1], period - resolution) << k << " at " << changes[k];
}

}  // namespace
}  // namespace kolsky
