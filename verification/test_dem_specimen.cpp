// DemSpecimen against the bar/specimen interface (core/specimen_coupling.hpp): walls follow
// the face intrusions, forces are the walls' normal resultants (compression +), the energy it
// reports changes by the work the faces do, and bad input is refused with InputError.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>

#include "core/errors.hpp"
#include "dem/dem_specimen.hpp"
#include "dem/test_fills.hpp"

namespace kolsky::dem {
namespace {

const std::vector<Material> kSand{{78e9, 0.3, 2650}};
constexpr double kR = 1.5e-4, kA = 2 * kR * 1.0005;  // grain radius, lattice spacing
constexpr int kLayers = 12;

// A jittered simple-cubic column packing of ~750 grains filling a tube of radius 1.5 mm.
Particles column_packing(double radius) {
  const Particles lat = cubic_lattice(11, 11, kLayers, kR, kA, {-5 * kA, -5 * kA, kR * 1.001},
                                      0, kSand);
  std::mt19937_64 gen(3);
  Particles p;
  for (std::size_t i = 0; i < lat.size(); ++i) {
    const Vec3 x = lat.x[i];
    if (std::hypot(x.x, x.y) > radius - kR) continue;
    const double jitter = 1e-6 * (static_cast<double>(gen() % 1000) / 500.0 - 1.0);
    p.add(x + Vec3{jitter, -jitter, 0}, kR * (1 - 1e-3 * static_cast<double>(i % 3)), 0, kSand);
  }
  return p;
}

SpecimenWalls walls_for(double radius) {
  SpecimenWalls w;
  w.length = kLayers * kA + 2 * kR * 0.001;
  w.radius = radius;
  w.tube_compliance = TubeCompliance{200e9, 2e-4, 8100, w.length};
  return w;
}

TEST(TestDemSpecimen, FollowsTheFacesAndReportsWallForces) {
  const double radius = 1.5e-3;
  const SpecimenWalls w = walls_for(radius);
  DemSpecimen s(column_packing(radius), kSand, HertzMindlin(kSand, {0.5, 0.5}), w);
  EXPECT_NEAR(s.area(), std::numbers::pi * radius * radius, 1e-18);
  EXPECT_EQ(s.length(), w.length);
  EXPECT_EQ(s.face_mass(), 0.0);
  EXPECT_EQ(s.stable_dt(), s.system().stable_dt());

  const double dt = 0.5 * (kDemStepFraction * s.stable_dt()), rate = 1.0;  // face speed, m/s (~270/s)
  FaceState faces;
  FaceForces f = s.forces(faces);
  const double e0 = s.energy().total();
  double work = 0, max_force = 0;
  const int n = 1600;  // 36 us: ~1 % strain, many wave transits (quasi-static)
  for (int k = 0; k < n; ++k) {
    s.advance(dt);
    FaceState next = faces;
    next.intrusion_front += rate * dt;
    next.rate_front = rate;
    const FaceForces g = s.forces(next);
    work += 0.5 * (f.front + g.front) * (next.intrusion_front - faces.intrusion_front);
    faces = next;
    f = g;
    max_force = std::max(max_force, g.front);
  }
  const DemSystem& sys = s.system();
  EXPECT_EQ(f.front, sys.plane_force(s.front_plane()));
  EXPECT_EQ(f.back, sys.plane_force(s.back_plane()));
  EXPECT_EQ(sys.plane_offset(s.front_plane()), faces.intrusion_front);
  EXPECT_EQ(sys.plane_offset(s.back_plane()), 0.0);
  EXPECT_NEAR(s.mean_strain(), faces.intrusion_front / w.length, 1e-15);
  EXPECT_TRUE(s.finite());
  EXPECT_GT(f.front, 0.0);  // compression positive
  // Quasi-static: the back wall carries the front wall's load. why 10 %: the wall forces
  // still ring with the last wave transits (~2 us) and the tube takes a little.
  EXPECT_NEAR(f.back / f.front, 1, 0.1);
  // Energy: total() changes by the faces' work. why 3 %: Mindlin's non-potential k_t(delta)
  // term and the O(dt) dashpot accounting (verify_dem_assembly measures both).
  const double de = s.energy().total() - e0;
  std::printf("  specimen: face work %.4e J, energy change %.4e J, F_front %.3f N, F_back "
              "%.3f N, tube u %.3e m, tube force %.3f N\n", work, de, f.front, f.back,
              sys.cylinder_displacement(0), sys.cylinder_force(0));
  EXPECT_GT(work, 0.0);
  EXPECT_NEAR(de / work, 1, 0.03);
}

TEST(TestDemSpecimen, RefusesBadInput) {
  const double radius = 1.5e-3;
  const SpecimenWalls w = walls_for(radius);
  DemSpecimen s(column_packing(radius), kSand, HertzMindlin(kSand, {0.5, 0.5}), w);
  s.forces({});
  try {
    s.advance(1.5 * s.stable_dt());
    ADD_FAILURE() << "dt above the stable limit accepted";
  } catch (const NumericalError& e) {
    EXPECT_NE(std::string(e.what()).find("above the stable limit"), std::string::npos);
  }
  Particles outside = column_packing(radius);
  outside.x[0].z = -1e-3;
  EXPECT_THROW(DemSpecimen(outside, kSand, HertzMindlin(kSand, {0.5, 0.5}), w), InputError);
  SpecimenWalls bad = w;
  bad.radius = 0;
  EXPECT_THROW(DemSpecimen(column_packing(radius), kSand, HertzMindlin(kSand, {}), bad),
               InputError);
}

}  // namespace
}  // namespace kolsky::dem
