#include "fe/quad_axisym.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace kolsky::fe {

namespace {

constexpr double kXi[4] = {-1.0, 1.0, 1.0, -1.0};   // node natural coordinates
constexpr double kEta[4] = {-1.0, -1.0, 1.0, 1.0};

struct GaussPoint {
  double xi, eta;
};

constexpr double kG = 0.57735026918962576451;  // 1/sqrt(3)
constexpr GaussPoint kGauss[kGaussPoints] = {{-kG, -kG}, {kG, -kG}, {kG, kG}, {-kG, kG}};

std::array<Quad4, kGaussPoints> make_shape_functions() {
  std::array<Quad4, kGaussPoints> n{};
  for (int g = 0; g < kGaussPoints; ++g)
    for (int a = 0; a < 4; ++a)
      n[g][a] = 0.25 * (1.0 + kXi[a] * kGauss[g].xi) * (1.0 + kEta[a] * kGauss[g].eta);
  return n;
}

// Natural-coordinate derivatives at the Gauss points, [gauss][node]: geometry independent.
struct NaturalGradients {
  std::array<Quad4, kGaussPoints> dxi{}, deta{};
};

NaturalGradients make_natural_gradients() {
  NaturalGradients d;
  for (int g = 0; g < kGaussPoints; ++g)
    for (int a = 0; a < 4; ++a) {
      d.dxi[g][a] = 0.25 * kXi[a] * (1.0 + kEta[a] * kGauss[g].eta);
      d.deta[g][a] = 0.25 * kEta[a] * (1.0 + kXi[a] * kGauss[g].xi);
    }
  return d;
}

const NaturalGradients& natural_gradients() {
  static const NaturalGradients d = make_natural_gradients();
  return d;
}

}  // namespace

const std::array<Quad4, kGaussPoints>& gauss_shape_functions() {
  static const std::array<Quad4, kGaussPoints> n = make_shape_functions();
  return n;
}

QuadGeometry quad_geometry(const Quad4& r, const Quad4& z) {
  QuadGeometry q;
  const auto& shape = gauss_shape_functions();
  const auto& nat = natural_gradients();
  for (int g = 0; g < kGaussPoints; ++g) {
    const Quad4& dn_dxi = nat.dxi[g];
    const Quad4& dn_deta = nat.deta[g];
    double r_xi = 0, r_eta = 0, z_xi = 0, z_eta = 0, rg = 0;
    for (int a = 0; a < 4; ++a) {
      r_xi += dn_dxi[a] * r[a];
      r_eta += dn_deta[a] * r[a];
      z_xi += dn_dxi[a] * z[a];
      z_eta += dn_deta[a] * z[a];
      rg += shape[g][a] * r[a];
    }
    const double det = r_xi * z_eta - r_eta * z_xi;
    if (!(det > 0.0) || !(rg > 0.0)) q.valid = false;
    const double inv = 1.0 / det, inv_r = 1.0 / rg;
    for (int a = 0; a < 4; ++a) {
      q.dn_dr[g][a] = inv * (z_eta * dn_dxi[a] - z_xi * dn_deta[a]);
      q.dn_dz[g][a] = inv * (-r_eta * dn_dxi[a] + r_xi * dn_deta[a]);
      q.n_over_r[g][a] = shape[g][a] * inv_r;
    }
    // Unit Gauss weights (2x2 rule); 2 pi r turns the r-z area element into a ring volume.
    q.weight[g] = 2.0 * std::numbers::pi * rg * det;
    q.volume += q.weight[g];
    for (int a = 0; a < 4; ++a) {
      // dV/dr_a = sum w (dN/dr + N/r): d(det J)/dr_a = det J dN_a/dr and d(r_g)/dr_a = N_a.
      q.dvol_dr[a] += q.weight[g] * (q.dn_dr[g][a] + q.n_over_r[g][a]);
      q.dvol_dz[a] += q.weight[g] * q.dn_dz[g][a];
    }
  }
  return q;
}

double courant_length(const Quad4& r, const Quad4& z) {
  const double area = 0.5 * ((r[2] - r[0]) * (z[3] - z[1]) - (r[3] - r[1]) * (z[2] - z[0]));
  double longest = 0.0;
  for (int a = 0; a < 4; ++a) {
    const double dr = r[(a + 1) % 4] - r[a], dz = z[(a + 1) % 4] - z[a];
    longest = std::max(longest, dr * dr + dz * dz);
  }
  return area / std::sqrt(longest);
}

Stiffness8 bbar_stiffness(const QuadGeometry& q, double bulk, double shear) {
  Stiffness8 k{};
  for (int g = 0; g < kGaussPoints; ++g) {
    // Deviatoric part at each Gauss point: D_dev = 2G (I - m m^T / 3) on the normal strains,
    // G on the engineering shear.
    double b[4][8] = {};  // rows rr, zz, tt, rz
    for (int a = 0; a < 4; ++a) {
      b[0][2 * a] = q.dn_dr[g][a];
      b[1][2 * a + 1] = q.dn_dz[g][a];
      b[2][2 * a] = q.n_over_r[g][a];
      b[3][2 * a] = q.dn_dz[g][a];
      b[3][2 * a + 1] = q.dn_dr[g][a];
    }
    for (int i = 0; i < 8; ++i) {
      const double tr = b[0][i] + b[1][i] + b[2][i];
      double s[4];  // D_dev B column i
      for (int c = 0; c < 3; ++c) s[c] = 2.0 * shear * (b[c][i] - tr / 3.0);
      s[3] = shear * b[3][i];
      for (int j = 0; j < 8; ++j)
        k[8 * j + i] += q.weight[g] * (b[0][j] * s[0] + b[1][j] * s[1] + b[2][j] * s[2] + b[3][j] * s[3]);
    }
  }
  double dv[8];
  for (int a = 0; a < 4; ++a) {
    dv[2 * a] = q.dvol_dr[a];
    dv[2 * a + 1] = q.dvol_dz[a];
  }
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) k[8 * i + j] += bulk * dv[i] * dv[j] / q.volume;
  return k;
}

}  // namespace kolsky::fe
