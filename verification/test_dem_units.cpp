// Unit tests of the DEM pieces: contact-law pieces and their analytic helpers, restitution
// maps, LS-DYNA stiffness (Eq. 3.1 with Table 3.2), rolling pieces, walls, the dt policy and
// input errors, the Verlet list (against brute force, history carry, thread invariance) and
// the test-assembly builders.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <limits>
#include <numbers>
#include <set>

#include "core/errors.hpp"
#include "dem/contact_damping.hpp"
#include "dem/dem_system.hpp"
#include "dem/spatial_sort.hpp"
#include "dem/test_fills.hpp"

namespace kolsky::dem {
namespace {

const std::vector<Material> kSand{{78e9, 0.3, 2650}};
const Material kRigid{std::numeric_limits<double>::infinity(), 0.0, 1.0};

ContactGeometry geometry(double overlap, double r_eff, double m_eff) {
  ContactGeometry g;
  g.overlap = overlap;
  g.normal = {0, 0, 1};
  g.r_eff = r_eff;
  g.m_eff = m_eff;
  return g;
}

TEST(TestDemPieces, EffectiveModuliAndRigidWall) {
  const Material m{70e9, 0.33, 2700};
  EXPECT_DOUBLE_EQ(effective_modulus(m, kRigid), 70e9 / (1 - 0.33 * 0.33));
  EXPECT_DOUBLE_EQ(effective_shear_modulus(m, kRigid), m.shear_modulus() / (2 - 0.33));
  // LIGGGHTS models the rigid plane as both bodies with E doubled: the same E* and G*.
  const Material doubled{140e9, 0.33, 2700};
  EXPECT_NEAR(effective_modulus(doubled, doubled) / effective_modulus(m, kRigid), 1, 1e-14);
  EXPECT_NEAR(effective_shear_modulus(doubled, doubled) / effective_shear_modulus(m, kRigid), 1,
              1e-14);
}

TEST(TestDemPieces, HertzForceStiffnessEnergyAreConsistent) {
  const HertzNormal h{42e9};
  const double d = 2e-6, eps = 1e-12;
  const NormalElastic a = h.force(geometry(d, 2.5e-4, 1e-6));
  const NormalElastic lo = h.force(geometry(d - eps, 2.5e-4, 1e-6));
  const NormalElastic hi = h.force(geometry(d + eps, 2.5e-4, 1e-6));
  EXPECT_NEAR((hi.energy - lo.energy) / (2 * eps) / a.force, 1, 1e-6);   // F = dE/d(delta)
  EXPECT_NEAR((hi.force - lo.force) / (2 * eps) / a.stiffness, 1, 1e-6);  // S_n = dF/d(delta)
  EXPECT_NEAR(a.contact_radius, std::sqrt(2.5e-4 * d), 1e-18);
}

TEST(TestDemPieces, DissertationEq410IsTheSecantOfHertzWithRbarTwiceRstar) {
  // Eq. 4.10: k_n = 2 G sqrt(2 R_bar) / (3 (1 - nu)) sqrt(U), identical grains (targets 4d).
  const Material m{78e9, 0.3, 2650};
  const double r = 2e-4, r_star = 0.5 * r, u = 1e-6;
  const double g = m.shear_modulus(), nu = m.poisson_ratio;
  auto eq_4_10 = [&](double r_bar) {
    return 2 * g * std::sqrt(2 * r_bar) / (3 * (1 - nu)) * std::sqrt(u);
  };
  const NormalElastic h = HertzNormal{effective_modulus(m, m)}.force(geometry(u, r_star, 1));
  EXPECT_NEAR(eq_4_10(2 * r_star) * u / h.force, 1, 1e-12);       // secant F/U, R_bar = 2R*
  EXPECT_NEAR(eq_4_10(r_star) * u / h.force, 1 / std::sqrt(2), 1e-12);  // R_bar = R*: too soft
  EXPECT_NEAR(h.stiffness / (eq_4_10(2 * r_star)), 1.5, 1e-12);   // tangent = 1.5 x secant
  // Mindlin's k_t = 8 G* a equals PFC's Hertz shear stiffness (the standard form targets 4e.6
  // recommends over the misprinted Eq. 4.11): k_s = 2 (3 G^2 (1-nu) R_bar)^{1/3} / (2-nu)
  // F_n^{1/3}, R_bar = 2R*.
  const double k_t = MindlinTangential{effective_shear_modulus(m, m), 0.5}.stiffness_at(h);
  const double k_s_pfc =
      2 * std::cbrt(3 * g * g * (1 - nu) * 2 * r_star) / (2 - nu) * std::cbrt(h.force);
  EXPECT_NEAR(k_t / k_s_pfc, 1, 1e-12);
}

TEST(TestDemPieces, TangentialSpringRotatesCapsAndDissipates) {
  ContactGeometry g = geometry(1e-6, 1e-4, 1e-6);
  g.normal = {0, 0, 1};
  ContactResult out;
  // History with a normal component is rotated onto the tangent plane, magnitude kept.
  Vec3 xi{3e-7, 0, 4e-7};
  Vec3 f = tangential_force(g, xi, 0.0, 1e6, 0.0, 10.0, 1.0, out);
  EXPECT_NEAR(xi.z, 0, 1e-20);
  EXPECT_NEAR(norm(xi), 5e-7, 1e-20);
  EXPECT_NEAR(f.x, 0.5, 1e-12);
  // Coulomb cap: spring force 0.5 N > mu F_el = 0.1 N -> slides to the limit, dissipating.
  out = {};
  xi = {5e-7, 0, 0};
  f = tangential_force(g, xi, 0.0, 1e6, 0.0, 0.1, 1.0, out);
  EXPECT_NEAR(norm(f), 0.1, 1e-15);
  EXPECT_NEAR(norm(xi), 1e-7, 1e-20);
  EXPECT_NEAR(out.dissipated, 0.1 * 4e-7, 1e-20);  // L x slip
  // Sticking with a dashpot that would exceed the limit: scaled to exactly the limit.
  out = {};
  xi = {5e-8, 0, 0};
  g.v_contact = {10, 0, 0};
  f = tangential_force(g, xi, 0.0, 1e6, 1.0, 0.1, 1.0, out);
  EXPECT_NEAR(norm(f), 0.1, 1e-14);
  EXPECT_GE(out.dissipated, 0.0);
  // Frictionless: no force, no stored displacement.
  out = {};
  xi = {5e-8, 1e-8, 0};
  f = tangential_force(g, xi, 1e-9, 1e6, 1.0, 0.0, 1.0, out);
  EXPECT_EQ(norm2(f), 0.0);
  EXPECT_EQ(norm2(xi), 0.0);
}

TEST(TestDemPieces, RestitutionMaps) {
  for (double e : {0.05, 0.2, 0.5, 0.8, 0.98, 1.0}) {
    const double zeta = damping_ratio_from_restitution(e);
    EXPECT_NEAR(linear_restitution(zeta), e, 1e-14);
    // Antypov & Elliott 2011: with the sqrt(5/6) factor the Hertz-Tsuji restitution equals
    // the linear formula. why 2e-6: RK4 and crossing-interpolation error of the helper.
    EXPECT_NEAR(hertz_restitution(zeta), e, 2e-6);
  }
  EXPECT_THROW(damping_ratio_from_restitution(0.0), std::invalid_argument);
  EXPECT_THROW(damping_ratio_from_restitution(1.2), std::invalid_argument);
  EXPECT_EQ(linear_restitution(1.0), 0.0);
}

TEST(TestDemPieces, LsDynaStiffnessOfTable32) {
  // targets.md 3a (DERIVED): k = 70 MPa / (1 - 0.4), equal r = 0.15 mm, NORMK 0.07 -> 612.5 N/m.
  const std::vector<Material> mats{{70e6, 0.2, 2650}};
  const LsDynaLinear law(mats, LsDynaParams{});
  EXPECT_NEAR(law.pair(0, 0).normal_stiffness(1.5e-4, 1.5e-4), 612.5, 1e-9);
  // K_s = SHEARK K_n and Coulomb FRIC: a sliding contact carries FRIC x F_el.
  ContactGeometry g = geometry(1e-6, 7.5e-5, 1e-8);
  g.r_i = g.r_j = 1.5e-4;
  g.v_contact = {1, 0, 0};
  Vec3 xi{};
  const ContactResult r = law.pair(0, 0).force(g, xi, 1e-6);
  EXPECT_NEAR(r.normal_force, 612.5e-6, 1e-15);  // undamped at v_n = 0
  EXPECT_NEAR(std::abs(r.force.x), 0.56 * 612.5e-6, 1e-15);
}

TEST(TestDemPieces, RollingFrictionTorque) {
  ContactGeometry g = geometry(1e-6, 1e-4, 1e-6);
  g.omega_rel = {10, 0, 5};  // the z part is twist about the normal, not rolling
  const Vec3 t = RollingFriction{0.1}.torque(g, 2.0);
  EXPECT_NEAR(t.x, -0.1 * 1e-4 * 2.0, 1e-18);
  EXPECT_EQ(t.y, 0.0);
  EXPECT_EQ(t.z, 0.0);
  EXPECT_EQ(norm2(RollingFriction{0.1}.torque(g, -1.0)), 0.0);  // no moment without contact
}

TEST(TestDemPieces, RollingRetardationFactor) {
  const RollingRetardation r{0.99999975, 1e-9};
  EXPECT_DOUBLE_EQ(r.factor(1e-9), 0.99999975);
  EXPECT_NEAR(r.factor(3.78e-8), std::pow(0.99999975, 37.8), 1e-15);
  EXPECT_EQ((RollingRetardation{0.0, 1e-9}.factor(1e-8)), 0.0);
  EXPECT_EQ((RollingRetardation{}.factor(1e-8)), 1.0);
}

TEST(TestDemPieces, TimeStepHelpers) {
  // bench/README: dt = 0.25 x Rayleigh step of the smallest grain (r = 0.15 mm) = 3.78e-8 s.
  EXPECT_NEAR(0.25 * rayleigh_time_step(1.5e-4, {78e9, 0.3, 2650}), 3.78e-8, 0.01e-8);
  EXPECT_NEAR(linear_contact_time_step(4.0, 1.0, 0.0), 2.0, 1e-15);
  EXPECT_NEAR(linear_contact_time_step(4.0, 1.0, 0.5), 2.0 * (std::sqrt(1.25) - 0.5), 1e-15);
  // Hertz contact time constant 2 B(2/5, 1/2)/(5/2) (15/16)^{2/5} = 2.8683.
  const HertzImpact h{1.0, 1.0, 1.0, 1.0};
  EXPECT_NEAR(h.contact_time(), 2.8683, 1e-4);
  EXPECT_NEAR(h.peak_force(), 4.0 / 3.0 * std::pow(h.max_overlap(), 1.5), 1e-15);
}

TEST(TestDemWalls, VelocityHistoryAndTube) {
  const VelocityHistory v{{0.0, 1.0, 3.0}, {0.0, 2.0, 2.0}};
  EXPECT_DOUBLE_EQ(v.at(0.5), 1.0);
  EXPECT_DOUBLE_EQ(v.at(9.0), 2.0);
  EXPECT_NEAR(v.displacement(0.0, 3.0), 1.0 + 4.0, 1e-15);
  EXPECT_NEAR(v.displacement(0.5, 2.0), 0.75 + 2.0, 1e-15);
  EXPECT_NEAR(v.displacement(4.0, 5.0), 2.0, 1e-15);
  // Hoop relation p = E t u / R^2 with p = F / (2 pi R H).
  const TubeCompliance t{200e9, 5e-3, 8100, 9.3e-3};
  const double radius = 9.55e-3, u = 1e-6;
  const double force = 200e9 * 5e-3 * u / (radius * radius) * 2 * std::numbers::pi * radius * 9.3e-3;
  EXPECT_NEAR(t.radial_stiffness(radius) * u / force, 1, 1e-14);
  EXPECT_NEAR(t.radial_stiffness(radius) / t.radial_mass(radius),
              200e9 / (8100 * radius * radius), 1e-3);
}

TEST(TestDemSystem, StableDtPolicyAndInputErrors) {
  Particles p;
  p.add({0, 0, 0}, 1.5e-4, 0, kSand);
  DemSystem sys(p, kSand, HertzMindlin(kSand, {0.5, 0.5}));
  EXPECT_NEAR(sys.stable_dt(), rayleigh_time_step(1.5e-4, kSand[0]), 1e-20);  // raw limit
  sys.add_plane({{0, 0, -1}, {0, 0, 1}, FixedPlane{}, linear_spring(1e9, 0, 0)});
  EXPECT_NEAR(sys.stable_dt(), std::sqrt(p.mass[0] / 1e9), 1e-20);  // stiff wall rules
  try {
    sys.step(2 * sys.stable_dt());
    ADD_FAILURE() << "dt above the limit was accepted";
  } catch (const NumericalError& e) {  // a step above the limit fails the run, output kept
    EXPECT_NE(std::string(e.what()).find("above the stable limit"), std::string::npos);
  }
  EXPECT_THROW(sys.step(-1.0), InputError);
  EXPECT_NO_THROW(sys.step(sys.stable_dt()));
  const std::vector<Material> two{kSand[0], kSand[0]};
  EXPECT_THROW(DemSystem(p, kSand, HertzMindlin(two, {0.5, 0.5})), InputError);
  Particles bad = p;
  bad.material[0] = 3;
  EXPECT_THROW(DemSystem(bad, kSand, HertzMindlin(kSand, {0.5, 0.5})), InputError);
  EXPECT_THROW(sys.drive_plane(0, 0.0, 0.0), InputError);  // a FixedPlane is not driven
  EXPECT_THROW(HertzMindlin(kSand, {0.5, 0.0}), InputError);   // restitution in (0, 1]
  EXPECT_THROW(HertzMindlin(kSand, {-0.1, 0.5}), InputError);  // friction >= 0
  EXPECT_THROW(sys.add_plane({{0, 0, 0}, {0, 0, 1}, FixedPlane{}, LinearSpring{}}), InputError);
  LsDynaParams lp;
  lp.ndamp = 1.0;
  EXPECT_THROW(LsDynaLinear(kSand, lp), InputError);
  EXPECT_EQ(name_of(ContactLaw(LsDynaLinear(kSand, {}))), "ls_dyna_linear");
  // Edits through mutable_particles(): a smaller grain tightens dt, a new grain gets contacts.
  const double before = sys.stable_dt();
  Particles& edit = sys.mutable_particles();
  edit.radius[0] /= 3;
  edit.mass[0] /= 27;
  edit.inertia[0] /= 243;
  EXPECT_NEAR(sys.stable_dt() / before, 1 / std::sqrt(27.0), 1e-12);
  edit.radius[0] *= 3;
  edit.mass[0] *= 27;
  edit.inertia[0] *= 243;
  sys.mutable_particles().add({0, 0, 2.9e-4}, 1.5e-4, 0, kSand);
  sys.compute_forces();
  EXPECT_EQ(sys.n_contacts(), 1u);
  EXPECT_NO_THROW(sys.step(0.5 * (kDemStepFraction * sys.stable_dt())));
  EXPECT_EQ(name_of(WallLaw(HertzMindlinWall(kSand, kRigid, {}))), "hertz_mindlin");
}

std::set<std::pair<int, int>> brute_pairs(const Particles& p, double skin) {
  std::set<std::pair<int, int>> s;
  for (int i = 0; i < static_cast<int>(p.size()); ++i)
    for (int j = i + 1; j < static_cast<int>(p.size()); ++j) {
      const double c = p.radius[i] + p.radius[j] + skin;
      if (norm2(p.x[j] - p.x[i]) < c * c) s.insert({i, j});
    }
  return s;
}

// The list holds exactly the brute-force pairs, in (i, j) order (std::set's order).
void expect_brute_force_list(const PairList& a, const Particles& p, double skin) {
  const auto ref = brute_pairs(p, skin);
  ASSERT_EQ(a.size(), ref.size());
  std::size_t k = 0;
  for (const auto& [i, j] : ref) {
    EXPECT_EQ(a.i[k], i);
    EXPECT_EQ(a.j[k], j);
    ++k;
  }
}

TEST(TestDemNeighbours, PairListMatchesBruteForceAndCarriesHistory) {
  Particles p = random_packing(2500, 1e-4, 4e-4, {{0, 0, 0}, {9e-3, 9e-3, 9e-3}}, 42, 0, kSand);
  const double skin = 5e-5;
  const PairList a = build_pair_list(p.x, p.radius, skin, {});
  expect_brute_force_list(a, p, skin);
  // History follows the pair through a rebuild after the particles moved.
  PairList b = a;
  for (std::size_t q = 0; q < b.size(); ++q) b.history[q] = {double(b.i[q]), double(b.j[q]), 1};
  for (auto& x : p.x) x += Vec3{2e-5, -1e-5, 3e-5};
  p.x[0] += Vec3{1e-3, 0, 0};
  const PairList c = build_pair_list(p.x, p.radius, skin, b);
  int carried = 0;
  for (std::size_t q = 0; q < c.size(); ++q) {
    if (c.history[q].z == 0) continue;
    EXPECT_EQ(c.history[q].x, c.i[q]);
    EXPECT_EQ(c.history[q].y, c.j[q]);
    ++carried;
  }
  EXPECT_GT(carried, static_cast<int>(0.9 * c.size()));
  // The list does not depend on the thread count.
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const PairList one = build_pair_list(p.x, p.radius, skin, b);
  omp_set_num_threads(2);
  const PairList two = build_pair_list(p.x, p.radius, skin, b);
  omp_set_num_threads(saved);
  EXPECT_EQ(one.j, two.j);
  EXPECT_EQ(one.first, two.first);
}

// Each pair is searched from its larger grain, and at equal radii from the lower index: with
// only two radii in the packing nearly every candidate is a tie, and no pair may be lost or
// found twice.
TEST(TestDemNeighbours, EqualRadiiAreFoundOnce) {
  Particles p = random_packing(2500, 1e-4, 4e-4, {{0, 0, 0}, {9e-3, 9e-3, 9e-3}}, 7, 0, kSand);
  for (std::size_t q = 0; q < p.size(); ++q) p.radius[q] = q % 3 == 0 ? 3e-4 : 1.5e-4;
  const double skin = 5e-5;
  const PairList a = build_pair_list(p.x, p.radius, skin, {});
  expect_brute_force_list(a, p, skin);
}

TEST(TestDemAssembly, BuildersGiveValidAssemblies) {
  const Particles lat = cubic_lattice(3, 4, 5, 1e-3, 2e-3, {0, 0, 0}, 0, kSand);
  EXPECT_EQ(lat.size(), 60u);
  EXPECT_NEAR(lat.mass[0], 4.0 / 3.0 * std::numbers::pi * 1e-9 * 2650, 1e-18);
  EXPECT_NEAR(lat.inertia[0], 0.4 * lat.mass[0] * 1e-6, 1e-24);
  const FillRegion cyl{{-3e-3, -3e-3, 0}, {3e-3, 3e-3, 4e-3}, 3e-3};
  Particles p = random_packing(400, 1e-4, 2e-4, cyl, 9, 0, kSand);
  EXPECT_EQ(brute_pairs(p, 0.0).size(), 0u);  // no overlaps
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_LE(std::hypot(p.x[i].x, p.x[i].y) + p.radius[i], 3e-3);
    EXPECT_GE(p.x[i].z - p.radius[i], 0.0);
  }
  double volume = 0;
  for (double r : p.radius) volume += r;
  sort_spatially(p, 4e-4);
  double after = 0;
  for (double r : p.radius) after += r;
  EXPECT_DOUBLE_EQ(volume, after);  // a permutation
  EXPECT_THROW(random_packing(100, 1e-3, 1e-3, {{0, 0, 0}, {3e-3, 3e-3, 3e-3}}, 1, 0, kSand, 100),
               InputError);
}

// On a full 4 x 4 x 4 lattice with one grain per cell, the Morton order puts the grain of cell
// (cx, cy, cz) at the index whose bits interleave those of cx, cy and cz (x lowest): written
// here bit by bit, independently of the solver's bit tricks.
TEST(TestDemAssembly, MortonOrderInterleavesTheCellBits) {
  Particles p = cubic_lattice(4, 4, 4, 1e-4, 1e-3, {0, 0, 0}, 0, kSand);
  std::vector<int> reversed(p.size());
  for (std::size_t k = 0; k < p.size(); ++k) reversed[k] = static_cast<int>(p.size() - 1 - k);
  p.permute(reversed);
  sort_morton(p, 0.999e-3);  // just under the spacing: cell index = lattice index
  for (int m = 0; m < 64; ++m) {
    int c[3] = {0, 0, 0};
    for (int bit = 0; bit < 6; ++bit) c[bit % 3] |= ((m >> bit) & 1) << (bit / 3);
    EXPECT_NEAR(p.x[m].x, c[0] * 1e-3, 1e-12) << m;
    EXPECT_NEAR(p.x[m].y, c[1] * 1e-3, 1e-12) << m;
    EXPECT_NEAR(p.x[m].z, c[2] * 1e-3, 1e-12) << m;
  }
  EXPECT_THROW(sort_morton(p, 0.0), InputError);
  EXPECT_THROW(sort_spatially(p, 1e-12), InputError);  // 3 mm / 1e-12 m: beyond 2^20 cells
}

}  // namespace
}  // namespace kolsky::dem
