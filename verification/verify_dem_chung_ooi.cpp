// The Chung & Ooi (2011, Granular Matter 13:643-656) DEM benchmark, tests 1-8, with the inputs
// of the public implementations (references.md Sec. 3; LIGGGHTS-PFM tests/contact_models/
// chung/test01-08). Rigid plane: a wall material with E = +inf, so E* = E/(1 - nu^2) and
// G* = G/(2 - nu) of the sphere alone (identical to LIGGGHTS' doubled-E wall; docs/dem.md).
// Expected outputs: Hertz closed forms (1-3), the rigid-body gross-sliding limits (4-8:
// Delta v_t = mu (1+e) v_n, Delta(R w) = 2.5 mu (1+e) v_n for a solid sphere), the published
// values the references list, and the model's own no-slip limit where the analytic Maw et al.
// curves depend on micro-slip that a Mindlin spring with a Coulomb cap does not represent.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>

#include "dem/impact.hpp"

namespace kolsky::dem {
namespace {

const Material kRigid{std::numeric_limits<double>::infinity(), 0.0, 1.0};
const Material kGlass{48e9, 0.20, 2800}, kLimestone{20e9, 0.25, 2500};
const Material kAlAlloy2{70e9, 0.30, 2699}, kMgAlloy{40e9, 0.35, 1800};
const Material kAlOxide{380e9, 0.23, 4000}, kCastIron{100e9, 0.25, 7000};
const Material kAlAlloy{70e9, 0.33, 2700}, kSteel{208e9, 0.30, 7850};
// LIGGGHTS-PFM tests 6-8 sweep of the initial spin (rad/s).
const double kSpins[] = {0.175, 0.30, 0.42, 0.60, 0.80, 1.0, 1.2, 1.5, 2.0, 2.4,
                         2.8,   3.0,  3.5,  4.0,  6.0,  8.0, 10.0, 12.0, 14.0, 21.0};

// One sphere just above the rigid plane z = 0, with velocity v and spin w.
DemSystem sphere_on_plane(const Material& m, double r, const HertzMindlinParams& hp,
                          const Vec3& v, const Vec3& w) {
  const std::vector<Material> mats{m};
  Particles p;
  p.add({0, 0, r * 1.0001}, r, 0, mats, v, w);
  DemSystem sys(p, mats, HertzMindlin(mats, hp));
  sys.add_plane({{0, 0, 0}, {0, 0, 1}, FixedPlane{}, HertzMindlinWall(mats, kRigid, hp)});
  return sys;
}

// dt as a fraction of the Hertz contact time of the normal impact.
double dt_for(const Material& m, double r, double mass, double vn, double steps) {
  return HertzImpact{effective_modulus(m, kRigid), r, mass, vn}.contact_time() / steps;
}

void expect_hertz(const ImpactRecord& rec, const HertzImpact& h, double tol) {
  ASSERT_TRUE(rec.separated);
  EXPECT_NEAR(rec.peak_force / h.peak_force(), 1, tol);
  EXPECT_NEAR(rec.max_overlap / h.max_overlap(), 1, tol);
  EXPECT_NEAR(rec.contact_time / h.contact_time(), 1, tol);
}

TEST(VerifyDemChungOoi, Test1ElasticNormalImpactOfTwoSpheres) {
  // Published (references.md): glass 10.70 kN, 274 um, 40.3 us; limestone 7.11 kN, 368 um,
  // 54.2 us. why 0.5 %: those are rounded to 3-4 digits.
  const double published[2][3] = {{10.70e3, 274e-6, 40.3e-6}, {7.11e3, 368e-6, 54.2e-6}};
  int k = 0;
  for (const Material& m : {kGlass, kLimestone}) {
    const std::vector<Material> mats{m};
    Particles p;
    p.add({0, 0, 0.01001}, 0.01, 0, mats, {0, 0, -10});
    p.add({0, 0, -0.01001}, 0.01, 0, mats, {0, 0, 10});
    DemSystem sys(p, mats, HertzMindlin(mats, {0.35, 1.0}));
    const HertzImpact h{effective_modulus(m, m), 0.005, 0.5 * p.mass[0], 20};
    const ImpactRecord rec = run_impact(sys, h.contact_time() / 400, 100000);
    expect_hertz(rec, h, 1e-4);  // why: O(dt^2) error at 400 steps/contact is ~3e-6
    EXPECT_NEAR(rec.peak_force / published[k][0], 1, 5e-3);
    EXPECT_NEAR(rec.max_overlap / published[k][1], 1, 5e-3);
    EXPECT_NEAR(rec.contact_time / published[k][2], 1, 5e-3);
    std::printf("  test 1 %s: F_max %.4g N, delta_max %.4g m, t_c %.4g s\n",
                k == 0 ? "glass" : "limestone", rec.peak_force, rec.max_overlap,
                rec.contact_time);
    ++k;
  }
}

TEST(VerifyDemChungOoi, Test2ElasticNormalImpactWithRigidPlane) {
  // Published: Al 11.37 kN, 49.7 um, 732 us; Mg 7.23 kN, 52.1 um, 767 us (Kratos' digitised
  // paper curve: 11.36 kN, t_c ~ 728 us). why 0.5 %: rounding of the printed values.
  const double published[2][3] = {{11.37e3, 49.7e-6, 732e-6}, {7.23e3, 52.1e-6, 767e-6}};
  int k = 0;
  for (const Material& m : {kAlAlloy2, kMgAlloy}) {
    DemSystem sys = sphere_on_plane(m, 0.1, {0.0, 1.0}, {0, 0, -0.2}, {});
    const double mass = sys.particles().mass[0];
    const HertzImpact h{effective_modulus(m, kRigid), 0.1, mass, 0.2};
    const ImpactRecord rec = run_impact(sys, h.contact_time() / 400, 100000);
    expect_hertz(rec, h, 1e-4);  // why: as test 1
    EXPECT_NEAR(rec.peak_force / published[k][0], 1, 5e-3);
    EXPECT_NEAR(rec.max_overlap / published[k][1], 1, 5e-3);
    EXPECT_NEAR(rec.contact_time / published[k][2], 1, 5e-3);
    ++k;
  }
}

TEST(VerifyDemChungOoi, Test3RestitutionAcrossE) {
  double worst = 0;
  for (const Material& m : {kAlOxide, kCastIron}) {
    for (double e : {0.2, 0.4, 0.6, 0.8, 1.0}) {
      DemSystem sys = sphere_on_plane(m, 0.0025, {0.0, e}, {0, 0, -3.9}, {});
      const double dt = dt_for(m, 0.0025, sys.particles().mass[0], 3.9, 400);
      ASSERT_TRUE(run_impact(sys, dt, 100000).separated);
      const double e_out = sys.particles().v[0].z / 3.9;
      // why 2e-3: the dashpot sees mid-step velocities, an O(dt) lag: ~1e-3 at 400 steps.
      EXPECT_NEAR(e_out, e, 2e-3) << "E = " << m.youngs_modulus << ", e_in = " << e;
      worst = std::max(worst, std::abs(e_out - e));
    }
  }
  std::printf("  test 3: worst |e_out - e_in| = %.2e over 10 runs\n", worst);
  // Elastic Al oxide reference (references.md): F_max = 615 N, t_c = 6.10 us.
  DemSystem sys = sphere_on_plane(kAlOxide, 0.0025, {0.0, 1.0}, {0, 0, -3.9}, {});
  const ImpactRecord rec =
      run_impact(sys, dt_for(kAlOxide, 0.0025, sys.particles().mass[0], 3.9, 400), 100000);
  EXPECT_NEAR(rec.peak_force / 615, 1, 5e-3);  // why: 3-digit rounding of the reference
  EXPECT_NEAR(rec.contact_time / 6.10e-6, 1, 5e-3);
}

TEST(VerifyDemChungOoi, Test4ObliqueImpactConstantSpeed) {
  const double v = 3.9, r = 0.0025, e = 0.98, mu = 0.092;
  double worst_et = 0, worst_w = 0;
  for (int deg = 5; deg <= 85; deg += 5) {
    const double th = deg * std::numbers::pi / 180;
    const double vt = v * std::sin(th), vn = v * std::cos(th);
    DemSystem sys = sphere_on_plane(kAlOxide, r, {mu, e}, {0, vt, -vn}, {});
    ASSERT_TRUE(run_impact(sys, dt_for(kAlOxide, r, sys.particles().mass[0], vn, 400), 200000)
                    .separated);
    const Particles& p = sys.particles();
    const double et = p.v[0].y / vt, w = p.omega[0].x;
    // Gross sliding throughout contact when tan(theta) > 3.5 mu (1 + e) (theta > 32.5 deg).
    if (std::tan(th) > 3.5 * mu * (1 + e) * 1.05) {
      const double et_sl = 1 - mu * (1 + e) / std::tan(th);
      const double w_sl = -2.5 * mu * (1 + e) * vn / r;
      EXPECT_NEAR(et, et_sl, 2e-3) << deg;  // why: O(dt) dashpot lag in e, ~1e-3 (test 3)
      EXPECT_NEAR(w / w_sl, 1, 5e-3) << deg;  // why: lever r - delta < R by up to 0.3 %
      worst_et = std::max(worst_et, std::abs(et - et_sl));
      worst_w = std::max(worst_w, std::abs(w / w_sl - 1));
    } else {
      // Partial slip: bounded by the gross-sliding line and by 1 (no tangential loss).
      EXPECT_GE(et, 1 - mu * (1 + e) / std::tan(th) - 2e-3) << deg;
      EXPECT_LE(et, 1.0) << deg;
    }
    // Kratos' reference curve (benchmark4_graph1_ref.dat): e_t = 0.948 (5), 0.616 (20),
    // 0.845 (50), 0.983 (85). why 0.02: Kratos' own gate is 1.6e-2 on this curve, and at small
    // angles the reference includes micro-slip that a capped Mindlin spring lacks.
    const double kratos = deg == 5 ? 0.948 : deg == 20 ? 0.616 : deg == 50 ? 0.845
                                                          : deg == 85 ? 0.983 : -1;
    if (kratos > 0) {
      EXPECT_NEAR(et, kratos, 0.02) << deg;
    }
    if (deg % 15 == 5)
      std::printf("  test 4, %2d deg: e_t %.4f, omega %.2f rad/s, rebound angle at contact "
                  "point %.2f deg\n", deg, et, w,
                  std::atan((p.v[0].y + r * w) / p.v[0].z) * 180 / std::numbers::pi);
  }
  std::printf("  test 4 sliding range: worst |e_t - e_t,sl| = %.2e, worst |w/w_sl - 1| = %.2e\n",
              worst_et, worst_w);
}

// Contact-point tangential velocity reversal of an impact that never slips, solved without
// the DEM machinery: Hertz normal motion and the Mindlin spring F_t = -k_t(delta) xi acting on
// the contact point with 1/m_t = 1/m + a^2/I, a = r - delta (RK4, 20,000 steps).
double no_slip_reversal(const Material& m, double r, double vn, double vt) {
  const double es = effective_modulus(m, kRigid), gs = effective_shear_modulus(m, kRigid);
  const double mass = 4.0 / 3.0 * std::numbers::pi * r * r * r * m.density;
  const double inertia = 0.4 * mass * r * r;
  const double tc = HertzImpact{es, r, mass, vn}.contact_time();
  const double h = 1.2 * tc / 20000;
  double s[4] = {0, vn, 0, vt};  // delta, d delta/dt, xi, d xi/dt
  auto rhs = [&](const double* y, double* dy) {
    const double d = std::max(y[0], 0.0), a = std::sqrt(r * d);
    dy[0] = y[1];
    dy[1] = -(4.0 / 3.0) * es * a * d / mass;
    dy[2] = y[3];
    const double lever = r - d;
    dy[3] = -8 * gs * a * y[2] * (1 / mass + lever * lever / inertia);
  };
  for (int k = 0; k < 30000 && !(s[0] < 0 && k > 10); ++k) {
    double k1[4], k2[4], k3[4], k4[4], y[4];
    rhs(s, k1);
    for (int q = 0; q < 4; ++q) y[q] = s[q] + 0.5 * h * k1[q];
    rhs(y, k2);
    for (int q = 0; q < 4; ++q) y[q] = s[q] + 0.5 * h * k2[q];
    rhs(y, k3);
    for (int q = 0; q < 4; ++q) y[q] = s[q] + h * k3[q];
    rhs(y, k4);
    for (int q = 0; q < 4; ++q) s[q] += h / 6 * (k1[q] + 2 * k2[q] + 2 * k3[q] + k4[q]);
  }
  return -s[3] / vt;
}

TEST(VerifyDemChungOoi, Test5ObliqueImpactConstantNormalSpeed) {
  const double r = 1e-5, vn = 5.0, mu = 0.3;
  double worst_nra = 0, worst_nrav = 0;
  for (double vt : {0.1, 0.3, 0.45, 0.6, 0.9, 1.2, 1.5, 1.8, 2.25, 2.7, 3.0, 3.75, 4.5, 5.25,
                    6.0, 7.5, 9.0, 12.0, 15.0, 18.0, 21.0}) {
    DemSystem sys = sphere_on_plane(kSteel, r, {mu, 1.0}, {0, vt, -vn}, {});
    ASSERT_TRUE(run_impact(sys, dt_for(kSteel, r, sys.particles().mass[0], vn, 400), 100000)
                    .separated);
    const Particles& p = sys.particles();
    const double nia = vt / (mu * vn);                                   // LIGGGHTS "nia"
    const double nra = (p.v[0].y + r * p.omega[0].x) / (mu * p.v[0].z);  // "nra"
    const double nrav = -r * p.omega[0].x / (mu * -vn);                  // "nrav"
    if (nia > 7 * 1.05) {  // gross sliding: nra = nia - 7, nrav = -5 (e = 1)
      EXPECT_NEAR(nra, nia - 7, 0.02 + 1e-3 * nia) << vt;  // why: arm r - delta, ~1e-3 rel.
      // why 0.04: the lever arm r - delta is up to delta_max/R = 0.65 % shorter than R.
      EXPECT_NEAR(nrav, -5, 0.04) << vt;
      worst_nra = std::max(worst_nra, std::abs(nra - (nia - 7)));
      worst_nrav = std::max(worst_nrav, std::abs(nrav + 5));
    } else {
      EXPECT_GE(nra, nia - 7 - 0.02) << vt;  // the sliding line bounds partial slip
      EXPECT_GE(nrav, -5 - 0.02) << vt;
    }
  }
  std::printf("  test 5 sliding range: worst |nra - (nia - 7)| = %.2e, |nrav + 5| = %.2e\n",
              worst_nra, worst_nrav);
  // No-slip limit (mu large): the DEM reversal equals the independent no-slip solution.
  for (double vt : {0.1, 1.0}) {
    DemSystem sys = sphere_on_plane(kSteel, r, {100.0, 1.0}, {0, vt, -vn}, {});
    ASSERT_TRUE(run_impact(sys, dt_for(kSteel, r, sys.particles().mass[0], vn, 400), 100000)
                    .separated);
    const Particles& p = sys.particles();
    const double beta = -(p.v[0].y + r * p.omega[0].x) / vt;
    const double ref = no_slip_reversal(kSteel, r, vn, vt);
    std::printf("  test 5 no-slip limit, v_t = %.1f: beta DEM %.5f, ODE %.5f\n", vt, beta, ref);
    EXPECT_NEAR(beta, ref, 5e-3);  // why: O(dt) lag of the tangential increment at 400 steps
  }
}

// Tests 6 and 8: a spinning sphere (R w0 about x) hits a plane or a large heavy sphere at
// v_n = 0.2 m/s; beta = -(v_y + R w_x)/(R w0) and the sliding limit
// beta_sl = 3.5 mu (1 + e) v_n / (R w0) - 1 (LIGGGHTS-PFM "betasl").
void spin_sweep(bool large_sphere) {
  const double r = 0.1, vn = 0.2, e = 0.5, mu = 0.4;
  double worst = 0;
  for (double w0 : kSpins) {
    std::vector<Material> mats{kAlAlloy};
    Particles p;
    p.add({0, 0, r * 1.0001}, r, 0, mats, {0, 0, -vn}, {w0, 0, 0});
    DemSystem sys = [&] {
      if (!large_sphere) return sphere_on_plane(kAlAlloy, r, {mu, e}, {0, 0, -vn}, {w0, 0, 0});
      mats.push_back({kAlAlloy.youngs_modulus, kAlAlloy.poisson_ratio, 1000 * kAlAlloy.density});
      p.add({0, 0, -5 * r}, 5 * r, 1, mats);  // case (B): same shear modulus, 1000x density
      return DemSystem(p, mats, HertzMindlin(mats, {mu, e}));
    }();
    const double dt = dt_for(kAlAlloy, r, sys.particles().mass[0], vn, 400);
    ASSERT_TRUE(run_impact(sys, dt, 100000).separated);
    const Particles& q = sys.particles();
    const double beta = -(q.v[0].y + r * q.omega[0].x) / (r * w0);
    const double beta_sl = 3.5 * mu * (1 + e) * vn / (r * w0) - 1;
    if (beta_sl < -0.05) {  // gross sliding throughout the contact
      // why 3e-3: O(dt) dashpot lag on the normal impulse (test 3) times 3.5 mu (1+e) v_n/(R w0)
      EXPECT_NEAR(beta, beta_sl, 3e-3) << w0;
      worst = std::max(worst, std::abs(beta - beta_sl));
      const double nra = (q.v[0].y + r * q.omega[0].x) / q.v[0].z;  // normalised rebound angle
      const double nra_sl = (r * w0 - 3.5 * mu * (1 + e) * vn) / (e * vn);
      // why: nra = v_c' / (e v_n) divides the O(dt) velocity errors by e v_n = 0.1 m/s.
      EXPECT_NEAR(nra, nra_sl, 1e-2 * std::max(1.0, std::abs(nra_sl))) << w0;
    } else {
      // Partial slip changes the contact-point velocity less than gross sliding would.
      EXPECT_LE(beta, beta_sl + 3e-3) << w0;
    }
  }
  std::printf("  test %d sliding range: worst |beta - beta_sl| = %.2e\n", large_sphere ? 8 : 6,
              worst);
}

TEST(VerifyDemChungOoi, Test6SpinningSphereOnPlane) { spin_sweep(false); }
TEST(VerifyDemChungOoi, Test8SpinningSphereOnLargeSphere) { spin_sweep(true); }

TEST(VerifyDemChungOoi, Test7TwoSpinningSpheres) {
  // LIGGGHTS-PFM test07: w = +w0 and -w0 about x for the upper and lower sphere. The contact
  // points then move together (both at R w0 along y): no tangential force, so by symmetry the
  // spins are unchanged and the tangential velocities stay 0.
  const double r = 0.1, v = 0.2, e = 0.5, mu = 0.4;
  const std::vector<Material> mats{kAlAlloy};
  double worst = 0;
  for (double w0 : kSpins) {
    for (bool same_sense : {false, true}) {
      Particles p;
      p.add({0, 0, r * 1.0001}, r, 0, mats, {0, 0, -v}, {w0, 0, 0});
      p.add({0, 0, -r * 1.0001}, r, 0, mats, {0, 0, v}, {same_sense ? w0 : -w0, 0, 0});
      DemSystem sys(p, mats, HertzMindlin(mats, {mu, e}));
      const double dt = HertzImpact{effective_modulus(kAlAlloy, kAlAlloy), 0.5 * r,
                                    0.5 * p.mass[0], 2 * v}.contact_time() / 400;
      ASSERT_TRUE(run_impact(sys, dt, 100000).separated);
      const Particles& q = sys.particles();
      if (!same_sense) {
        EXPECT_NEAR(q.omega[0].x / w0, 1, 1e-12) << w0;  // why: exact, rounding only
        EXPECT_NEAR(q.v[0].y, 0, 1e-12) << w0;
        EXPECT_NEAR(q.v[1].y, 0, 1e-12) << w0;
        continue;
      }
      // Same sense: slip 2 R w0; impulse J = m* (1+e) 2v; gross sliding when
      // 2 R w0 > 2 * 3.5 mu J / m, then v_y = -mu J/m and w = w0 - 2.5 mu J/(m R), and the
      // pair stays antisymmetric.
      const double j_over_m = 0.5 * (1 + e) * 2 * v;
      EXPECT_NEAR(q.v[0].y + q.v[1].y, 0, 1e-12);  // why: symmetry, rounding only
      EXPECT_NEAR(q.omega[0].x - q.omega[1].x, 0, 1e-12 * w0);
      if (r * w0 > 3.5 * mu * j_over_m * 1.05) {
        EXPECT_NEAR(q.v[0].y / (-mu * j_over_m), 1, 3e-3) << w0;  // why: dashpot lag (test 3)
        worst = std::max(worst, std::abs(q.v[0].y / (-mu * j_over_m) - 1));
        EXPECT_NEAR(q.omega[0].x, w0 - 2.5 * mu * j_over_m / r, 3e-3 * 2.5 * mu * j_over_m / r)
            << w0;
      }
    }
  }
  std::printf("  test 7 same-sense sliding: worst |v_y / v_y,sl - 1| = %.2e\n", worst);
}

}  // namespace
}  // namespace kolsky::dem
