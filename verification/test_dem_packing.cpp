// Packing generator (dem/packing.hpp) on the reconstructed Song et al. (2009) grain-size curve
// upscaled by N = 2 (the dissertation's Ch. 4 specimen), in small cylinders so the tests stay
// fast: porosity, count, grain-size curve, containment and overlaps, determinism.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.hpp"
#include "dem/packing.hpp"
#include "io/csv.hpp"
#include "psd/sampling.hpp"
#include "song_packing.hpp"

namespace kolsky::dem {
namespace {

psd::GrainSizeCurve song_curve(double upscale) {
  const io::CsvTable t = io::read_csv(std::string(KOLSKY_SOURCE_DIR) +
                                      "/data/digitized/chapter4/song2009_psd_reconstructed.csv");
  psd::GrainSizeCurve c{t.column("diameter_m"), t.column("percent_passing")};
  return psd::upscale(c, upscale);
}

PackingParams small_song(double diameter, double length, std::uint64_t seed) {
  PackingParams p;
  p.curve = song_curve(2.0);
  p.porosity = 0.44;
  p.diameter = diameter;
  p.length = length;
  p.seed = seed;
  p.material = Material{78e9, 0.3, 2650};
  return p;
}

// Two packings from the same input are bitwise the same grain for grain.
void expect_same_packing(const PackingResult& a, const PackingResult& b) {
  ASSERT_EQ(a.count, b.count);
  for (std::size_t i = 0; i < a.count; ++i) {
    ASSERT_EQ(a.particles.x[i].x, b.particles.x[i].x);
    ASSERT_EQ(a.particles.x[i].y, b.particles.x[i].y);
    ASSERT_EQ(a.particles.x[i].z, b.particles.x[i].z);
    ASSERT_EQ(a.particles.radius[i], b.particles.radius[i]);
  }
  EXPECT_EQ(a.steps, b.steps);
}

TEST(DemPacking, ReachesPorosityCountCurveAndStaysInside) {
  const PackingParams in = small_song(0.006, 0.004, 7);  // ~1,500 grains
  const PackingResult r = generate_packing(in);
  const double volume = psd::cylinder_volume(in.diameter, in.length);
  // Porosity: sample_diameters meets V(1 - n) within half the largest grain's volume, so
  // |n - n_target| <= pi d_max^3 / 12 / V (0.0040 here); the radii end exactly at target.
  const double d_max = in.curve.d_max();
  const double tol_n = std::numbers::pi * d_max * d_max * d_max / 12 / volume;
  EXPECT_NEAR(r.porosity, 0.44, tol_n);
  // Count: the sample's count follows the curve's mean grain volume; stratified sampling
  // (fine-to-coarse bins) keeps it within a few percent of V(1 - n)/v_mean at ~1,500 grains.
  EXPECT_GT(r.count, 1000u);
  EXPECT_NEAR(static_cast<double>(r.count) / r.expected_count, 1.0, 0.05);
  // Grain-size curve of the generated grains vs the input, within the sampling guarantee.
  std::vector<double> diam;
  for (double rad : r.particles.radius) diam.push_back(2 * rad);
  EXPECT_DOUBLE_EQ(psd::max_passing_deviation(in.curve, diam), r.curve_deviation);
  EXPECT_LE(r.curve_deviation, r.curve_deviation_bound);
  EXPECT_LT(r.curve_deviation, 2.0);
  // Settled: every grain inside the cylinder and between the planes, overlaps < 1e-3 r_mean.
  EXPECT_TRUE(r.settled);
  EXPECT_LT(r.max_overlap, in.overlap_tolerance);
  double mean_r = 0;
  for (double rad : r.particles.radius) mean_r += rad;
  mean_r /= static_cast<double>(r.count);
  const double slack = in.overlap_tolerance * mean_r;
  for (std::size_t i = 0; i < r.count; ++i) {
    const Vec3& x = r.particles.x[i];
    const double rad = r.particles.radius[i];
    ASSERT_LE(std::hypot(x.x, x.y) + rad, in.diameter / 2 + slack) << i;
    ASSERT_GE(x.z - rad, -slack) << i;
    ASSERT_LE(x.z + rad, in.length + slack) << i;
    ASSERT_EQ(r.particles.v[i].x, 0.0);
  }
  EXPECT_DOUBLE_EQ(max_packing_overlap(r.particles, in.diameter, in.length) / mean_r,
                   r.max_overlap);
  EXPECT_GE(r.coordination, 0.0);
  EXPECT_LT(r.coordination, 12.0);
}

TEST(DemPacking, DeterministicForASeed) {
  const PackingParams in = small_song(0.004, 0.003, 11);  // ~450 grains
  const PackingResult a = generate_packing(in), b = generate_packing(in);
  expect_same_packing(a, b);
  PackingParams other = in;
  other.seed = 12;
  const PackingResult c = generate_packing(other);
  bool differs = c.count != a.count;
  for (std::size_t i = 0; !differs && i < a.count; ++i) differs = c.particles.x[i].x != a.particles.x[i].x;
  EXPECT_TRUE(differs);
}

// Jamming stage (jam = true): the same porosity, count and curve guarantees (the radii are the
// sampled ones), plus a frictional contact network. ~1,500 grains; overlap tolerance 5e-3 r_mean
// (0.5 % of a radius, 1 um here) so the quenched settling stops within the test's budget.
void expect_frictional_network(const PackingParams& in) {
  const PackingResult r = generate_packing(in);
  testing::expect_packing_guarantees(in, r);
  EXPECT_DOUBLE_EQ(r.packing_friction, in.jam_friction);
  // Frictional jamming: the load-bearing grains (rattlers, < 2 contacts, removed repeatedly)
  // have between the isostatic counts 4 (mu -> infinity) and 6 (mu = 0); 3.5 leaves room for
  // the wall layer of a small cylinder (measured 3.8-4.2 on 500-34,000 grains). The loose
  // frictionless packing has 0.03-0.3 contacts per grain, so Z > 2 (with rattlers) tells the
  // two apart; rattlers are a minority (measured 30-40 %).
  EXPECT_GT(r.coordination_no_rattlers, 3.5);
  EXPECT_LT(r.coordination_no_rattlers, 6.0);
  EXPECT_GT(r.coordination, 2.0);
  EXPECT_GE(r.coordination_with_walls, r.coordination);
  EXPECT_LT(r.rattler_fraction, 0.5);
  // Residual stress with Hertz contacts at the final overlaps: small against the 10 MPa of the
  // Ch. 4 comparison (Hertz with overlaps < 5e-3 r gives at most ~1e5 Pa here).
  EXPECT_GT(r.mean_stress_hertz, 0.0);
  EXPECT_LT(r.mean_stress_hertz, 2e5);
  // With density scaling too, the result carries the grains' own masses and inertias, not
  // the scaled ones.
  for (std::size_t i = 0; i < r.count; ++i) {
    const double rad = r.particles.radius[i];
    const double m = 4.0 / 3.0 * std::numbers::pi * rad * rad * rad * in.material.density;
    ASSERT_DOUBLE_EQ(r.particles.mass[i], m) << i;
    ASSERT_DOUBLE_EQ(r.particles.inertia[i], 0.4 * m * rad * rad) << i;
  }
}

PackingParams small_jammed_song() {
  PackingParams in = small_song(0.006, 0.004, 7);
  in.jam = true;
  in.overlap_tolerance = 5e-3;
  in.max_settle_stages = 300;
  return in;
}

TEST(DemPacking, JammedPackingHasAFrictionalContactNetwork) {
  expect_frictional_network(small_jammed_song());
}

// Density scaling (docs/dem.md, "Packing"): the same acceptance rules, with the scene's
// setting of kJamScaledStepsPerStage steps per stage.
TEST(DemPacking, DensityScaledJammedPackingHasAFrictionalContactNetwork) {
  PackingParams in = small_jammed_song();
  in.jam_mass_scaling = true;
  in.jam_steps_per_stage = kJamScaledStepsPerStage;
  expect_frictional_network(in);
}

TEST(DemPacking, JammedPackingIsDeterministic) {
  PackingParams in = small_song(0.004, 0.003, 11);
  in.jam = true;
  in.max_settle_stages = 5;  // determinism does not need convergence
  const PackingResult a = generate_packing(in), b = generate_packing(in);
  expect_same_packing(a, b);
  EXPECT_EQ(a.mean_stress, b.mean_stress);
}

TEST(DemPacking, RefusesBadInput) {
  PackingParams in = small_song(0.004, 0.003, 1);
  in.porosity = 1.0;
  EXPECT_THROW(generate_packing(in), InputError);
  in = small_song(0.004, 0.003, 1);
  in.initial_solid_fraction = 0.6;  // above 1 - n
  EXPECT_THROW(generate_packing(in), InputError);
  in = small_song(0.001, 0.003, 1);  // largest grain (1.2 mm) does not fit
  EXPECT_THROW(generate_packing(in), InputError);
  in = small_song(0.004, 0.003, 1);
  in.jam_friction = -0.1;
  EXPECT_THROW(generate_packing(in), InputError);
  in = small_song(0.004, 0.003, 1);
  in.jam_overlap = 0;
  EXPECT_THROW(generate_packing(in), InputError);
}

}  // namespace
}  // namespace kolsky::dem
