// The simulated SHPB test: an assembly (shpb/assembly.hpp: 1-D bars + specimen model, meshed
// bars + FE specimen, or strain-rate walls + DEM specimen) chosen once from the ExperimentSpec,
// advanced by the one explicit loop (time/explicit_loop.hpp), sampled into named probes at the
// output cadence, and the analysis of a finished run (analyse: the face-referred waves the
// classic analysis consumes, or the walls' stresses directly).
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
/// The bar, specimen and accumulator fields are those of OneDimBarsAssembly (io/checkpoint_hdf5
/// writes them). StrainRateWallsAssembly, the other assembly that checkpoints, fills specimen
/// (DEM) and forces, keeps its wall work in w_i and the gross wall work (its energy scale) in
/// injected, and leaves the bar states empty.
struct ShpbState {
  long next_step = 0;
  RunResult partial;  ///< t, probes, steps, dt recorded so far
  time_loop::Schedule schedule;  ///< the run's schedule then (refined after breaks, or as planned)
  BarState incident, transmission;
  SpecimenState specimen;
  FaceForces forces;
  double w_i = 0, w_r = 0, w_t = 0, prev[3] = {0, 0, 0}, injected = 0;
};

/// What SimulatedShpb::analyze returns: the face waves (empty for a direct analysis) and the
/// specimen history on their clock (t = 0 at the incident arrival; for strain-rate walls the
/// run's own clock).
struct RunAnalysis {
  FaceWaves waves;
  SpecimenHistory history;
};

/// Incident-wave arrival at the specimen face from the bar alone, L_I / c_I (sphere chains:
/// the chain's long-wave speed over its N - 1 contacts), s: what every bar assembly reports.
double incident_arrival_time(BarKind kind, const BarSpec& incident);

/// The part of SimulatedShpb::require_analysable_end that needs no assembly, for a check before
/// the expensive build (a DEM packing takes minutes): throws InputError("", "time.end", ...)
/// unless time.end exceeds the arrival plus one output interval, which the exact rule (two
/// samples after the arrival, in whole steps) never asks less than.
void require_reachable_end(const ExperimentSpec& spec);

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
  /// two probe samples after the incident wave's arrival (strain-rate walls: after t = 0).
  void require_analysable_end() const;
  /// Bars and specimen as the wave analysis sees them (the default bars for strain-rate walls,
  /// which analyze() does not use).
  AnalysisSetup analysis_setup() const;
  /// A finished run's analysis: for bar assemblies, the classic analysis of the face waves
  /// (RunResult::face_waves, analyze); for strain-rate walls the direct one of the face
  /// stresses (analyze_faces; waves empty, no wave energies). std::invalid_argument from the
  /// wave analysis when fewer than 2 wave samples exist (a run stopped before the arrival).
  RunAnalysis analyze(const RunResult& r) const;
  /// Whether analyze(r) has the 2 samples it needs (after the arrival, for the wave analysis).
  /// A run stopped by a numerical failure before that has none: its probes are still kept.
  bool can_analyze(const RunResult& r) const;
  /// Whether the run is analysed without waves (strain-rate walls: no bars, no gauges).
  bool direct_analysis() const;
  /// The probes run() records, in its order (the HDF5 order), with empty values.
  std::vector<Probe> declared_probes() const;
  /// A DEM specimen's end-wall stresses as packed, before any step (Pa, compression +): the
  /// packing's residual or pre-stress, which the bars carry from t = 0 unless it sits on the
  /// supports. nullopt for the other specimen models.
  std::optional<FaceForces> initial_wall_stress() const;

  const ShpbAssembly& assembly() const { return assembly_; }
  /// The DEM specimen, whichever assembly holds it (1-D bars, strain-rate walls, FE bars around
  /// it); nullptr for the other specimen models. For reading its final state after a run.
  const dem::DemSpecimen* dem_specimen() const;
  /// The 1-D assembly's specimen and bars. Meshed bars and strain-rate walls have none: these
  /// throw std::logic_error there (use assembly(), MeshedBarsAssembly::body(),
  /// StrainRateWallsAssembly::specimen()).
  const Specimen& specimen() const;
  const Bar& incident_bar() const;
  const Bar& transmission_bar() const;

 private:
  template <class A>
  RunResult run_on(A& assembly, Progress* progress, const RunControl& control);
  const OneDimBarsAssembly& one_dim(const char* accessor) const;
  ShpbState save_state(const RunResult& r, long next_step, const time_loop::Schedule& schedule) const;
  void restore_state(const ShpbState& s, RunResult& r, time_loop::Schedule& schedule);
  ExperimentSpec spec_;
  ShpbAssembly assembly_;
  time_loop::Schedule schedule_;
};

}  // namespace kolsky::shpb
