// Breakage inside the DEM engine over a busy run (dem/breakage_engine.hpp,
// DemSpecimen::enable_breakage), the busy compressed grains of dem_busy_scene.hpp:
//  - dozens of breaks give the same events and bitwise the same grains with 1 and 2 threads;
//  - a DemSpecimen restarted from a state saved after some breaks continues bitwise as the
//    uninterrupted run.
// The engine's decisions and a single replacement are in test_breakage_engine.cpp.
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>

#include "core/errors.hpp"
#include "dem/breakage_engine.hpp"
#include "dem/contact_hertz_mindlin.hpp"
#include "dem/dem_specimen.hpp"
#include "dem/dem_state.hpp"
#include "dem_busy_scene.hpp"

namespace kolsky::dem {
namespace {

HertzianContactCriterion& hc(BreakageParams& p) { return std::get<HertzianContactCriterion>(p.criterion); }

using test::kBusySand;
const HertzMindlinParams kHm{0.5, 0.5};

struct BusyRun {
  Particles grains;
  BreakageLedger ledger;
  std::vector<std::uint64_t> ids;
};

BusyRun busy_breaking_run(int threads, int steps) {
  omp_set_num_threads(threads);
  test::BusyScene scene;
  BreakageParams bp;
  hc(bp).sigma_lim0 = 0.2e9;  // critical overlaps ~0.4 um: the platen reaches them within 1000 steps
  bp.coordination_limit = 0;
  DemOptions opt = test::busy_options();
  opt.owner_block = 256;
  const Particles grains = test::busy_grains(scene);
  opt.smallest_radius_to_come = smallest_radius_to_come(bp, grains);
  DemSystem sys(grains, kBusySand, HertzMindlin(kBusySand, kHm), opt);
  const WallLaw hw = HertzMindlinWall(kBusySand, kBusySand[0], kHm);
  sys.add_plane({{0, 0, 0}, {0, 0, 1}, FixedPlane{}, hw});
  sys.add_plane({{0, 0, scene.top()}, {0, 0, -1}, PrescribedPlane{{{0.0}, {10.0}}}, hw});
  BreakageState s = start_breakage(bp, 17, sys.particles());
  const double dt = kDemStepFraction * sys.stable_dt();
  for (int n = 0; n < steps; ++n) {
    sys.step(dt);
    apply_breaks(sys, s, find_breaks(sys, s));
  }
  omp_set_num_threads(2);
  return {sys.particles(), s.ledger, s.id};
}

TEST(BreakageEngine, BusySceneBreaksTheSameWithOneAndTwoThreads) {
  const BusyRun one = busy_breaking_run(1, 1000), two = busy_breaking_run(2, 1000);
  RecordProperty("breaks", std::to_string(n_breaks(one.ledger)));
  RecordProperty("grains", std::to_string(one.grains.size()));
  EXPECT_GE(n_breaks(one.ledger), 24u);  // "dozens of breaks" (the issue)
  EXPECT_EQ(n_breaks(one.ledger), n_breaks(two.ledger));
  EXPECT_EQ(one.ledger.n_secondary, two.ledger.n_secondary);
  ASSERT_EQ(one.grains.size(), two.grains.size());
  EXPECT_EQ(one.ids, two.ids);
  EXPECT_EQ(std::memcmp(one.grains.x.data(), two.grains.x.data(), one.grains.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(one.grains.v.data(), two.grains.v.data(), one.grains.size() * sizeof(Vec3)), 0);
}

// The busy grains as a specimen between faces closing at 5 m/s each, breaking as they go.
DemSpecimen breaking_specimen() {
  test::BusyScene scene;
  BreakageParams bp;
  hc(bp).sigma_lim0 = 0.2e9;
  bp.coordination_limit = 0;
  const Particles grains = test::busy_grains(scene);
  DemOptions opt = test::busy_options();
  opt.smallest_radius_to_come = smallest_radius_to_come(bp, grains);
  SpecimenWalls walls;
  walls.length = scene.top() + scene.r;
  walls.radius = scene.tube_radius;
  DemSpecimen s(grains, kBusySand, HertzMindlin(kBusySand, kHm), walls, opt);
  bp.cadence.check_interval = 7;
  s.enable_breakage(bp, 17);  // the checkpoint at 120 falls between two checks
                              // (breaks at steps 50-400: 8 by 100, 18 by 400)
  return s;
}

void drive(DemSpecimen& s, int from, int to, double dt) {
  for (int n = from; n < to; ++n) {
    const double u = 5.0 * dt * n;
    s.forces(FaceState{u, u, 5.0, 5.0});
    s.apply_due_breaks();  // the caller's, between the forces and the step (as the run's hook)
    s.advance(dt);
  }
}

TEST(BreakageEngine, RestartAfterBreaksContinuesBitwise) {
  DemSpecimen whole = breaking_specimen();
  const double dt = kDemStepFraction * whole.stable_dt();
  drive(whole, 0, 1600, dt);
  DemSpecimen first = breaking_specimen();
  drive(first, 0, 120, dt);
  const DemSpecimenState saved = first.save_state();
  ASSERT_TRUE(saved.breakage.has_value());
  ASSERT_GT(saved.breakage->n_primary, 0u) << "no break before the checkpoint: the test proves nothing";
  DemSpecimen resumed = breaking_specimen();
  resumed.restore_state(saved);
  drive(resumed, 120, 1600, dt);
  const Particles &a = whole.system().particles(), &b = resumed.system().particles();
  RecordProperty("breaks_at_checkpoint", std::to_string(saved.breakage->n_primary + saved.breakage->n_secondary));
  RecordProperty("breaks_at_end", std::to_string(n_breaks(whole.breakage()->ledger)));
  EXPECT_GT(n_breaks(whole.breakage()->ledger), saved.breakage->n_primary + saved.breakage->n_secondary);
  EXPECT_EQ(n_breaks(whole.breakage()->ledger), n_breaks(resumed.breakage()->ledger));
  ASSERT_EQ(a.size(), b.size());
  EXPECT_EQ(whole.breakage()->id, resumed.breakage()->id);
  EXPECT_EQ(std::memcmp(a.x.data(), b.x.data(), a.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(std::memcmp(a.v.data(), b.v.data(), a.size() * sizeof(Vec3)), 0);
  EXPECT_EQ(whole.energy().internal_work, resumed.energy().internal_work);
  // A checkpoint without breakage state does not restore into a breaking specimen.
  DemSpecimenState plain = saved;
  plain.breakage.reset();
  DemSpecimen other = breaking_specimen();
  EXPECT_THROW(other.restore_state(plain), kolsky::InputError);
}

}  // namespace
}  // namespace kolsky::dem
