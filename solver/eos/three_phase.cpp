// Three-phase EOS branches and the Eq. 2.9 right-hand side (see three_phase.hpp).
#include "eos/three_phase.hpp"

#include <cmath>
#include <stdexcept>

namespace kolsky::eos {

ThreePhaseModel::ThreePhaseModel(const ThreePhaseParams& params) : params_(params) {
  validate(params_);
  initial_ = initial_volumes(params_.porosity, params_.water_content, params_.solid.rho0,
                             params_.water.rho0);
}

double friction_pressure(const ThreePhaseModel& m, double closure) {
  return m.params().friction * m.params().k_p * closure;
}

double friction_stiffness(const ThreePhaseModel& m) { return m.params().friction * m.params().k_p; }

double bond_pressure(const ThreePhaseModel& m, double closure) {
  // dV_p = -s is negative in compression, so exp(B dV_p) = exp(-B s) grows for B = -5: this is
  // the stiffening the text asks of the EOS. V_p = V_p0 - s is the current void volume.
  const double vp = m.initial().voids() - closure;
  return m.params().e_o * closure * std::exp(-m.params().b * closure) / vp;
}

double bond_stiffness(const ThreePhaseModel& m, double closure) {
  const double b = m.params().b;
  const double vp = m.initial().voids() - closure;
  return m.params().e_o * std::exp(-b * closure) *
         ((1.0 - b * closure) / vp + closure / (vp * vp));
}

PhaseVolumes phase_volumes(const ThreePhaseModel& m, const EosState& x) {
  const ThreePhaseParams& p = m.params();
  const PhaseVolumes& v0 = m.initial();
  PhaseVolumes v;
  // Each phase starts at its reference density under the ambient pressure, so its absolute
  // pressure is its own p0 plus the gauge pressure it carries.
  v.solid = v0.solid * volume_ratio(p.solid, p.solid.p0 + x.p);
  v.water = v0.water * volume_ratio(p.water, p.water.p0 + x.p_bc);
  v.air = v0.air * volume_ratio(p.air, p.air.p0 + x.p_bc);
  return v;
}

double void_stiffness(const ThreePhaseModel& m, double p_bc) {
  const ThreePhaseParams& p = m.params();
  const PhaseVolumes& v0 = m.initial();
  // Series: one pressure, volumes add, so the compliances -dV/dP = V/K add.
  const double pw = p.water.p0 + p_bc;
  const double pa = p.air.p0 + p_bc;
  const double c_water = v0.water * volume_ratio(p.water, pw) / bulk_modulus(p.water, pw);
  const double c_air = v0.air * volume_ratio(p.air, pa) / bulk_modulus(p.air, pa);
  return 1.0 / (c_water + c_air);
}

double solid_compliance(const ThreePhaseModel& m, double p) {
  const TaitEos& s = m.params().solid;
  return m.initial().solid * volume_ratio(s, s.p0 + p) / bulk_modulus(s, s.p0 + p);
}

double void_branches_stiffness(const ThreePhaseModel& m, const EosState& x) {
  return void_stiffness(m, x.p_bc) + friction_stiffness(m) + bond_stiffness(m, x.closure);
}

double tangent_modulus(const ThreePhaseModel& m, const EosState& x) {
  // Eq. 2.9 with dV = -deps, dV_s = -(V_s/K_s) dP: dP = K_tot (deps - (V_s/K_s) dP).
  const double k_tot = void_branches_stiffness(m, x);
  return k_tot / (1.0 + k_tot * solid_compliance(m, x.p));
}

double closure_rate(const ThreePhaseModel& m, const EosState& x) {
  const double k_tot = void_branches_stiffness(m, x);
  return 1.0 / (1.0 + k_tot * solid_compliance(m, x.p));
}

ThreePhaseRhs::State ThreePhaseRhs::pack(const EosState& x) {
  return {x.p / kPressureScale, x.closure, x.p_bc / kPressureScale};
}

EosState ThreePhaseRhs::unpack(const State& y) {
  return {y[0] * kPressureScale, y[1], y[2] * kPressureScale};
}

void ThreePhaseRhs::operator()(const State& y, State& dydeps, double /*eps_v*/) const {
  const EosState x = unpack(y);
  const double k_tot = void_branches_stiffness(*model, x);
  const double ds = 1.0 / (1.0 + k_tot * solid_compliance(*model, x.p));
  dydeps[0] = k_tot * ds / kPressureScale;                         // Eq. 2.9: dP = K_tot ds
  dydeps[1] = ds;                                                  // Eq. 2.2: ds = deps + dV_s
  dydeps[2] = void_stiffness(*model, x.p_bc) * ds / kPressureScale;  // branch BC's share
}

}  // namespace kolsky::eos
