// SHPB assembly (d): strain-rate-controlled walls, methodology 1 of Sec. 5.2.1 (the Wang et al.
// 2018 and Huang et al. 2013 tests, which report only the specimen's strain rate). No bars: a
// DEM specimen in its tube between two end walls, driven through the face interface of
// core/specimen_coupling.hpp (FaceState in, FaceForces out) exactly as the bars drive it.
//   Incident-side wall: intrusion u(t) = L0 eps(t), speed L0 rate(t), with eps(t) the Eq. 5.1
//   integral of the tabulated rate (strain_rate_history.hpp) and L0 the initial specimen
//   length: eps is an engineering strain (u over the initial length), so the wall speed is
//   L0 rate, not L(t) rate. Transmission-side wall: fixed (u = 0, speed 0).
//   Step n (t^n -> t^{n+1}): walls placed at t^n, the specimen returns the wall forces at t^n,
//   breaks the grains due and advances; the wall work is the trapezoid of force and wall displacement between steps
//   (as DemSystem books a moving plane's work).
//   Face stresses: wall force / (pi R^2), R the tube radius (the specimen's cross-section).
//   Probes: the applied strain and rate, front, back and average stress (Eq. 4.16), alpha
//   (Eq. 2.15; NaN while the run goes, filled by finish() over the whole record with the floor
//   of AnalysisOptions, as the wave analysis does), the wall motion, the energy ledger, and the
//   DEM probes of specimen_models.hpp. No waves, no gauges: arrival_time() = 0, and the run is
//   analysed directly (analyze_faces), not by the wave analysis.
//   Energy ledger (observe): held = the specimen's energy; supplied = the wall work; judged
//   against the gross wall work (sum of |F du|, which cannot be near zero once the wall has
//   pushed) plus the packing's initial elastic energy, with time.energy_tolerance.
//   Checkpoint/restart through ShpbState: the DEM state, the wall forces, and the wall work in
//   w_i, its gross amount in injected (the bar fields stay empty).
// specimen.preload_on_supports is refused: there are no bar supports to hold a preload, the
// walls report the whole force.
// The members every assembly provides are listed in shpb/assembly.hpp.
#pragma once
#include "core/specimen_coupling.hpp"
#include "dem/dem_specimen.hpp"
#include "shpb/experiment.hpp"
#include "shpb/probe_record.hpp"
#include "shpb/run_control.hpp"
#include "shpb/run_result.hpp"
#include "shpb/strain_rate_history.hpp"
#include "time/explicit_loop.hpp"

namespace kolsky::shpb {

class StrainRateWallsAssembly {
 public:
  /// spec.strain_rate is set. Throws InputError("", "specimen.model", ...) unless the
  /// specimen is dem, ("", "specimen.preload_on_supports", ...) when it asks for a preload on
  /// the supports; packs the DEM specimen.
  explicit StrainRateWallsAssembly(const ExperimentSpec& spec);

  double stable_dt() const { return specimen_.stable_dt(); }  ///< the specimen's raw limit, s
  double arrival_time() const { return 0.0; }  ///< no wave to wait for: loading starts at t = 0
  /// Step n in the loop's three calls (assembly.hpp). compute_forces: the walls at t^n and
  /// their forces (hooks of t^n, wall work).
  void compute_forces(long n, double t, const RunControl& control);
  /// The breaks due (the specimen's limit may fall); asks the loop to re-plan dt after a break
  /// when the run refines its step (time.dt = 0 with time.refine_after_breaks: the specimen
  /// was then built without planning for the smallest daughter up front).
  time_loop::AfterForces after_forces() { return {specimen_.apply_due_breaks() > 0 && refines_dt_}; }
  /// The step from t^n with the dt the loop chose after the hook.
  void advance(double dt) { specimen_.advance(dt); }
  /// At an output step: finiteness and the energy ledger (throws NumericalError).
  void observe(double t);
  ProbeRecords probes() const;       ///< samplers read *this (probe_record.hpp, "Lifetime")
  void finish(RunResult& r) const;   ///< alpha over the whole record (Eq. 2.15)
  bool can_checkpoint() const { return true; }
  void save_into(ShpbState& s) const;
  /// Throws InputError("", "restart", ...) for a state written by another assembly or model.
  void check_fits(const ShpbState& s) const;
  void restore_from(const ShpbState& s);

  const dem::DemSpecimen& specimen() const { return specimen_; }
  const StrainRateHistory& history() const { return history_; }
  double initial_length() const { return length_; }  ///< L0, m
  /// The walls at the last step: intrusion and speed of each (back: 0), m and m/s.
  const FaceState& faces() const { return faces_; }
  const FaceForces& forces() const { return forces_; }  ///< wall forces at the last step, N

 private:
  StrainRateHistory history_;
  double energy_tolerance_;
  bool check_stability_;  // time.check_stability: the energy check is on
  bool refines_dt_;       // time.dt = 0: dt follows the limit after breaks
  dem::DemSpecimen specimen_;
  double length_, area_;       // L0 (m), pi R^2 (m^2)
  FaceState faces_;
  FaceForces forces_;
  double work_ = 0, gross_ = 0;  // wall work on the grains and sum |F du|, J
  double held_ = 0;            // specimen energy at the last observe(), J
};

}  // namespace kolsky::shpb
