// Three-phase soil EOS (Henrych 1979, modified by Wang et al. 2004; Sec. 2.3.6, Eqs. 2.1-2.9).
// The solid grains (branch A, Eq. 2.4) carry the total pressure P in series with the voids;
// the void closure s = -dV_p is shared by three parallel branches: BC (air and water in series
// at one pore pressure P_BC, Eqs. 2.3/2.5), D (friction, Eq. 2.6) and E (elastobrittle bonds,
// Eq. 2.8). Eq. 2.9 then reads dP = K_tot ds, ds = deps_v - (V_s/K_s) dP. Sign and unit
// resolution (docs/eos.md): compression positive, volumes per unit initial volume, |dV_p| for
// magnitudes and signed dV_p = -s in the exponent of Eq. 2.8. Pressures are gauge (Pa above the
// initial ambient state P_ao), so P(0) = 0.
#pragma once
#include <vector>

#include "eos/three_phase_params.hpp"

namespace kolsky::eos {

/// Validated parameters plus the derived initial phase volumes.
class ThreePhaseModel {
 public:
  /// Throws std::invalid_argument (see validate(ThreePhaseParams)).
  explicit ThreePhaseModel(const ThreePhaseParams& params);
  const ThreePhaseParams& params() const { return params_; }
  /// Initial volumes per unit initial total volume (Eq. 2.2 at eps_v = 0).
  const PhaseVolumes& initial() const { return initial_; }

 private:
  ThreePhaseParams params_;
  PhaseVolumes initial_;
};

/// One point of the loading path; pressures are gauge, Pa.
struct EosState {
  double p = 0.0;        ///< total pressure P (Eq. 2.1)
  double closure = 0.0;  ///< void closure s = V_p0 - V_p >= 0, per unit initial volume
  double p_bc = 0.0;     ///< pore pressure P_BC shared by air and water
};

/// Eq. 2.6 with |dV_p|: P_D = f K_p s, Pa.
double friction_pressure(const ThreePhaseModel& m, double closure);
/// dP_D/ds = f K_p, Pa.
double friction_stiffness(const ThreePhaseModel& m);
/// Eq. 2.8 with |dV_p| in front and signed dV_p = -s in the exponent:
/// P_E = E_o s exp(-B s) / (V_p0 - s), Pa; requires s < V_p0.
double bond_pressure(const ThreePhaseModel& m, double closure);
/// dP_E/ds = E_o exp(-B s) [(1 - B s)/(V_p0 - s) + s/(V_p0 - s)^2], Pa.
double bond_stiffness(const ThreePhaseModel& m, double closure);

/// Phase volumes on the path: solid at the total pressure P (branch A in series), water and air
/// at the pore pressure P_BC (Eqs. 2.3-2.5 inverted).
PhaseVolumes phase_volumes(const ThreePhaseModel& m, const EosState& x);
/// Branch BC stiffness -dP_BC/dV_p = (V_w/K_w + V_a/K_a)^-1 (air and water in series), Pa.
double void_stiffness(const ThreePhaseModel& m, double p_bc);
/// Solid compliance -dV_s/dP = V_s/K_s at the total pressure, 1/Pa.
double solid_compliance(const ThreePhaseModel& m, double p);
/// K_tot = K_BC + f K_p + dP_E/ds: the parallel branches' stiffness against void closure, Pa.
double void_branches_stiffness(const ThreePhaseModel& m, const EosState& x);
/// Eq. 2.9 solved for the tangent: dP/deps_v = K_tot / (1 + K_tot V_s/K_s), Pa.
double tangent_modulus(const ThreePhaseModel& m, const EosState& x);
/// ds/deps_v = 1 / (1 + K_tot V_s/K_s): the share of the strain taken by the voids.
double closure_rate(const ThreePhaseModel& m, const EosState& x);

/// Right-hand side of Eq. 2.9 in the strain eps_v, for Boost.Odeint. The state is scaled so one
/// absolute tolerance fits all three components: {P / 1 MPa, s, P_BC / 1 MPa}.
struct ThreePhaseRhs {
  /// Three entries. A vector rather than std::array: odeint copies its steppers, and copies of
  /// their uninitialized std::array scratch trip GCC's -Wmaybe-uninitialized.
  using State = std::vector<double>;
  static constexpr double kPressureScale = 1e6;  ///< Pa per state unit (pressures ~0.1-100 MPa)

  const ThreePhaseModel* model = nullptr;

  void operator()(const State& y, State& dydeps, double eps_v) const;
  static State pack(const EosState& x);
  static EosState unpack(const State& y);
};

}  // namespace kolsky::eos
