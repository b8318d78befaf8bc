// dem::held_by_coordination, the diagnostic of the coordination limit (breakage_engine.hpp):
// a grain is counted exactly when find_breaks would break it but for c_lim, so it must count
// the loaded grain of a cluster with c_lim or more contacts and nothing else: not a grain that
// breaks (fewer contacts), not one below its force criterion, not a daughter, and nothing with
// the limit off. Exact counts: the cases are built so that each grain is clearly on one side.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "dem/breakage_engine.hpp"
#include "dem/contact_hertz_mindlin.hpp"
#include "dem_busy_scene.hpp"

namespace kolsky::dem {
namespace {

// A grain of 1 mm radius touched by n grains of 0.1 mm spread evenly over its surface (a
// Fibonacci sphere), each overlapping it by delta. The small grains are below the comminution
// limit (0.2 mm < 0.22 x d50 = 0.44 mm) and never count; each presses ~6 N at delta = 5 um,
// past the large grain's crushing force with the default parameters.
DemSystem loaded_grain(int n, double delta) {
  const double R = 1e-3, r = 1e-4, d = R + r - delta;
  Particles p;
  p.add({0, 0, 0}, R, 0, test::kBusySand);
  const double golden = std::numbers::pi * (3 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k) {
    const double z = 1 - 2 * (k + 0.5) / n, s = std::sqrt(1 - z * z), phi = golden * k;
    p.add({d * s * std::cos(phi), d * s * std::sin(phi), d * z}, r, 0, test::kBusySand);
  }
  DemSystem sys(p, test::kBusySand, HertzMindlin(test::kBusySand, HertzMindlinParams{0.5, 0.5}));
  sys.compute_forces();
  return sys;
}

TEST(BreakageHeld, CountsTheLoadedGrainThatTheLimitKeepsWhole) {
  const BreakageParams bp;  // c_lim = 8
  for (const int n : {8, 10}) {
    const DemSystem sys = loaded_grain(n, 5e-6);
    const BreakageState s = start_breakage(bp, 5, sys.particles());
    EXPECT_TRUE(find_breaks(sys, s).empty()) << n << " contacts";
    const HeldByCoordination held = held_by_coordination(sys, s);
    EXPECT_EQ(held.primary, 1u) << n << " contacts";
    EXPECT_EQ(held.primary_at_limit, n == 8 ? 1u : 0u) << n << " contacts";
  }
}

TEST(BreakageHeld, CountsNothingTheCriterionOrTheLimitDoesNotHold) {
  const BreakageParams bp;
  // Seven contacts: the grain breaks, so the limit holds nothing.
  const DemSystem seven = loaded_grain(7, 5e-6);
  const BreakageState s7 = start_breakage(bp, 5, seven.particles());
  EXPECT_EQ(find_breaks(seven, s7).size(), 1u);
  EXPECT_EQ(held_by_coordination(seven, s7).primary, 0u);
  // Eight contacts far below the crushing force: nothing to hold.
  const DemSystem light = loaded_grain(8, 1e-9);
  EXPECT_EQ(held_by_coordination(light, start_breakage(bp, 5, light.particles())).primary, 0u);
  // Eight loaded contacts with the limit off: the grain breaks and none is held.
  const DemSystem eight = loaded_grain(8, 5e-6);
  BreakageState off = start_breakage(bp, 5, eight.particles());
  off.params.coordination_limit = 0;
  EXPECT_EQ(find_breaks(eight, off).size(), 1u);
  EXPECT_EQ(held_by_coordination(eight, off).primary, 0u);
  // A daughter (generation 1) is not a grain of the initial specimen.
  BreakageState daughter = start_breakage(bp, 5, eight.particles());
  daughter.generation[0] = 1;
  EXPECT_EQ(held_by_coordination(eight, daughter).primary, 0u);
}

}  // namespace
}  // namespace kolsky::dem
