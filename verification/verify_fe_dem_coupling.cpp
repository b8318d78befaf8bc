// FE-DEM coupling (coupling/fe_dem.hpp, docs/coupling.md): DEM grains against meshed FE bar
// faces and an FE tube wall. Force transfer (ring loads sum to the contact force), the rigid
// face against the plane wall, manufactured face and tube shapes against the interpolation
// formula, the coupled energy balance, thread-count determinism and the refused scenes.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <random>

#include "coupling/fe_dem.hpp"
#include "dem/dem_system.hpp"
#include "dem/test_fills.hpp"
#include "scene/scene.hpp"
#include "shpb/assembly.hpp"
#include "test_support.hpp"

namespace kolsky {
namespace {

using dem::Vec3;
const std::vector<dem::Material> kSand{{78e9, 0.3, 2650}};
constexpr double kR = 1.5e-4, kA = 2 * kR * 1.0001;  // grain radius, lattice spacing (m)
constexpr int kLayers = 12;
const double kLength = kLayers * kA + 2 * kR * 0.001;  // specimen length (m)

// Grains on a cubic lattice inside a tube of radius `radius`, kLayers deep, radii shrunk by
// 0, 0.1 or 0.2 % in turn (no overlap at the start: the packing stores no energy to release).
dem::Particles column(double radius) {
  const int n = static_cast<int>(2 * radius / kA);
  const dem::Particles lat = dem::cubic_lattice(n, n, kLayers, kR, kA, {-0.5 * (n - 1) * kA, -0.5 * (n - 1) * kA, kR * 1.001},
                                                0, kSand);
  dem::Particles p;
  for (std::size_t i = 0; i < lat.size(); ++i) {
    const Vec3 x = lat.x[i];
    if (std::hypot(x.x, x.y) > radius - 1.01 * kR) continue;
    p.add(x, kR * (1 - 1e-3 * static_cast<double>(i % 3)), 0, kSand);
  }
  return p;
}

// Linear grain springs with 5 % damping and friction: every energy share is booked exactly
// (no Mindlin non-potential part).
dem::ContactLaw grain_law() { return dem::linear_spring(2.6e6, 1.6e6, 0.3, 0.05, 0.05); }

dem::DemSpecimen specimen(double radius, dem::Particles grains) {
  dem::SpecimenWalls w;
  w.length = kLength;
  w.radius = radius;
  return dem::DemSpecimen(std::move(grains), kSand, grain_law(), w);
}

coupling::FeDemParams params(double radius, bool meshed_tube, int threads, double amplitude = 5e6,
                             double bar_length = 0.03) {
  coupling::FeDemParams p;
  const fe::LinearElastic steel{200e9, 0.3, 7850};
  p.fe.incident = {steel, bar_length, radius, {0.5 * bar_length}};
  p.fe.transmission = {steel, bar_length, radius, {0.5 * bar_length}};
  p.fe.bar_n_r = 3;
  p.fe.bar_element_length = 5e-4;
  p.fe.specimen_length = kLength;
  p.fe.specimen_radius = radius;
  if (meshed_tube) p.fe.tube = fe::MeshedTube{steel, 1e-3, 2 * kLength, 2, 16};
  const bar::TrapezoidPulse pulse{amplitude, 2e-6, 10e-6, 2e-6, 0.0};
  p.fe.applied_stress = [pulse](double t) { return pulse(t); };
  p.fe.threads = threads;
  return p;
}

// ---------------------------------------------------------------- ring loads
TEST(FeDemCoupling, RingLoadsSumToTheContactForceWithLinearShapes) {
  // One contact force F at station s on a 4-node face: the two nodal shares add to F (b = w F,
  // a = F - b: exact to the last bit or two) and their first moment about the axis is F s
  // (the linear shape functions' centroid property), for any s in the segment.
  dem::WallProfile face{{0.0, 0.5e-3, 1.0e-3, 1.5e-3}, {0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}};
  std::mt19937_64 gen(11);
  std::uniform_real_distribution<double> u(0.0, 1.0);
  double worst = 0;
  for (int k = 0; k < 200; ++k) {
    const double s = 1.5e-3 * u(gen), phi = 6.283185307179586 * u(gen);
    const Vec3 x{s * std::cos(phi), s * std::sin(phi), 1e-4};
    const Vec3 f{3.0 * (u(gen) - 0.5), 3.0 * (u(gen) - 0.5), -10.0 * u(gen)};
    coupling::RingLoads l(4);
    coupling::add_contact(l, face, s, x, f);
    double sz = 0, sr = 0, moment = 0;
    for (int a = 0; a < 4; ++a) sz += l.f_z[a], sr += l.f_r[a], moment += l.f_z[a] * face.station[a];
    const double f_r = (f.x * x.x + f.y * x.y) / s;
    EXPECT_DOUBLE_EQ(sz, f.z);  // 4 ulp: the sum of two shares of one force
    EXPECT_NEAR(sr, f_r, 1e-14 * 3.0);  // f_r recomputed here in another order
    EXPECT_NEAR(moment, f.z * s, 1e-13 * std::abs(f.z) * 1.5e-3);  // round-off of a few terms
    worst = std::max(worst, std::abs(sz - f.z) / std::abs(f.z));
    EXPECT_NEAR(l.torque_z, x.x * f.y - x.y * f.x, 1e-13 * 3 * 1.5e-3);  // the moment about z, kept aside
  }
  testing::record("ring_load_axial_sum_error", worst);
}

TEST(FeDemCoupling, SingleGrainPressedOnTheDeformingFaceLoadsItsNodesWithMinusItsForce) {
  // One grain inside the incident face's second segment, overlapping the face by 0.5 um, the
  // face bulged by the incident pulse: after each coupled step, the ring loads on the face
  // nodes sum to minus the grain's wall-contact force (axial: exactly the force's z part).
  const double radius = 1.5e-3;
  dem::Particles p;
  p.add({0.7e-3, 0.0, kR - 0.5e-6}, kR, 0, kSand);
  coupling::FeDemShpb m(params(radius, false, 1, 20e6), specimen(radius, std::move(p)));
  const double dt = 0.3 * m.stable_dt();
  double worst = 0;
  int loaded = 0;
  for (int n = 0; n < 60; ++n) {
    m.step(n * dt, dt);
    Vec3 f_grain{};
    int touching = 0;
    m.dem().system().for_each_wall_force(0, [&](int, const Vec3& f) { f_grain += f, ++touching; });
    const coupling::RingLoads& l = m.last_loads(fe::Surface::incident_face);
    double sz = 0, sr = 0;
    for (std::size_t a = 0; a < l.f_z.size(); ++a) sz += l.f_z[a], sr += l.f_r[a];
    if (touching == 0) continue;
    ++loaded;
    EXPECT_EQ(sz, -f_grain.z) << n;  // two shares of one force: exact here
    EXPECT_DOUBLE_EQ(sr, -f_grain.x);  // grain on the +x axis: radial = x
    EXPECT_EQ(m.face_force(0), f_grain.z);
    worst = std::max(worst, std::abs(sz + f_grain.z));
  }
  EXPECT_GT(loaded, 5);  // the grain is pushed off again within ~10 steps
  testing::record("single_grain_axial_sum_error_N", worst);
}

// ---------------------------------------------------------------- DEM geometry
TEST(FeDemCoupling, RigidlyMovingProfileActsAsTheMovingPlane) {
  // A grain falling at 1 m/s onto a plane that moves at 0.3 m/s into it: the plane driven by
  // drive_plane (the existing plane wall) and by a uniform profile (every node at the same
  // offset and speed) must give the same bounce. Agreement to 1e-12 relative: the two overlap
  // formulas round differently (r - (x - o) n vs r - x n + o), nothing else differs.
  auto run = [](bool profiled) {
    dem::Particles p;
    p.add({0.3e-3, 0.2e-3, kR + 2e-6}, kR, 0, kSand);
    p.v[0] = {0.05, 0.0, -1.0};
    dem::DemSystem sys(std::move(p), kSand, grain_law());
    const int k = sys.add_plane({{0, 0, 0}, {0, 0, 1}, dem::DrivenPlane{}, dem::linear_spring(dem::LinearParams{})});
    const double dt = 0.2 * sys.stable_dt(), v_plane = 0.3;
    double f_max = 0;
    for (int n = 0; n < 4000; ++n) {
      const double off = v_plane * n * dt;
      if (profiled)
        sys.drive_plane_profile(k, {{0.0, 1e-3, 2e-3}, {off, off, off}, {v_plane, v_plane, v_plane}, {0, 0, 0}});
      else
        sys.drive_plane(k, off, v_plane);
      sys.step(dt);
      f_max = std::max(f_max, sys.particles().f[0].z);
    }
    return std::make_tuple(sys.particles().x[0], sys.particles().v[0], f_max);
  };
  const auto [xa, va, fa] = run(false);
  const auto [xb, vb, fb] = run(true);
  EXPECT_GT(fa, 0.1);  // it did bounce (N)
  EXPECT_GT(va.z, 0.3);  // and leaves faster than the plane
  EXPECT_NEAR(xb.z, xa.z, 1e-12 * std::abs(xa.z));
  EXPECT_NEAR(vb.z, va.z, 1e-12 * std::abs(va.z));
  EXPECT_NEAR(vb.x, va.x, 1e-12 * std::abs(va.x));
  EXPECT_NEAR(fb, fa, 1e-12 * fa);
}

TEST(FeDemCoupling, ManufacturedFaceAndTubeShapesGiveTheInterpolatedOverlap) {
  // FE face nodes at r_a = a h (h = 0.5 mm) with u_z = c0 + c2 r^2 (a bulged face), tube
  // nodes at z_b with u_r = d0 + d1 sin(pi z / L): a grain at station s meets the surface at
  // the linear interpolation of the nodal values, so its overlap is
  //   face: r_g - (z_g - [(1 - w) u_a + w u_{a+1}]),  tube: r_g + rho - (R + [(1 - w) u_b + w u_{b+1}]),
  // to round-off (1e-15 m), and the normal force of the linear wall law is k_n x overlap. The
  // interpolation differs from the smooth shape by at most |u''| h^2 / 8 (here 2 c2 h^2 / 8).
  fe::Nodes nd;
  const double h = 0.5e-3, c0 = 1e-6, c2 = 0.5;  // c2 r^2: 1.1 um at r = 1.5 mm
  std::vector<int> face, wall;
  for (int a = 0; a <= 3; ++a) face.push_back(static_cast<int>(nd.add(a * h, 0.0)));
  for (std::size_t a = 0; a < nd.size(); ++a) nd.uz[a] = c0 + c2 * nd.r0[a] * nd.r0[a];
  const double R = 1.5e-3, d0 = 0.4e-6, d1 = 0.6e-6;
  for (int b = 0; b <= 8; ++b) wall.push_back(static_cast<int>(nd.add(R, b * kLength / 8)));
  for (int n : wall) nd.ur[n] = d0 + d1 * std::sin(std::numbers::pi * nd.z0[n] / kLength);
  for (auto& v : {&nd.vr, &nd.vz}) v->assign(nd.size(), 0.0);

  const double rho_face = 0.83e-3, z_tube = 0.37 * kLength;
  dem::Particles p;
  p.add({rho_face * 0.6, rho_face * 0.8, kR + c0 + c2 * rho_face * rho_face - 0.3e-6}, kR, 0, kSand);
  p.add({R - kR + 1.5e-6, 0.0, z_tube}, kR, 0, kSand);
  const dem::LinearParams wall_law;  // Table 4.1: k_n 2.6e6 N/m, no damping
  dem::DemSystem sys(std::move(p), kSand, grain_law());
  const int plane = sys.add_plane({{0, 0, 0}, {0, 0, 1}, dem::DrivenPlane{}, dem::linear_spring(wall_law)});
  dem::CylinderWall cyl;
  cyl.radius = R;
  cyl.law = dem::linear_spring(wall_law);
  sys.add_cylinder(cyl);
  const dem::WallProfile fp = coupling::face_profile(nd, face, coupling::FaceSide::front);
  const dem::WallProfile tp = coupling::tube_profile(nd, wall);
  sys.drive_plane_profile(plane, fp);
  sys.drive_cylinder(0, tp);
  sys.compute_forces();

  const auto [ka, wa] = fp.segment(rho_face);
  const double u_face = (1 - wa) * fp.offset[ka] + wa * fp.offset[ka + 1];
  const double overlap_face = kR - (sys.particles().x[0].z - u_face);
  const auto [kb, wb] = tp.segment(z_tube);
  const double u_tube = (1 - wb) * tp.offset[kb] + wb * tp.offset[kb + 1];
  const double overlap_tube = kR + (R - kR + 1.5e-6) - (R + u_tube);
  EXPECT_LE(std::abs(u_face - (c0 + c2 * rho_face * rho_face)), 2 * c2 * h * h / 8);
  double seen_face = -1, seen_tube = -1, fn_face = 0, fn_tube = 0;
  sys.for_each_touching_contact([](int, int, const Vec3&, double) {},
                                [&](int i, int slot, const Vec3&, double overlap, double fn) {
                                  (slot == 0 ? seen_face : seen_tube) = overlap;
                                  (slot == 0 ? fn_face : fn_tube) = fn;
                                  (void)i;
                                });
  EXPECT_NEAR(seen_face, overlap_face, 1e-15);
  EXPECT_NEAR(seen_tube, overlap_tube, 1e-15);
  EXPECT_GT(overlap_face, 0.2e-6);
  EXPECT_GT(overlap_tube, 0.0);
  EXPECT_NEAR(fn_face, wall_law.normal_stiffness * overlap_face, 1e-9 * fn_face);
  EXPECT_NEAR(fn_tube, wall_law.normal_stiffness * overlap_tube, 1e-9 * fn_tube);
  testing::record("face_overlap_m", overlap_face);
  testing::record("tube_overlap_m", overlap_tube);
}

// ---------------------------------------------------------------- coupled runs
TEST(FeDemCoupling, CoupledEnergyBalanceClosesAndOffAxisPartIsSmall) {
  // ~700 grains between 30 mm meshed bars in a meshed steel tube, a 20 MPa, 10 us pulse, 24 us:
  // the wave crosses the specimen and loads the transmission bar. Ledger: FE kinetic +
  // material work + DEM kinetic + stored + dissipated against the pulse's work.
  const double radius = 1.5e-3;
  coupling::FeDemShpb m(params(radius, true, 1, 20e6), specimen(radius, column(radius)));
  const double dt = 0.3 * m.stable_dt();
  const int n_steps = static_cast<int>(24e-6 / dt);
  double peak_back = 0;
  for (int n = 0; n < n_steps; ++n) {
    m.step(n * dt, dt);
    peak_back = std::max(peak_back, m.face_force(1) / m.specimen_area());
    if (getenv("FEDEM_DEBUG") && n % 200 == 0) {
      const coupling::FeDemEnergy e = m.energy();
      printf("%d fe_k %.3e fe_w %.3e dem_k %.3e dem_s %.3e dem_d %.3e app %.3e if %.3e F0 %.3e F1 %.3e\n", n, e.fe_kinetic,
             e.fe_material_work, e.dem_kinetic, e.dem_stored, e.dem_dissipated, e.applied_work, e.interface_work,
             m.face_force(0), m.face_force(1));
    }
  }
  const coupling::FeDemEnergy e = m.energy();
  const double rel = std::abs(e.balance_error()) / e.applied_work;
  const double dem_gain = e.dem_kinetic + e.dem_stored + e.dem_dissipated;
  testing::record("energy_balance_error", rel);
  testing::record("applied_work_J", e.applied_work);
  testing::record("dem_gain_J", dem_gain);
  testing::record("interface_work_J", e.interface_work);
  testing::record("face_off_axis_fraction", m.off_axis().face_fraction());
  testing::record("tube_off_axis_fraction", m.off_axis().tube_fraction());
  testing::record("peak_back_stress_Pa", peak_back);
  EXPECT_GT(peak_back, 0.5e6);         // the grains carried the load through
  EXPECT_GT(dem_gain, 1e-3 * e.applied_work);
  EXPECT_LT(rel, 2e-3);  // measured 5.8e-4: the lagged wall velocity in the dampers, O(dt)
  // The FE side's work of the ring loads is minus what the grains gained (to the same bound).
  EXPECT_NEAR(-e.interface_work, dem_gain, 2e-3 * e.applied_work);
  EXPECT_LT(m.off_axis().face_fraction(), 0.01);  // measured 8.8e-4
  EXPECT_LE(m.off_axis().tube_fraction(), 0.05);  // (a cubic lattice barely presses the tube)
}

TEST(FeDemCoupling, SameBitsOnOneAndTwoThreads) {
  // ~3000 grains (above the DEM's 2048-grain threshold for parallel loops) and the FE element
  // loop on 1 and 2 threads: 100 steps give bitwise the same faces, gauges and grains.
  const double radius = 2.5e-3;
  auto run = [&](int threads) {
    omp_set_num_threads(threads);
    // 6 mm bars: the wave reaches the grains after 1.2 us, within the 100 steps (~2 us).
    coupling::FeDemShpb m(params(radius, true, threads, 50e6, 0.006), specimen(radius, column(radius)));
    const double dt = 0.3 * m.stable_dt();
    for (int n = 0; n < 100; ++n) m.step(n * dt + 4e-6, dt);  // the pulse already at its plateau
    return std::make_tuple(m.face_force(0), m.gauge_strain(0, 0), m.dem().system().particles().x, m.tube_force());
  };
  const auto a = run(1), b = run(2);
  omp_set_num_threads(1);
  EXPECT_GT(std::get<2>(a).size(), 2048u);
  EXPECT_NE(std::get<0>(a), 0.0);
  EXPECT_EQ(std::get<0>(a), std::get<0>(b));
  EXPECT_EQ(std::get<1>(a), std::get<1>(b));
  EXPECT_EQ(std::get<3>(a), std::get<3>(b));
  for (std::size_t i = 0; i < std::get<2>(a).size(); ++i) ASSERT_EQ(std::get<2>(a)[i].z, std::get<2>(b)[i].z) << i;
}

// ---------------------------------------------------------------- scenes
class FeDemScene : public ::testing::Test {
 protected:
  void SetUp() override { std::ofstream(dir_.file("psd.csv")) << "diameter_m,percent_passing\n1e-4,0\n3e-4,50\n6e-4,100\n"; }
  static nlohmann::json scene(const nlohmann::json& extra) {
    nlohmann::json j = nlohmann::json::parse(R"({
      "bars": {"kind": "meshed", "mesh_radial": 2, "element_length": 0.004,
               "incident": {"length": 0.2, "diameter": 0.006, "gauges": [0.1]},
               "transmission": {"length": 0.2, "diameter": 0.006, "gauges": [0.1]}},
      "pulse": {"kind": "trapezoid", "amplitude": 5e6, "rise_time": 5e-6, "duration": 20e-6, "fall_time": 5e-6},
      "specimen": {"model": "dem", "grain_size_curve": "psd.csv", "upscale": 3,
                   "length": 0.004, "diameter": 0.006, "tube": "meshed", "tube_thickness": 0.002,
                   "tube_length": 0.008},
      "time": {"end": 1e-4}})");
    if (extra.is_object()) j.merge_patch(extra);
    return j;
  }
  InputError refused(const nlohmann::json& j) {
    return testing::input_error([&] { scene::parse_scene(j, "s.json", dir_.str()); });
  }
  testing::TempDir dir_{"kolsky_fedem"};
};

TEST_F(FeDemScene, MeshedBarsMeshedTubeAndDemBuildTheCoupledAssembly) {
  const scene::Scene s = scene::parse_scene(scene({}), "s.json", dir_.str());
  ASSERT_TRUE(s.spec.dem_tube.has_value());
  EXPECT_EQ(s.spec.dem_tube->thickness, 0.002);
  const shpb::ShpbAssembly a = shpb::make_assembly(s.spec);
  ASSERT_TRUE(std::holds_alternative<shpb::FeDemBarsAssembly>(a));
  EXPECT_TRUE(std::get<shpb::FeDemBarsAssembly>(a).model().fe().has_surface(fe::Surface::tube_wall));
  // Without specimen.tube: the grains' rigid cylinder inside the meshed bars.
  nlohmann::json rigid = scene({});
  rigid["specimen"].erase("tube");
  rigid["specimen"].erase("tube_thickness");
  rigid["specimen"].erase("tube_length");
  const shpb::ShpbAssembly b = shpb::make_assembly(scene::parse_scene(rigid, "s.json", dir_.str()).spec);
  ASSERT_TRUE(std::holds_alternative<shpb::FeDemBarsAssembly>(b));
  EXPECT_FALSE(std::get<shpb::FeDemBarsAssembly>(b).model().fe().has_surface(fe::Surface::tube_wall));
}

TEST_F(FeDemScene, UnsupportedCombinationsAreRefusedNamingTheKey) {
  const std::vector<std::pair<nlohmann::json, std::string>> cases = {
      {{{"bars", {{"kind", "sphere_chain"}, {"mesh_radial", nullptr}, {"element_length", nullptr}}}}, "specimen.tube"},
      {{{"specimen", {{"tube", "spring"}}}}, "specimen.tube"},
      {{{"specimen", {{"tube", "none"}}}}, "specimen.tube"},
      {{{"specimen", {{"hold_until_loaded", true}}}}, "specimen.hold_until_loaded"},
      {{{"specimen", {{"preload_on_supports", true}}}}, "specimen.preload_on_supports"},
      {{{"output", {{"snapshot_interval", 1e-6}}}}, "output.snapshot_interval"},
      {{{"specimen", {{"tube_length", 0.003}}}}, "specimen.tube_length"},
  };
  for (const auto& [patch, key] : cases) {
    const InputError e = refused(scene(patch));
    EXPECT_EQ(e.path(), key) << patch.dump() << ": " << e.what();
    EXPECT_EQ(e.file(), "s.json") << key;
  }
}

}  // namespace
}  // namespace kolsky
