#include "time/explicit_loop.hpp"

#include <algorithm>
#include <cstdio>

namespace kolsky::time_loop {

static std::string sci(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", x);
  return b;
}

Schedule plan_steps(const StepPolicy& p, double stable_dt) {
  Schedule s;
  s.stable_dt = stable_dt;
  if (p.dt > 0.0) {
    if (p.check_stability && p.dt > stable_dt)
      throw InputError("", "time.dt",
                       "time step " + sci(p.dt) + " s is above the stability limit " +
                           sci(stable_dt) + " s");
    s.dt = p.dt;
  } else {
    s.dt = p.safety_factor * stable_dt;
  }
  // The count as a double first: end / dt can exceed every integer type (time.end = 1e300,
  // time.dt = 1e-300), and converting such a double to long is undefined behaviour.
  const double steps = std::ceil(p.end_time / s.dt - 1e-9) + 1;
  if (!(steps <= kMaxSteps)) {
    // A fixed dt that the stable step would not need so many steps for is the key at fault.
    const double at_stable = p.end_time / (p.safety_factor * stable_dt);
    const bool dt_at_fault = p.dt > 0.0 && at_stable <= kMaxSteps;
    throw InputError("", dt_at_fault ? "time.dt" : "time.end",
                     "time.end / dt = " + sci(p.end_time) + " s / " + sci(s.dt) + " s is " +
                         sci(steps) + " steps, more than the " + sci(kMaxSteps) +
                         " a run may take");
  }
  s.n_steps = static_cast<long>(steps);
  const double interval = p.output_interval > 0.0 ? p.output_interval : 1e-6;
  // Clamped to the run (sampling only step 0 either way): a huge interval must not overflow.
  const double every = std::min(std::round(interval / s.dt), static_cast<double>(s.n_steps));
  s.sample_every = std::max(1L, static_cast<long>(every));
  s.planned_dt = s.dt;
  return s;
}

bool refine(Schedule& s, long n, double limit, double safety_factor) {
  const double target = safety_factor * limit;
  if (!(target > 0.0))
    throw NumericalError("the models' stable time step fell to " + sci(limit) + " s", s.time_of(n));
  if (s.dt <= target) return false;
  // The smallest integer q >= 2 with dt / q <= target: an integer so that the times of every
  // cadence stay on the new grid; q = ceil(dt / target), bumped if round-off left it short.
  double q = std::max(2.0, std::ceil(s.dt / target));
  if (s.dt / q > target) q += 1.0;
  const double remaining = static_cast<double>(s.n_steps - n) * q;
  const double last_tick = static_cast<double>(s.tick(n)) * q + remaining;
  if (!(static_cast<double>(n) + remaining <= kMaxSteps) || !(last_tick <= kMaxSteps))
    throw NumericalError("the models' stable time step fell to " + sci(limit) + " s: refining dt " +
                             sci(s.dt) + " s by " + sci(q) + " would take the run past " +
                             sci(kMaxSteps) + " steps", s.time_of(n));
  const long qi = static_cast<long>(q);
  s.t_base = s.time_of(n);
  s.tick_base = s.tick(n) * qi;
  s.n_base = n;
  s.n_steps = n + (s.n_steps - n) * qi;
  s.ticks_per_planned_step *= qi;
  s.dt /= q;
  s.stable_dt = limit;
  ++s.refinements;
  return true;
}

}  // namespace kolsky::time_loop
