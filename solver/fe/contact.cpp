#include "fe/contact.hpp"

#include <algorithm>
#include <cmath>

namespace kolsky::fe {

namespace {

// Coulomb update of one stick spring; returns the new tangential force on the slave and adds
// the energy the spring took from the relative motion (trapezoid of -f_t d(slip)).
double coulomb(double f_old, double f_n, double k, double mu, double slip, double& work) {
  double f = f_old - k * slip;
  const double cap = mu * f_n;
  if (!(cap > 0.0)) f = 0.0;  // frictionless, or no contact: no shear at all
  else if (std::fabs(f) > cap) f = std::copysign(cap, f);
  work -= 0.5 * (f_old + f) * slip;
  return f;
}

// Coordinate of node i along axis a (0: r, 1: z) in the current configuration.
double coord(const Nodes& nd, std::size_t i, int a) { return a == 0 ? nd.r(i) : nd.z(i); }
double incr(const Nodes& nd, std::size_t i, int a) {
  return a == 0 ? nd.ur[i] - nd.ur_prev[i] : nd.uz[i] - nd.uz_prev[i];
}
double vel(const Nodes& nd, std::size_t i, int a) { return a == 0 ? nd.vr[i] : nd.vz[i]; }
double& ext(Nodes& nd, std::size_t i, int a) { return a == 0 ? nd.fr_ext[i] : nd.fz_ext[i]; }

// Segment j of the polyline with x_j <= x < x_{j+1} (x the coordinate along axis `along`),
// walking from the previous one. A slave just past an end (by less than half the end segment:
// a specimen face node pushed slightly beyond a tube of the specimen's own length, or radially
// beyond a meshed bar face) gets the end segment, its weight clamped onto the end node;
// farther out it is off the surface (-1).
int find_segment(const Nodes& nd, const std::vector<int>& master, double x, int guess, int along) {
  const int n_seg = static_cast<int>(master.size()) - 1;
  auto xm = [&](int j) { return coord(nd, static_cast<std::size_t>(master[static_cast<std::size_t>(j)]), along); };
  if (n_seg < 1) return -1;
  if (x < xm(0)) return xm(0) - x <= 0.5 * (xm(1) - xm(0)) ? 0 : -1;
  if (x >= xm(n_seg)) return x - xm(n_seg) <= 0.5 * (xm(n_seg) - xm(n_seg - 1)) ? n_seg - 1 : -1;
  int j = std::clamp(guess, 0, n_seg - 1);
  while (j > 0 && x < xm(j)) --j;
  while (j < n_seg - 1 && x >= xm(j + 1)) ++j;
  return j;
}

// Normal force of slave k for the signed gap g, its rate g_dot and the relative normal
// displacement increment dg since the last call; accumulates the normal work.
double normal(ContactSet& c, std::size_t k, double g, double g_dot, double dg) {
  // The damper may slow the separation but never pull (no adhesion).
  const double fn = g > 0.0 ? std::max(0.0, c.stiffness[k] * g + c.damping[k] * g_dot) : 0.0;
  c.normal_work += 0.5 * (c.normal_force[k] + fn) * dg;
  c.penetration[k] = std::max(g, 0.0);
  return fn;
}

}  // namespace

void ContactSet::reset_history() {
  const std::size_t n = node.size();
  normal_force.assign(n, 0.0);
  tangential_force.assign(n, 0.0);
  penetration.assign(n, 0.0);
  segment.assign(n, 0);
  if (damping.size() != n) damping.assign(n, 0.0);
  normal_work = 0.0;
  friction_work = 0.0;
}

double ContactSet::normal_energy() const {
  double e = 0.0;
  for (std::size_t i = 0; i < node.size(); ++i) e += 0.5 * stiffness[i] * penetration[i] * penetration[i];
  return e;
}

double ContactSet::max_penetration() const {
  double g = 0.0;
  for (double x : penetration) g = std::max(g, x);
  return g;
}

double ContactSet::total_normal() const {
  double f = 0.0;
  for (double x : normal_force) f += x;
  return f;
}

double ContactSet::total_shear() const {
  double f = 0.0;
  for (double x : tangential_force) f += std::fabs(x);
  return f;
}

double contact_plane(ContactSet& c, Nodes& nd, double z_plane, double v_plane, int side) {
  double total = 0.0;
  const double dz_plane = z_plane - c.surface_position;
  c.surface_position = z_plane;
  for (std::size_t k = 0; k < c.node.size(); ++k) {
    const auto i = static_cast<std::size_t>(c.node[k]);
    const double fn = normal(c, k, side * (z_plane - nd.z(i)), side * (v_plane - nd.vz[i]),
                             side * (dz_plane - (nd.uz[i] - nd.uz_prev[i])));
    // The plane does not move radially: the slip is the node's own radial increment.
    const double ft = coulomb(c.tangential_force[k], fn, c.stiffness[k], c.friction,
                              nd.ur[i] - nd.ur_prev[i], c.friction_work);
    c.normal_force[k] = fn;
    c.tangential_force[k] = ft;
    nd.fz_ext[i] += side * fn;
    nd.fr_ext[i] += ft;
    total += fn;
  }
  return total;
}

void contact_cylinder(ContactSet& c, Nodes& nd, double radius) {
  for (std::size_t k = 0; k < c.node.size(); ++k) {
    const auto i = static_cast<std::size_t>(c.node[k]);
    const double fn = normal(c, k, nd.r(i) - radius, nd.vr[i], nd.ur[i] - nd.ur_prev[i]);
    const double ft = coulomb(c.tangential_force[k], fn, c.stiffness[k], c.friction,
                              nd.uz[i] - nd.uz_prev[i], c.friction_work);
    c.normal_force[k] = fn;
    c.tangential_force[k] = ft;
    nd.fr_ext[i] -= fn;
    nd.fz_ext[i] += ft;
  }
}

void contact_polyline(ContactSet& c, Nodes& nd, const std::vector<int>& master, int normal_direction,
                      int side) {
  const int n = normal_direction, a_ax = 1 - normal_direction;  // normal and along axes
  for (std::size_t k = 0; k < c.node.size(); ++k) {
    const auto s = static_cast<std::size_t>(c.node[k]);
    const int j = find_segment(nd, master, coord(nd, s, a_ax), c.segment[k], a_ax);
    double fn = 0.0, ft = 0.0;
    if (j >= 0) {
      c.segment[k] = j;
      const auto a = static_cast<std::size_t>(master[static_cast<std::size_t>(j)]);
      const auto b = static_cast<std::size_t>(master[static_cast<std::size_t>(j) + 1]);
      const double xi = std::clamp((coord(nd, s, a_ax) - coord(nd, a, a_ax)) /
                                       (coord(nd, b, a_ax) - coord(nd, a, a_ax)),
                                   0.0, 1.0);
      auto on_master = [&](auto f) { return (1.0 - xi) * f(a) + xi * f(b); };
      // Penetration: the slave past the master surface on the master's side.
      const double g = side * (on_master([&](std::size_t i) { return coord(nd, i, n); }) - coord(nd, s, n));
      const double g_dot = side * (on_master([&](std::size_t i) { return vel(nd, i, n); }) - vel(nd, s, n));
      const double dg = side * (on_master([&](std::size_t i) { return incr(nd, i, n); }) - incr(nd, s, n));
      fn = normal(c, k, g, g_dot, dg);
      const double slip = incr(nd, s, a_ax) - on_master([&](std::size_t i) { return incr(nd, i, a_ax); });
      ft = coulomb(c.tangential_force[k], fn, c.stiffness[k], c.friction, slip, c.friction_work);
      ext(nd, s, n) += side * fn;
      ext(nd, s, a_ax) += ft;
      ext(nd, a, n) -= side * (1.0 - xi) * fn;
      ext(nd, b, n) -= side * xi * fn;
      ext(nd, a, a_ax) -= (1.0 - xi) * ft;
      ext(nd, b, a_ax) -= xi * ft;
    } else {
      // Off the end of the surface: no contact, the stick spring lets go.
      normal(c, k, 0.0, 0.0, 0.0);
      ft = coulomb(c.tangential_force[k], 0.0, c.stiffness[k], c.friction, 0.0, c.friction_work);
    }
    c.normal_force[k] = fn;
    c.tangential_force[k] = ft;
  }
}

void contact_springs(const ContactSet& c, const Nodes& nd, const std::vector<int>* master,
                     int normal_direction, bool abs_weights, std::vector<SpringStencil>& out) {
  const int tangential = 1 - normal_direction;
  for (std::size_t k = 0; k < c.node.size(); ++k) {
    const int s = c.node[k];
    SpringStencil sp;
    sp.k = c.stiffness[k];
    sp.dof[0] = 2 * s + normal_direction;
    sp.weight[0] = 1.0;
    if (master) {
      // The master polyline runs along the tangential axis.
      const double xs = coord(nd, static_cast<std::size_t>(s), tangential);
      const int j = find_segment(nd, *master, xs, c.segment[k], tangential);
      if (j < 0) continue;
      const int a = (*master)[static_cast<std::size_t>(j)], b = (*master)[static_cast<std::size_t>(j) + 1];
      const double za = coord(nd, static_cast<std::size_t>(a), tangential);
      const double zb = coord(nd, static_cast<std::size_t>(b), tangential);
      const double xi = std::clamp((xs - za) / (zb - za), 0.0, 1.0);
      sp.dof[1] = 2 * a + normal_direction;
      sp.dof[2] = 2 * b + normal_direction;
      sp.weight[1] = abs_weights ? 1.0 : -(1.0 - xi);
      sp.weight[2] = abs_weights ? 1.0 : -xi;
    }
    out.push_back(sp);
    if (c.friction > 0.0) {
      for (int d = 0; d < 3; ++d)
        if (sp.dof[static_cast<std::size_t>(d)] >= 0)
          sp.dof[static_cast<std::size_t>(d)] += tangential - normal_direction;
      out.push_back(sp);
    }
  }
}

}  // namespace kolsky::fe
