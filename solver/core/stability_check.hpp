// The two run-time stability checks every explicit model uses (docs/architecture.md, "One
// time-step policy"): the step against the model's current limit, and the energy balance.
// Both throw NumericalError: the run's dt was checked against the limit when it was planned
// (an InputError there, time_loop::plan_steps), so a failure here arose during the run (an
// edit, a break, a stiffening contact) and the output computed so far is kept (exit 3).
//
// Energy: each model keeps its own ledger, because what it holds differs (a bar's
// faces, an FE body's material work, a DEM packing's contacts), and reduces it to three
// numbers; this file judges them all by one rule.
//
// The rule is one-sided: a central-difference step above its stability limit amplifies a mode
// and so creates energy (x1.9 per step at 1.05 times the critical step of an FE mesh,
// verification/verify_fe_stability.cpp); energy that disappears is unaccounted dissipation or
// bookkeeping, which the verification energy-balance checks measure with their own, tighter
// bounds (verification/checks/checks_specimen.cpp), not a reason to stop a run.
#pragma once
#include <string>

namespace kolsky {

/// Throws NumericalError("<who>: time step dt s is above the stable limit L s at t = T s
/// (<limit_is>)") unless 0 < dt <= limit (1 + 1e-12): the slack admits a limit recomputed in
/// another summation order. `limit_is` says what the limit is made of, for the user.
void check_time_step(double dt, double limit, const std::string& who, double t, const std::string& limit_is);

struct EnergyLedger {
  double held = 0.0;      ///< J: kinetic + stored + dissipated (+ booked at edits) now
  double supplied = 0.0;  ///< J: energy at the start + work done on the model since
  /// J: the energy growth is judged against; one that cannot be near zero while energy sits in
  /// the model (a peak, or what the loading injected). Not judged while <= 0.
  double scale = 0.0;
  double excess() const { return held - supplied; }
};

/// Throws NumericalError("<who>: energy grows: ...", t) when excess() > tolerance x scale
/// (tolerance > 0, relative). `who` names the model ("fe specimen", "meshed bars", "bars and
/// specimen").
void check_energy_growth(const EnergyLedger& e, double tolerance, const std::string& who, double t);

}  // namespace kolsky
