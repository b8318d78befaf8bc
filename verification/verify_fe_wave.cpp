// Elastic wave speed of a meshed rod (axisymmetric cylinder, radius a, length L), measured from
// the period of its first free-free axial mode (mode shape cos(pi z / L) given as the initial
// velocity; the modal coordinate is the mass-weighted projection on it):
//   lateral surface free:        omega = c0 k / sqrt(1 + nu^2 k^2 a^2 / 2), c0 = sqrt(E/rho)
//                                (Rayleigh-Love lateral-inertia correction; Graff 1975,
//                                Wave Motion in Elastic Solids, Sec. 2.11), three meshes give
//                                the observed order of convergence;
//   lateral surface constrained: uniaxial strain, constrained modulus M = K + 4G/3; the discrete
//                                system is then exactly the 1-D lumped chain, whose central-
//                                difference frequency is (2/dt) asin((c dt/h) sin(k h/2)).
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "fe/body.hpp"
#include "verify_fe_helpers.hpp"

namespace kolsky::fe {
namespace {

constexpr double kPi = std::numbers::pi;
const LinearElastic kSteel{200e9, 0.33, 8100};  // Sec. 2.3.1 bar steel: c0 = 4969 m/s
constexpr double kRadius = 5e-3, kLength = 0.1;

struct ModeRun {
  double omega;  // measured angular frequency, rad/s
  double dt;
};

// Runs the first free-free axial mode for about 2.3 periods at dt = courant * stable dt and
// returns the frequency from the zero crossings of the modal coordinate.
ModeRun run_mode(int n_r, int n_z, bool constrained, double courant) {
  Mesh mesh;
  add_block(mesh, 0.0, kRadius, 0.0, kLength, n_r, n_z);
  if (constrained)
    for (std::size_t i = 0; i < mesh.nodes.size(); ++i) mesh.nodes.fixed_r[i] = 1;
  Body body(std::move(mesh), {Part{kSteel, 0, n_r * n_z}}, 1);
  Nodes& nd = body.nodes();
  std::vector<double> phi(nd.size());
  for (std::size_t i = 0; i < nd.size(); ++i) {
    phi[i] = std::cos(kPi * nd.z0[i] / kLength);
    nd.vz[i] = 1e-3 * phi[i];  // 1 mm/s: strains ~1e-9, geometric effects ~1e-9 relative
  }
  const double dt = courant * body.stable_dt();
  const double period = 2.0 * kLength / std::sqrt(kSteel.youngs_modulus / kSteel.density);
  const long n_steps = static_cast<long>(2.3 * period / dt);
  std::vector<double> crossings;
  double q_prev = 0.0;
  for (long n = 0; n <= n_steps; ++n) {
    double q = 0.0;
    for (std::size_t i = 0; i < nd.size(); ++i) q += nd.mass[i] * phi[i] * nd.uz[i];
    if (n > 0 && ((q_prev < 0.0) != (q < 0.0)) && q != 0.0)
      crossings.push_back(dt * (static_cast<double>(n - 1) + q_prev / (q_prev - q)));
    q_prev = q;
    body.update_internal_forces();
    body.advance(dt, 0.0);
  }
  // Crossings at T/2, T, 3T/2, 2T: a least-squares slope through them.
  const double m = static_cast<double>(crossings.size());
  double sx = 0, sy = 0, sxx = 0, sxy = 0;
  for (std::size_t k = 0; k < crossings.size(); ++k) {
    const double x = static_cast<double>(k + 1);
    sx += x;
    sy += crossings[k];
    sxx += x * x;
    sxy += x * crossings[k];
  }
  const double half_period = (m * sxy - sx * sy) / (m * sxx - sx * sx);
  return {kPi / half_period, dt};
}

TEST(VerifyFeWave, BarSpeedWithLateralFreeSurfaceConverges) {
  const double c0 = std::sqrt(kSteel.youngs_modulus / kSteel.density);
  const double k = kPi / kLength, nu = kSteel.poisson_ratio;
  const double omega_ref = c0 * k / std::sqrt(1.0 + 0.5 * nu * nu * k * k * kRadius * kRadius);
  double err[3];
  for (int level = 0; level < 3; ++level) {
    const int f = 1 << level;
    err[level] = run_mode(f, 10 * f, false, 0.5).omega / omega_ref - 1.0;
    RecordProperty("relative_error_nz" + std::to_string(10 * f), verify::sci(err[level]));
  }
  const double order_1 = std::log2(err[0] / err[1]), order_2 = std::log2(err[1] / err[2]);
  RecordProperty("observed_order", verify::sci(order_1) + ", " + verify::sci(order_2));
  // Lumped mass + bilinear elements + central differences: second order in h (at a fixed
  // Courant fraction); 0.3 of slack for the lateral-inertia term's own mesh error.
  EXPECT_NEAR(order_1, 2.0, 0.3);
  EXPECT_NEAR(order_2, 2.0, 0.3);
  // Finest mesh (h_z = 2.5 mm, kh = 0.079): the 1-D dispersion estimate (kh)^2/24 = 2.6e-4.
  EXPECT_LT(std::fabs(err[2]), 5e-4);
  // Richardson extrapolation removes the h^2 term; what is left is the Love model's own
  // O((ka)^4) error (~1e-7) and higher-order mesh terms.
  const double extrapolated = err[2] + (err[2] - err[1]) / 3.0;
  RecordProperty("richardson_error", verify::sci(extrapolated));
  EXPECT_LT(std::fabs(extrapolated), 5e-5);
}

TEST(VerifyFeWave, ConstrainedRodIsTheExactLumpedChain) {
  const int n_z = 40;
  const auto run = run_mode(2, n_z, true, 0.5);
  const double c = std::sqrt(kSteel.constrained_modulus() / kSteel.density);
  const double h = kLength / n_z, k = kPi / kLength;
  const double omega_chain = 2.0 / run.dt * std::asin(c * run.dt / h * std::sin(0.5 * k * h));
  const double rel = run.omega / omega_chain - 1.0;
  RecordProperty("relative_error_vs_chain", verify::sci(rel));
  // Uniaxial strain is an exact solution of the discrete axisymmetric system, so only the
  // zero-crossing measurement errs: O((omega dt)^3) per crossing, below 1e-6.
  EXPECT_LT(std::fabs(rel), 1e-6);
  RecordProperty("constrained_speed_m_per_s", verify::sci(run.omega / k));
}

}  // namespace
}  // namespace kolsky::fe
