// Unit tests of the axisymmetric quad (volume, volume gradient, zero-energy modes of the
// mean-dilatation stiffness: the hourglass check), the materials (compaction EOS, Mohr-Coulomb
// cap of the pseudo-tensor model) and the Lame wall stiffness.
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <vector>
#include <numbers>

#include "core/errors.hpp"
#include "fe/fe_specimen.hpp"
#include "fe/materials.hpp"
#include "fe/quad_axisym.hpp"

namespace kolsky::fe {
namespace {

constexpr double kPi = std::numbers::pi;

// Eigenvalues of a stiffness with the fixed dofs removed (their rows and columns replaced by a
// clearly non-zero diagonal, so they add no zero mode), by cyclic Jacobi rotations.
std::array<double, 8> free_eigenvalues(const Stiffness8& k, const std::vector<int>& fixed) {
  double a[8][8];
  double scale = 0.0;
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) {
      a[i][j] = k[static_cast<std::size_t>(8 * i + j)];
      scale = std::max(scale, std::fabs(a[i][j]));
    }
  for (int d : fixed) {
    for (int j = 0; j < 8; ++j) a[d][j] = a[j][d] = 0.0;
    a[d][d] = scale;
  }
  for (int sweep = 0; sweep < 50; ++sweep)
    for (int p = 0; p < 7; ++p)
      for (int q = p + 1; q < 8; ++q) {
        if (std::fabs(a[p][q]) < 1e-300) continue;
        const double theta = 0.5 * std::atan2(2 * a[p][q], a[q][q] - a[p][p]);
        const double c = std::cos(theta), s = std::sin(theta);
        for (int j = 0; j < 8; ++j) {  // rows p, q
          const double ap = a[p][j], aq = a[q][j];
          a[p][j] = c * ap - s * aq;
          a[q][j] = s * ap + c * aq;
        }
        for (int i = 0; i < 8; ++i) {  // columns p, q
          const double ap = a[i][p], aq = a[i][q];
          a[i][p] = c * ap - s * aq;
          a[i][q] = s * ap + c * aq;
        }
      }
  std::array<double, 8> ev{};
  for (int i = 0; i < 8; ++i) ev[static_cast<std::size_t>(i)] = a[i][i];
  return ev;
}

int count_zero(const std::array<double, 8>& ev) {
  double top = 0.0;
  for (double x : ev) top = std::max(top, std::fabs(x));
  int n = 0;
  // Round-off of the rotations is ~1e-14 of the largest eigenvalue; a true mode of these
  // elements is above 1e-3 of it.
  for (double x : ev) n += std::fabs(x) < 1e-9 * top;
  return n;
}

TEST(FeQuad, RingVolumeIsExact) {
  // Rectangle: pi (r2^2 - r1^2) h.
  const auto g = quad_geometry({1e-3, 3e-3, 3e-3, 1e-3}, {0, 0, 2e-3, 2e-3});
  EXPECT_NEAR(g.volume, kPi * (9e-6 - 1e-6) * 2e-3, 1e-20);  // exact up to round-off
  // Distorted quad: Pappus, V = 2 pi * (first moment of the polygon about the axis).
  const Quad4 r = {1e-3, 4e-3, 3.5e-3, 0.5e-3}, z = {0, 0.5e-3, 3e-3, 2e-3};
  double moment = 0.0;
  for (int a = 0; a < 4; ++a) {
    const int b = (a + 1) % 4;
    moment += (r[a] + r[b]) * (r[a] * z[b] - r[b] * z[a]) / 6.0;
  }
  EXPECT_NEAR(quad_geometry(r, z).volume, 2 * kPi * moment, 1e-12 * 2 * kPi * moment);  // exact rule
}

TEST(FeQuad, VolumeGradientMatchesFiniteDifferences) {
  Quad4 r = {1e-3, 4e-3, 3.5e-3, 0.5e-3}, z = {0, 0.5e-3, 3e-3, 2e-3};
  const auto g = quad_geometry(r, z);
  const double h = 1e-9;
  for (int a = 0; a < 4; ++a) {
    Quad4 rp = r, rm = r, zp = z, zm = z;
    rp[a] += h;
    rm[a] -= h;
    zp[a] += h;
    zm[a] -= h;
    const double dr = (quad_geometry(rp, z).volume - quad_geometry(rm, z).volume) / (2 * h);
    const double dz = (quad_geometry(r, zp).volume - quad_geometry(r, zm).volume) / (2 * h);
    // V is cubic in the coordinates: central differences err by h^2 * 1e-3 relative.
    EXPECT_NEAR(g.dvol_dr[a], dr, 1e-6 * std::fabs(dr) + 1e-18);
    EXPECT_NEAR(g.dvol_dz[a], dz, 1e-6 * std::fabs(dz) + 1e-18);
  }
}

TEST(FeQuad, MeanDilatationElementHasNoHourglassModes) {
  const LinearElastic steel{200e9, 0.3, 8100};
  // Off the axis: all 8 dofs free; the only zero-energy mode is the axial translation (radial
  // translation strains the hoop direction).
  const auto off = quad_geometry({2e-3, 3e-3, 3.2e-3, 1.9e-3}, {0, 0.1e-3, 1.1e-3, 0.9e-3});
  const auto k_off = bbar_stiffness(off, steel.bulk_modulus(), steel.shear_modulus());
  EXPECT_EQ(count_zero(free_eigenvalues(k_off, {})), 1);
  // On the axis (nodes 0 and 3 at r = 0, u_r fixed there): again only the axial translation.
  const auto on = quad_geometry({0, 1e-3, 1e-3, 0}, {0, 0, 1e-3, 1e-3});
  const auto k_on = bbar_stiffness(on, steel.bulk_modulus(), steel.shear_modulus());
  EXPECT_EQ(count_zero(free_eigenvalues(k_on, {0, 6})), 1);

  // The check has teeth: one-point integration of the same element shows the hourglass modes.
  Stiffness8 k1{};
  const auto& g = off;
  // Centroid gradients = mean of the Gauss gradients for a bilinear map's constant part.
  double b[4][8] = {};
  double w = g.volume;
  for (int a = 0; a < 4; ++a)
    for (int gp = 0; gp < kGaussPoints; ++gp) {
      b[0][2 * a] += 0.25 * g.dn_dr[gp][a];
      b[1][2 * a + 1] += 0.25 * g.dn_dz[gp][a];
      b[2][2 * a] += 0.25 * g.n_over_r[gp][a];
      b[3][2 * a] += 0.25 * g.dn_dz[gp][a];
      b[3][2 * a + 1] += 0.25 * g.dn_dr[gp][a];
    }
  const double lam = steel.bulk_modulus() - 2.0 / 3.0 * steel.shear_modulus(), mu = steel.shear_modulus();
  const double d[4][4] = {
      {lam + 2 * mu, lam, lam, 0}, {lam, lam + 2 * mu, lam, 0}, {lam, lam, lam + 2 * mu, 0}, {0, 0, 0, mu}};
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j)
      for (int p = 0; p < 4; ++p)
        for (int q = 0; q < 4; ++q)
          k1[static_cast<std::size_t>(8 * i + j)] += w * b[p][i] * d[p][q] * b[q][j];
  const int one_point_zero_modes = count_zero(free_eigenvalues(k1, {}));
  RecordProperty("one_point_zero_modes", one_point_zero_modes);
  EXPECT_GE(one_point_zero_modes, 2);
}

TEST(FeQuad, CourantLengthIsTheShortSideOfARectangle) {
  EXPECT_NEAR(courant_length({0, 2e-3, 2e-3, 0}, {0, 0, 0.5e-3, 0.5e-3}), 0.5e-3, 1e-15);  // exact
  EXPECT_NEAR(courant_length({0, 1e-3, 1e-3, 0}, {0, 0, 1e-3, 1e-3}), 1e-3, 1e-15);        // exact
}

CompactionEos sand_eos() {
  CompactionEos e;
  e.loading.x = {0.0, 0.05, 0.10, 0.20};
  e.loading.y = {0.0, 7.25e6, 18e6, 60e6};  // initial slope 145 MPa (Sec. 2.3.4)
  e.unloading_bulk_modulus = 2e9;
  return e;
}

TEST(FeMaterials, CompactionEosLoadsUnloadsAndReloads) {
  const auto e = sand_eos();
  EXPECT_NO_THROW(e.validate("eos"));
  EXPECT_DOUBLE_EQ(e.pressure(0.05, 0.0), 7.25e6);                    // on the curve
  EXPECT_DOUBLE_EQ(e.pressure(0.10, 0.05), 18e6);                     // virgin loading moves on
  EXPECT_DOUBLE_EQ(e.pressure(0.099, 0.10), 18e6 - 2e9 * 0.001);      // unloading line
  EXPECT_DOUBLE_EQ(e.pressure(0.05, 0.10), 0.0);                      // no tension
  EXPECT_DOUBLE_EQ(e.pressure(0.30, 0.0), 60e6 + 420e6 * 0.10);       // last segment extended
  EXPECT_DOUBLE_EQ(e.pressure(-0.01, 0.0), 0.0);                      // dilation: no pressure
  EXPECT_DOUBLE_EQ(e.max_tangent(), 2e9);
}

TEST(FeMaterials, CompactionEosRejectsEnergyCreatingUnloading) {
  auto e = sand_eos();
  e.unloading_bulk_modulus = 300e6;  // below the 420 MPa last slope
  EXPECT_THROW(e.validate("eos"), InputError);
  auto f = sand_eos();
  f.loading.y[0] = 1e5;
  EXPECT_THROW(f.validate("eos"), InputError);
}

TEST(FeMaterials, PseudoTensorCapIsTheMohrCoulombCompressionMeridian) {
  PseudoTensorModeI m;
  m.eos = sand_eos();
  const double s = std::sin(33.0 * kPi / 180.0);
  EXPECT_NEAR(m.yield_slope(), 6 * s / (3 - s), 1e-15);  // exact expression
  EXPECT_DOUBLE_EQ(m.yield_intercept(), 0.0);            // no cohesion (Sec. 2.3.2)
  // Triaxial compression at the cap: sigma_1/sigma_3 = (1 + sin phi)/(1 - sin phi).
  const double p = 10e6, q = m.yield_stress(p);
  const double s1 = p + 2 * q / 3, s3 = p - q / 3;
  EXPECT_NEAR(s1 / s3, (1 + s) / (1 - s), 1e-12);  // identity up to round-off
  // Radial return lands on the cap and keeps the deviator's direction.
  Deviator d = {-2 * q / 3, 4 * q / 3, -2 * q / 3, 0.0};
  limit_deviator(d, q);
  EXPECT_NEAR(mises(d), q, 1e-9 * q);
  EXPECT_NEAR(d[1] / d[0], -2.0, 1e-12);
  Deviator zero_p = {1e5, -1e5, 0, 0};
  limit_deviator(zero_p, m.yield_stress(0.0));  // no cohesion, no pressure: no shear strength
  EXPECT_EQ(mises(zero_p), 0.0);
}

TEST(FeMaterials, LameWallStiffnessThinLimit) {
  const LinearElastic steel{200e9, 0.33, 8100};
  const double a = 9.55e-3, t = 1e-6;
  // Thin wall: p/u = E t / a^2; the thick-wall correction is O(t/a) = 1e-4.
  EXPECT_NEAR(lame_wall_stiffness(steel, a, t), 200e9 * t / (a * a), 2e-4 * 200e9 * t / (a * a));
}

}  // namespace
}  // namespace kolsky::fe
