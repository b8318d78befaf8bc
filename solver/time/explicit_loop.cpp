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
  s.n_steps = static_cast<long>(std::ceil(p.end_time / s.dt - 1e-9)) + 1;
  const double interval = p.output_interval > 0.0 ? p.output_interval : 1e-6;
  s.sample_every = std::max(1L, static_cast<long>(std::lround(interval / s.dt)));
  return s;
}

}  // namespace kolsky::time_loop
