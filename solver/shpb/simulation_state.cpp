// SimulatedShpb checkpoint and restart (simulation.hpp): the loop's state after a step and its
// sample, handed out by run() and taken back to continue bitwise. The assembly fills and takes
// back its part (bars, specimen, accumulators: OneDimBarsAssembly::save_into / restore_from,
// which collect the plain-struct states the bars and specimens provide); this file adds the
// loop's part (step, probes so far) and checks that a state fits the simulation it is
// restored into.
#include <stdexcept>
#include <string>

#include "core/errors.hpp"
#include "shpb/simulation.hpp"

namespace kolsky::shpb {

namespace {
[[noreturn]] void misfit(const std::string& rule) { throw InputError("", "restart", rule); }
}  // namespace

ShpbState SimulatedShpb::save_state(const RunResult& r, long next_step,
                                    const time_loop::Schedule& schedule) const {
  ShpbState s;
  s.next_step = next_step;
  s.partial = r;
  s.schedule = schedule;
  std::visit([&](const auto& a) { a.save_into(s); }, assembly_);
  return s;
}

void SimulatedShpb::restore_state(const ShpbState& s, RunResult& r, time_loop::Schedule& schedule) {
  std::visit([&](const auto& a) { a.check_fits(s); }, assembly_);  // bar kind, specimen model
  // The plan must be this run's; the checkpoint's schedule (refined or not) then continues it.
  const time_loop::Schedule& c = s.schedule;
  if (s.partial.dt != schedule_.dt || c.planned_dt != schedule_.dt)
    misfit("the checkpoint's time step " + std::to_string(s.partial.dt) + " s differs from this "
           "run's " + std::to_string(schedule_.dt) + " s");
  if (c.sample_every != schedule_.sample_every || c.ticks_per_planned_step < 1 ||
      !(c.dt > 0 && c.dt <= schedule_.dt) || c.n_steps < schedule_.n_steps)
    misfit("the checkpoint's schedule does not continue this run's plan (output cadence or dt)");
  if (s.next_step < 0 || s.next_step > c.n_steps)
    misfit("the checkpoint lies beyond time.end (step " + std::to_string(s.next_step) + " of " +
           std::to_string(c.n_steps) + ")");
  if (s.partial.steps != s.next_step) misfit("the checkpoint's step count is inconsistent");
  // Probes by name: the checkpoint must record what this run declares, in the same order
  // (the order is the HDF5 order of the finished run file).
  if (s.partial.probes.size() != r.probes.size())
    misfit("the checkpoint has " + std::to_string(s.partial.probes.size()) + " probes, this run " +
           std::to_string(r.probes.size()));
  for (std::size_t k = 0; k < r.probes.size(); ++k) {
    if (s.partial.probes[k].name != r.probes[k].name)
      misfit("probe " + std::to_string(k) + " is '" + s.partial.probes[k].name + "', expected '" +
             r.probes[k].name + "'");
    if (s.partial.probes[k].value.size() != s.partial.t.size())
      misfit("probe '" + r.probes[k].name + "' has another length than t");
  }
  std::visit([&](auto& a) { a.restore_from(s); }, assembly_);
  r.t = s.partial.t;
  for (std::size_t k = 0; k < r.probes.size(); ++k) r.probes[k].value = s.partial.probes[k].value;
  r.steps = s.partial.steps;
  schedule = c;
}

}  // namespace kolsky::shpb
