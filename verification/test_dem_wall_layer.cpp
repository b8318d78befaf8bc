// Wall-layer solid fraction profile (dem/wall_layer.hpp): the lattice count against exact solid
// volumes, the profile's shape next to a wall, thread independence, bad input.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <cstdio>
#include <numbers>

#include "core/errors.hpp"
#include "dem/test_fills.hpp"
#include "dem/wall_layer.hpp"

namespace kolsky::dem {
namespace {

const std::vector<Material> kSand{{78e9, 0.3, 2650}};
constexpr double kPi = std::numbers::pi;

// RSA grains (no overlaps, all inside the cylinder): the exact solid fraction is their volume
// over the cylinder's.
struct RsaCase {
  Particles p;
  double diameter = 6e-3, length = 4e-3, exact = 0;
};
RsaCase rsa_case() {
  RsaCase c;
  const double R = c.diameter / 2;
  c.p = random_packing(3000, 1e-4, 2e-4, {{-R, -R, 0}, {R, R, c.length}, R}, 5, 0, kSand);
  double v = 0;
  for (double r : c.p.radius) v += 4.0 / 3.0 * kPi * r * r * r;
  c.exact = v / (kPi * R * R * c.length);
  return c;
}

TEST(TestDemWallLayer, LatticeCountConvergesToTheExactSolidFraction) {
  const RsaCase c = rsa_case();
  // Measured relative errors for this case (3,000 grains, r 0.1-0.2 mm, phi 0.414): 7.7e-4,
  // 2.0e-4 and 4.8e-5 at spacings 50, 25 and 12.5 um (r_min / 2, / 4, / 8): about second
  // order. Bounds: 2.5x the measured error at r_min / 2 (the spacing the Chapter 4 report
  // uses is r_min / 3), and at least first-order convergence over the two halvings.
  double err_coarse = 0, err_fine = 0;
  for (double h : {5e-5, 2.5e-5, 1.25e-5}) {
    const WallLayerProfile prof = wall_layer_profile(c.p, c.diameter, c.length, h, 5e-5);
    const double err = std::abs(prof.fraction_beyond(0) / c.exact - 1);
    std::printf("spacing %.3g mm: phi %.5f exact %.5f relative error %.2e\n", h * 1e3,
                prof.fraction_beyond(0), c.exact, err);
    if (h == 5e-5) err_coarse = err;
    if (h == 1.25e-5) err_fine = err;
    EXPECT_NEAR(prof.volume_share_beyond(0), 1.0, 1e-15);
  }
  EXPECT_LT(err_coarse, 2e-3);
  EXPECT_LT(err_fine, err_coarse / 4);
}

TEST(TestDemWallLayer, CubicLatticeGivesPiOverSixAwayFromTheWalls) {
  // Touching spheres on a simple cubic lattice covering the whole cylinder: pi / 6 at every
  // distance from the walls (spheres poking out of the cylinder only count inside it). The
  // sample lattice's spacing is incommensurate with the spheres' (ratio 0.0977), so each
  // sphere is sampled at another offset.
  const double r = 1e-4, a = 2 * r, D = 6e-3, L = 4e-3;
  const Particles lat = cubic_lattice(32, 32, 22, r, a, {-3.1e-3, -3.1e-3, -0.1e-3}, 0, kSand);
  const WallLayerProfile prof = wall_layer_profile(lat, D, L, 0.0977 * a, 0.5e-3);
  // Tolerance 1 %: the count itself is good to ~1e-4 at h ~ r / 5 (above), but the curved
  // boundary of each region cuts the periodic lattice at no particular phase, an error of the
  // order of a / R ~ 0.07 times the contrast between a cut cell and the mean; measured 0.1-0.7 %
  // (0.52661, 0.52298, 0.52734, 0.52457 beyond 0, 0.5, 1, 1.5 mm).
  for (double d : {0.0, 0.5e-3, 1e-3, 1.5e-3}) EXPECT_NEAR(prof.fraction_beyond(d), kPi / 6, 0.01 * kPi / 6) << d;
  EXPECT_GT(prof.volume_share_beyond(0.5e-3), prof.volume_share_beyond(1e-3));
  EXPECT_TRUE(std::isnan(WallLayerProfile{}.fraction(0)));
}

TEST(TestDemWallLayer, RsaGrainsLeaveALooserLayerAtTheWall) {
  // Grains cannot cross a wall: the first bin (within r_min / 2 of a wall) holds only the caps
  // of the grains that touch it, far below the core.
  const RsaCase c = rsa_case();
  const WallLayerProfile prof = wall_layer_profile(c.p, c.diameter, c.length, 2.5e-5, 5e-5);
  EXPECT_LT(prof.fraction(0), 0.6 * prof.fraction_beyond(4e-4));
  EXPECT_GT(prof.fraction_beyond(4e-4), prof.fraction_beyond(0));
}

TEST(TestDemWallLayer, SameCountsForAnyThreadCountAndBadInputRefused) {
  const RsaCase c = rsa_case();
  const int saved = omp_get_max_threads();
  omp_set_num_threads(1);
  const WallLayerProfile one = wall_layer_profile(c.p, c.diameter, c.length, 5e-5, 5e-5);
  omp_set_num_threads(2);
  const WallLayerProfile two = wall_layer_profile(c.p, c.diameter, c.length, 5e-5, 5e-5);
  omp_set_num_threads(saved);
  EXPECT_EQ(one.points, two.points);
  EXPECT_EQ(one.solid, two.solid);
  EXPECT_THROW(wall_layer_profile(c.p, 0, c.length, 5e-5, 5e-5), InputError);
  EXPECT_THROW(wall_layer_profile(c.p, c.diameter, c.length, 0, 5e-5), InputError);
  EXPECT_THROW(wall_layer_profile(c.p, c.diameter, c.length, 5e-5, -1), InputError);
  EXPECT_THROW(wall_layer_profile(c.p, c.diameter, c.length, 1e-2, 5e-5), InputError);
}

}  // namespace
}  // namespace kolsky::dem
