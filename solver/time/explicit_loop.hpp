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

struct Schedule {
  double dt = 0;
  long n_steps = 0;
  long sample_every = 1;
  double stable_dt = 0;
};

/// The most steps a run may plan: far beyond any run that can finish (1e10 steps of the
/// cheapest assembly, about a microsecond each, take three hours; a DEM step takes
/// milliseconds), and far below where a step count or t = n dt stops being exact.
inline constexpr double kMaxSteps = 1e10;

/// Throws InputError("", "time.dt", ...) for a dt above the stability limit (when checked),
/// and InputError("", "time.end" or "time.dt", ...) for more than kMaxSteps steps.
Schedule plan_steps(const StepPolicy& p, double stable_dt);

/// Runs the steps n = first .. n_steps - 1 at t^n = n dt; samples after the steps n = 0, k,
/// 2k, ... (k = sample_every), i.e. at the times t^n whose state the step just completed.
/// Returns t^n of the last step. first > 0 continues a run restored from a checkpoint taken
/// after step first - 1: the same steps and samples as the uninterrupted run.
template <class StepFn, class SampleFn>
double run_loop_from(const Schedule& s, long first, StepFn&& step, SampleFn&& sample,
                     Progress* progress) {
  double t = 0.0;
  for (long n = first; n < s.n_steps; ++n) {
    t = static_cast<double>(n) * s.dt;
    step(t, s.dt);
    if (n % s.sample_every == 0) sample(t);
    if (progress && n % 256 == 0) progress->update(t);
  }
  if (progress) progress->finish();
  return t;
}

template <class StepFn, class SampleFn>
double run_loop(const Schedule& s, StepFn&& step, SampleFn&& sample, Progress* progress) {
  return run_loop_from(s, 0, step, sample, progress);
}

}  // namespace kolsky::time_loop
