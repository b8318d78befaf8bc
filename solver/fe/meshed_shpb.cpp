#include "fe/meshed_shpb.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <string>

#include "core/stability_check.hpp"
#include "core/errors.hpp"
#include "fe/stability.hpp"

namespace kolsky::fe {

void check_meshed_bar(const MeshedBar& b, const std::string& side) {
  auto throw_unless = [](bool ok, const std::string& path, const char* rule) {
    if (!ok) throw InputError("", path, rule);
  };
  throw_unless(b.length > 0.0, "bars." + side + ".length", "must be > 0");
  throw_unless(b.radius > 0.0, "bars." + side + ".diameter", "must be > 0");
  b.material.validate(("bars." + side).c_str());
  for (double d : b.gauges)
    throw_unless(d > 0.0 && d < b.length, "bars." + side + ".gauges", "each gauge must lie strictly inside (0, length)");
}

int axial_element_count(double length, double h) { return std::max(2, static_cast<int>(std::lround(length / h))); }

namespace {

void require(bool ok, const std::string& path, const std::string& rule) {
  if (!ok) throw InputError("", path, rule);
}


// Validates p and builds specimen (+ tube), incident bar and transmission bar, in that order.
Body build(const MeshedShpbParams& p, Block& specimen, std::optional<Block>& tube, Block& incident,
           Block& transmission) {
  const FeSpecimenParams& sp = p.specimen;
  check_meshed_bar(p.incident, "incident");
  check_meshed_bar(p.transmission, "transmission");
  require(p.bar_n_r >= 1, "bars.mesh_radial", "must be >= 1");
  require(p.bar_element_length > 0.0, "bars.element_length", "must be > 0");
  require(static_cast<bool>(p.applied_stress), "pulse", "meshed bars need an applied stress history");
  Mesh mesh;
  std::vector<Part> parts;
  add_specimen_blocks(sp, mesh, parts, specimen, tube);
  incident = add_block(mesh, 0.0, p.incident.radius, -p.incident.length, 0.0, p.bar_n_r,
                       axial_element_count(p.incident.length, p.bar_element_length));
  parts.push_back(Part{p.incident.material, incident.first_element, incident.n_elements()});
  transmission = add_block(mesh, 0.0, p.transmission.radius, sp.length, sp.length + p.transmission.length,
                           p.bar_n_r, axial_element_count(p.transmission.length, p.bar_element_length));
  parts.push_back(Part{p.transmission.material, transmission.first_element, transmission.n_elements()});
  return Body(std::move(mesh), std::move(parts), sp.threads);
}

}  // namespace

MeshedShpb::MeshedShpb(const MeshedShpbParams& p)
    : p_(p), body_(build(p, specimen_, tube_block_, incident_, transmission_)) {
  const FeSpecimenParams& sp = p.specimen;
  const Nodes& nd = body_.nodes();

  // Specimen end rows against the bar faces: FeSpecimen's plane penalty, node for node.
  const double modulus = max_constrained_modulus(sp.material);
  face_contact_sets(sp, specimen_, nd, modulus, front_, back_);
  for (int i = 0; i <= p.bar_n_r; ++i) {
    incident_face_.push_back(incident_.node(i, incident_.n_z));
    transmission_face_.push_back(transmission_.node(i, 0));
  }
  tube_ = tube_contact_set(sp, specimen_, modulus);
  if (tube_block_)
    for (int j = 0; j <= tube_block_->n_z; ++j) tube_surface_.push_back(tube_block_->node(0, j));
  for (ContactSet* c : {&front_, &back_, &tube_}) set_contact_damping(*c, nd, sp.contact_damping);

  // Far-end traction and face means: ring areas of the incident bar's radial stations (both
  // bars have bar_n_r uniform radial elements, so the normalised weights of the face means are
  // the same for the transmission bar whatever its radius).
  std::vector<double> rb;
  for (int i = 0; i <= p.bar_n_r; ++i) rb.push_back(nd.r0[static_cast<std::size_t>(incident_.node(i, 0))]);
  bar_ring_area_ = ring_tributary_areas(rb);
  load_prev_.assign(bar_ring_area_.size(), 0.0);

  // Gauges: position in edge-midpoint coordinates of the outer node column.
  for (int b = 0; b < 2; ++b) {
    const Block& blk = bar_block(b);
    const MeshedBar& bar = b == 0 ? p.incident : p.transmission;
    for (double d : bar.gauges) {
      const double s = (b == 0 ? bar.length - d : d) / bar.length * blk.n_z - 0.5;
      const int j = std::clamp(static_cast<int>(std::floor(s)), 0, blk.n_z - 2);
      gauges_[b].push_back({j, std::clamp(s - j, 0.0, 1.0)});
    }
  }
}

double MeshedShpb::specimen_area() const {
  return std::numbers::pi * p_.specimen.radius * p_.specimen.radius;
}

std::vector<SpringStencil> MeshedShpb::springs() const {
  std::vector<SpringStencil> s;
  const Nodes& nd = body_.nodes();
  contact_springs(front_, nd, &incident_face_, 1, true, s);
  contact_springs(back_, nd, &transmission_face_, 1, true, s);
  contact_springs(tube_, nd, tube_block_ ? &tube_surface_ : nullptr, 0, true, s);
  return s;
}

double MeshedShpb::stable_dt() const {
  // Lagged-velocity dampers: see FeSpecimen::stable_dt.
  const double z = p_.specimen.contact_damping, f = std::sqrt(1.0 + z * z) - z;
  return compose_stable_dt(body_.stable_dt(), spring_eigen_bound(body_.nodes(), springs()) / (f * f));
}

void MeshedShpb::step(double t, double dt) {
  forces(t);
  advance(dt);
}

void MeshedShpb::forces(double t) {
  body_.update_internal_forces();
  Nodes& nd = body_.nodes();
  std::fill(nd.fr_ext.begin(), nd.fr_ext.end(), 0.0);
  std::fill(nd.fz_ext.begin(), nd.fz_ext.end(), 0.0);
  const double sigma = p_.applied_stress(t);
  for (std::size_t i = 0; i < bar_ring_area_.size(); ++i) {
    const auto n = static_cast<std::size_t>(incident_.node(static_cast<int>(i), 0));
    const double f = sigma * bar_ring_area_[i];  // pushes +z, into the bar
    applied_work_ += 0.5 * (load_prev_[i] + f) * (nd.uz[n] - nd.uz_prev[n]);
    load_prev_[i] = f;
    nd.fz_ext[n] += f;
  }
  contact_polyline(front_, nd, incident_face_, 1, +1);
  contact_polyline(back_, nd, transmission_face_, 1, -1);
  apply_tube_contact(p_.specimen.tube, tube_, nd, p_.specimen.radius, tube_surface_);
  faces_ = {front_.total_normal(), back_.total_normal()};
}

void MeshedShpb::advance(double dt) {
  if (p_.specimen.check_dt)
    check_time_step(dt, stable_dt(), "meshed bars", body_.time(), "element Courant bound with contact springs");
  body_.advance(dt, 0.0);
  ++n_steps_;
  if (!body_.finite()) throw NumericalError("meshed bars: non-finite state", body_.time());
  const MeshedEnergy e = energy_ledger();
  peak_energy_ = std::max({peak_energy_, std::fabs(e.held()), std::fabs(e.applied_work)});
  constexpr long kWarmupSteps = 16;  // as FeSpecimen::advance
  const double tolerance = p_.specimen.energy_tolerance;
  if (p_.specimen.check_energy && n_steps_ > kWarmupSteps)
    check_energy_growth({e.held(), e.applied_work, std::max(peak_energy_, energy_check_floor(p_.specimen) / tolerance)},
                        tolerance, "meshed bars", body_.time());
}

double MeshedShpb::face_mean(const Block& b, int j, bool velocity) const {
  const Nodes& nd = body_.nodes();
  double num = 0.0, den = 0.0;
  for (int i = 0; i <= b.n_r; ++i) {
    const auto n = static_cast<std::size_t>(b.node(i, j));
    num += bar_ring_area_[static_cast<std::size_t>(i)] * (velocity ? nd.vz[n] : nd.uz[n]);
    den += bar_ring_area_[static_cast<std::size_t>(i)];
  }
  return num / den;
}

double MeshedShpb::mean_strain() const {
  return (face_mean(incident_, incident_.n_z, false) - face_mean(transmission_, 0, false)) / p_.specimen.length;
}

double MeshedShpb::face_rate(int bar) const {
  return bar == 0 ? face_mean(incident_, incident_.n_z, true) : -face_mean(transmission_, 0, true);
}

double MeshedShpb::edge_strain(const Block& b, int j) const {
  const Nodes& nd = body_.nodes();
  const auto lo = static_cast<std::size_t>(b.node(b.n_r, j)), hi = static_cast<std::size_t>(b.node(b.n_r, j + 1));
  return (nd.uz[hi] - nd.uz[lo]) / (nd.z0[hi] - nd.z0[lo]);
}

double MeshedShpb::gauge_strain(int bar, std::size_t k) const {
  const Gauge& g = gauges_[bar].at(k);
  const Block& b = bar_block(bar);
  return (1.0 - g.weight) * edge_strain(b, g.edge) + g.weight * edge_strain(b, g.edge + 1);
}

MeshedEnergy MeshedShpb::energy_ledger() const {
  MeshedEnergy e;
  e.kinetic = body_.kinetic_energy();
  e.material_work = body_.material_work();
  for (const ContactSet* c : {&front_, &back_, &tube_}) e.contact_work += c->normal_work + c->friction_work;
  e.applied_work = applied_work_;
  return e;
}

}  // namespace kolsky::fe
