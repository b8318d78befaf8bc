// The FE specimen between characteristic bars (massless faces, penalty contact): the energy
// the bars deliver equals what the specimen holds (kinetic + material + contact work), and
// the 1-D reduction: an elastic FE specimen in a rigid, frictionless tube is in uniaxial strain,
// so the classic analysis must return its constrained modulus K + 4G/3.
#include <algorithm>
#include <cmath>

#include "checks/check.hpp"
#include "checks/song_setup.hpp"
#include "shpb/analysis.hpp"
#include "shpb/simulation.hpp"

namespace kolsky::verify {

namespace {

shpb::ExperimentSpec fe_spec(const fe::Material& m) {
  auto spec = song_spec(bar::LinearElastic{230e6});
  fe::FeSpecimenParams f;
  f.n_r = 6;
  f.n_z = 12;
  f.material = m;
  f.tube = fe::RigidTube{};
  spec.specimen = f;
  spec.pulse = bar::TrapezoidPulse{100e6, 150e-6, 500e-6, 100e-6, 0.0};
  spec.time.safety_factor = 0.7;
  spec.time.end_time = 1.7e-3;
  return spec;
}

}  // namespace

std::vector<CheckResult> fe_coupling_checks() {
  // Elastic sand-like FE specimen: E = 130 MPa, nu = 0.3 -> D = E(1-nu)/((1+nu)(1-2nu)).
  const fe::LinearElastic elastic{130e6, 0.3, 1457.5};
  shpb::SimulatedShpb sim(fe_spec(elastic));
  const auto r = sim.run();
  const auto& held = r.probe("energy_held").value;
  const auto& delivered = r.probe("energy_delivered").value;
  double worst = 0;
  for (size_t k = 0; k < held.size(); ++k) worst = std::max(worst, std::fabs(held[k] - delivered[k]));
  const double wi = r.probe("w_incident").value.back();
  CheckResult e;
  e.id = "fe.shpb_energy_balance";
  e.description = "elastic FE specimen (6x12, rigid tube) between characteristic bars: delivered vs held energy";
  e.closed_form = "bar-delivered energy = specimen kinetic + material + contact work";
  e.unit = "-";
  e.relative = false;
  e.expected = 0;
  e.got = worst / wi;
  // Issue bound (0.5 %). The massless faces advance by Adams-Bashforth 2 (second order);
  // measured ~1e-6 of W_i (first-order Euler gave ~2e-4).
  e.tolerance = 5e-3;
  e.why_tolerance = "issue bound 0.5% of W_i; second-order face update";
  e.note = "W_i = " + std::to_string(wi) + " J; worst mismatch " + std::to_string(worst) + " J; " +
           (r.complete ? "complete" : "INCOMPLETE: " + r.failure);

  const auto setup = sim.analysis_setup();
  const auto w = r.face_waves(setup.incident.youngs_modulus, setup.transmission.youngs_modulus);
  const auto h = shpb::analyze(w, setup);
  const long i_eq = shpb::first_equilibrium_index(h.alpha, 0.05, 4);
  const long end = std::upper_bound(h.t.begin(), h.t.end(), 400e-6) - h.t.begin();
  const double nu = elastic.poisson_ratio;
  CheckResult d;
  d.id = "fe.confined_modulus";
  d.description = "elastic FE specimen in a rigid frictionless tube: classic-analysis slope once alpha < 0.05";
  d.closed_form = "D = E (1 - nu) / ((1 + nu)(1 - 2 nu)) (uniaxial strain)";
  d.unit = "MPa";
  d.expected = elastic.youngs_modulus * (1 - nu) / ((1 + nu) * (1 - 2 * nu)) / 1e6;
  d.got = i_eq >= 0 ? shpb::fitted_slope(h.strain, h.stress_back, i_eq, end) / 1e6 : std::nan("");
  // Same 2 % criterion as the 1-D column, plus the penalty contact's compliance at the faces
  // and wall (penalty_scale 4: ~1/4 of an element's strain), which softens the measured slope.
  d.tolerance = 0.03;
  d.why_tolerance = "2% (alpha < 0.05 criterion) + penalty contact compliance ~1%";
  return {finish(e), finish(d)};
}

}  // namespace kolsky::verify
