// Assembly-level checks of the DEM engine: energy conservation of a frictionless, undamped
// gas of spheres in a box of walls with the observed dt^2 order of the energy error; the energy
// ledger (kinetic + elastic + dissipated = initial + wall work) with friction, damping,
// rolling retardation and a moving wall; no contact missed by the Verlet list; and results
// bitwise independent of the number of OpenMP threads.
#include <gtest/gtest.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>

#include "dem/dem_system.hpp"
#include "dem/spatial_sort.hpp"
#include "dem/test_fills.hpp"
#include "dem_busy_scene.hpp"

namespace kolsky::dem {
namespace {

const std::vector<Material> kSand{{78e9, 0.3, 2650}};

// n spheres (r in [0.5, 1] mm) in a cube of side `side` closed by six planes.
DemSystem gas_in_box(int n, double side, double speed, const HertzMindlinParams& hp,
                     const WallLaw& walls, DemOptions opt = {}) {
  Particles p = random_packing(n, 5e-4, 1e-3, {{0, 0, 0}, {side, side, side}}, 7, 0, kSand);
  randomize_velocities(p, speed, 11);
  sort_spatially(p, 2e-3);
  DemSystem sys(p, kSand, HertzMindlin(kSand, hp), opt);
  const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const Vec3& a : axes) {
    sys.add_plane({{0, 0, 0}, a, FixedPlane{}, walls});
    sys.add_plane({side * a, -a, FixedPlane{}, walls});
  }
  return sys;
}

double total(const DemEnergy& e) { return e.kinetic + e.elastic + e.dissipated - e.wall_work; }

// Largest |E(t) - E(0)| / E(0) over a run of duration t_end with step dt.
double max_energy_error(double dt, double t_end) {
  const HertzMindlinParams hp{0.0, 1.0};
  DemSystem sys = gas_in_box(300, 0.013, 5.0, hp, HertzMindlinWall(kSand, kSand[0], hp));
  sys.compute_forces();
  const double e0 = total(sys.energy());
  double worst = 0;
  const int n = static_cast<int>(std::lround(t_end / dt));
  for (int k = 0; k < n; ++k) {
    sys.step(dt);
    worst = std::max(worst, std::abs(total(sys.energy()) - e0) / e0);
  }
  return worst;
}

TEST(VerifyDemAssembly, EnergyConservedWithDtSquaredDrift) {
  const double h = 1.2e-7, t_end = 1.2e-4;  // h ~ t_c / 20 for the smallest grains at 5 m/s
  const double e1 = max_energy_error(h, t_end), e2 = max_energy_error(h / 2, t_end),
               e3 = max_energy_error(h / 4, t_end);
  const double p1 = std::log2(e1 / e2), p2 = std::log2(e2 / e3);
  std::printf("  300 spheres, frictionless: max |dE|/E = %.3e, %.3e, %.3e at dt = h, h/2, h/4; "
              "observed orders %.2f, %.2f\n", e1, e2, e3, p1, p2);
  EXPECT_LT(e1, 1e-2);  // why: ~20 steps per contact keeps velocity Verlet well inside 1 %
  // why 1.7: velocity Verlet is second order; the Hertz force is only C^1 at first touch.
  EXPECT_GT(p1, 1.7);
  EXPECT_GT(p2, 1.7);
}

TEST(VerifyDemAssembly, EnergyLedgerClosesWithDissipation) {
  DemOptions opt;
  opt.rolling.factor_per_reference_step = 0.9999;  // strong retardation: exercises the ledger
  const HertzMindlinParams hp{0.5, 0.5};
  DemSystem sys = gas_in_box(300, 0.013, 5.0, hp, linear_spring(2e6, 1.5e6, 0.3, 0.2, 0.2), opt);
  // Replace nothing; add a seventh plane that moves into the box at 2 m/s for the work term.
  sys.add_plane({{0, 0, 0.013}, {0, 0, -1}, PrescribedPlane{{{0.0}, {2.0}}},
                 linear_spring(2e6, 1.5e6, 0.3)});
  sys.compute_forces();
  const double e0 = total(sys.energy()), dt = 5e-8;
  for (int k = 0; k < 4000; ++k) sys.step(dt);
  const DemEnergy e = sys.energy();
  const double scale = e.dissipated + std::abs(e.wall_work);
  std::printf("  ledger: kinetic %.4e, elastic %.3e, dissipated %.4e, wall work %.4e, "
              "imbalance %.2e J (%.2e of dissipated + |work|)\n", e.kinetic, e.elastic,
              e.dissipated, e.wall_work, total(e) - e0, (total(e) - e0) / scale);
  EXPECT_GT(e.dissipated, 0.1 * e0);  // the run must actually dissipate
  // why 3 %: Mindlin's k_t(delta) makes 1/2 k_t xi^2 a non-potential term (measured ~2 % of
  // the dissipation here, not shrinking with dt), plus the O(dt) accounting of dashpot work
  // with mid-step velocities (~0.8 % at this dt, halving with dt).
  EXPECT_LT(std::abs(total(e) - e0), 0.03 * scale);
}

TEST(VerifyDemAssembly, EnergyLedgerClosesForLinearContacts) {
  // Constant stiffnesses: the springs are potentials, so only the O(dt) dashpot accounting
  // remains; it must halve with dt.
  double imbalance[2];
  for (int level = 0; level < 2; ++level) {
    const std::vector<Material> mats = kSand;
    Particles p = random_packing(300, 5e-4, 1e-3, {{0, 0, 0}, {0.013, 0.013, 0.013}}, 7, 0, mats);
    randomize_velocities(p, 5.0, 11);
    const LinearSpring law = linear_spring(2e6, 1.5e6, 0.5, 0.2, 0.2);
    DemSystem sys(p, mats, law);
    const Vec3 axes[3] = {{1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
    for (const Vec3& a : axes) {
      sys.add_plane({{0, 0, 0}, a, FixedPlane{}, law});
      sys.add_plane({0.013 * a, -a, FixedPlane{}, law});
    }
    sys.add_plane({{0, 0, 0.013}, {0, 0, -1}, PrescribedPlane{{{0.0}, {2.0}}}, law});
    sys.compute_forces();
    const double e0 = total(sys.energy()), dt = 5e-8 / (1 << level);
    for (int k = 0; k < (4000 << level); ++k) sys.step(dt);
    const DemEnergy e = sys.energy();
    imbalance[level] = (total(e) - e0) / (e.dissipated + std::abs(e.wall_work));
  }
  std::printf("  linear ledger imbalance %.2e (dt), %.2e (dt/2)\n", imbalance[0], imbalance[1]);
  EXPECT_LT(std::abs(imbalance[0]), 0.015);  // why: O(dt) accounting, 0.8 % measured at dt
  EXPECT_LT(std::abs(imbalance[1]), 0.6 * std::abs(imbalance[0]));  // why: first order in dt
}

// Touching pairs by brute force, to compare with the Verlet list's count.
std::size_t brute_force_contacts(const Particles& p) {
  std::size_t n = 0;
  for (std::size_t i = 0; i < p.size(); ++i)
    for (std::size_t j = i + 1; j < p.size(); ++j) {
      const double c = p.radius[i] + p.radius[j];
      if (norm2(p.x[j] - p.x[i]) < c * c) ++n;
    }
  return n;
}

// 3281 grains in a confining tube between two planes, all physics on (friction, damping,
// rolling retardation, compliant tube, a moving plane): a slightly overlapping lattice with
// random velocities, big enough that every loop runs in parallel (DemSystem runs loops under
// 2048 items on one thread).
DemSystem busy_specimen() {
  return test::busy_system({.cells = 17, .tube_radius = 2.5e-3, .tube_wall = 5e-4, .speed = 5.0});
}

TEST(VerifyDemAssembly, OneAndTwoThreadsAgreeBitwise) {
  const int saved = omp_get_max_threads();
  Particles out[2];
  std::size_t rebuilds = 0;
  for (int threads : {1, 2}) {
    omp_set_num_threads(threads);
    DemSystem sys = busy_specimen();
    const double dt = 0.5 * (kDemStepFraction * sys.stable_dt());
    for (int k = 0; k < 300; ++k) sys.step(dt);
    out[threads - 1] = sys.particles();
    rebuilds = sys.n_rebuilds();
    EXPECT_GE(sys.n_pairs(), 2048u);  // so that the pair loop really runs on both threads
  }
  omp_set_num_threads(saved);
  EXPECT_GT(rebuilds, 2u);  // the list was rebuilt (history carried) during the run
  const std::size_t bytes = out[0].size() * sizeof(Vec3);
  EXPECT_EQ(std::memcmp(out[0].x.data(), out[1].x.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(out[0].v.data(), out[1].v.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(out[0].omega.data(), out[1].omega.data(), bytes), 0);
  EXPECT_EQ(std::memcmp(out[0].f.data(), out[1].f.data(), bytes), 0);
}

TEST(VerifyDemAssembly, VerletListMissesNoContact) {
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);  // one thread: keeps the check fast on a loaded machine
  DemSystem sys = busy_specimen();
  const double dt = 0.5 * (kDemStepFraction * sys.stable_dt());
  for (int k = 0; k < 100; ++k) {
    sys.step(dt);
    if (k % 25 == 24) {
      EXPECT_EQ(sys.n_contacts(), brute_force_contacts(sys.particles())) << k;
    }
  }
  EXPECT_GT(sys.n_contacts(), 0u);
  omp_set_num_threads(saved);
}

}  // namespace
}  // namespace kolsky::dem
