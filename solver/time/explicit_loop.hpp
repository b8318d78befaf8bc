// The one explicit time loop: the physics reports its stable dt, the loop owns the dt policy
// (safety factor, refusal of a dt above the limit), the step count, the output cadence and the
// progress bar. Physics supplies `step(t, dt)` and `sample(t)`; either may throw
// NumericalError, which the caller turns into an incomplete output and exit code 3.
#pragma once
#include <cmath>
#include <string>

#include "core/errors.hpp"
#include "core/progress.hpp"

namespace kolsky::time_loop {

struct StepPolicy {
  double end_time = 0;        ///< s
  double dt = 0;              ///< s; 0 = safety_factor * stable dt
  double safety_factor = 0.5; ///< fraction of the stable dt used when dt = 0
  bool check_stability = true;
  double output_interval = 1e-6;  ///< s; rounded to a whole number of steps
};

/// The plan of a run: dt, the step count and the output cadence. A run whose models can lower
/// their limit mid-run (a grain breaking into smaller daughters) may refine it downward at a
/// step boundary (refine): from step n_base on, dt = planned_dt / ticks_per_planned_step. A
/// tick is the finest step so far; step n lies at tick tick_base + (n - n_base), and an event
/// due every k planned steps (samples, checkpoints, snapshots) falls on the ticks that are
/// multiples of k * ticks_per_planned_step: the same times as in the unrefined plan.
/// Without a refinement (n_base = tick_base = 0, t_base = 0, one tick per planned step) every
/// formula below reduces bitwise to t^n = n dt and n % k == 0.
struct Schedule {
  double dt = 0;              ///< s, the step now (the planned one until a refinement)
  long n_steps = 0;           ///< steps of the whole run, as now planned
  long sample_every = 1;      ///< planned steps between samples
  double stable_dt = 0;       ///< s, the models' limit the plan was made against
  double planned_dt = 0;      ///< s, the dt of the plan made before the first step
  long n_base = 0;            ///< step of the last refinement
  long tick_base = 0;         ///< its tick
  double t_base = 0;          ///< s, its time
  long ticks_per_planned_step = 1;
  long refinements = 0;

  double time_of(long n) const { return t_base + static_cast<double>(n - n_base) * dt; }
  long tick(long n) const { return tick_base + (n - n_base); }
  /// Whether step n is due for an event every `every` planned steps (every >= 1).
  bool due(long n, long every) const { return tick(n) % (every * ticks_per_planned_step) == 0; }
};

/// The most steps a run may plan: far beyond any run that can finish (1e10 steps of the
/// cheapest assembly, about a microsecond each, take three hours; a DEM step takes
/// milliseconds), and far below where a step count or t = n dt stops being exact.
inline constexpr double kMaxSteps = 1e10;

/// Throws InputError("", "time.dt", ...) for a dt above the stability limit (when checked),
/// and InputError("", "time.end" or "time.dt", ...) for more than kMaxSteps steps.
Schedule plan_steps(const StepPolicy& p, double stable_dt);

/// Refines s at step n (whose time stays s.time_of(n)) when the models' limit has fallen to
/// `limit` below s.dt / safety_factor: dt becomes dt / q with q the smallest integer >= 2 for
/// which dt / q <= safety_factor * limit, the remaining steps are q times as many and every
/// cadence keeps its times. Never coarsens (returns false, s unchanged, when dt still fits).
/// Throws NumericalError when the refined run would exceed kMaxSteps (or the limit is not a
/// positive number): the run stops as a failure, what was sampled kept.
bool refine(Schedule& s, long n, double limit, double safety_factor);

/// What a model asks of the loop at the after-forces point of a step: after the forces of
/// t^n, before the step from t^n takes its dt. The one event there today is breakage, which
/// replaces grains by smaller daughters and so may lower the limit; a model whose dt may follow
/// its limit then asks for a re-plan, and the loop asks the limit again and refines dt when it
/// no longer fits (refine above). A plain value, so that a model without such events returns
/// {} and the loop needs no branch on what the model is.
struct AfterForces {
  bool replan_dt = false;  ///< the limit may have fallen: ask it again before choosing dt
};

/// Runs the steps n = first .. s.n_steps - 1 at t^n = s.time_of(n); samples after the steps
/// due every s.sample_every planned steps, i.e. at the times t^n whose state the step just
/// completed. step(n, t, dt) may refine s (refine above) for the step it is taking: the loop
/// reads s afresh after every step. Returns t^n of the last step. first > 0 continues a run
/// restored from a checkpoint taken after step first - 1 (with its schedule): the same steps
/// and samples as the uninterrupted run.
template <class StepFn, class SampleFn>
double run_loop_from(Schedule& s, long first, StepFn&& step, SampleFn&& sample, Progress* progress) {
  double t = 0.0;
  for (long n = first; n < s.n_steps; ++n) {
    t = s.time_of(n);
    step(n, t, s.dt);
    if (s.due(n, s.sample_every)) sample(t);
    if (progress && n % 256 == 0) progress->update(t);
  }
  if (progress) progress->finish();
  return t;
}

template <class StepFn, class SampleFn>
double run_loop(Schedule& s, StepFn&& step, SampleFn&& sample, Progress* progress) {
  return run_loop_from(s, 0, step, sample, progress);
}

}  // namespace kolsky::time_loop
