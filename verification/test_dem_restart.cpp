// DEM checkpoint/restart (dem/dem_state.hpp): a run interrupted after T steps, whose state is
// saved and restored into a freshly built system, continues bitwise as the uninterrupted run,
// at the DemSystem level (between steps) and the DemSpecimen level (mid-step, as the bars
// leave it). A negative control drops the tangential histories and must differ, so the
// comparison can fail. A state of another system is refused.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "core/errors.hpp"
#include "dem/dem_specimen.hpp"
#include "dem/dem_state.hpp"
#include "dem_busy_scene.hpp"

namespace kolsky::dem {
namespace {

using test::kBusySand;
const test::BusyScene kScene{};  // ~400 grains, 9 x 9 x 9 lattice in a 1.3 mm tube
const std::vector<Material>& kSand = kBusySand;

Particles grains() { return test::busy_grains(kScene); }
DemOptions options() { return test::busy_options(); }
DemSystem busy_system() { return test::busy_system(kScene); }

template <class T>
bool same_bits(const std::vector<T>& a, const std::vector<T>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(T)) == 0;
}

// Every particle array and every wall/energy output, bitwise.
void expect_identical(const DemSystem& a, const DemSystem& b) {
  const Particles &p = a.particles(), &q = b.particles();
  EXPECT_TRUE(same_bits(p.x, q.x));
  EXPECT_TRUE(same_bits(p.v, q.v));
  EXPECT_TRUE(same_bits(p.omega, q.omega));
  EXPECT_TRUE(same_bits(p.f, q.f));
  EXPECT_TRUE(same_bits(p.torque, q.torque));
  const DemEnergy ea = a.energy(), eb = b.energy();
  EXPECT_EQ(ea.kinetic, eb.kinetic);
  EXPECT_EQ(ea.elastic, eb.elastic);
  EXPECT_EQ(ea.dissipated, eb.dissipated);
  EXPECT_EQ(ea.wall_work, eb.wall_work);
  for (int k = 0; k < a.n_planes(); ++k) EXPECT_EQ(a.plane_force(k), b.plane_force(k));
  EXPECT_EQ(a.cylinder_displacement(0), b.cylinder_displacement(0));
  EXPECT_EQ(a.cylinder_force(0), b.cylinder_force(0));
  EXPECT_EQ(a.n_contacts(), b.n_contacts());
  EXPECT_EQ(a.n_wall_contacts(), b.n_wall_contacts());
  EXPECT_EQ(a.time(), b.time());
}

TEST(TestDemRestart, SystemContinuesBitwiseAfterRestore) {
  constexpr int kHalf = 300;
  DemSystem whole = busy_system();
  const double dt = 0.5 * (kDemStepFraction * whole.stable_dt());
  for (int k = 0; k < 2 * kHalf; ++k) whole.step(dt);

  DemSystem first = busy_system();
  for (int k = 0; k < kHalf; ++k) first.step(dt);
  const DemState saved = first.save_state();
  EXPECT_GT(saved.pair_history.size(), 10u);  // friction histories are really carried
  EXPECT_GT(saved.wall_history.size(), 0u);
  DemSystem resumed = busy_system();
  resumed.restore_state(saved);
  for (int k = 0; k < kHalf; ++k) resumed.step(dt);
  EXPECT_GT(whole.n_rebuilds(), 3u);  // the lists were rebuilt during the run
  EXPECT_GT(whole.n_contacts(), 20u);
  expect_identical(whole, resumed);

  // Negative control: without the tangential histories the continuation differs.
  DemState no_history = saved;
  no_history.pair_i.clear();
  no_history.pair_j.clear();
  no_history.pair_history.clear();
  DemSystem forgetful = busy_system();
  forgetful.restore_state(no_history);
  for (int k = 0; k < kHalf; ++k) forgetful.step(dt);
  EXPECT_FALSE(same_bits(forgetful.particles().v, whole.particles().v));
}

TEST(TestDemRestart, SpecimenContinuesBitwiseFromMidStep) {
  SpecimenWalls w;
  w.length = kScene.top() + kScene.r;
  w.radius = kScene.tube_radius;
  w.tube_compliance = TubeCompliance{200e9, 2e-4, 8100, w.length};
  auto make = [&] {
    Particles p = grains();
    for (auto& x : p.x) x.z += 0.5 * kScene.r;  // centres strictly inside 0 < z < L
    return DemSpecimen(p, kSand, HertzMindlin(kSand, {0.5, 0.5}), w, options());
  };
  DemSpecimen whole = make(), first = make();
  const double dt = 0.5 * (kDemStepFraction * whole.stable_dt()), rate = 5.0;
  // forces(t^n) then advance(dt): the bars' order; the state is saved after advance().
  auto drive = [&](DemSpecimen& s, int from, int to) {
    for (int k = from; k < to; ++k) {
      const double x = rate * dt * k;
      s.forces({x, 0.5 * x, rate, 0.5 * rate});
      s.advance(dt);
    }
  };
  constexpr int kHalf = 120;
  drive(whole, 0, 2 * kHalf);
  drive(first, 0, kHalf);
  const DemSpecimenState saved = first.save_state();
  EXPECT_TRUE(saved.stepping);
  EXPECT_GT(saved.system.pending_dt, 0.0);
  DemSpecimen resumed = make();
  resumed.restore_state(saved);
  drive(resumed, kHalf, 2 * kHalf);
  expect_identical(whole.system(), resumed.system());
  EXPECT_EQ(whole.energy().internal_work, resumed.energy().internal_work);
  EXPECT_EQ(whole.mean_strain(), resumed.mean_strain());
}

TEST(TestDemRestart, RefusesAStateOfAnotherSystem) {
  DemSystem sys = busy_system();
  DemState s = sys.save_state();
  s.particles.x.pop_back();
  try {
    sys.restore_state(s);
    ADD_FAILURE() << "a state with another particle count was accepted";
  } catch (const InputError& e) {
    EXPECT_EQ(e.path(), "dem.state");
  }
  DemState t = sys.save_state();
  t.planes.pop_back();
  EXPECT_THROW(sys.restore_state(t), InputError);
}

}  // namespace
}  // namespace kolsky::dem
