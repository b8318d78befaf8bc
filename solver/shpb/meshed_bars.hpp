// SHPB assembly (b): meshed bars. Incident bar, FE specimen (with its tube) and transmission
// bar are one axisymmetric FE body (fe::MeshedShpb), loaded by the applied stress on the
// incident bar's far end. This assembly owns that body and nothing else: no 1-D bar and no
// FeSpecimen is built.
//   Step n: MeshedShpb::step (forces at t^n, central-difference step; it checks dt, finiteness
//   and its own energy balance every step).
//   Probes: the names and units of the 1-D assembly, so analysis and outputs do not care which
//   bars ran. The gauges are the meshed bars' surface strains (tension +, as measured); the
//   face waves and their energies are not known during the run: they read 0 while it runs and
//   are derived after it from the first gauge of each bar by the 1-D shift (gauge_waves.hpp),
//   as the classic analysis does with lab records. energy_delivered is the work of the far-end
//   traction, energy_held what the whole body holds.
//   No checkpoint/restart (the fe specimen has no checkpoint state).
// The members every assembly provides are listed in shpb/assembly.hpp.
#pragma once
#include "fe/meshed_shpb.hpp"
#include "shpb/experiment.hpp"
#include "shpb/probe_record.hpp"
#include "shpb/run_control.hpp"
#include "shpb/run_result.hpp"
#include "time/explicit_loop.hpp"

namespace kolsky::shpb {

class MeshedBarsAssembly {
 public:
  /// Throws InputError("", "bars.kind", ...) unless spec.specimen is fe and each bar has a gauge.
  explicit MeshedBarsAssembly(const ExperimentSpec& spec);

  double stable_dt() const { return meshed_.stable_dt(); }
  double arrival_time() const;  ///< L_I / c_I (s)
  /// Step n in the loop's three calls (assembly.hpp): the forces of t^n, a hook with nothing
  /// to do (an FE specimen's elements never change), the step to t^{n+1}.
  void compute_forces(long, double t, const RunControl&) { meshed_.forces(t); }
  time_loop::AfterForces after_forces() { return {}; }
  void advance(double dt) { meshed_.advance(dt); }
  /// At an output step: throws NumericalError on a non-finite state or energy ledger, and keeps
  /// the ledger for the energy probes.
  void observe(double t);
  ProbeRecords probes() const;     ///< samplers read *this (probe_record.hpp, "Lifetime")
  void finish(RunResult& r) const;  ///< the face waves and their energies from the gauges
  bool can_checkpoint() const { return false; }
  [[noreturn]] void save_into(ShpbState&) const;  ///< std::logic_error: no checkpoint state
  void check_fits(const ShpbState&) const;      ///< InputError: no checkpoint fits
  [[noreturn]] void restore_from(const ShpbState&);

  const fe::MeshedShpb& body() const { return meshed_; }

 private:
  BarSpec incident_spec_, transmission_spec_;  // materials, gauges (the spec's, copied)
  bar::Pulse pulse_;
  fe::MeshedShpb meshed_;
  fe::MeshedEnergy ledger_;  // at the last observe()
};

}  // namespace kolsky::shpb
