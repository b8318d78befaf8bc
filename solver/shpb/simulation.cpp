#include "shpb/simulation.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <sstream>
#include <stdexcept>
#include <type_traits>

#include "core/errors.hpp"
#include "shpb/gauge_waves.hpp"

namespace kolsky::shpb {

namespace {

Bar make_bar(BarKind kind, const BarSpec& b, std::optional<bar::Pulse> load, double face_mass) {
  if (kind == BarKind::sphere_chain) {
    const int n = b.n_spheres > 0 ? b.n_spheres
                                  : bar::sphere_count(b.geometry.length, b.geometry.diameter);
    return bar::SphereChainBar(b.material, b.geometry, n, std::move(load), face_mass);
  }
  return bar::CharacteristicBar(b.material, b.geometry, std::move(load), face_mass);
}

Specimen make_specimen(const SpecimenSpec& s) {
  struct {
    Specimen operator()(const bar::ColumnParams& p) const { return bar::SpecimenColumn(p); }
    Specimen operator()(const fe::FeSpecimenParams& p) const { return fe::FeSpecimen(p); }
    Specimen operator()(const dem::DemSpecimenParams& p) const { return dem::make_dem_specimen(p); }
  } build;
  return std::visit(build, s);
}

template <class V>
double stable_dt_of(const V& v) {
  return std::visit([](const auto& x) { return x.stable_dt(); }, v);
}

double face_mass_of(const Specimen& s) {
  return std::visit([](const auto& x) { return x.face_mass(); }, s);
}

fe::MeshedBar meshed_bar(const BarSpec& b) {
  return {fe::LinearElastic{b.material.youngs_modulus, b.material.poisson_ratio, b.material.density},
          b.geometry.length, 0.5 * b.geometry.diameter, b.gauges};
}

std::optional<fe::MeshedShpb> make_meshed(const ExperimentSpec& spec) {
  if (spec.bar_kind != BarKind::meshed) return std::nullopt;
  const auto* fe_params = std::get_if<fe::FeSpecimenParams>(&spec.specimen);
  if (!fe_params) throw InputError("", "bars.kind", "meshed bars need specimen.model = fe");
  if (spec.incident.gauges.empty() || spec.transmission.gauges.empty())
    throw InputError("", "bars.kind", "meshed bars need a gauge on each bar (the face waves come from them)");
  fe::MeshedShpbParams p;
  p.specimen = *fe_params;
  p.incident = meshed_bar(spec.incident);
  p.transmission = meshed_bar(spec.transmission);
  p.bar_n_r = spec.bar_mesh.n_radial;
  p.bar_element_length = spec.bar_mesh.element_length;
  p.applied_stress = [pulse = spec.pulse](double t) { return bar::evaluate(pulse, t); };
  return fe::MeshedShpb(p);
}

time_loop::StepPolicy policy(const TimeSpec& t, const OutputSpec& o) {
  return {t.end_time, t.dt, t.safety_factor, t.check_stability, o.interval};
}

}  // namespace

double specimen_length(const SpecimenSpec& s) {
  struct {
    double operator()(const bar::ColumnParams& c) const { return c.length; }
    double operator()(const fe::FeSpecimenParams& f) const { return f.length; }
    double operator()(const dem::DemSpecimenParams& d) const { return d.packing.length; }
  } v;
  return std::visit(v, s);
}

double specimen_diameter(const SpecimenSpec& s) {
  struct {
    double operator()(const bar::ColumnParams& c) const { return c.diameter; }
    double operator()(const fe::FeSpecimenParams& f) const { return 2.0 * f.radius; }
    double operator()(const dem::DemSpecimenParams& d) const { return d.packing.diameter; }
  } v;
  return std::visit(v, s);
}

const Probe& RunResult::probe(const std::string& name) const {
  for (const auto& p : probes)
    if (p.name == name) return p;
  throw std::out_of_range("no probe named '" + name + "'");
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

SimulatedShpb::SimulatedShpb(const ExperimentSpec& spec)
    : spec_(spec),
      specimen_(make_specimen(spec.specimen)),
      incident_(make_bar(spec.bar_kind, spec.incident, spec.pulse, face_mass_of(specimen_))),
      transmission_(make_bar(spec.bar_kind, spec.transmission, std::nullopt, face_mass_of(specimen_))),
      meshed_(make_meshed(spec)) {
  const double stable = meshed_ ? meshed_->stable_dt()
                                : std::min({stable_dt_of(specimen_), stable_dt_of(incident_),
                                            stable_dt_of(transmission_)});
  schedule_ = time_loop::plan_steps(policy(spec.time, spec.output), stable);
}

void SimulatedShpb::require_analysable_end() const {
  // The analysis needs the incident wave at the specimen and two samples after it.
  const double needed = arrival_time() + 2.0 * schedule_.dt * schedule_.sample_every;
  if (spec_.time.end_time >= needed) return;
  std::ostringstream msg;
  msg << std::setprecision(4) << "must be at least " << needed
      << " s: the incident wave reaches the specimen at L_I / c_I = " << arrival_time()
      << " s, and the analysis needs two probe samples after that";
  throw InputError("", "time.end", msg.str());
}

double SimulatedShpb::arrival_time() const {
  const auto& g = spec_.incident.geometry;
  if (spec_.bar_kind == BarKind::sphere_chain) {
    // Ball 0 is loaded; the wave crosses N-1 contacts spaced 2R at the chain's long-wave speed.
    const auto& chain = std::get<bar::SphereChainBar>(incident_);
    return (chain.size() - 1) * g.diameter / chain.properties().long_wave_speed();
  }
  return g.length / spec_.incident.material.wave_speed();
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

void SimulatedShpb::step(double t, double dt) {
  if (meshed_) {
    meshed_->step(t, dt);
    forces_ = meshed_->face_forces();
    const double applied = bar::evaluate(spec_.pulse, t);
    injected_ += dt * spec_.incident.geometry.area() / spec_.incident.material.specific_impedance() * applied * applied;
    return;
  }
  auto intrusion = [](const Bar& b) { return std::visit([](const auto& x) { return x.intrusion(); }, b); };
  auto rate = [](const Bar& b) { return std::visit([](const auto& x) { return x.rate(); }, b); };
  bar::FaceState faces{intrusion(incident_), intrusion(transmission_), rate(incident_),
                       rate(transmission_)};
  std::visit([&](auto& sp) {
    forces_ = sp.forces(faces);
    // Snapshot here, between the force evaluation and the next half kick and drift: the only
    // point where positions, velocities and forces all belong to t^n.
    if constexpr (std::is_same_v<std::decay_t<decltype(sp)>, dem::DemSpecimen>) {
      const RunControl* c = control_;
      if (c && c->snapshot && c->snapshot_every > 0 && step_index_ % c->snapshot_every == 0)
        c->snapshot(step_index_, t, sp.system().particles());
    }
    sp.advance(dt);
  }, specimen_);
  std::visit([&](auto& b) { b.step(t, dt, forces_.front); }, incident_);
  std::visit([&](auto& b) { b.step(t, dt, forces_.back); }, transmission_);

  // Wave energies, Eqs. 2.11-2.13, trapezoid in time on the face waves.
  const double s[3] = {std::visit([](const auto& b) { return b.incoming_at_step(); }, incident_),
                       std::visit([](const auto& b) { return b.outgoing_at_step(); }, incident_),
                       std::visit([](const auto& b) { return b.outgoing_at_step(); }, transmission_)};
  const auto& mi = spec_.incident.material;
  const auto& mt = spec_.transmission.material;
  const double ki = spec_.incident.geometry.area() / mi.specific_impedance();
  const double kt = spec_.transmission.geometry.area() / mt.specific_impedance();
  w_i_ += 0.5 * dt * ki * (prev_[0] * prev_[0] + s[0] * s[0]);
  w_r_ += 0.5 * dt * ki * (prev_[1] * prev_[1] + s[1] * s[1]);
  w_t_ += 0.5 * dt * kt * (prev_[2] * prev_[2] + s[2] * s[2]);
  std::copy(s, s + 3, prev_);
  // Energy scale for the blow-up bound: what the applied pulse has injected at the far end.
  const double applied = bar::evaluate(spec_.pulse, t);
  injected_ += dt * ki * applied * applied;
}

void SimulatedShpb::sample_meshed(double t, RunResult& r) {
  const fe::MeshedEnergy e = meshed_->energy_ledger();
  if (!meshed_->finite() || !std::isfinite(e.held()) || !std::isfinite(e.applied_work))
    throw NumericalError("non-finite state at t = " + std::to_string(t) + " s", t);
  const double area_s = meshed_->specimen_area();
  // Face waves and their energies are derived from the gauges after the run (gauge_waves.hpp).
  std::vector<double> v{0.0, 0.0, 0.0, forces_.front / area_s, forces_.back / area_s, meshed_->mean_strain(),
                        meshed_->face_rate(0), meshed_->face_rate(1), 0.0, 0.0, 0.0, e.held(), e.applied_work,
                        bar::evaluate(spec_.pulse, t)};
  for (int b = 0; b < 2; ++b)
    for (std::size_t k = 0; k < (b == 0 ? spec_.incident : spec_.transmission).gauges.size(); ++k)
      v.push_back(meshed_->gauge_strain(b, k));  // surface strain, tension +: as measured
  r.t.push_back(t);
  for (size_t k = 0; k < v.size(); ++k) r.probes[k].value.push_back(v[k]);
}

void SimulatedShpb::sample(double t, RunResult& r) {
  if (meshed_) return sample_meshed(t, r);
  const auto& mi = spec_.incident.material;
  const auto& mt = spec_.transmission.material;
  const double area_s = std::visit([](const auto& sp) { return sp.area(); }, specimen_);
  auto face_ke = [](const Bar& b) { return std::visit([](const auto& x) { return x.face_kinetic_energy(); }, b); };
  auto delivered = [](const Bar& b) { return std::visit([](const auto& x) { return x.delivered_energy(); }, b); };
  const double held = std::visit([](const auto& sp) { return sp.energy().total(); }, specimen_) +
                      face_ke(incident_) + face_ke(transmission_);
  const double in = delivered(incident_) + delivered(transmission_);

  bool ok = std::visit([](const auto& sp) { return sp.finite(); }, specimen_) &&
            std::isfinite(held) && std::isfinite(in);
  ok = ok && std::visit([](const auto& b) { return b.finite(); }, incident_) &&
       std::visit([](const auto& b) { return b.finite(); }, transmission_);
  if (!ok) throw NumericalError("non-finite state at t = " + std::to_string(t) + " s", t);
  // Scale of the bound: the energy injected so far, plus what a DEM packing holds in its
  // residual overlaps at t = 0 (its ledger's round-off and non-potential residue scale with
  // that, and before the pulse arrives the injected energy is still ~0).
  const double stored_0 = std::visit(
      [](const auto& sp) {
        if constexpr (std::is_same_v<std::decay_t<decltype(sp)>, dem::DemSpecimen>)
          return sp.initial_elastic_energy();
        else
          return 0.0;
      },
      specimen_);
  const double scale = injected_ + stored_0;
  if (held - in > spec_.time.energy_tolerance * scale && scale > 0.0) {
    std::ostringstream msg;
    msg << std::setprecision(4) << "energy grows: specimen and bar faces hold " << held
        << " J but only " << in << " J entered through the faces (t = " << t
        << " s; bound " << spec_.time.energy_tolerance << " x " << scale << " J)";
    throw NumericalError(msg.str(), t);
  }

  std::vector<double> v;
  v.push_back(std::visit([](const auto& b) { return b.incoming_at_step(); }, incident_));
  v.push_back(std::visit([](const auto& b) { return b.outgoing_at_step(); }, incident_));
  v.push_back(std::visit([](const auto& b) { return b.outgoing_at_step(); }, transmission_));
  v.push_back(forces_.front / area_s);
  v.push_back(forces_.back / area_s);
  v.push_back(std::visit([](const auto& sp) { return sp.mean_strain(); }, specimen_));
  v.push_back(std::visit([](const auto& b) { return b.rate_at_step(); }, incident_));
  v.push_back(std::visit([](const auto& b) { return b.rate_at_step(); }, transmission_));
  v.push_back(w_i_);
  v.push_back(w_r_);
  v.push_back(w_t_);
  v.push_back(held);
  v.push_back(in);
  v.push_back(bar::evaluate(spec_.pulse, t));
  for (double d : spec_.incident.gauges)
    v.push_back(-std::visit([&](const auto& b) { return b.gauge_stress(d, t); }, incident_) /
                mi.youngs_modulus);
  for (double d : spec_.transmission.gauges)
    v.push_back(-std::visit([&](const auto& b) { return b.gauge_stress(d, t); }, transmission_) /
                mt.youngs_modulus);
  if (const auto* d = std::get_if<dem::DemSpecimen>(&specimen_)) {
    // Contact counts cost a pass over the contact flags: sampled here, at the probe cadence.
    const dem::DemSystem& sys = d->system();
    const double n = static_cast<double>(sys.particles().size());
    const double pairs = static_cast<double>(sys.n_contacts());
    const double walls = static_cast<double>(sys.n_wall_contacts());
    v.push_back(sys.particles().kinetic_energy());
    v.push_back(2.0 * pairs / n);
    v.push_back((2.0 * pairs + walls) / n);
    v.push_back(pairs);
    v.push_back(walls);
  }
  r.t.push_back(t);
  for (size_t k = 0; k < v.size(); ++k) r.probes[k].value.push_back(v[k]);
}

RunResult SimulatedShpb::run(Progress* progress, const RunControl& control) {
  RunResult r;
  r.dt = schedule_.dt;
  r.stable_dt = schedule_.stable_dt;
  r.arrival_time = arrival_time();
  r.probes = {
      {"wave_incident", "Pa", "incident wave at the incident-bar face (compression +)", {}},
      {"wave_reflected", "Pa", "reflected wave at the incident-bar face (compression +)", {}},
      {"wave_transmitted", "Pa", "transmitted wave at the transmission-bar face (compression +)", {}},
      {"stress_front", "Pa", "interface stress, incident-bar face: force / specimen area", {}},
      {"stress_back", "Pa", "interface stress, transmission-bar face: force / specimen area", {}},
      {"specimen_strain", "1", "mean engineering strain from the face motion (compression +)", {}},
      {"face_rate_front", "m/s", "incident-bar face velocity into the specimen", {}},
      {"face_rate_back", "m/s", "transmission-bar face velocity into the specimen", {}},
      {"w_incident", "J", "Eq. 2.11 incident wave energy", {}},
      {"w_reflected", "J", "Eq. 2.12 reflected wave energy", {}},
      {"w_transmitted", "J", "Eq. 2.13 transmitted wave energy", {}},
      {"energy_held", "J", "specimen kinetic + internal work + face-mass kinetic energy", {}},
      {"energy_delivered", "J", "energy the bars delivered to the faces", {}},
      {"applied_stress", "Pa", "stress applied at the incident bar's far end", {}},
  };
  for (size_t k = 0; k < spec_.incident.gauges.size(); ++k)
    r.probes.push_back({k == 0 ? "incident_gauge_strain" : "incident_gauge_strain_" + std::to_string(k + 1),
                        "1", "incident-bar gauge strain as measured (compression -)", {}});
  for (size_t k = 0; k < spec_.transmission.gauges.size(); ++k)
    r.probes.push_back({k == 0 ? "transmission_gauge_strain" : "transmission_gauge_strain_" + std::to_string(k + 1),
                        "1", "transmission-bar gauge strain as measured (compression -)", {}});
  if (std::holds_alternative<dem::DemSpecimen>(specimen_)) {
    r.probes.push_back({"grain_kinetic_energy", "J", "kinetic energy of the grains (translation + rotation)", {}});
    r.probes.push_back({"coordination_number", "1", "2 x touching grain pairs / grains", {}});
    r.probes.push_back({"coordination_with_walls", "1", "(2 x touching grain pairs + grain-wall contacts) / grains", {}});
    r.probes.push_back({"grain_contacts", "1", "touching grain pairs", {}});
    r.probes.push_back({"wall_contacts", "1", "touching grain-wall contacts (end planes and tube)", {}});
  }
  const bool checkpointing = control.checkpoint_every > 0 && control.checkpoint;
  if ((checkpointing || control.resume) && !can_checkpoint())
    throw InputError("", "specimen.model", "checkpoint and restart are not available for the fe specimen");
  long first = 0;
  if (control.resume) {
    restore_state(*control.resume, r);
    first = control.resume->next_step;
  }
  control_ = &control;
  try {
    time_loop::run_loop_from(
        schedule_, first,
        [&](double t, double dt) {
          step_index_ = r.steps;  // = n: one step per call since step 0
          if (checkpointing && r.steps > first && r.steps % control.checkpoint_every == 0)
            control.checkpoint(save_state(r, r.steps));
          step(t, dt);
          ++r.steps;
        },
        [this, &r](double t) { sample(t, r); }, progress);
  } catch (const NumericalError& e) {
    if (progress) progress->finish();
    r.complete = false;
    r.failure = e.what();
  } catch (...) {
    control_ = nullptr;
    throw;
  }
  control_ = nullptr;
  if (meshed_) waves_from_gauges(r, spec_.incident, spec_.transmission);
  return r;
}

}  // namespace kolsky::shpb
