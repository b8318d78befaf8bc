#include "fe/meshed_bars_tube.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

#include "core/errors.hpp"

namespace kolsky::fe {

namespace {

void require(bool ok, const std::string& path, const std::string& rule) {
  if (!ok) throw InputError("", path, rule);
}


Body build(const MeshedBarsTubeParams& p, Block& incident, Block& transmission, std::optional<Block>& tube) {
  check_meshed_bar(p.incident, "incident");
  check_meshed_bar(p.transmission, "transmission");
  require(p.bar_n_r >= 1, "bars.mesh_radial", "must be >= 1");
  require(p.bar_element_length > 0.0, "bars.element_length", "must be > 0");
  require(p.specimen_length > 0.0, "specimen.length", "must be > 0");
  require(p.specimen_radius > 0.0, "specimen.diameter", "must be > 0");
  require(static_cast<bool>(p.applied_stress), "pulse", "meshed bars need an applied stress history");
  Mesh mesh;
  std::vector<Part> parts;
  incident = add_block(mesh, 0.0, p.incident.radius, -p.incident.length, 0.0, p.bar_n_r,
                       axial_element_count(p.incident.length, p.bar_element_length));
  parts.push_back(Part{p.incident.material, incident.first_element, incident.n_elements()});
  transmission = add_block(mesh, 0.0, p.transmission.radius, p.specimen_length,
                           p.specimen_length + p.transmission.length, p.bar_n_r,
                           axial_element_count(p.transmission.length, p.bar_element_length));
  parts.push_back(Part{p.transmission.material, transmission.first_element, transmission.n_elements()});
  if (p.tube) tube = add_tube_block(mesh, parts, *p.tube, p.specimen_length, p.specimen_radius);
  return Body(std::move(mesh), std::move(parts), p.threads);
}

}  // namespace

Block add_tube_block(Mesh& mesh, std::vector<Part>& parts, const MeshedTube& t, double specimen_length,
                     double specimen_radius) {
  require(t.thickness > 0.0, "specimen.tube_thickness", "must be > 0");
  require(t.length >= specimen_length, "specimen.tube_length", "must be >= the specimen length");
  require(t.n_r >= 1 && t.n_z >= 1, "specimen.tube", "the tube mesh needs n_r, n_z >= 1");
  t.material.validate("specimen.tube");
  const double zc = 0.5 * specimen_length;
  const Block tube = add_block(mesh, specimen_radius, specimen_radius + t.thickness, zc - 0.5 * t.length,
                               zc + 0.5 * t.length, t.n_r, t.n_z);
  parts.push_back(Part{t.material, tube.first_element, tube.n_elements()});
  return tube;
}

void tube_wall_surface(const Block& tube, double tube_length, double specimen_radius, std::vector<int>& nodes,
                       std::vector<double>& areas) {
  const double h = tube_length / tube.n_z;
  for (int j = 0; j <= tube.n_z; ++j) {
    nodes.push_back(tube.node(0, j));
    const double span = (j == 0 || j == tube.n_z) ? 0.5 * h : h;
    areas.push_back(2.0 * std::numbers::pi * specimen_radius * span);
  }
}

void add_surface_loads(Nodes& nd, const std::vector<int>& nodes, const std::vector<double>& f_r,
                       const std::vector<double>& f_z, std::vector<double>& prev_fr, std::vector<double>& prev_fz,
                       double& work) {
  if (f_r.size() != nodes.size() || f_z.size() != nodes.size())
    throw std::invalid_argument("add_surface_loads: one load per surface node");
  for (std::size_t a = 0; a < nodes.size(); ++a) {
    const auto n = static_cast<std::size_t>(nodes[a]);
    // Trapezoid over [t^{n-1}, t^n], as the far-end traction.
    work += 0.5 * (prev_fr[a] + f_r[a]) * (nd.ur[n] - nd.ur_prev[n]) +
            0.5 * (prev_fz[a] + f_z[a]) * (nd.uz[n] - nd.uz_prev[n]);
    prev_fr[a] = f_r[a];
    prev_fz[a] = f_z[a];
    nd.fr_ext[n] += f_r[a];
    nd.fz_ext[n] += f_z[a];
  }
}

MeshedBarsTube::MeshedBarsTube(const MeshedBarsTubeParams& p)
    : p_(p), body_(build(p, incident_, transmission_, tube_)) {
  const Nodes& nd = body_.nodes();
  for (int i = 0; i <= p.bar_n_r; ++i) {
    surfaces_[0].push_back(incident_.node(i, incident_.n_z));
    surfaces_[1].push_back(transmission_.node(i, 0));
  }
  for (int s = 0; s < 2; ++s) {
    std::vector<double> r;
    for (int n : surfaces_[s]) r.push_back(nd.r0[static_cast<std::size_t>(n)]);
    areas_[s] = ring_tributary_areas(r);
  }
  if (tube_) tube_wall_surface(*tube_, p.tube->length, p.specimen_radius, surfaces_[2], areas_[2]);
  for (int s = 0; s < 3; ++s) {
    prev_fr_[s].assign(surfaces_[s].size(), 0.0);
    prev_fz_[s].assign(surfaces_[s].size(), 0.0);
  }
  bar_ring_area_ = areas_[0];
  load_prev_.assign(bar_ring_area_.size(), 0.0);
  for (int b = 0; b < 2; ++b) {  // gauges in edge-midpoint coordinates of the outer node column
    const Block& blk = b == 0 ? incident_ : transmission_;
    const MeshedBar& bar = b == 0 ? p.incident : p.transmission;
    for (double d : bar.gauges) {
      const double s = (b == 0 ? bar.length - d : d) / bar.length * blk.n_z - 0.5;
      const int j = std::clamp(static_cast<int>(std::floor(s)), 0, blk.n_z - 2);
      gauges_[b].push_back({j, std::clamp(s - j, 0.0, 1.0)});
    }
  }
}

void MeshedBarsTube::begin_forces(double t) {
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
}

void MeshedBarsTube::add_surface_loads(Surface s, const std::vector<double>& f_r, const std::vector<double>& f_z) {
  const int k = static_cast<int>(s);
  fe::add_surface_loads(body_.nodes(), surfaces_[k], f_r, f_z, prev_fr_[k], prev_fz_[k], surface_work_);
}

void MeshedBarsTube::advance(double dt) { body_.advance(dt, 0.0); }

double MeshedBarsTube::face_mean(int bar, bool velocity) const {
  const Nodes& nd = body_.nodes();
  const std::vector<int>& face = surfaces_[bar == 0 ? 0 : 1];
  double num = 0.0, den = 0.0;
  for (std::size_t a = 0; a < face.size(); ++a) {
    const auto n = static_cast<std::size_t>(face[a]);
    num += bar_ring_area_[a] * (velocity ? nd.vz[n] : nd.uz[n]);
    den += bar_ring_area_[a];
  }
  return num / den;
}

double MeshedBarsTube::edge_strain(const Block& b, int j) const {
  const Nodes& nd = body_.nodes();
  const auto lo = static_cast<std::size_t>(b.node(b.n_r, j)), hi = static_cast<std::size_t>(b.node(b.n_r, j + 1));
  return (nd.uz[hi] - nd.uz[lo]) / (nd.z0[hi] - nd.z0[lo]);
}

double MeshedBarsTube::gauge_strain(int bar, std::size_t k) const {
  const Gauge& g = gauges_[bar].at(k);
  const Block& b = bar == 0 ? incident_ : transmission_;
  return (1.0 - g.weight) * edge_strain(b, g.edge) + g.weight * edge_strain(b, g.edge + 1);
}

}  // namespace kolsky::fe
