// The simulated SHPB test: incident bar -> specimen -> transmission bar, coupled through the
// face degrees of freedom and advanced by the one explicit loop. Produces probes (time series)
// and the face-referred waves the classic analysis consumes.
//   Energy accounting: each bar reports the energy it delivered to its face; the specimen and
//   face masses hold it. Their difference is the energy-balance error; growth beyond
//   energy_tolerance * (energy the pulse injected) stops the run as a blow-up (NumericalError).
//   Checkpoint/restart: ShpbState is everything the loop carries from one step to the next
//   (bars, specimen, wave-energy accumulators, probes so far); run() can hand it out every k
//   steps and resume from it, continuing bitwise as the uninterrupted run. Not for fe (nor,
//   therefore, for meshed bars).
//   Meshed bars (BarKind::meshed, FE specimen only): bars and specimen are one FE body
//   (fe::MeshedShpb); the 1-D bar objects are then unused. The probes keep their names: gauges
//   are the meshed bars' surface strains, the face waves are derived from the first gauge of
//   each bar by the 1-D shift (gauge_waves.hpp), as the classic analysis does with lab records;
//   energy_delivered is the work of the far-end traction.
#pragma once
#include <functional>
#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "bar/characteristic_bar.hpp"
#include "bar/specimen_column.hpp"
#include "bar/sphere_chain.hpp"
#include "fe/meshed_shpb.hpp"
#include "core/progress.hpp"
#include "dem/dem_state.hpp"
#include "shpb/analysis.hpp"
#include "shpb/experiment.hpp"
#include "time/explicit_loop.hpp"

namespace kolsky::shpb {

/// One sampled series on RunResult::t.
struct Probe {
  std::string name, unit, description;
  std::vector<double> value;
};

struct RunResult {
  std::vector<double> t;       ///< s, from the start of loading at the incident bar's far end
  std::vector<Probe> probes;
  bool complete = true;
  std::string failure;         ///< why the run stopped early (empty when complete)
  double dt = 0, stable_dt = 0, arrival_time = 0;
  long steps = 0;

  const Probe& probe(const std::string& name) const;  ///< throws std::out_of_range
  /// Face waves (compression-positive bar strains) with t = 0 at the incident arrival, up to
  /// the first sample where a wave is undefined (gauge-derived waves of meshed bars).
  FaceWaves face_waves(double incident_modulus, double transmission_modulus) const;
};

using Bar = std::variant<bar::CharacteristicBar, bar::SphereChainBar>;
using Specimen = std::variant<bar::SpecimenColumn, fe::FeSpecimen, dem::DemSpecimen>;

using BarState = std::variant<bar::CharacteristicBar::State, bar::SphereChainBar::State>;
using SpecimenState = std::variant<bar::SpecimenColumn::State, dem::DemSpecimenState>;

/// The loop's state after step next_step - 1 (and its sample): resume with step next_step.
struct ShpbState {
  long next_step = 0;
  RunResult partial;  ///< t, probes, steps, dt recorded so far
  BarState incident, transmission;
  SpecimenState specimen;
  FaceForces forces;
  double w_i = 0, w_r = 0, w_t = 0, prev[3] = {0, 0, 0}, injected = 0;
};

/// Optional hooks of run(). Both are called from the loop's thread.
struct RunControl {
  /// Steps between checkpoints (0: none): checkpoint(state) before the steps k, 2k, ...
  long checkpoint_every = 0;
  std::function<void(const ShpbState&)> checkpoint;
  /// Steps between particle snapshots of a DEM specimen (0: none): snapshot(n, t^n, grains)
  /// at the steps n = 0, k, 2k, ..., with positions, velocities and forces all at t^n.
  long snapshot_every = 0;
  std::function<void(long step, double t, const dem::Particles&)> snapshot;
  /// Continue from this state (a checkpoint of a simulation built from the same spec).
  const ShpbState* resume = nullptr;
};

class SimulatedShpb {
 public:
  /// Throws InputError("", "time.dt", ...) when the requested dt exceeds the stable limit.
  explicit SimulatedShpb(const ExperimentSpec& spec);
  RunResult run(Progress* progress = nullptr) { return run(progress, RunControl{}); }
  /// Throws InputError("", "specimen.model", ...) when asked to checkpoint or resume an fe
  /// specimen, InputError("", "restart", ...) for a state that does not fit this simulation.
  RunResult run(Progress* progress, const RunControl& control);
  /// Whether the specimen model supports save/restore (all but fe).
  bool can_checkpoint() const;
  const time_loop::Schedule& schedule() const { return schedule_; }
  /// Incident-wave arrival time at the specimen face, L_I / c_I (s).
  double arrival_time() const;
  /// Throws InputError("", "time.end", ...) when the run ends before the classic analysis has
  /// two probe samples after the incident wave's arrival.
  void require_analysable_end() const;
  AnalysisSetup analysis_setup() const;
  const Specimen& specimen() const { return specimen_; }
  const Bar& incident_bar() const { return incident_; }
  const Bar& transmission_bar() const { return transmission_; }

 private:
  void step(double t, double dt);
  void sample(double t, RunResult& r);
  void sample_meshed(double t, RunResult& r);
  ShpbState save_state(const RunResult& r, long next_step) const;
  void restore_state(const ShpbState& s, RunResult& r);
  const RunControl* control_ = nullptr;  // during run(): the snapshot hook
  long step_index_ = 0;
  ExperimentSpec spec_;
  Specimen specimen_;
  Bar incident_, transmission_;
  std::optional<fe::MeshedShpb> meshed_;      // BarKind::meshed: bars + specimen in one FE body
  time_loop::Schedule schedule_;
  bar::FaceForces forces_;
  double w_i_ = 0, w_r_ = 0, w_t_ = 0;         // Eqs. 2.11-2.13 from the face waves
  double prev_[3] = {0, 0, 0};                 // s_i, s_r, s_t at the previous step
  double injected_ = 0;                        // A/(rho c) * integral sigma_app^2 dt
};

}  // namespace kolsky::shpb
