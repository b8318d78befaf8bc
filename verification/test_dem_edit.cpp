// DemSystem::edit (particle_edit.cpp): removing and adding grains between steps.
//  - An edit away from every contact (isolated spectator grains, some in the middle of the
//    index range so that every later grain's index shifts) leaves the busy grains' following
//    steps bitwise those of a run without the edit, with 1 and 2 threads: the owner blocks and
//    the histories are carried. A negative control (the same edit through mutable_particles(),
//    which drops the histories) must differ, so the comparison can fail.
//  - An edit that removes loaded grains keeps the other contacts' histories and closes the
//    energy ledger through DemEnergy::edited.
//  - Checkpoint/restart of an edited system (another particle count) continues bitwise.
//  - The locality re-sort keeps every grain and contact, and the returned map says where.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstring>

#include "core/errors.hpp"
#include "dem/contact_hertz_mindlin.hpp"
#include "dem/dem_state.hpp"
#include "dem_busy_scene.hpp"

namespace kolsky::dem {
namespace {

using test::kBusySand;

// A 14^3 jittered lattice (2,744 grains: above the 2048 at which loops go parallel) between
// two planes, no tube, with isolated spectator grains beside it (x = +6 mm) inserted after
// lattice grains `after`.
constexpr int kCells = 14;
const std::vector<int> kInsertAfter = {300, 1500, 2600};

Vec3 spectator_position(int k) { return {6e-3, 1e-3 * k, 1e-3}; }

Particles scene_grains(bool spectators) {
  test::BusyScene s;
  s.cells = kCells;
  s.tube_radius = 1.0;  // keeps the whole lattice
  const Particles lattice = test::busy_grains(s);
  Particles p;
  std::size_t next = 0;
  for (std::size_t i = 0; i < lattice.size(); ++i) {
    p.add(lattice.x[i], lattice.radius[i], 0, kBusySand, lattice.v[i], lattice.omega[i]);
    if (spectators && next < kInsertAfter.size() && static_cast<int>(i) == kInsertAfter[next])
      p.add(spectator_position(static_cast<int>(next++)), 1.4e-4, 0, kBusySand, {0.1, 0, 0});
  }
  return p;
}

DemSystem scene(bool spectators, double resort_fraction = 0.1) {
  DemOptions opt = test::busy_options();
  opt.owner_block = 256;  // several blocks, so a shifted index would change block membership
  opt.resort_added_fraction = resort_fraction;
  const HertzMindlinParams hp{0.5, 0.5};
  DemSystem sys(scene_grains(spectators), kBusySand, HertzMindlin(kBusySand, hp), opt);
  const WallLaw hw = HertzMindlinWall(kBusySand, kBusySand[0], hp);
  test::BusyScene s;
  s.cells = kCells;
  sys.add_plane({{0, 0, 0}, {0, 0, 1}, FixedPlane{}, hw});
  sys.add_plane({{0, 0, s.top()}, {0, 0, -1}, PrescribedPlane{{{0.0}, {10.0}}}, hw});
  return sys;
}

template <class T>
bool same_bits(const T* a, const T* b, std::size_t n) {
  return std::memcmp(a, b, n * sizeof(T)) == 0;
}

/// Every array of the lattice grains equals b's, bitwise (lattice grain i at in_a[i] in a and
/// in_b[i] in b).
bool lattice_identical(const DemSystem& a, const std::vector<int>& in_a, const DemSystem& b,
                       const std::vector<int>& in_b) {
  const Particles &p = a.particles(), &q = b.particles();
  for (std::size_t i = 0; i < in_a.size(); ++i) {
    const auto k = static_cast<std::size_t>(in_a[i]), m = static_cast<std::size_t>(in_b[i]);
    if (!same_bits(&p.x[k], &q.x[m], 1) || !same_bits(&p.v[k], &q.v[m], 1) ||
        !same_bits(&p.omega[k], &q.omega[m], 1) || !same_bits(&p.f[k], &q.f[m], 1) ||
        !same_bits(&p.torque[k], &q.torque[m], 1))
      return false;
  }
  return true;
}

std::vector<int> identity(std::size_t n) {
  std::vector<int> m(n);
  for (std::size_t i = 0; i < n; ++i) m[i] = static_cast<int>(i);
  return m;
}

/// Index in the spectator scene of lattice grain i.
std::vector<int> lattice_in_spectator_scene(std::size_t n_lattice) {
  std::vector<int> m(n_lattice);
  int shift = 0;
  for (std::size_t i = 0; i < n_lattice; ++i) {
    m[i] = static_cast<int>(i) + shift;
    for (int a : kInsertAfter) shift += static_cast<int>(i) == a ? 1 : 0;
  }
  return m;
}

ParticleEdit spectator_swap(const DemSystem& sys, const std::vector<int>& lattice_at) {
  ParticleEdit e;
  for (int a : kInsertAfter) e.removed.push_back(lattice_at[static_cast<std::size_t>(a)] + 1);
  for (int k = 0; k < 2; ++k)
    e.added.add({-6e-3, 1e-3 * k, 1.2e-3}, 1.3e-4, 0, sys.materials(), {0, -0.2, 0});
  return e;
}

constexpr int kBefore = 100, kAfter = 150;

TEST(TestDemEdit, EditAwayFromContactsLeavesTheFollowingStepsBitwise) {
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    // Both carry the spectators; only `edited` swaps them (3 out, 2 others in) mid-run.
    DemSystem plain = scene(true), edited = scene(true);
    const double dt = 0.5 * (kDemStepFraction * plain.stable_dt());
    const std::vector<int> at = lattice_in_spectator_scene(plain.particles().size() - kInsertAfter.size());
    for (int k = 0; k < kBefore; ++k) {
      plain.step(dt);
      edited.step(dt);
    }
    const EditMap map = edited.edit(spectator_swap(edited, at));
    std::vector<int> now(at.size());
    for (std::size_t i = 0; i < at.size(); ++i) now[i] = map.old_to_new[static_cast<std::size_t>(at[i])];
    EXPECT_NE(now.back(), at.back());  // indices did shift
    EXPECT_EQ(edited.particles().size() + 1, plain.particles().size());
    EXPECT_NE(edited.block_first(), plain.block_first());  // carried, not uniform
    for (int k = 0; k < kAfter; ++k) {
      plain.step(dt);
      edited.step(dt);
    }
    EXPECT_GT(plain.n_contacts(), 200u);  // a busy scene (283 touching pairs measured): histories matter
    EXPECT_TRUE(lattice_identical(edited, now, plain, at)) << threads << " thread(s)";
    EXPECT_EQ(edited.n_contacts(), plain.n_contacts());
  }
  omp_set_num_threads(2);
}

TEST(TestDemEdit, NegativeControlDroppingHistoriesDiffers) {
  // The same removal of the spectators by rewriting the arrays (mutable_particles): the count
  // changes, so the histories and the owner blocks start afresh.
  DemSystem plain = scene(true), dropped = scene(true);
  const double dt = 0.5 * (kDemStepFraction * plain.stable_dt());
  const std::vector<int> at = lattice_in_spectator_scene(plain.particles().size() - kInsertAfter.size());
  for (int k = 0; k < kBefore; ++k) {
    plain.step(dt);
    dropped.step(dt);
  }
  Particles lattice;
  const Particles& all = dropped.particles();
  for (int i : at) lattice.add(all.x[i], all.radius[i], 0, dropped.materials(), all.v[i], all.omega[i]);
  dropped.mutable_particles() = lattice;
  for (int k = 0; k < kAfter; ++k) {
    plain.step(dt);
    dropped.step(dt);
  }
  EXPECT_FALSE(lattice_identical(dropped, identity(at.size()), plain, at));
}

// Removes the 20 lattice grains with the largest contact force: loaded grains, as breakage does.
ParticleEdit remove_loaded(const DemSystem& sys) {
  std::vector<int> order(sys.particles().size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = static_cast<int>(i);
  const auto& f = sys.particles().f;
  std::partial_sort(order.begin(), order.begin() + 20, order.end(),
                    [&](int a, int b) { return norm2(f[a]) > norm2(f[b]); });
  ParticleEdit e;
  e.removed.assign(order.begin(), order.begin() + 20);
  return e;
}

double ledger(const DemEnergy& e) { return e.kinetic + e.elastic + e.dissipated + e.edited - e.wall_work; }

TEST(TestDemEdit, RemovingLoadedGrainsKeepsOtherHistoriesAndClosesTheLedger) {
  DemSystem sys = scene(false);
  const double dt = 0.5 * (kDemStepFraction * sys.stable_dt());
  for (int k = 0; k < kBefore; ++k) sys.step(dt);
  const DemState before = sys.save_state();
  const DemEnergy e0 = sys.energy();
  const ParticleEdit e = remove_loaded(sys);
  const EditMap map = sys.edit(e);
  const DemState after = sys.save_state();
  // Every non-zero history of a pair of survivors is still there (a removed grain's are gone).
  std::size_t expected = 0, found = 0;
  double worst = 0;
  for (std::size_t k = 0; k < before.pair_i.size(); ++k) {
    const int a = map.old_to_new[before.pair_i[k]], b = map.old_to_new[before.pair_j[k]];
    if (a < 0 || b < 0) continue;
    ++expected;
    for (std::size_t m = 0; m < after.pair_i.size(); ++m) {
      if (after.pair_i[m] != a || after.pair_j[m] != b) continue;
      ++found;
      const Vec3 d = after.pair_history[m] - before.pair_history[k];
      worst = std::max(worst, std::sqrt(norm2(d) / norm2(before.pair_history[k])));
    }
  }
  EXPECT_GT(expected, 200u);  // 280 measured
  EXPECT_EQ(found, expected);
  // The edit evaluates the forces again at once (contacts were lost): that re-projects each
  // history on its unchanged tangent plane, a round-off change only.
  EXPECT_LT(worst, 1e-12);
  // Ledger: what the removed grains held went to `edited`, nothing was created.
  const DemEnergy e1 = sys.energy();
  EXPECT_GT(e1.edited, 0.0);
  EXPECT_NEAR(ledger(e1), ledger(e0), 1e-12 * std::fabs(ledger(e0)));
  EXPECT_EQ(sys.particles().size() + 20, before.particles.size());
}

TEST(TestDemEdit, EditedSystemRestartsBitwiseAndThreadsAgree) {
  omp_set_num_threads(2);
  DemSystem whole = scene(false);
  const double dt = 0.5 * (kDemStepFraction * whole.stable_dt());
  for (int k = 0; k < kBefore; ++k) whole.step(dt);
  whole.edit(remove_loaded(whole));
  for (int k = 0; k < 50; ++k) whole.step(dt);
  const DemState mid = whole.save_state();
  for (int k = 0; k < kAfter; ++k) whole.step(dt);

  DemSystem resumed = scene(false);  // built with the original count
  resumed.restore_state(mid);
  EXPECT_EQ(resumed.block_first(), mid.owner_blocks);
  for (int k = 0; k < kAfter; ++k) resumed.step(dt);
  const std::vector<int> same = identity(whole.particles().size());
  EXPECT_TRUE(lattice_identical(resumed, same, whole, same));
  EXPECT_EQ(resumed.energy().edited, whole.energy().edited);

  omp_set_num_threads(1);
  DemSystem serial = scene(false);
  for (int k = 0; k < kBefore; ++k) serial.step(dt);
  serial.edit(remove_loaded(serial));
  for (int k = 0; k < 50 + kAfter; ++k) serial.step(dt);
  omp_set_num_threads(2);
  EXPECT_TRUE(lattice_identical(serial, same, whole, same));
}

TEST(TestDemEdit, LocalityResortKeepsEveryGrainAndContact) {
  DemSystem sys = scene(false, 0.001);  // 0.1 %: three added grains already re-sort
  const double dt = 0.5 * (kDemStepFraction * sys.stable_dt());
  for (int k = 0; k < kBefore; ++k) sys.step(dt);
  const Particles old = sys.particles();
  const std::size_t contacts = sys.n_contacts();
  ParticleEdit e;
  for (int k = 0; k < 3; ++k) e.added.add({-6e-3, 1e-3 * k, 1.2e-3}, 1.3e-4, 0, sys.materials());
  const EditMap map = sys.edit(e);
  EXPECT_EQ(sys.n_resorts(), 1u);
  for (std::size_t i = 0; i < old.size(); ++i)
    ASSERT_EQ(sys.particles().x[map.old_to_new[i]].x, old.x[i].x);
  for (int k = 0; k < 3; ++k) EXPECT_EQ(sys.particles().x[map.added_at[k]].y, 1e-3 * k);
  EXPECT_EQ(sys.n_contacts(), contacts);
  sys.step(dt);  // and it runs on
  EXPECT_TRUE(sys.finite());
}

TEST(TestDemEdit, BadEditsAreRefused) {
  DemSystem sys = scene(false);
  ParticleEdit e;
  e.removed = {3, 3};
  try {
    sys.edit(e);
    FAIL() << "duplicate accepted";
  } catch (const InputError& err) {
    EXPECT_EQ(err.path(), "dem.edit.removed[1]");
  }
  e.removed = {-1};
  EXPECT_THROW(sys.edit(e), InputError);
  sys.begin_step(0.5 * (kDemStepFraction * sys.stable_dt()));
  e.removed = {1};
  EXPECT_THROW(sys.edit(e), std::logic_error);
}

}  // namespace
}  // namespace kolsky::dem
