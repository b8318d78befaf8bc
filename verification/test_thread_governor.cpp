// The thread-count rule of DemSystem's step (time/thread_governor.hpp, issue 18) fed with
// made-up step times, so each branch is exercised without depending on the machine's clock;
// and a DemSystem whose governor switches between one and two threads every few steps gives
// bitwise the results of a fixed count (the choice changes the speed only).
#include <gtest/gtest.h>
#include <omp.h>

#include <cstring>
#include <functional>

#include "dem/dem_system.hpp"
#include "time/thread_governor.hpp"
#include "dem_busy_scene.hpp"

namespace kolsky::dem {
namespace {

using time_loop::ThreadGovernor;
using time_loop::ThreadGovernorOptions;

// Feeds `steps` steps whose time is seconds_for(threads) and returns how many of them ran with
// one thread.
long run_steps(ThreadGovernor& g, long steps, const std::function<double(int)>& seconds_for) {
  long single = 0;
  for (long k = 0; k < steps; ++k) {
    const int t = g.threads();
    single += t == 1;
    g.record(seconds_for(t));
  }
  return single;
}

const ThreadGovernorOptions kSmall{.window = 8, .first_probe = 64, .max_probe_interval = 512,
                                   .margin = 0.05};

TEST(ThreadGovernor, OneThreadAvailableNeverProbes) {
  ThreadGovernor g(1, kSmall);
  run_steps(g, 1000, [](int) { return 1.0; });
  EXPECT_EQ(g.threads(), 1);
  EXPECT_EQ(g.probes(), 0);
}

// Idle machine: two threads take 0.55 of one thread's time. The governor stays at two, and the
// probes at one thread thin out (the interval doubles up to max_probe_interval), so their
// share of the steps is small.
TEST(ThreadGovernor, IdleMachineKeepsTwoThreads) {
  ThreadGovernor g(2, kSmall);
  const long single = run_steps(g, 20000, [](int t) { return t == 2 ? 0.55 : 1.0; });
  EXPECT_EQ(g.threads(), 2);
  EXPECT_EQ(g.switches(), 0);
  EXPECT_GT(g.probes(), 5);
  // Probes of 8 steps at most every 512 steps after the ramp: well under 5 % of the steps.
  EXPECT_LT(static_cast<double>(single) / 20000, 0.05);
}

// One core busy: two threads take 2.5x one thread's time (measured 1.5-3.5x on pack_35k). The
// governor leaves two threads after its first window and two winning probes (four windows).
TEST(ThreadGovernor, BusyCoreSwitchesToOneThreadWithinFourWindows) {
  ThreadGovernor g(2, kSmall);
  run_steps(g, 3 * kSmall.window, [](int t) { return t == 2 ? 2.5 : 1.0; });
  EXPECT_EQ(g.threads(), 1);  // the confirming probe, still at one thread
  EXPECT_EQ(g.switches(), 0);
  run_steps(g, kSmall.window, [](int t) { return t == 2 ? 2.5 : 1.0; });
  EXPECT_EQ(g.threads(), 1);
  EXPECT_EQ(g.switches(), 1);
  const long single = run_steps(g, 20000, [](int t) { return t == 2 ? 2.5 : 1.0; });
  EXPECT_EQ(g.switches(), 1);
  EXPECT_GT(static_cast<double>(single) / 20000, 0.95);
}

// The other process ends: the next probe at two threads wins and the governor goes back.
TEST(ThreadGovernor, ReturnsToTwoThreadsWhenTheCoreFreesUp) {
  ThreadGovernor g(2, kSmall);
  run_steps(g, 5000, [](int t) { return t == 2 ? 2.5 : 1.0; });
  ASSERT_EQ(g.threads(), 1);
  run_steps(g, kSmall.max_probe_interval + 4 * kSmall.window,
            [](int t) { return t == 2 ? 0.55 : 1.0; });
  EXPECT_EQ(g.threads(), 2);
  EXPECT_EQ(g.switches(), 2);
}

// One window slowed by the host (3x, as another VM's burst) makes the next probe win once; the
// confirming probe loses, so the count stays, and the interval keeps growing.
TEST(ThreadGovernor, OneSlowWindowDoesNotSwitch) {
  ThreadGovernor g(2, kSmall);
  long step = 0;
  run_steps(g, 4000, [&](int t) {
    const bool spike = step++ < kSmall.window;  // the first window, at two threads
    return t == 2 ? (spike ? 3.0 : 0.55) : 1.0;
  });
  EXPECT_EQ(g.threads(), 2);
  EXPECT_EQ(g.switches(), 0);
}

// A governor started at one thread (the process's last choice, as DemSystem passes it) on an
// idle machine takes two threads back within four windows.
TEST(ThreadGovernor, StartsFromTheGivenCount) {
  ThreadGovernorOptions o = kSmall;
  o.start_threads = 1;
  ThreadGovernor g(2, o);
  EXPECT_EQ(g.threads(), 1);
  run_steps(g, 4 * kSmall.window, [](int t) { return t == 2 ? 0.55 : 1.0; });
  EXPECT_EQ(g.threads(), 2);
  EXPECT_EQ(g.switches(), 1);
  o.start_threads = 3;  // out of range: the largest count
  EXPECT_EQ(ThreadGovernor(2, o).threads(), 2);
}

// A difference inside the margin (3 % < 5 %) is noise: no switch, in either direction.
TEST(ThreadGovernor, DifferenceInsideTheMarginDoesNotSwitch) {
  ThreadGovernor g(2, kSmall);
  run_steps(g, 5000, [](int t) { return t == 1 ? 0.97 : 1.0; });
  EXPECT_EQ(g.threads(), 2);
  EXPECT_EQ(g.switches(), 0);
}

// The DemSystem side: a governor told to switch at every probe (margin -1e9: the other count
// always "wins") alternates the count every few steps, and the run is bitwise the fixed
// two-thread run (docs/dem.md, "Parallel determinism").
TEST(ThreadGovernor, SwitchingRunIsBitwiseTheFixedCountRun) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(2);
  const test::BusyScene scene{.cells = 17, .tube_radius = 2.5e-3, .tube_wall = 5e-4, .speed = 5.0};
  Particles out[2];
  long switches = 0;
  for (int adaptive : {0, 1}) {
    DemOptions opt = test::busy_options();
    opt.adapt_threads = adaptive != 0;
    opt.governor = {.window = 4, .first_probe = 4, .max_probe_interval = 4, .margin = -1e9};
    DemSystem sys = test::busy_system(scene, opt);
    const double dt = 0.5 * (kDemStepFraction * sys.stable_dt());
    for (int k = 0; k < 200; ++k) sys.step(dt);
    out[adaptive] = sys.particles();
    if (adaptive) switches = sys.thread_governor().switches();
  }
  omp_set_num_threads(saved);
  EXPECT_GT(switches, 10);  // the count really changed during the run
  const std::size_t bytes = out[0].size() * sizeof(Vec3);
  EXPECT_EQ(std::memcmp(out[0].x.data(), out[1].x.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(out[0].v.data(), out[1].v.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(out[0].omega.data(), out[1].omega.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(out[0].f.data(), out[1].f.data(), bytes), 0);
}

}  // namespace
}  // namespace kolsky::dem
