// Optional hooks of SimulatedShpb::run(): checkpoints, a restart state and DEM particle
// snapshots. Kept apart from simulation.hpp so that the assemblies (which call the snapshot
// hook from their step) can include it without including the simulation that owns them.
#pragma once
#include <csignal>
#include <functional>

#include "dem/particles.hpp"
#include "psd/grain_size_curve.hpp"

namespace kolsky::shpb {

struct ShpbState;  // simulation.hpp: the loop's state after a step, for checkpoint and restart

/// Every hook is called from the loop's thread.
struct RunControl {
  /// Steps between checkpoints (0: none): checkpoint(state) before the steps k, 2k, ...
  long checkpoint_every = 0;
  std::function<void(const ShpbState&)> checkpoint;
  /// Steps between particle snapshots of a DEM specimen (0: none): snapshot(n, t^n, grains)
  /// at the steps n = 0, k, 2k, ..., with positions, velocities and forces all at t^n.
  /// Assemblies without grains never call it.
  long snapshot_every = 0;
  std::function<void(long step, double t, const dem::Particles&)> snapshot;
  /// At the same steps (snapshot_every), for a specimen whose grains break: its grain-size
  /// curve then (grains plus fines, dem::current_grain_size_curve; docs/breakage.md), with or
  /// without a snapshot hook.
  std::function<void(long step, double t, const psd::GrainSizeCurve&)> grain_size_curve;
  /// Steps between progress calls (0: none): progress(n, t^n) before the steps k, 2k, ... on
  /// the planned steps' clock, like the checkpoints. For progress lines: it copies nothing,
  /// where a checkpoint copies the whole state.
  long progress_every = 0;
  std::function<void(long step, double t)> progress;
  /// Continue from this state (a checkpoint of a simulation built from the same spec).
  const ShpbState* resume = nullptr;
  /// Polled before every step: once non-zero (a signal handler's flag), the run stops there
  /// and returns what it computed, incomplete, its failure saying so (StopRequested).
  const volatile std::sig_atomic_t* stop = nullptr;
};

}  // namespace kolsky::shpb
