// Hertz normal impact, sphere-sphere and sphere-rigid plane, against the closed forms
// (Johnson 1985, Sec. 11.4): delta_max = (15 m* v^2 / (16 E* sqrt(R*)))^{2/5},
// F_max = 4/3 E* sqrt(R*) delta_max^{3/2}, t_c = 2.8683 (m*^2 / (R* E*^2 v))^{1/5}; and the
// observed order of convergence of the three errors (and of the rebound speed) in dt.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "dem/impact.hpp"

namespace kolsky::dem {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

struct ImpactErrors {
  double overlap, force, time, speed;  // relative errors
};

// Glass spheres of Chung & Ooi test 1 (R = 10 mm, E = 48 GPa, nu = 0.2, rho = 2800) meeting at
// relative speed v (sphere-sphere) or one of them hitting a rigid plane at v.
ImpactErrors impact_errors(bool with_plane, double steps_per_contact) {
  const std::vector<Material> mats{{48e9, 0.2, 2800}};
  const double r = 0.01, v = with_plane ? 3.0 : 20.0;
  Particles p;
  p.add({0, 0, 0.0105}, r, 0, mats, {0, 0, with_plane ? -v : -0.5 * v});
  if (!with_plane) p.add({0, 0, -0.0105}, r, 0, mats, {0, 0, 0.5 * v});
  const HertzMindlinParams hp{0.0, 1.0};
  DemSystem sys(p, mats, HertzMindlin(mats, hp));
  const double mass = p.mass[0];
  HertzImpact theory{effective_modulus(mats[0], mats[0]), 0.5 * r, 0.5 * mass, v};
  if (with_plane) {
    const Material rigid{kInf, 0.0, 1.0};
    sys.add_plane({{0, 0, 0}, {0, 0, 1}, FixedPlane{}, HertzMindlinWall(mats, rigid, hp)});
    theory = {effective_modulus(mats[0], rigid), r, mass, v};
  }
  const double dt = theory.contact_time() / steps_per_contact;
  const ImpactRecord rec = run_impact(sys, dt, 100000);
  EXPECT_TRUE(rec.separated);
  const double rebound = std::abs(sys.particles().v[0].z - (with_plane ? 0.0 : sys.particles().v[1].z));
  return {rec.max_overlap / theory.max_overlap() - 1, rec.peak_force / theory.peak_force() - 1,
          rec.contact_time / theory.contact_time() - 1, rebound / v - 1};
}

void check_impact(bool with_plane) {
  const ImpactErrors e = impact_errors(with_plane, 400);
  // why 1e-4: at 400 steps per contact the O(dt^2) errors measure ~3e-6; an O(dt) defect
  // would show ~1e-3.
  const double tol = 1e-4;
  EXPECT_NEAR(e.overlap, 0, tol);
  EXPECT_NEAR(e.force, 0, tol);
  EXPECT_NEAR(e.time, 0, tol);
  EXPECT_NEAR(e.speed, 0, tol);
  std::printf("  Hertz %s, 400 steps/contact: rel. errors overlap %.2e force %.2e time %.2e "
              "rebound %.2e\n", with_plane ? "sphere-plane" : "sphere-sphere", e.overlap,
              e.force, e.time, e.speed);
}

TEST(VerifyDemHertz, SphereSphereClosedForms) { check_impact(false); }
TEST(VerifyDemHertz, SpherePlaneClosedForms) { check_impact(true); }

TEST(VerifyDemHertz, ObservedOrderInDt) {
  for (bool with_plane : {false, true}) {
    const ImpactErrors a = impact_errors(with_plane, 25), b = impact_errors(with_plane, 50),
                       c = impact_errors(with_plane, 100);
    auto order = [](double coarse, double fine) {
      return std::log2(std::abs(coarse) / std::abs(fine));
    };
    // Velocity Verlet is second order; the sampled maxima and the interpolated crossing
    // times keep O(dt^2). why 1.6: the Hertz force is only C^1 at first touch
    // (delta^{3/2}), which costs a little order at coarse steps.
    const double p_time = order(b.time, c.time), p_speed = order(b.speed, c.speed);
    const double p_overlap = order(b.overlap, c.overlap), p_force = order(b.force, c.force);
    std::printf("  %s: orders (25->50, 50->100 steps/contact) time %.2f %.2f, rebound %.2f "
                "%.2f, overlap %.2f %.2f, force %.2f %.2f\n",
                with_plane ? "sphere-plane" : "sphere-sphere", order(a.time, b.time), p_time,
                order(a.speed, b.speed), p_speed, order(a.overlap, b.overlap), p_overlap,
                order(a.force, b.force), p_force);
    EXPECT_GT(p_time, 1.6);
    EXPECT_GT(p_speed, 1.6);
    EXPECT_GT(p_overlap, 1.6);
    EXPECT_GT(p_force, 1.6);
  }
}

}  // namespace
}  // namespace kolsky::dem
