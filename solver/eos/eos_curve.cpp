// Eq. 2.9 solved along the volumetric strain, and the tables and work derived from the path
// (see eos_curve.hpp).
#include "eos/eos_curve.hpp"

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace kolsky::eos {

std::vector<double> uniform_strains(double eps_max, std::size_t n_points) {
  if (!(eps_max > 0.0) || !std::isfinite(eps_max))
    throw std::invalid_argument("eps_max: must be finite and > 0");
  if (n_points < 2) throw std::invalid_argument("n_points: must be >= 2");
  std::vector<double> e(n_points);
  for (std::size_t i = 0; i < n_points; ++i)
    e[i] = eps_max * static_cast<double>(i) / static_cast<double>(n_points - 1);
  e.back() = eps_max;
  return e;
}

EosCurve solve_eos(const ThreePhaseModel& m, const std::vector<double>& strains,
                   const OdeSettings& ode) {
  if (strains.empty()) throw std::invalid_argument("strains: empty");
  if (!(strains.front() >= 0.0)) throw std::invalid_argument("strains: first must be >= 0");
  for (std::size_t i = 1; i < strains.size(); ++i)
    if (!(strains[i] > strains[i - 1]))
      throw std::invalid_argument("strains: must increase strictly (entry " + std::to_string(i) +
                                  ")");
  // The voids cannot close more than they exist (P_E of Eq. 2.8 diverges at s = V_p0).
  if (!(strains.back() < m.initial().voids()))
    throw std::invalid_argument("strains: last must be below the porosity " +
                                std::to_string(m.initial().voids()));

  std::vector<double> times;
  const bool prepend = strains.front() > 0.0;
  if (prepend) times.push_back(0.0);
  times.insert(times.end(), strains.begin(), strains.end());

  EosCurve c;
  c.ode = ode;
  ThreePhaseRhs rhs{&m};
  ThreePhaseRhs::State y = ThreePhaseRhs::pack(EosState{});
  std::size_t k = 0;
  auto observe = [&](const ThreePhaseRhs::State& state, double eps) {
    if (prepend && k++ == 0) return;
    const EosState x = ThreePhaseRhs::unpack(state);
    c.eps_v.push_back(eps);
    c.p.push_back(x.p);
    c.p_bc.push_back(x.p_bc);
    c.p_d.push_back(friction_pressure(m, x.closure));
    c.p_e.push_back(bond_pressure(m, x.closure));
    c.closure.push_back(x.closure);
    c.tangent.push_back(tangent_modulus(m, x));
  };
  c.stats = integrate_observed(rhs, y, times, ode, observe);
  return c;
}

double pressure_sum_residual(const EosCurve& c, std::size_t i) {
  return c.p.at(i) - (c.p_bc.at(i) + c.p_d.at(i) + c.p_e.at(i));
}

Table1D loading_table(const EosCurve& c) {
  Table1D t{c.eps_v, c.p, false};
  t.validate();
  return t;
}

Table1D tangent_table(const EosCurve& c) {
  Table1D t{c.eps_v, c.tangent, false};
  t.validate();
  return t;
}

EosWork loading_work(const EosCurve& c, double eps_v) {
  if (c.size() < 2 || c.eps_v.front() != 0.0)
    throw std::invalid_argument("loading_work: the curve must start at eps_v = 0");
  if (!(eps_v >= 0.0 && eps_v <= c.eps_v.back()))
    throw std::invalid_argument("loading_work: eps_v outside the solved range");
  // The solid's compression c_s = V_s0 - V_s follows from Eq. 2.2: deps = ds + dc_s.
  auto solid_strain = [&](std::size_t i) { return c.eps_v[i] - c.closure[i]; };
  EosWork w;
  for (std::size_t i = 1; i < c.size() && c.eps_v[i - 1] < eps_v; ++i) {
    // Fraction of interval i taken: 1 for full intervals, less for the last, partial one.
    const double a = std::min(1.0, (eps_v - c.eps_v[i - 1]) / (c.eps_v[i] - c.eps_v[i - 1]));
    auto end = [&](const std::vector<double>& v) { return v[i - 1] + a * (v[i] - v[i - 1]); };
    const double de = end(c.eps_v) - c.eps_v[i - 1];
    const double ds = end(c.closure) - c.closure[i - 1];
    const double dc = a * (solid_strain(i) - solid_strain(i - 1));
    auto mean = [&](const std::vector<double>& v) { return 0.5 * (v[i - 1] + end(v)); };
    w.total += mean(c.p) * de;
    w.voids += mean(c.p_bc) * ds;
    w.friction += mean(c.p_d) * ds;
    w.bonds += mean(c.p_e) * ds;
    w.solid += mean(c.p) * dc;
  }
  return w;
}

}  // namespace kolsky::eos
