// dem::interior_porosity (packing.hpp; issue 31, H1: "porosity counted over the whole sleeve,
// with the loose layer at the wall"): a Monte Carlo estimate checked against exact solid
// fractions of spheres placed by hand, to four standard errors (sqrt(n (1 - n) / samples):
// the estimate is a binomial proportion), and the margin that keeps the wall layer out.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <stdexcept>

#include "dem/packing.hpp"

namespace kolsky::dem {
namespace {

constexpr double kD = 0.019, kL = 0.0093;  // the Chapter 4 specimen (m)

Particles spheres(std::initializer_list<std::pair<Vec3, double>> list) {
  const std::vector<Material> materials(1);
  Particles p;
  for (const auto& [x, r] : list) p.add(x, r, 0, materials);
  return p;
}

double standard_error(double n, long samples) { return std::sqrt(n * (1 - n) / samples); }

TEST(DemInteriorPorosity, OneSphereGivesItsExactVolumeFraction) {
  const double a = 0.004, R = kD / 2;
  const Particles p = spheres({{{0, 0, kL / 2}, a}});
  const long samples = 200000;
  const double exact = 1 - (4.0 / 3.0 * std::numbers::pi * a * a * a) / (std::numbers::pi * R * R * kL);
  const double n = interior_porosity(p, kD, kL, 0.0, samples, 7);
  EXPECT_NEAR(n, exact, 4 * standard_error(exact, samples)) << "exact " << exact;
  // The same sphere in an interior 1 mm in from every wall (it still lies wholly inside).
  const double m = 0.001, Ri = R - m, Li = kL - 2 * m;
  const double exact_i = 1 - (4.0 / 3.0 * std::numbers::pi * a * a * a) / (std::numbers::pi * Ri * Ri * Li);
  EXPECT_NEAR(interior_porosity(p, kD, kL, m, samples, 7), exact_i, 4 * standard_error(exact_i, samples));
  EXPECT_EQ(interior_porosity(p, kD, kL, m, samples, 7), interior_porosity(p, kD, kL, m, samples, 7));
}

TEST(DemInteriorPorosity, TheMarginLeavesTheWallLayerOut) {
  // Grains touching the tube and an end wall, all within 1 mm of them: the interior is empty
  // of solid, while the whole cylinder is not.
  const double r = 0.0004, R = kD / 2;
  const Particles p = spheres({{{R - r, 0, kL / 2}, r}, {{0, -(R - r), kL / 2}, r}, {{0, 0, r}, r}});
  EXPECT_EQ(interior_porosity(p, kD, kL, 2 * r, 100000, 3), 1.0);
  EXPECT_LT(interior_porosity(p, kD, kL, 0.0, 1000000, 3), 1.0);
  EXPECT_THROW(interior_porosity(p, kD, kL, kL / 2, 1000, 1), std::invalid_argument);  // no interior
  EXPECT_THROW(interior_porosity(p, kD, kL, 0.0, 0, 1), std::invalid_argument);
}

}  // namespace
}  // namespace kolsky::dem
