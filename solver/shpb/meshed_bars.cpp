#include "shpb/meshed_bars.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"
#include "shpb/gauge_waves.hpp"
#include "shpb/simulation.hpp"
#include "shpb/specimen_models.hpp"

namespace kolsky::shpb {

namespace {

fe::MeshedBar meshed_bar(const BarSpec& b) {
  return {fe::LinearElastic{b.material.youngs_modulus, b.material.poisson_ratio, b.material.density},
          b.geometry.length, 0.5 * b.geometry.diameter, b.gauges};
}

fe::MeshedShpbParams meshed_params(const ExperimentSpec& spec) {
  const auto* fe_params = std::get_if<fe::FeSpecimenParams>(&spec.specimen);
  if (!fe_params) throw InputError("", "bars.kind", "meshed bars need specimen.model = fe or dem");
  if (spec.incident.gauges.empty() || spec.transmission.gauges.empty())
    throw InputError("", "bars.kind", "meshed bars need a gauge on each bar (the face waves come from them)");
  fe::MeshedShpbParams p;
  p.specimen = with_checks(*fe_params, spec.time.check_stability);
  p.incident = meshed_bar(spec.incident);
  p.transmission = meshed_bar(spec.transmission);
  p.bar_n_r = spec.bar_mesh.n_radial;
  p.bar_element_length = spec.bar_mesh.element_length;
  p.applied_stress = [pulse = spec.pulse](double t) { return bar::evaluate(pulse, t); };
  return p;
}

}  // namespace

MeshedBarsAssembly::MeshedBarsAssembly(const ExperimentSpec& spec)
    : incident_spec_(spec.incident),
      transmission_spec_(spec.transmission),
      pulse_(spec.pulse),
      meshed_(meshed_params(spec)) {}

double MeshedBarsAssembly::arrival_time() const {
  return incident_arrival_time(BarKind::meshed, incident_spec_);
}

void MeshedBarsAssembly::observe(double t) {
  ledger_ = meshed_.energy_ledger();
  if (!meshed_.finite() || !std::isfinite(ledger_.held()) || !std::isfinite(ledger_.applied_work))
    throw NumericalError("non-finite state at t = " + std::to_string(t) + " s", t);
}

ProbeRecords MeshedBarsAssembly::probes() const {
  const fe::MeshedShpb* m = &meshed_;
  const fe::MeshedEnergy* e = &ledger_;
  const double area_s = meshed_.specimen_area();
  auto later = [](double) { return 0.0; };  // filled by finish() from the gauges
  ProbeRecords r = {
      {"wave_incident", "Pa", "incident wave at the incident-bar face (compression +), from the "
       "first incident gauge by the 1-D shift", later},
      {"wave_reflected", "Pa", "reflected wave at the incident-bar face (compression +), from the "
       "first incident gauge by the 1-D shift", later},
      {"wave_transmitted", "Pa", "transmitted wave at the transmission-bar face (compression +), "
       "from the first transmission gauge by the 1-D shift", later},
      {"stress_front", "Pa", "interface stress, incident-bar face: contact force / specimen area",
       [m, area_s](double) { return m->face_forces().front / area_s; }},
      {"stress_back", "Pa", "interface stress, transmission-bar face: contact force / specimen area",
       [m, area_s](double) { return m->face_forces().back / area_s; }},
      {"specimen_strain", "1", "mean engineering strain from the ring-area mean face displacements "
       "(compression +)", [m](double) { return m->mean_strain(); }},
      {"face_rate_front", "m/s", "incident-bar face velocity into the specimen (ring-area mean)",
       [m](double) { return m->face_rate(0); }},
      {"face_rate_back", "m/s", "transmission-bar face velocity into the specimen (ring-area mean)",
       [m](double) { return m->face_rate(1); }},
      {"w_incident", "J", "Eq. 2.11 incident wave energy, from the gauge-derived wave", later},
      {"w_reflected", "J", "Eq. 2.12 reflected wave energy, from the gauge-derived wave", later},
      {"w_transmitted", "J", "Eq. 2.13 transmitted wave energy, from the gauge-derived wave", later},
      {"energy_held", "J", "kinetic + material work + contact work of bars, specimen and tube",
       [e](double) { return e->held(); }},
      {"energy_delivered", "J", "work of the traction on the incident bar's far end",
       [e](double) { return e->applied_work; }},
      {"applied_stress", "Pa", "stress applied at the incident bar's far end",
       [pulse = &pulse_](double t) { return bar::evaluate(*pulse, t); }},
  };
  for (int b = 0; b < 2; ++b) {
    const BarSpec& spec = b == 0 ? incident_spec_ : transmission_spec_;
    const std::string side = b == 0 ? "incident" : "transmission";
    for (std::size_t k = 0; k < spec.gauges.size(); ++k)
      r.push_back({gauge_probe_name(side, k), "1",
                   side + "-bar surface gauge strain as measured (compression -)",
                   [m, b, k](double) { return m->gauge_strain(b, k); }});
  }
  return r;
}

void MeshedBarsAssembly::finish(RunResult& r) const { waves_from_gauges(r, incident_spec_, transmission_spec_); }

void MeshedBarsAssembly::save_into(ShpbState&) const {
  throw std::logic_error("save_state: meshed bars (an fe specimen) have no checkpoint state");
}

void MeshedBarsAssembly::check_fits(const ShpbState&) const {
  throw InputError("", "restart", "meshed bars (an fe specimen) cannot be restarted from a checkpoint");
}

void MeshedBarsAssembly::restore_from(const ShpbState&) {
  throw std::logic_error("restore_state: meshed bars (an fe specimen) have no checkpoint state");
}

}  // namespace kolsky::shpb
