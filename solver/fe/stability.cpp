#include "fe/stability.hpp"

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>

#include "fe/quad_axisym.hpp"

namespace kolsky::fe {

namespace {

bool fixed_dof(const Nodes& nd, int dof) {
  const auto i = static_cast<std::size_t>(dof / 2);
  return dof % 2 == 0 ? nd.fixed_r[i] != 0 : nd.fixed_z[i] != 0;
}

}  // namespace

double spring_eigen_bound(const Nodes& nd, const std::vector<SpringStencil>& springs) {
  // Row i of sum_c k_c |h_c| |h_c|^T with h_c = w / sqrt(m): k_c |h_ci| * sum_j |h_cj|.
  std::vector<double> row(2 * nd.size(), 0.0);
  for (const auto& sp : springs) {
    double h[3] = {0, 0, 0}, sum = 0.0;
    for (std::size_t j = 0; j < 3; ++j) {
      const int d = sp.dof[j];
      if (d < 0 || fixed_dof(nd, d)) continue;
      h[j] = std::fabs(sp.weight[j]) / std::sqrt(nd.mass[static_cast<std::size_t>(d / 2)]);
      sum += h[j];
    }
    for (std::size_t j = 0; j < 3; ++j)
      if (h[j] > 0.0) row[static_cast<std::size_t>(sp.dof[j])] += sp.k * h[j] * sum;
  }
  return row.empty() ? 0.0 : *std::max_element(row.begin(), row.end());
}

double compose_stable_dt(double dt_elements, double spring_bound) {
  const double lam = 4.0 / (dt_elements * dt_elements) + spring_bound;
  return 2.0 / std::sqrt(lam);
}

double critical_dt(const Body& body, const std::vector<SpringStencil>& springs, int n_lanczos) {
  const Mesh& mesh = body.mesh();
  const Nodes& nd = mesh.nodes;
  const auto n = static_cast<Eigen::Index>(2 * nd.size());
  // Element stiffnesses at the current geometry with each part's steepest tangent.
  std::vector<Stiffness8> ke(mesh.quads.size());
  for (const auto& part : body.parts()) {
    const double kb = std::visit([](const auto& m) { return max_bulk_tangent(m); }, part.material);
    const double g = std::visit([](const auto& m) { return shear_modulus(m); }, part.material);
    for (int e = part.first_element; e < part.first_element + part.n_elements; ++e) {
      Quad4 r, z;
      current_coordinates(mesh, e, r, z);
      ke[static_cast<std::size_t>(e)] = bbar_stiffness(quad_geometry(r, z), kb, g);
    }
  }
  Eigen::VectorXd inv_sqrt_m = Eigen::VectorXd::Zero(n);  // 0 on fixed dofs: removes them
  for (Eigen::Index d = 0; d < n; ++d)
    if (!fixed_dof(nd, static_cast<int>(d)))
      inv_sqrt_m[d] = 1.0 / std::sqrt(nd.mass[static_cast<std::size_t>(d / 2)]);

  auto apply = [&](const Eigen::VectorXd& x, Eigen::VectorXd& y) {  // y = M^-1/2 K M^-1/2 x
    const Eigen::VectorXd xs = inv_sqrt_m.cwiseProduct(x);
    y.setZero(n);
    for (std::size_t e = 0; e < mesh.quads.size(); ++e) {
      Eigen::Index dof[8];
      for (std::size_t a = 0; a < 4; ++a) {
        dof[2 * a] = 2 * static_cast<Eigen::Index>(mesh.quads[e][a]);
        dof[2 * a + 1] = dof[2 * a] + 1;
      }
      for (std::size_t i = 0; i < 8; ++i) {
        double s = 0.0;
        for (std::size_t j = 0; j < 8; ++j) s += ke[e][8 * i + j] * xs[dof[j]];
        y[dof[i]] += s;
      }
    }
    for (const auto& sp : springs) {
      double s = 0.0;
      for (std::size_t j = 0; j < 3; ++j)
        if (sp.dof[j] >= 0) s += sp.weight[j] * xs[sp.dof[j]];
      for (std::size_t j = 0; j < 3; ++j)
        if (sp.dof[j] >= 0) y[sp.dof[j]] += sp.k * sp.weight[j] * s;
    }
    y = inv_sqrt_m.cwiseProduct(y);
  };

  const auto m = static_cast<Eigen::Index>(std::min<std::int64_t>(n_lanczos, n));
  if (m < 1) throw std::invalid_argument("critical_dt needs at least one Lanczos step");
  Eigen::MatrixXd q(n, m);
  Eigen::VectorXd alpha(m), beta(m);
  // Deterministic start vector with every mode present (no rng: reproducible everywhere).
  Eigen::VectorXd v(n);
  for (Eigen::Index d = 0; d < n; ++d)
    v[d] = inv_sqrt_m[d] > 0.0 ? 1.0 + 0.5 * std::sin(1.7 * static_cast<double>(d) + 0.3) : 0.0;
  v.normalize();
  Eigen::VectorXd w;
  Eigen::Index k = 0;
  for (; k < m; ++k) {
    q.col(k) = v;
    apply(v, w);
    alpha[k] = w.dot(v);
    // Full re-orthogonalisation (twice is enough, Kahan-Parlett).
    for (int pass = 0; pass < 2; ++pass)
      for (Eigen::Index j = 0; j <= k; ++j) w -= q.col(j).dot(w) * q.col(j);
    beta[k] = w.norm();
    if (beta[k] < 1e-12 * std::fabs(alpha[k])) {
      ++k;
      break;
    }
    v = w / beta[k];
  }
  Eigen::SelfAdjointEigenSolver<Eigen::MatrixXd> eig;
  Eigen::VectorXd diag = alpha.head(k);
  Eigen::VectorXd sub = beta.head(std::max<Eigen::Index>(k - 1, 0));
  eig.computeFromTridiagonal(diag, sub, Eigen::EigenvaluesOnly);
  return 2.0 / std::sqrt(eig.eigenvalues().maxCoeff());
}

}  // namespace kolsky::fe
