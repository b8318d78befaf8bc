// The solved three-phase EOS: Eq. 2.9 integrated in the volumetric strain with the Odeint wrapper,
// sampled at requested strains with its branch components (Eq. 2.1), and what Chapter 2 needs
// from it: a tabulated loading curve for a compaction EOS (pressure vs volumetric strain), the
// tangent (unloading candidate) modulus table, and the work done per branch along the loading
// path (branch D friction and branch E bonds are the dissipative mechanism 2 of Sec. 2.4.1).
// Units: Pa, J/m^3 (per unit initial volume); eps_v = 1 - V/V0, compression positive.
#pragma once
#include <cstddef>
#include <vector>

#include "core/table.hpp"
#include "eos/ode_integrate.hpp"
#include "eos/three_phase.hpp"

namespace kolsky::eos {

/// P(eps_v) with its components, one entry per requested strain (struct of arrays).
struct EosCurve {
  std::vector<double> eps_v;    ///< volumetric strain, compression positive
  std::vector<double> p;        ///< total gauge pressure P from Eq. 2.9, Pa
  std::vector<double> p_bc;     ///< air-water branch BC, Pa
  std::vector<double> p_d;      ///< friction branch D (Eq. 2.6), Pa
  std::vector<double> p_e;      ///< bond branch E (Eq. 2.8), Pa
  std::vector<double> closure;  ///< void closure s = -dV_p, per unit initial volume
  std::vector<double> tangent;  ///< dP/deps_v from Eq. 2.9 at the solved state, Pa
  OdeSettings ode;              ///< the stepper and tolerances used (record them)
  OdeStats stats;
  std::size_t size() const { return eps_v.size(); }
};

/// n_points strains 0, eps_max/(n-1), ..., eps_max. Throws std::invalid_argument if
/// eps_max <= 0 or n_points < 2.
std::vector<double> uniform_strains(double eps_max, std::size_t n_points);

/// Integrates Eq. 2.9 from the initial state (eps_v = 0, all gauge pressures 0) and samples it
/// at `strains` (strictly increasing, first >= 0, last < V_p0; the start is added internally
/// when strains.front() > 0). Throws std::invalid_argument for a bad grid or settings,
/// kolsky::NumericalError if the state becomes non-finite.
EosCurve solve_eos(const ThreePhaseModel& m, const std::vector<double>& strains,
                   const OdeSettings& ode);

/// Residual of Eq. 2.1 at sample i: P - (P_BC + P_D + P_E), Pa (zero up to the ODE tolerance,
/// since P is integrated and the components are not).
double pressure_sum_residual(const EosCurve& c, std::size_t i);

/// Loading curve for a tabulated compaction EOS: x = eps_v, y = P (Pa); ends held.
Table1D loading_table(const EosCurve& c);
/// Tangent bulk modulus table: x = eps_v, y = dP/deps_v (Pa); the natural unloading modulus.
Table1D tangent_table(const EosCurve& c);

/// Work per unit initial volume done on the specimen along the loading path, J/m^3.
struct EosWork {
  double total = 0.0;     ///< integral of P deps_v
  double voids = 0.0;     ///< branch BC: integral of P_BC ds (stored in the air and water)
  double friction = 0.0;  ///< branch D: integral of P_D ds = f K_p s^2 / 2
  double bonds = 0.0;     ///< branch E: integral of P_E ds
  double solid = 0.0;     ///< branch A: integral of P (-dV_s), grain compression
  /// Mechanism 2 (D + E): Sec. 2.4.1 attributes the dissipation trend to K_p (friction) and
  /// E_o (bonds), so their loading work is the dissipation proxy.
  double dissipated() const { return friction + bonds; }
};

/// Trapezoidal work from eps_v = 0 to `eps_v` (linear within the last, partial interval).
/// Requires c.eps_v.front() == 0 and eps_v within the curve; throws std::invalid_argument.
EosWork loading_work(const EosCurve& c, double eps_v);

}  // namespace kolsky::eos
