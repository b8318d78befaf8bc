// The wall concept (solver/dem/wall.hpp): gap, normal, velocity and R* of each shape at chosen
// points against hand values (numbers exact in binary, so the checks are exact), the slot
// rule of DemSystem's walls, and a grain against a plane and inside a cylinder given the same
// force, bit for bit, as the two hard-wired kernels it replaced (their formulas written out
// here from dem_forces.cpp before the change).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <variant>

#include "core/errors.hpp"
#include "dem/contact_hertz_mindlin.hpp"
#include "dem/dem_specimen_params.hpp"
#include "dem/dem_system.hpp"
#include "dem/wall.hpp"

namespace kolsky::dem {
namespace {

const std::vector<Material> kSand{{78e9, 0.3, 2650}};

void expect_vec(const Vec3& got, const Vec3& want) {
  EXPECT_EQ(got.x, want.x);
  EXPECT_EQ(got.y, want.y);
  EXPECT_EQ(got.z, want.z);
}

WallProfile profile(std::vector<double> station, std::vector<double> offset, std::vector<double> normal_speed,
                    std::vector<double> tangential_speed) {
  return {std::move(station), std::move(offset), std::move(normal_speed), std::move(tangential_speed)};
}

TEST(TestDemWall, PlaneGapNormalVelocity) {
  PlaneWall pw;
  pw.point = {0, 0, 1};
  pw.normal = {0, 0, 1};
  pw.motion = DrivenPlane{};
  Wall w = make_wall(pw);
  drive(std::get<Plane>(w.shape), 0.5, -2.0);  // surface at z = 1.5, moving down at 2 m/s
  const Vec3 x{0.25, -0.75, 2.25};
  EXPECT_EQ(gap_at(w, x, 0.125), 2.25 - 1.5 - 0.125);
  EXPECT_EQ(gap_at(w, {0, 0, 1.5}, 0.125), -0.125);  // overlap 0.125
  expect_vec(normal_at(w, x), {0, 0, -1});
  expect_vec(velocity_at(w, x), {0, 0, -2});
  EXPECT_EQ(contact_radius_at(w, x, 0.125), 0.125);
  // A FixedPlane cannot be driven.
  Plane fixed = std::get<Plane>(make_wall(PlaneWall{}).shape);
  EXPECT_THROW(drive(fixed, 0.0, 0.0), InputError);
}

TEST(TestDemWall, ProfiledPlaneUsesTheStationOfThePoint) {
  PlaneWall pw;  // through the origin, normal +z
  pw.motion = DrivenPlane{};
  Wall w = make_wall(pw);
  // Station = distance from the z axis: at rho = 1 the profile reads offset 0.5, normal speed
  // 3, radial speed 3.
  drive_profile(std::get<Plane>(w.shape), profile({0, 2}, {0, 1}, {2, 4}, {0, 6}));
  const Vec3 x{0, 1, 3};
  EXPECT_EQ(gap_at(w, x, 0.25), 3 - 0.25 - 0.5);
  expect_vec(normal_at(w, x), {0, 0, -1});
  expect_vec(velocity_at(w, x), {0, 3, 3});
  // Only a driven plane normal to z through the axis takes a profile.
  PlaneWall tilted = pw;
  tilted.normal = {1, 0, 0};
  Wall t = make_wall(tilted);
  EXPECT_THROW(drive_profile(std::get<Plane>(t.shape), profile({0, 1}, {0, 0}, {0, 0}, {0, 0})), InputError);
}

TEST(TestDemWall, CylinderGapNormalVelocityAndConcaveRadius) {
  CylinderWall cw;
  cw.cx = 0.5;
  cw.radius = 2;
  cw.compliance = TubeCompliance{};
  Wall w = make_wall(cw);
  Cylinder& c = std::get<Cylinder>(w.shape);
  EXPECT_GT(c.stiffness, 0);
  EXPECT_GT(c.mass, 0);
  c.u = 0.25;  // the ring has opened to R = 2.25, at 3 m/s
  c.u_dot = 3;
  const Vec3 x{0.5, -1, 7};  // 1 from the axis, on -y
  EXPECT_EQ(gap_at(w, x, 0.5), 2.25 - (0.5 + 1));
  expect_vec(normal_at(w, x), {0, -1, 0});
  expect_vec(velocity_at(w, x), {0, -3, 0});
  EXPECT_EQ(contact_radius_at(w, x, 0.5), 0.5 * 2.25 / (2.25 - 0.5));
  expect_vec(normal_at(w, {0.5, 0, 0}), {1, 0, 0});  // on the axis: any radial direction
  // The ring drifts by dt u_dot and is kicked by its force against its hoop spring.
  w.force = 1e3;
  const double u_dot = c.u_dot;
  kick(w, 1e-6);
  EXPECT_EQ(c.u_dot, u_dot + 1e-6 * (1e3 - c.stiffness * 0.25) / c.mass);
  drift(w, 0.0, 1e-6);
  EXPECT_EQ(c.u, 0.25 + 1e-6 * c.u_dot);
  EXPECT_THROW(drive_profile(c, profile({0, 1}, {0, 0}, {0, 0}, {0, 0})), InputError);  // compliant
}

TEST(TestDemWall, ProfiledCylinderUsesTheStationZ) {
  Wall w = make_wall(CylinderWall{0, 0, 2, std::nullopt, linear_spring(LinearParams{})});
  drive_profile(std::get<Cylinder>(w.shape), profile({0, 4}, {0, 0.5}, {0, 2}, {1, 3}));
  const Vec3 x{1, 0, 2};  // station z = 2: offset 0.25, normal speed 1, axial speed 2
  EXPECT_EQ(gap_at(w, x, 0.5), 2.25 - 1.5);
  expect_vec(velocity_at(w, x), {1, 0, 2});
  // A profile the lists were not built with has moved without bound; once built, not at all.
  EXPECT_EQ(moved_since_build(w), std::numeric_limits<double>::infinity());
  mark_built(w);
  EXPECT_EQ(moved_since_build(w), 0.0);
}

TEST(TestDemWall, SlotsKeepPlanesFirstWhateverTheOrderOfAdding) {
  Particles p;
  p.add({0, 0, 0.5e-3}, 0.25e-3, 0, kSand);
  DemSystem sys(p, kSand, linear_spring(LinearParams{}));
  EXPECT_EQ(sys.add_cylinder(CylinderWall{}), 0);
  EXPECT_EQ(sys.add_plane(PlaneWall{}), 0);
  EXPECT_EQ(sys.add_plane(PlaneWall{{0, 0, 1e-3}, {0, 0, -1}}), 1);
  ASSERT_EQ(sys.walls().size(), 3u);
  EXPECT_TRUE(std::holds_alternative<Plane>(sys.walls()[0].shape));
  EXPECT_TRUE(std::holds_alternative<Plane>(sys.walls()[1].shape));
  EXPECT_TRUE(std::holds_alternative<Cylinder>(sys.walls()[2].shape));
  EXPECT_EQ(sys.wall_slots().slot(WallKind::cylinder, 0), 2);
  EXPECT_EQ(sys.plane(1).normal.z, -1.0);
  EXPECT_THROW(sys.drive_plane(2, 0, 0), std::out_of_range);
}

// The kernels before the wall concept, written out (dem_forces.cpp's plane_forces and
// tube_forces at 7ce5bd7): the geometry of one grain-wall contact.
ContactGeometry old_geometry(double overlap, const Vec3& n, const Vec3& v_wall, double r_eff, double r, double m,
                             const Vec3& v, const Vec3& w) {
  ContactGeometry g;
  g.normal = n;
  g.overlap = overlap;
  const double a = r - overlap;
  g.v_contact = v_wall - v - a * cross(w, n);
  g.omega_rel = w;
  g.r_i = r;
  g.r_j = std::numeric_limits<double>::infinity();
  g.r_eff = r_eff;
  g.m_eff = m;
  return g;
}

// One grain touching a driven (profiled or flat) plane or a driven (profiled or rigid)
// cylinder, with Hertz-Mindlin walls (R* matters) and damping (the wall velocity matters):
// the force DemSystem gives is the old kernel's, bit for bit.
void expect_force_as_before(bool profiled) {
  const std::vector<Material>& m = kSand;
  const WallLaw law = HertzMindlinWall(m, m[0], {0.4, 0.7});
  const double r = 0.3e-3;
  const Vec3 v{0.1, -0.2, 0.3}, w{50, 20, -10};
  for (int shape = 0; shape < 2; ++shape) {
    Particles p;
    const Vec3 x = shape == 0 ? Vec3{0.7e-3, 0.4e-3, 1.27e-3} : Vec3{3.1e-3, 2.2e-3, 4e-3};
    p.add(x, r, 0, m, v, w);
    DemSystem sys(p, m, linear_spring(LinearParams{}));  // one grain: no pairs
    const WallProfile prof = profile({0, 2e-3, 5e-3}, {1e-6, 3e-6, -2e-6}, {0.5, -0.25, 0.125}, {0.3, 0.1, -0.2});
    ContactGeometry g;
    if (shape == 0) {
      PlaneWall pw{{0, 0, 1e-3}, {0, 0, 1}, DrivenPlane{}, law};
      sys.add_plane(pw);
      const double offset = 0.0123e-3, speed = 1.7;
      sys.drive_plane(0, offset, speed);
      if (profiled) sys.drive_plane_profile(0, prof);
      const Vec3 nw = pw.normal;
      const Vec3 base = pw.point + offset * nw;
      const double rho = std::hypot(x.x, x.y);
      const WallProfile::Sample a = prof.at(rho);
      const Vec3 e_rho{x.x / rho, x.y / rho, 0};
      const double overlap = profiled ? r - dot(x - pw.point, nw) + a.offset : r - dot(x - base, nw);
      const Vec3 v_wall = profiled ? a.normal_speed * nw + a.tangential_speed * e_rho : speed * nw;
      g = old_geometry(overlap, -nw, v_wall, r, r, p.mass[0], v, w);
    } else {
      const CylinderWall cw{0, 0, 4.1e-3, std::nullopt, law};
      sys.add_cylinder(cw);
      if (profiled) sys.drive_cylinder(0, prof);
      const double dx = x.x - cw.cx, dy = x.y - cw.cy;
      const double rho = std::sqrt(dx * dx + dy * dy);
      const WallProfile::Sample a = prof.at(x.z);
      const double radius = cw.radius + 0.0 + (profiled ? a.offset : 0.0);
      const double overlap = r + rho - radius;
      const Vec3 n{dx / rho, dy / rho, 0};
      const double r_eff = radius > r ? r * radius / (radius - r) : r;
      const Vec3 v_wall = profiled ? (0.0 + a.normal_speed) * n + Vec3{0, 0, a.tangential_speed} : 0.0 * n;
      g = old_geometry(overlap, n, v_wall, r_eff, r, p.mass[0], v, w);
    }
    ASSERT_GT(g.overlap, 0) << "the grain must touch the wall (shape " << shape << ")";
    Vec3 history{};
    const ContactResult want = std::get<HertzMindlinWall>(law).pair(0).force(g, history, 0.0);
    sys.compute_forces();
    SCOPED_TRACE(shape == 0 ? "plane" : "cylinder");
    ASSERT_EQ(sys.n_wall_contacts(), 1u);
    expect_vec(sys.particles().f[0], want.force);
    EXPECT_EQ(shape == 0 ? sys.plane_force(0) : sys.cylinder_force(0), want.normal_force);
    // The contact visit reports the overlap that produced the force.
    double seen = 0;
    sys.for_each_touching_contact([](int, int, const Vec3&, double) {},
                                  [&](int, int, const Vec3&, double overlap, double) { seen = overlap; });
    EXPECT_EQ(seen, g.overlap);
  }
}

TEST(TestDemWall, GrainAgainstPlaneAndInsideCylinderGivesTheForceOfBefore) { expect_force_as_before(false); }
TEST(TestDemWall, GrainAgainstProfiledWallsGivesTheForceOfBefore) { expect_force_as_before(true); }

TEST(WallFamily, OneSlotRuleAndOneDefault) {
  const WallSlots s{2, 1};  // a DemSpecimen: front and back planes, then the tube
  EXPECT_EQ(s.count(), 3);
  EXPECT_EQ(s.slot(WallKind::plane, 1), 1);
  EXPECT_EQ(s.slot(WallKind::cylinder, 0), 2);
  for (int w = 0; w < s.count(); ++w) EXPECT_EQ(s.slot(s.kind(w), s.index(w)), w);
  EXPECT_EQ(s.kind(2), WallKind::cylinder);
  // Every wall default is LinearParams{} (Table 4.1), written once.
  const LinearParams t41;
  for (const WallLaw& w : {SpecimenWalls{}.end_law, SpecimenWalls{}.tube_law, PlaneWall{}.law,
                           CylinderWall{}.law}) {
    const auto& l = std::get<LinearSpring>(w);
    EXPECT_EQ(l.normal.stiffness, t41.normal_stiffness);
    EXPECT_EQ(l.tangential.stiffness, t41.shear_stiffness);
    EXPECT_EQ(l.tangential.friction, t41.friction);
    EXPECT_EQ(name_of(w), "linear");
  }
  EXPECT_EQ(t41.normal_stiffness, 2.6e6);
  EXPECT_EQ(t41.shear_stiffness, 1.6e6);
  EXPECT_EQ(t41.friction, 0.3);
}

}  // namespace
}  // namespace kolsky::dem
