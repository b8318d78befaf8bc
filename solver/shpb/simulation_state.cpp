// SimulatedShpb checkpoint and restart (simulation.hpp): the loop's state after a step and its
// sample, handed out by run() and taken back to continue bitwise. The bars and specimens
// provide their own plain-struct states; this file only collects them and checks that a state
// fits the simulation it is restored into.
#include <algorithm>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "core/errors.hpp"
#include "shpb/simulation.hpp"

namespace kolsky::shpb {

namespace {
[[noreturn]] void misfit(const std::string& rule) { throw InputError("", "restart", rule); }
}  // namespace

bool SimulatedShpb::can_checkpoint() const { return !std::holds_alternative<fe::FeSpecimen>(specimen_); }

ShpbState SimulatedShpb::save_state(const RunResult& r, long next_step) const {
  ShpbState s;
  s.next_step = next_step;
  s.partial = r;
  auto bar_state = [](const Bar& b) {
    return std::visit([](const auto& x) -> BarState { return x.save_state(); }, b);
  };
  s.incident = bar_state(incident_);
  s.transmission = bar_state(transmission_);
  if (const auto* c = std::get_if<bar::SpecimenColumn>(&specimen_)) s.specimen = c->save_state();
  else if (const auto* d = std::get_if<dem::DemSpecimen>(&specimen_)) s.specimen = d->save_state();
  else throw std::logic_error("save_state: the fe specimen has no checkpoint state");
  s.forces = forces_;
  s.w_i = w_i_;
  s.w_r = w_r_;
  s.w_t = w_t_;
  std::copy(prev_, prev_ + 3, s.prev);
  s.injected = injected_;
  return s;
}

void SimulatedShpb::restore_state(const ShpbState& s, RunResult& r) {
  // Bar kinds: CharacteristicBar <-> State 0, SphereChainBar <-> State 1 (same variant order).
  if (s.incident.index() != incident_.index() || s.transmission.index() != transmission_.index())
    misfit("the checkpoint was written for another bar model (bars.kind)");
  const bool column_fits = std::holds_alternative<bar::SpecimenColumn>(specimen_) &&
                           std::holds_alternative<bar::SpecimenColumn::State>(s.specimen);
  const bool dem_fits = std::holds_alternative<dem::DemSpecimen>(specimen_) &&
                        std::holds_alternative<dem::DemSpecimenState>(s.specimen);
  if (!column_fits && !dem_fits) misfit("the checkpoint was written for another specimen model");
  if (s.partial.dt != schedule_.dt)
    misfit("the checkpoint's time step " + std::to_string(s.partial.dt) + " s differs from this "
           "run's " + std::to_string(schedule_.dt) + " s");
  if (s.next_step < 0 || s.next_step > schedule_.n_steps)
    misfit("the checkpoint lies beyond time.end (step " + std::to_string(s.next_step) + " of " +
           std::to_string(schedule_.n_steps) + ")");
  if (s.partial.steps != s.next_step) misfit("the checkpoint's step count is inconsistent");
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
  std::visit([](auto& b, const auto& st) {
    using B = std::decay_t<decltype(b)>;
    using S = std::decay_t<decltype(st)>;
    if constexpr (std::is_same_v<typename B::State, S>) b.restore_state(st);
  }, incident_, s.incident);
  std::visit([](auto& b, const auto& st) {
    using B = std::decay_t<decltype(b)>;
    using S = std::decay_t<decltype(st)>;
    if constexpr (std::is_same_v<typename B::State, S>) b.restore_state(st);
  }, transmission_, s.transmission);
  if (column_fits)
    std::get<bar::SpecimenColumn>(specimen_).restore_state(std::get<bar::SpecimenColumn::State>(s.specimen));
  else
    std::get<dem::DemSpecimen>(specimen_).restore_state(std::get<dem::DemSpecimenState>(s.specimen));
  forces_ = s.forces;
  w_i_ = s.w_i;
  w_r_ = s.w_r;
  w_t_ = s.w_t;
  std::copy(s.prev, s.prev + 3, prev_);
  injected_ = s.injected;
  r.t = s.partial.t;
  for (std::size_t k = 0; k < r.probes.size(); ++k) r.probes[k].value = s.partial.probes[k].value;
  r.steps = s.partial.steps;
}

}  // namespace kolsky::shpb
