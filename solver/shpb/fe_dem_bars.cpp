#include "shpb/fe_dem_bars.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"
#include "dem/dem_specimen_params.hpp"
#include "shpb/gauge_waves.hpp"
#include "shpb/simulation.hpp"
#include "shpb/specimen_models.hpp"

namespace kolsky::shpb {

namespace {

fe::MeshedBar meshed_bar(const BarSpec& b) {
  return {fe::LinearElastic{b.material.youngs_modulus, b.material.poisson_ratio, b.material.density},
          b.geometry.length, 0.5 * b.geometry.diameter, b.gauges};
}

const dem::DemSpecimenParams& dem_params(const ExperimentSpec& spec) {
  const auto* d = std::get_if<dem::DemSpecimenParams>(&spec.specimen);
  if (!d) throw InputError("", "specimen.model", "the FE-DEM coupling needs specimen.model = dem");
  return *d;
}

}  // namespace

coupling::FeDemParams fe_dem_params(const ExperimentSpec& spec) {
  const dem::DemSpecimenParams& d = dem_params(spec);
  check_fe_dem_supported(spec);
  coupling::FeDemParams p;
  p.fe.incident = meshed_bar(spec.incident);
  p.fe.transmission = meshed_bar(spec.transmission);
  p.fe.bar_n_r = spec.bar_mesh.n_radial;
  p.fe.bar_element_length = spec.bar_mesh.element_length;
  p.fe.specimen_length = d.packing.length;
  p.fe.specimen_radius = 0.5 * d.packing.diameter;
  p.fe.tube = spec.dem_tube;
  p.fe.applied_stress = [pulse = spec.pulse](double t) { return bar::evaluate(pulse, t); };
  p.check_dt = p.check_energy = spec.time.check_stability;
  p.energy_tolerance = spec.time.energy_tolerance;
  return p;
}

FeDemBarsAssembly::FeDemBarsAssembly(const ExperimentSpec& spec)
    : incident_spec_(spec.incident),
      transmission_spec_(spec.transmission),
      pulse_(spec.pulse),
      model_(fe_dem_params(spec), dem::make_dem_specimen(dem_params(spec))) {}

double FeDemBarsAssembly::arrival_time() const { return incident_arrival_time(BarKind::meshed, incident_spec_); }

void FeDemBarsAssembly::observe(double t) {
  ledger_ = model_.energy();
  if (!model_.finite() || !std::isfinite(ledger_.held()) || !std::isfinite(ledger_.applied_work))
    throw NumericalError("non-finite state at t = " + std::to_string(t) + " s", t);
}

ProbeRecords FeDemBarsAssembly::probes() const {
  const coupling::FeDemShpb* m = &model_;
  const coupling::FeDemEnergy* e = &ledger_;
  const double area_s = model_.specimen_area();
  auto later = [](double) { return 0.0; };  // filled by finish() from the gauges
  ProbeRecords r = {
      {"wave_incident", "Pa", "incident wave at the incident-bar face (compression +), from the "
       "first incident gauge by the 1-D shift", later},
      {"wave_reflected", "Pa", "reflected wave at the incident-bar face (compression +), from the "
       "first incident gauge by the 1-D shift", later},
      {"wave_transmitted", "Pa", "transmitted wave at the transmission-bar face (compression +), "
       "from the first transmission gauge by the 1-D shift", later},
      {"stress_front", "Pa", "interface stress, incident-bar face: summed grain contact forces on "
       "the FE face / specimen area", [m, area_s](double) { return m->face_force(0) / area_s; }},
      {"stress_back", "Pa", "interface stress, transmission-bar face: summed grain contact forces "
       "on the FE face / specimen area", [m, area_s](double) { return m->face_force(1) / area_s; }},
      {"specimen_strain", "1", "mean engineering strain from the ring-area mean face displacements "
       "(compression +)", [m](double) { return m->mean_strain(); }},
      {"face_rate_front", "m/s", "incident-bar face velocity into the specimen (ring-area mean)",
       [m](double) { return m->face_rate(0); }},
      {"face_rate_back", "m/s", "transmission-bar face velocity into the specimen (ring-area mean)",
       [m](double) { return m->face_rate(1); }},
      {"w_incident", "J", "Eq. 2.11 incident wave energy, from the gauge-derived wave", later},
      {"w_reflected", "J", "Eq. 2.12 reflected wave energy, from the gauge-derived wave", later},
      {"w_transmitted", "J", "Eq. 2.13 transmitted wave energy, from the gauge-derived wave", later},
      {"energy_held", "J", "FE kinetic + material work, DEM kinetic + stored (less the packing's "
       "initial) + dissipated", [e](double) { return e->held(); }},
      {"energy_delivered", "J", "work of the traction on the incident bar's far end",
       [e](double) { return e->applied_work; }},
      {"interface_work", "J", "work of the grains' ring loads on the FE bars and tube",
       [e](double) { return e->interface_work; }},
      {"tube_force", "N", "radial force of the grains on the tube wall",
       [m](double) { return m->tube_force(); }},
      {"off_axis_fraction", "1", "largest lateral resultant of the face contact forces / largest "
       "axial force so far (what the axisymmetric ring loads neglect)",
       [m](double) { return m->off_axis().face_fraction(); }},
      {"applied_stress", "Pa", "stress applied at the incident bar's far end",
       [pulse = &pulse_](double t) { return bar::evaluate(*pulse, t); }},
  };
  for (int b = 0; b < 2; ++b) {
    const BarSpec& spec = b == 0 ? incident_spec_ : transmission_spec_;
    const std::string side = b == 0 ? "incident" : "transmission";
    for (std::size_t k = 0; k < spec.gauges.size(); ++k)
      r.push_back({gauge_probe_name(side, k), "1", side + "-bar surface gauge strain as measured (compression -)",
                   [m, b, k](double) { return m->gauge_strain(b, k); }});
  }
  add_model_probes(model_.dem(), r);
  return r;
}

void FeDemBarsAssembly::finish(RunResult& r) const { waves_from_gauges(r, incident_spec_, transmission_spec_); }

void FeDemBarsAssembly::save_into(ShpbState&) const {
  throw std::logic_error("save_state: the FE-DEM coupling has no checkpoint state");
}

void FeDemBarsAssembly::check_fits(const ShpbState&) const {
  throw InputError("", "restart", "meshed bars with a dem specimen cannot be restarted from a checkpoint");
}

void FeDemBarsAssembly::restore_from(const ShpbState&) {
  throw std::logic_error("restore_state: the FE-DEM coupling has no checkpoint state");
}

}  // namespace kolsky::shpb
