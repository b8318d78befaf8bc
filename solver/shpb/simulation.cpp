#include "shpb/simulation.hpp"

#include <cmath>
#include <iomanip>
#include <optional>
#include <sstream>
#include <stdexcept>

#include "core/errors.hpp"
#include "core/stability_check.hpp"

namespace kolsky::shpb {

namespace {

time_loop::StepPolicy policy(const ExperimentSpec& e) {
  const TimeSpec& t = e.time;
  const double safety = t.safety_factor > 0 ? t.safety_factor : default_safety_factor(e.specimen);
  return {t.end_time, t.dt, safety, t.check_stability, e.output.interval};
}

std::vector<Probe> empty_probes(const ProbeRecords& records) {
  std::vector<Probe> p;
  for (const ProbeRecord& rec : records) p.push_back({rec.name, rec.unit, rec.description, {}});
  return p;
}

}  // namespace

double incident_arrival_time(BarKind kind, const BarSpec& b) {
  const auto& g = b.geometry;
  if (kind == BarKind::sphere_chain) {
    // Ball 0 is loaded; the wave crosses N-1 contacts spaced 2R at the chain's long-wave speed.
    const int n = b.n_spheres > 0 ? b.n_spheres : bar::sphere_count(g.length, g.diameter);
    return (n - 1) * g.diameter / bar::sphere_chain_properties(b.material, g.diameter).long_wave_speed();
  }
  return g.length / b.material.wave_speed();
}

void require_reachable_end(const ExperimentSpec& spec) {
  const double arrival = spec.strain_rate ? 0.0 : incident_arrival_time(spec.bar_kind, spec.incident);
  const double interval = spec.output.interval > 0.0 ? spec.output.interval : 1e-6;
  // The exact rule needs arrival + 2 dt k, k = max(1, round(interval / dt)) steps per sample;
  // dt k >= interval / 2 for every dt, so arrival + interval is a bound it never undercuts.
  if (spec.time.end_time > arrival + interval) return;
  std::ostringstream msg;
  msg << std::setprecision(4) << "must be more than " << arrival + interval << " s: ";
  if (spec.strain_rate)
    msg << "the analysis needs two probe samples (output.interval = " << interval << " s apart)";
  else
    msg << "the incident wave reaches the specimen at L_I / c_I = " << arrival
        << " s, and the analysis needs two probe samples (output.interval = " << interval
        << " s apart) after that";
  throw InputError("", "time.end", msg.str());
}

bool RunResult::has_probe(const std::string& name) const {
  for (const auto& p : probes)
    if (p.name == name) return true;
  return false;
}

const Probe& RunResult::probe(const std::string& name) const {
  for (const auto& p : probes)
    if (p.name == name) return p;
  std::string have;
  for (const auto& p : probes) have += (have.empty() ? "" : ", ") + p.name;
  throw std::out_of_range("no probe named '" + name + "' in this run (it has: " +
                          (have.empty() ? std::string("none") : have) + ")");
}

FaceWaves RunResult::face_waves(double incident_modulus, double transmission_modulus) const {
  FaceWaves w;
  const auto& si = probe("wave_incident").value;
  const auto& sr = probe("wave_reflected").value;
  const auto& st = probe("wave_transmitted").value;
  for (size_t k = 0; k < t.size(); ++k) {
    if (t[k] < arrival_time - 1e-12) continue;
    // Gauge-derived waves (meshed bars) end where the shifted record does.
    if (!std::isfinite(si[k]) || !std::isfinite(sr[k]) || !std::isfinite(st[k])) break;
    w.t.push_back(t[k] - arrival_time);
    w.eps_i.push_back(si[k] / incident_modulus);
    w.eps_r.push_back(sr[k] / incident_modulus);
    w.eps_t.push_back(st[k] / transmission_modulus);
  }
  return w;
}

SimulatedShpb::SimulatedShpb(const ExperimentSpec& spec) : spec_(spec), assembly_(make_assembly(spec)) {
  const double stable = std::visit([](const auto& a) { return a.stable_dt(); }, assembly_);
  schedule_ = time_loop::plan_steps(policy(spec), stable);
}

bool SimulatedShpb::can_checkpoint() const {
  return std::visit([](const auto& a) { return a.can_checkpoint(); }, assembly_);
}

double SimulatedShpb::arrival_time() const {
  return std::visit([](const auto& a) { return a.arrival_time(); }, assembly_);
}

std::vector<Probe> SimulatedShpb::declared_probes() const {
  return std::visit([](const auto& a) { return empty_probes(a.probes()); }, assembly_);
}

const dem::DemSpecimen* SimulatedShpb::dem_specimen() const {
  if (const auto* a = std::get_if<OneDimBarsAssembly>(&assembly_)) return std::get_if<dem::DemSpecimen>(&a->specimen());
  if (const auto* w = std::get_if<StrainRateWallsAssembly>(&assembly_)) return &w->specimen();
  if (const auto* c = std::get_if<FeDemBarsAssembly>(&assembly_)) return &c->model().dem();
  return nullptr;
}

std::optional<FaceForces> SimulatedShpb::initial_wall_stress() const {
  // The FE-coupled specimen's walls are FE profiles, not planes with a seating load: none.
  if (std::holds_alternative<FeDemBarsAssembly>(assembly_)) return std::nullopt;
  const dem::DemSpecimen* d = dem_specimen();
  if (!d) return std::nullopt;
  const FaceForces f = d->initial_forces();
  return FaceForces{f.front / d->area(), f.back / d->area()};
}

const OneDimBarsAssembly& SimulatedShpb::one_dim(const char* accessor) const {
  if (const auto* a = std::get_if<OneDimBarsAssembly>(&assembly_)) return *a;
  throw std::logic_error(std::string("SimulatedShpb::") + accessor +
                         ": this assembly (meshed bars or strain-rate walls) builds no 1-D bar "
                         "or specimen variant (see assembly())");
}

const Specimen& SimulatedShpb::specimen() const { return one_dim("specimen()").specimen(); }
const Bar& SimulatedShpb::incident_bar() const { return one_dim("incident_bar()").incident_bar(); }
const Bar& SimulatedShpb::transmission_bar() const { return one_dim("transmission_bar()").transmission_bar(); }

void SimulatedShpb::require_analysable_end() const {
  // The analysis needs the incident wave at the specimen and two samples after it.
  const double needed = arrival_time() + 2.0 * schedule_.dt * schedule_.sample_every;
  if (spec_.time.end_time >= needed) return;
  std::ostringstream msg;
  msg << std::setprecision(4) << "must be at least " << needed << " s: ";
  if (direct_analysis())
    msg << "the analysis needs two probe samples";
  else
    msg << "the incident wave reaches the specimen at L_I / c_I = " << arrival_time()
        << " s, and the analysis needs two probe samples after that";
  throw InputError("", "time.end", msg.str());
}

AnalysisSetup SimulatedShpb::analysis_setup() const {
  auto as_analysis_bar = [](const BarSpec& b) {
    AnalysisBar a;
    a.youngs_modulus = b.material.youngs_modulus;
    a.density = b.material.density;
    a.poisson_ratio = b.material.poisson_ratio;
    a.diameter = b.geometry.diameter;
    a.gauge_distance = b.gauges.empty() ? 0.0 : b.gauges.front();
    return a;
  };
  AnalysisSetup s;
  s.incident = as_analysis_bar(spec_.incident);
  s.transmission = as_analysis_bar(spec_.transmission);
  s.specimen_length = specimen_length(spec_.specimen);
  s.specimen_diameter = specimen_diameter(spec_.specimen);
  return s;
}

bool SimulatedShpb::direct_analysis() const {
  return std::holds_alternative<StrainRateWallsAssembly>(assembly_);
}

RunAnalysis SimulatedShpb::analyze(const RunResult& r) const {
  RunAnalysis a;
  if (direct_analysis()) {  // Sec. 5.2.1: stresses from the wall forces, strain from Eq. 5.1
    a.history = analyze_faces(r.t, r.probe("specimen_strain").value, r.probe("strain_rate").value,
                              r.probe("stress_front").value, r.probe("stress_back").value);
    return a;
  }
  const AnalysisSetup setup = analysis_setup();
  a.waves = r.face_waves(setup.incident.youngs_modulus, setup.transmission.youngs_modulus);
  a.history = shpb::analyze(a.waves, setup);  // the free function, not this member
  return a;
}

bool SimulatedShpb::can_analyze(const RunResult& r) const {
  if (direct_analysis()) return r.t.size() >= 2;
  const AnalysisSetup setup = analysis_setup();
  return r.face_waves(setup.incident.youngs_modulus, setup.transmission.youngs_modulus).t.size() >= 2;
}

RunResult SimulatedShpb::run(Progress* progress, const RunControl& control) {
  // One dispatch per run: the loop below is compiled for each assembly type.
  return std::visit([&](auto& a) { return run_on(a, progress, control); }, assembly_);
}

namespace {
/// Thrown by the sampler when loading.end_at_back_stress is reached; caught by run_on alone.
struct EndRuleReached : std::runtime_error {
  using std::runtime_error::runtime_error;
};
}  // namespace

template <class A>
RunResult SimulatedShpb::run_on(A& assembly, Progress* progress, const RunControl& control) {
  RunResult r;
  r.dt = schedule_.dt;
  r.stable_dt = schedule_.stable_dt;
  r.arrival_time = assembly.arrival_time();
  // The records live for this run only: their samplers read the assembly where it is now.
  const ProbeRecords records = assembly.probes();
  r.probes = empty_probes(records);  // entry k of r.probes is records[k]: made from it here
  const bool checkpointing = control.checkpoint_every > 0 && control.checkpoint;
  if ((checkpointing || control.resume) && !assembly.can_checkpoint())
    throw InputError("", "specimen.model", "checkpoint and restart are not available for this model (an fe specimen or an FE mesh around a dem specimen)");
  // This run's schedule: the plan, refined during the run when a break lowers the limit.
  time_loop::Schedule s = schedule_;
  long first = 0;
  if (control.resume) {
    restore_state(*control.resume, r, s);
    first = control.resume->next_step;
  }
  // The hooks as the assembly sees them: snapshot cadence and step index on the schedule's
  // ticks, which are the steps themselves until a refinement.
  RunControl hooks = control;
  hooks.snapshot_every = control.snapshot_every * s.ticks_per_planned_step;
  const double safety = policy(spec_).safety_factor;
  // loading.end_at_back_stress: the probe it watches (only strain-rate walls record it).
  std::optional<std::size_t> end_probe;
  if (spec_.end_at_back_stress > 0) {
    for (std::size_t k = 0; k < records.size(); ++k)
      if (records[k].name == "stress_back") end_probe = k;
    if (!end_probe)
      throw InputError("", "loading.end_at_back_stress", "this assembly records no back-wall stress (loading.kind = strain_rate only)");
  }
  auto step = [&](long n, double t, double) {
    if (control.stop && *control.stop) {
      std::ostringstream msg;
      msg << std::setprecision(6) << "stopped on request (signal) before the step at t = " << t << " s";
      throw StopRequested(msg.str());
    }
    if (checkpointing && n > first && s.due(n, control.checkpoint_every))
      control.checkpoint(save_state(r, n, s));
    if (control.progress && control.progress_every > 0 && n > first && s.due(n, control.progress_every))
      control.progress(n, t);
    // Every assembly's step in the same three calls (assembly.hpp). The hooks see step n on the
    // schedule's ticks; between the forces of t^n and the step from t^n, the after-forces
    // hook may ask for the limit again (a break), and dt is refined before it is used.
    assembly.compute_forces(s.tick(n), t, hooks);
    if (assembly.after_forces().replan_dt && time_loop::refine(s, n, assembly.stable_dt(), safety))
      hooks.snapshot_every = control.snapshot_every * s.ticks_per_planned_step;
    assembly.advance(s.dt);
    ++r.steps;
  };
  auto sample = [&](double t) {
    // The loop asks the models for their limit again at every output step: an event during
    // the run (grains edited or broken) can lower it below the planned dt. A step above it is
    // a numerical failure (exit 3, what was sampled kept), not an input error.
    if (spec_.time.check_stability) {
      std::ostringstream planned;
      planned << std::setprecision(6) << "the models' limit now; the run was planned against "
              << s.stable_dt << " s, so something during the run lowered it";
      check_time_step(s.dt, assembly.stable_dt(), "run", t, planned.str());
    }
    assembly.observe(t);  // throws before anything of this sample is recorded
    r.t.push_back(t);
    for (std::size_t k = 0; k < records.size(); ++k) r.probes[k].value.push_back(records[k].sample(t));
    if (end_probe && r.probes[*end_probe].value.back() >= spec_.end_at_back_stress) {
      std::ostringstream msg;
      msg << std::setprecision(6) << "back-wall stress " << r.probes[*end_probe].value.back()
          << " Pa reached loading.end_at_back_stress at t = " << t << " s";
      throw EndRuleReached(msg.str());
    }
  };
  try {
    time_loop::run_loop_from(s, first, step, sample, progress);
  } catch (const NumericalError& e) {
    if (progress) progress->finish();
    r.complete = false;
    r.failure = e.what();
  } catch (const StopRequested& e) {  // what was computed is kept, as after a blow-up
    if (progress) progress->finish();
    r.complete = false;
    r.failure = e.what();
  } catch (const EndRuleReached& e) {  // the scene's own end: complete
    if (progress) progress->finish();
    r.ended_by = e.what();
  }
  r.dt_final = s.dt;
  r.dt_refinements = s.refinements;
  assembly.finish(r);
  return r;
}

}  // namespace kolsky::shpb
