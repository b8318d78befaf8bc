#include "shpb/one_dim_bars.hpp"

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>
#include <type_traits>

#include "core/stability_check.hpp"
#include "core/errors.hpp"
#include "shpb/simulation.hpp"
#include "shpb/specimen_models.hpp"

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

Specimen make_specimen(const SpecimenSpec& s, bool check_stability) {
  struct {
    bool check;
    Specimen operator()(const bar::ColumnParams& p) const { return bar::SpecimenColumn(p); }
    Specimen operator()(const fe::FeSpecimenParams& p) const { return fe::FeSpecimen(with_checks(p, check)); }
    Specimen operator()(const dem::DemSpecimenParams& p) const { return dem::make_dem_specimen(p); }
  } build{check_stability};
  return std::visit(build, s);
}

double face_mass_of(const Specimen& s) {
  return std::visit([](const auto& x) { return x.face_mass(); }, s);
}

template <class V>
double stable_dt_of(const V& v) {
  return std::visit([](const auto& x) { return x.stable_dt(); }, v);
}

// The bars' face quantities, visited (a jump on the bar kind, no virtual call).
double intrusion(const Bar& b) { return std::visit([](const auto& x) { return x.intrusion(); }, b); }
double rate(const Bar& b) { return std::visit([](const auto& x) { return x.rate(); }, b); }
double incoming(const Bar& b) { return std::visit([](const auto& x) { return x.incoming_at_step(); }, b); }
double outgoing(const Bar& b) { return std::visit([](const auto& x) { return x.outgoing_at_step(); }, b); }
double rate_at_step(const Bar& b) { return std::visit([](const auto& x) { return x.rate_at_step(); }, b); }
double face_ke(const Bar& b) { return std::visit([](const auto& x) { return x.face_kinetic_energy(); }, b); }
double delivered(const Bar& b) { return std::visit([](const auto& x) { return x.delivered_energy(); }, b); }
bool finite(const Bar& b) { return std::visit([](const auto& x) { return x.finite(); }, b); }
double gauge_stress(const Bar& b, double d, double t) {
  return std::visit([&](const auto& x) { return x.gauge_stress(d, t); }, b);
}

[[noreturn]] void misfit(const std::string& rule) { throw InputError("", "restart", rule); }

// The FE tube of a dem specimen (spec.dem_tube), built around the packed grains.
std::optional<coupling::FeTube> make_fe_tube(const ExperimentSpec& spec, const Specimen& specimen) {
  if (!spec.dem_tube) return std::nullopt;
  const auto* d = std::get_if<dem::DemSpecimen>(&specimen);
  if (!d) throw InputError("", "specimen.tube", "a meshed tube here needs specimen.model = dem");
  check_fe_tube_supported(spec);
  coupling::FeTubeParams p;
  p.tube = *spec.dem_tube;
  p.specimen_length = d->length();
  p.specimen_radius = std::sqrt(d->area() / std::numbers::pi);
  return coupling::FeTube(p, d->system());
}

}  // namespace

OneDimBarsAssembly::OneDimBarsAssembly(const ExperimentSpec& spec)
    : incident_spec_(spec.incident),
      transmission_spec_(spec.transmission),
      kind_(spec.bar_kind),
      pulse_(spec.pulse),
      energy_tolerance_(spec.time.energy_tolerance),
      check_stability_(spec.time.check_stability),
      specimen_(make_specimen(spec.specimen, spec.time.check_stability)),
      incident_(make_bar(spec.bar_kind, spec.incident, spec.pulse, face_mass_of(specimen_))),
      transmission_(make_bar(spec.bar_kind, spec.transmission, std::nullopt, face_mass_of(specimen_))),
      tube_(make_fe_tube(spec, specimen_)) {}

double OneDimBarsAssembly::stable_dt() const {
  const double dt = std::min({stable_dt_of(specimen_), stable_dt_of(incident_), stable_dt_of(transmission_)});
  return tube_ ? std::min(dt, tube_->stable_dt()) : dt;
}

double OneDimBarsAssembly::arrival_time() const { return incident_arrival_time(kind_, incident_spec_); }

void OneDimBarsAssembly::compute_forces(long n, double t, const RunControl& control) {
  FaceState faces{intrusion(incident_), intrusion(transmission_), rate(incident_), rate(transmission_)};
  if (tube_) tube_->drive(std::get<dem::DemSpecimen>(specimen_).coupled_system());
  std::visit([&](auto& sp) {
    forces_ = sp.forces(faces);
    at_forces_evaluated(sp, n, t, control);  // positions, velocities, forces all at t^n here
  }, specimen_);
  t_ = t;
}

time_loop::AfterForces OneDimBarsAssembly::after_forces() {
  // The breaks of a DEM specimen; never a re-plan: the characteristic bars interpolate on a
  // uniform time grid, so the specimen was planned for its smallest daughter up front.
  std::visit([](auto& sp) { apply_due_breaks(sp); }, specimen_);
  return {};
}

void OneDimBarsAssembly::advance(double dt) {
  const double t = t_;
  std::visit([&](auto& sp) {
    if constexpr (std::is_same_v<std::decay_t<decltype(sp)>, dem::DemSpecimen>)
      if (tube_) tube_->load_and_advance(sp.system(), dt);  // before the drift moves the grains
    sp.advance(dt);  // (no breaks came before the tube's loads: the two are refused together)
  }, specimen_);
  std::visit([&](auto& b) { b.step(t, dt, forces_.front); }, incident_);
  std::visit([&](auto& b) { b.step(t, dt, forces_.back); }, transmission_);

  // Wave energies, Eqs. 2.11-2.13, trapezoid in time on the face waves.
  const double s[3] = {incoming(incident_), outgoing(incident_), outgoing(transmission_)};
  const auto& mi = incident_spec_.material;
  const auto& mt = transmission_spec_.material;
  const double ki = incident_spec_.geometry.area() / mi.specific_impedance();
  const double kt = transmission_spec_.geometry.area() / mt.specific_impedance();
  w_i_ += 0.5 * dt * ki * (prev_[0] * prev_[0] + s[0] * s[0]);
  w_r_ += 0.5 * dt * ki * (prev_[1] * prev_[1] + s[1] * s[1]);
  w_t_ += 0.5 * dt * kt * (prev_[2] * prev_[2] + s[2] * s[2]);
  std::copy(s, s + 3, prev_);
  // Energy scale for the blow-up bound: what the applied pulse has injected at the far end.
  const double applied = bar::evaluate(pulse_, t);
  injected_ += dt * ki * applied * applied;
}

void OneDimBarsAssembly::observe(double t) {
  held_ = std::visit([](const auto& sp) { return sp.energy().total(); }, specimen_) +
          face_ke(incident_) + face_ke(transmission_);
  if (tube_) held_ += tube_->kinetic_energy() + tube_->material_work();
  delivered_ = delivered(incident_) + delivered(transmission_);

  bool ok = std::visit([](const auto& sp) { return sp.finite(); }, specimen_) &&
            std::isfinite(held_) && std::isfinite(delivered_);
  ok = ok && finite(incident_) && finite(transmission_) && (!tube_ || tube_->finite());
  if (!ok) throw NumericalError("non-finite state at t = " + std::to_string(t) + " s", t);
  const double stored_0 = std::visit([](const auto& sp) { return energy_stored_at_start(sp); }, specimen_);
  // Held: specimen and bar faces; supplied: what entered through the faces; judged against
  // what the applied pulse injected at the far end plus the specimen's energy at the start.
  // time.check_stability = false lifts it, as it lifts the dt limit (an unstable step then
  // grows until the state overflows, which the finiteness check above stops).
  if (check_stability_)
    check_energy_growth({held_, delivered_, injected_ + stored_0}, energy_tolerance_, "bars and specimen", t);
}

ProbeRecords OneDimBarsAssembly::probes() const {
  const double area_s = std::visit([](const auto& sp) { return sp.area(); }, specimen_);
  const Bar* bi = &incident_;
  const Bar* bt = &transmission_;
  const Specimen* sp = &specimen_;
  const FaceForces* f = &forces_;
  const OneDimBarsAssembly* a = this;
  const bar::Pulse* pulse = &pulse_;
  ProbeRecords r = {
      {"wave_incident", "Pa", "incident wave at the incident-bar face (compression +)",
       [bi](double) { return incoming(*bi); }},
      {"wave_reflected", "Pa", "reflected wave at the incident-bar face (compression +)",
       [bi](double) { return outgoing(*bi); }},
      {"wave_transmitted", "Pa", "transmitted wave at the transmission-bar face (compression +)",
       [bt](double) { return outgoing(*bt); }},
      {"stress_front", "Pa", "interface stress, incident-bar face: force / specimen area",
       [f, area_s](double) { return f->front / area_s; }},
      {"stress_back", "Pa", "interface stress, transmission-bar face: force / specimen area",
       [f, area_s](double) { return f->back / area_s; }},
      {"specimen_strain", "1", "mean engineering strain from the face motion (compression +)",
       [sp](double) { return std::visit([](const auto& x) { return x.mean_strain(); }, *sp); }},
      {"face_rate_front", "m/s", "incident-bar face velocity into the specimen",
       [bi](double) { return rate_at_step(*bi); }},
      {"face_rate_back", "m/s", "transmission-bar face velocity into the specimen",
       [bt](double) { return rate_at_step(*bt); }},
      {"w_incident", "J", "Eq. 2.11 incident wave energy", [a](double) { return a->w_i_; }},
      {"w_reflected", "J", "Eq. 2.12 reflected wave energy", [a](double) { return a->w_r_; }},
      {"w_transmitted", "J", "Eq. 2.13 transmitted wave energy", [a](double) { return a->w_t_; }},
      {"energy_held", "J", "specimen kinetic + internal work + face-mass kinetic energy",
       [a](double) { return a->held_; }},
      {"energy_delivered", "J", "energy the bars delivered to the faces",
       [a](double) { return a->delivered_; }},
      {"applied_stress", "Pa", "stress applied at the incident bar's far end",
       [pulse](double t) { return bar::evaluate(*pulse, t); }},
  };
  // Gauges read the bar's stress as strain, compression negative: as a foil gauge measures.
  const double ei = incident_spec_.material.youngs_modulus;
  const double et = transmission_spec_.material.youngs_modulus;
  for (std::size_t k = 0; k < incident_spec_.gauges.size(); ++k)
    r.push_back({gauge_probe_name("incident", k), "1", "incident-bar gauge strain as measured (compression -)",
                 [bi, d = incident_spec_.gauges[k], ei](double t) { return -gauge_stress(*bi, d, t) / ei; }});
  for (std::size_t k = 0; k < transmission_spec_.gauges.size(); ++k)
    r.push_back({gauge_probe_name("transmission", k), "1",
                 "transmission-bar gauge strain as measured (compression -)",
                 [bt, d = transmission_spec_.gauges[k], et](double t) { return -gauge_stress(*bt, d, t) / et; }});
  if (tube_) {
    const coupling::FeTube* tube = &*tube_;
    r.push_back({"tube_force", "N", "radial force of the grains on the FE tube wall",
                 [tube](double) { return tube->radial_force(); }});
    r.push_back({"tube_wall_displacement", "m", "ring-area mean radial displacement of the FE tube's inner wall",
                 [tube](double) { return tube->mean_wall_displacement(); }});
  }
  std::visit([&](const auto& s) { add_model_probes(s, r); }, specimen_);
  return r;
}

void OneDimBarsAssembly::save_into(ShpbState& s) const {
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
}

void OneDimBarsAssembly::check_fits(const ShpbState& s) const {
  // Bar kinds: CharacteristicBar <-> State 0, SphereChainBar <-> State 1 (same variant order).
  if (s.incident.index() != incident_.index() || s.transmission.index() != transmission_.index())
    misfit("the checkpoint was written for another bar model (bars.kind)");
  const bool column_fits = std::holds_alternative<bar::SpecimenColumn>(specimen_) &&
                           std::holds_alternative<bar::SpecimenColumn::State>(s.specimen);
  const bool dem_fits = std::holds_alternative<dem::DemSpecimen>(specimen_) &&
                        std::holds_alternative<dem::DemSpecimenState>(s.specimen);
  if (!column_fits && !dem_fits) misfit("the checkpoint was written for another specimen model");
}

void OneDimBarsAssembly::restore_from(const ShpbState& s) {
  auto restore_bar = [](Bar& bar, const BarState& state) {
    std::visit([](auto& b, const auto& st) {
      using B = std::decay_t<decltype(b)>;
      using S = std::decay_t<decltype(st)>;
      if constexpr (std::is_same_v<typename B::State, S>) b.restore_state(st);
    }, bar, state);
  };
  restore_bar(incident_, s.incident);
  restore_bar(transmission_, s.transmission);
  if (auto* c = std::get_if<bar::SpecimenColumn>(&specimen_))
    c->restore_state(std::get<bar::SpecimenColumn::State>(s.specimen));
  else
    std::get<dem::DemSpecimen>(specimen_).restore_state(std::get<dem::DemSpecimenState>(s.specimen));
  forces_ = s.forces;
  w_i_ = s.w_i;
  w_r_ = s.w_r;
  w_t_ = s.w_t;
  std::copy(s.prev, s.prev + 3, prev_);
  injected_ = s.injected;
}

}  // namespace kolsky::shpb
