// The simulated SHPB test: an assembly (shpb/assembly.hpp: 1-D bars + specimen model, or
// meshed bars + FE specimen) chosen once from the ExperimentSpec, advanced by the one explicit
// loop (time/explicit_loop.hpp), sampled into named probes at the output cadence, and the
// face-referred waves the classic analysis consumes.
//   Who owns what: SimulatedShpb owns the spec, the schedule (dt, steps, cadence) and the
//   assembly; the assembly owns the bodies it steps, its energy ledger and its probe records;
//   run() owns the RunResult it fills.
//   Energy: each assembly checks its own ledger at every output step (observe); growth beyond
//   time.energy_tolerance of the energy that entered stops the run as a blow-up
//   (NumericalError): the RunResult keeps what was sampled and is marked incomplete.
//   Checkpoint/restart: ShpbState is everything the loop carries from one step to the next
//   (the 1-D assembly's bars, specimen, wave-energy accumulators, and the probes so far); run()
//   can hand it out every k steps and resume from it, continuing bitwise as the uninterrupted
//   run. Not for an fe specimen (so not for meshed bars).
#pragma once
#include <optional>
#include <string>
#include <vector>

#include "core/progress.hpp"
#include "shpb/analysis.hpp"
#include "shpb/assembly.hpp"
#include "shpb/experiment.hpp"
#include "shpb/run_control.hpp"
#include "shpb/run_result.hpp"
#include "time/explicit_loop.hpp"

namespace kolsky::shpb {

/// The loop's state after step next_step - 1 (and its sample): resume with step next_step.
/// The bar, specimen and accumulator fields are those of OneDimBarsAssembly, the only
/// assembly that checkpoints (io/checkpoint_hdf5 writes them).
struct ShpbState {
  long next_step = 0;
  RunResult partial;  ///< t, probes, steps, dt recorded so far
  BarState incident, transmission;
  SpecimenState specimen;
  FaceForces forces;
  double w_i = 0, w_r = 0, w_t = 0, prev[3] = {0, 0, 0}, injected = 0;
};

class SimulatedShpb {
 public:
  /// Throws InputError("", "time.dt", ...) when the requested dt exceeds the stable limit, and
  /// the assembly's InputErrors (e.g. "bars.kind": meshed bars need an fe specimen).
  explicit SimulatedShpb(const ExperimentSpec& spec);
  RunResult run(Progress* progress = nullptr) { return run(progress, RunControl{}); }
  /// Throws InputError("", "specimen.model", ...) when asked to checkpoint or resume an fe
  /// specimen, InputError("", "restart", ...) for a state that does not fit this simulation.
  RunResult run(Progress* progress, const RunControl& control);
  /// Whether the assembly supports save/restore (all but an fe specimen).
  bool can_checkpoint() const;
  const time_loop::Schedule& schedule() const { return schedule_; }
  /// Incident-wave arrival time at the specimen face, L_I / c_I (s; sphere chains: the chain's
  /// long-wave speed over its N - 1 contacts).
  double arrival_time() const;
  /// Throws InputError("", "time.end", ...) when the run ends before the classic analysis has
  /// two probe samples after the incident wave's arrival.
  void require_analysable_end() const;
  AnalysisSetup analysis_setup() const;
  /// The probes run() records, in its order (the HDF5 order), with empty values.
  std::vector<Probe> declared_probes() const;

  const ShpbAssembly& assembly() const { return assembly_; }
  /// The 1-D assembly's specimen and bars. Meshed bars have none: these throw std::logic_error
  /// there (use assembly() and MeshedBarsAssembly::body()).
  const Specimen& specimen() const;
  const Bar& incident_bar() const;
  const Bar& transmission_bar() const;

 private:
  template <class A>
  RunResult run_on(A& assembly, Progress* progress, const RunControl& control);
  const OneDimBarsAssembly& one_dim(const char* accessor) const;
  ShpbState save_state(const RunResult& r, long next_step) const;
  void restore_state(const ShpbState& s, RunResult& r);
  ExperimentSpec spec_;
  ShpbAssembly assembly_;
  time_loop::Schedule schedule_;
};

}  // namespace kolsky::shpb
