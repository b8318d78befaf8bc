#include "shpb/strain_rate_walls.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"
#include "core/stability_check.hpp"
#include "dem/dem_specimen_params.hpp"
#include "dem/dem_state.hpp"
#include "shpb/analysis.hpp"
#include "shpb/simulation.hpp"
#include "shpb/specimen_models.hpp"

namespace kolsky::shpb {

namespace {

const dem::DemSpecimenParams& dem_params(const ExperimentSpec& spec) {
  const auto* d = std::get_if<dem::DemSpecimenParams>(&spec.specimen);
  if (!d)
    throw InputError("", "specimen.model",
                     "strain-rate-controlled walls (loading.kind = strain_rate) need "
                     "specimen.model = dem");
  if (d->walls.preload_on_supports)
    throw InputError("", "specimen.preload_on_supports",
                     "there are no bar supports with loading.kind = strain_rate: the walls "
                     "report the whole force; set it to false");
  return *d;
}

const StrainRateHistory& history_of(const ExperimentSpec& spec) {
  if (!spec.strain_rate) throw std::logic_error("StrainRateWallsAssembly: spec.strain_rate is not set");
  return *spec.strain_rate;
}

[[noreturn]] void misfit(const std::string& rule) { throw InputError("", "restart", rule); }

// With time.dt = 0 the run refines its step after each break (time.refine_after_breaks), so
// the specimen need not plan for the smallest daughter from the first step.
bool refines_after_breaks(const ExperimentSpec& spec) { return spec.time.dt == 0.0 && spec.time.refine_after_breaks; }

dem::DemSpecimenParams params_for_run(const ExperimentSpec& spec) {
  dem::DemSpecimenParams p = dem_params(spec);
  p.step_for_daughters_up_front = !refines_after_breaks(spec);
  return p;
}

}  // namespace

StrainRateWallsAssembly::StrainRateWallsAssembly(const ExperimentSpec& spec)
    : history_(history_of(spec)),
      energy_tolerance_(spec.time.energy_tolerance),
      check_stability_(spec.time.check_stability),
      refines_dt_(refines_after_breaks(spec)),
      specimen_(dem::make_dem_specimen(params_for_run(spec))),
      length_(specimen_.length()),
      area_(specimen_.area()) {}

void StrainRateWallsAssembly::compute_forces(long n, double t, const RunControl& control) {
  // The walls at t^n: Eq. 5.1 strain over the initial length (engineering strain).
  const FaceState now{length_ * history_.strain(t), 0.0, length_ * history_.rate(t), 0.0};
  const FaceForces f = specimen_.forces(now);
  at_forces_evaluated(specimen_, n, t, control);  // positions, velocities, forces all at t^n
  // Wall work since the last step, trapezoid in force and displacement (the fixed wall does
  // none); at step 0 the wall has not moved (eps(0) = 0), so the initial forces_ do not count.
  const double du = now.intrusion_front - faces_.intrusion_front;
  const double dw = 0.5 * (forces_.front + f.front) * du;
  work_ += dw;
  gross_ += std::abs(dw);
  faces_ = now;
  forces_ = f;
}

void StrainRateWallsAssembly::observe(double t) {
  held_ = specimen_.energy().total();
  if (!specimen_.finite() || !std::isfinite(held_) || !std::isfinite(work_))
    throw NumericalError("non-finite state at t = " + std::to_string(t) + " s", t);
  // Held: the specimen's energy since the start; supplied: the wall work; scale: the gross
  // wall work plus the packing's residual elastic energy (which it may release unloaded).
  // Off with time.check_stability = false, as in the 1-D assembly.
  if (check_stability_)
    check_energy_growth({held_, work_, gross_ + specimen_.initial_elastic_energy()}, energy_tolerance_,
                      "strain-rate walls and specimen", t);
}

ProbeRecords StrainRateWallsAssembly::probes() const {
  const StrainRateWallsAssembly* a = this;
  const StrainRateHistory* h = &history_;
  const double area = area_;
  auto front = [a, area](double) { return a->forces_.front / area; };
  auto back = [a, area](double) { return a->forces_.back / area; };
  ProbeRecords r = {
      {"specimen_strain", "1", "Eq. 5.1 applied engineering strain: integral of the strain rate "
       "(compression +)", [h](double t) { return h->strain(t); }},
      {"strain_rate", "1/s", "applied strain rate (tabulated; linear between rows, 0 after the last)",
       [h](double t) { return h->rate(t); }},
      {"stress_front", "Pa", "interface stress, incident-side wall: wall force / specimen area", front},
      {"stress_back", "Pa", "interface stress, transmission-side wall: wall force / specimen area", back},
      {"stress_avg", "Pa", "Eq. 4.16 average of the front and back stresses",
       [front, back](double t) { return 0.5 * (front(t) + back(t)); }},
      {"alpha", "1", "Eq. 2.15 stress non-uniformity |front - back| / average (NaN below the "
       "floor; computed after the run over the whole record)",
       [](double) { return std::numeric_limits<double>::quiet_NaN(); }},
      {"face_displacement_front", "m", "incident-side wall displacement into the specimen, L0 x strain",
       [a](double) { return a->faces_.intrusion_front; }},
      {"face_rate_front", "m/s", "incident-side wall velocity into the specimen, L0 x strain rate",
       [a](double) { return a->faces_.rate_front; }},
      {"face_rate_back", "m/s", "transmission-side wall velocity (fixed: 0)",
       [a](double) { return a->faces_.rate_back; }},
      {"energy_held", "J", "specimen kinetic energy + internal work since the start",
       [a](double) { return a->held_; }},
      {"energy_delivered", "J", "work of the incident-side wall on the grains",
       [a](double) { return a->work_; }},
  };
  add_model_probes(specimen_, r);
  return r;
}

void StrainRateWallsAssembly::finish(RunResult& r) const {
  // alpha needs the record's peak average stress for its floor: computed once, here, by the
  // analysis itself (the same function kolsky run reports), over every sample so far.
  if (!r.has_probe("alpha")) return;
  const SpecimenHistory h =
      analyze_faces(r.t, r.probe("specimen_strain").value, r.probe("strain_rate").value,
                    r.probe("stress_front").value, r.probe("stress_back").value);
  for (Probe& p : r.probes)
    if (p.name == "alpha") p.value = h.alpha;
}

void StrainRateWallsAssembly::save_into(ShpbState& s) const {
  s.specimen = specimen_.save_state();  // holds the faces of the last step too
  s.forces = forces_;
  s.w_i = work_;
  s.injected = gross_;
}

void StrainRateWallsAssembly::check_fits(const ShpbState& s) const {
  if (!std::holds_alternative<dem::DemSpecimenState>(s.specimen))
    misfit("the checkpoint was written for another specimen model");
  // A bar run's checkpoint carries its bars' histories and a wave arrival time; ours neither.
  const auto* bi = std::get_if<bar::CharacteristicBar::State>(&s.incident);
  const auto* bt = std::get_if<bar::CharacteristicBar::State>(&s.transmission);
  if (!bi || !bt || !bi->s_out.empty() || !bt->s_out.empty() || s.partial.arrival_time != 0.0)
    misfit("the checkpoint was written for a run with bars, not for strain-rate walls (loading.kind)");
}

void StrainRateWallsAssembly::restore_from(const ShpbState& s) {
  const auto& d = std::get<dem::DemSpecimenState>(s.specimen);
  specimen_.restore_state(d);
  faces_ = d.faces;
  forces_ = s.forces;
  work_ = s.w_i;
  gross_ = s.injected;
}

}  // namespace kolsky::shpb
