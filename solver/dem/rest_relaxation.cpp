// Relaxation of a prepared specimen to rest under the run's own laws (see rest_relaxation.hpp).
#include "dem/rest_relaxation.hpp"

#include <algorithm>
#include <cmath>

#include "core/errors.hpp"

namespace kolsky::dem {

namespace {
double coordination(const DemSystem& sys) {
  const double n = static_cast<double>(sys.particles().size());
  return n > 0 ? 2.0 * static_cast<double>(sys.n_contacts()) / n : 0.0;
}
}  // namespace

void validate(const RestRelaxationParams& p) {
  if (!(p.kinetic_tolerance > 0)) throw InputError("", "dem.rest.kinetic_tolerance", "must be > 0");
  if (p.check_steps < 1) throw InputError("", "dem.rest.check_steps", "must be >= 1");
  if (p.max_steps < 1) throw InputError("", "dem.rest.max_steps", "must be >= 1");
  if (!(p.step_fraction > 0 && p.step_fraction <= 1))
    throw InputError("", "dem.rest.step_fraction", "must be in (0, 1]");
}

RestRelaxationOutcome relax_to_rest(DemSystem& sys, const RestRelaxationParams& p,
                                    const std::function<void(const RestRelaxationOutcome&)>& on_window) {
  validate(p);
  RestRelaxationOutcome out;
  sys.compute_forces();
  out.elastic_before = sys.energy().elastic;
  out.coordination_before = coordination(sys);
  const double dt = p.step_fraction * sys.stable_dt();
  double previous = sys.particles().kinetic_energy(), peak = 0;
  while (out.steps < p.max_steps) {
    sys.step(dt);
    ++out.steps;
    const double kinetic = sys.particles().kinetic_energy();
    peak = std::max(peak, kinetic);
    if (kinetic < previous) {  // past a peak: stop every grain (kinetic damping)
      sys.stop_grains();
      ++out.quenches;
      previous = 0;
    } else {
      previous = kinetic;
    }
    if (out.steps % p.check_steps != 0) continue;
    out.kinetic_to_elastic = peak / std::max(out.elastic_before, 1e-300);
    peak = 0;
    out.converged = out.kinetic_to_elastic < p.kinetic_tolerance;
    if (on_window) {
      out.coordination_after = coordination(sys);
      on_window(out);
    }
    if (out.converged) break;
  }
  sys.stop_grains();
  out.elastic_after = sys.energy().elastic;
  out.coordination_after = coordination(sys);
  return out;
}

}  // namespace kolsky::dem
