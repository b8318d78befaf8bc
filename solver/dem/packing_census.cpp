// Census of a finished packing (packing.hpp, packing_internal.hpp): overlaps, contact counts,
// rattlers, the Hertz contact-virial stress and the porosity.
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <utility>
#include <vector>

#include "core/rng.hpp"
#include "dem/hertz.hpp"
#include "dem/packing_internal.hpp"
#include "psd/sampling.hpp"

namespace kolsky::dem {

double max_packing_overlap(const Particles& p, double diameter, double length) {
  const double R = diameter / 2;
  double r_max = 0;
  for (double r : p.radius) r_max = std::max(r_max, r);
  double worst = 0;
  if (p.size() == 0) return 0;
  CellGrid grid(2 * r_max, R, length);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& c = p.x[i];
    const double r = p.radius[i];
    worst = std::max({worst, r - c.z, c.z + r - length, std::hypot(c.x, c.y) + r - R});
    grid.visit(c, [&](int q) {
      const double d = r + p.radius[q];
      const double dist2 = norm2(p.x[q] - c);
      if (dist2 < d * d) worst = std::max(worst, d - std::sqrt(dist2));
      return true;
    });
    grid.insert(c, static_cast<int>(i));
  }
  return worst;
}

double interior_porosity(const Particles& p, double diameter, double length, double margin, long samples,
                         std::uint64_t seed) {
  const double R = diameter / 2 - margin, z0 = margin, z1 = length - margin;
  if (!(R > 0 && z1 > z0)) throw std::invalid_argument("interior_porosity: the margin leaves no interior");
  if (samples < 1) throw std::invalid_argument("interior_porosity: samples must be >= 1");
  double r_max = 0;
  for (double r : p.radius) r_max = std::max(r_max, r);
  if (p.size() == 0) return 1.0;
  // Cells of one largest diameter: a point inside grain q lies in q's cell or a neighbour.
  CellGrid grid(2 * r_max, diameter / 2, length);
  for (std::size_t i = 0; i < p.size(); ++i) grid.insert(p.x[i], static_cast<int>(i));
  Xoshiro256ss rng(seed);
  long solid = 0;
  for (long k = 0; k < samples; ++k) {
    Vec3 s;  // uniform in the interior disc x [z0, z1]: rejection from its square
    do {
      s.x = R * (2 * rng.uniform_open() - 1);
      s.y = R * (2 * rng.uniform_open() - 1);
    } while (s.x * s.x + s.y * s.y > R * R);
    s.z = z0 + (z1 - z0) * rng.uniform_open();
    const bool inside = !grid.visit(s, [&](int q) { return norm2(p.x[q] - s) > p.radius[q] * p.radius[q]; });
    solid += inside ? 1 : 0;
  }
  return 1.0 - static_cast<double>(solid) / static_cast<double>(samples);
}

namespace {

// Contact census of a packing: per-grain contact counts (pairs and walls), the largest
// overlap, and the trace of the contact virial sum_c f_c l_c with a normal force law
// f(delta, r_i, r_j) for grain pairs (l = centre distance) and g(delta, r) for the walls
// (l = r - delta, centre to contact point). Brute force on a cell grid, in index order.
struct Census {
  std::vector<int> contacts;  // per grain: touching grains + touching walls
  std::size_t pairs = 0, walls = 0;
  double virial = 0;          // sum f l, N m
};

template <class PairForce, class WallForce>
Census contact_census(const Particles& p, double diameter, double length, PairForce&& fp,
                      WallForce&& fw) {
  Census c;
  c.contacts.assign(p.size(), 0);
  if (p.size() == 0) return c;
  const double R = diameter / 2;
  double r_max = 0;
  for (double r : p.radius) r_max = std::max(r_max, r);
  CellGrid grid(2 * r_max, R, length);
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& x = p.x[i];
    const double r = p.radius[i];
    const double gaps[3] = {x.z - r, length - x.z - r, R - std::hypot(x.x, x.y) - r};
    for (double g : gaps)
      if (g < 0) {
        ++c.contacts[i];
        ++c.walls;
        c.virial += fw(-g, r) * (r + g);
      }
    grid.visit(x, [&](int q) {
      const double dd = r + p.radius[q];
      const double dist2 = norm2(p.x[q] - x);
      if (dist2 < dd * dd) {
        const double dist = std::sqrt(dist2);
        ++c.contacts[i];
        ++c.contacts[q];
        ++c.pairs;
        c.virial += fp(dd - dist, r, p.radius[q]) * dist;
      }
      return true;
    });
    grid.insert(x, static_cast<int>(i));
  }
  return c;
}

// Grains with fewer than two contacts carry no load; removing them can strand others, so the
// removal is repeated until none is left. Returns (coordination of the rest counting walls,
// fraction removed).
std::pair<double, double> without_rattlers(const Particles& p, double diameter, double length) {
  const std::size_t n = p.size();
  const double R = diameter / 2;
  // Contact lists (pairs only; wall contacts as a count).
  std::vector<std::vector<int>> nb(n);
  std::vector<int> walls(n, 0);
  double r_max = 0;
  for (double r : p.radius) r_max = std::max(r_max, r);
  CellGrid grid(2 * r_max, R, length);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3& x = p.x[i];
    const double r = p.radius[i];
    walls[i] = (x.z < r) + (length - x.z < r) + (R - std::hypot(x.x, x.y) < r);
    grid.visit(x, [&](int q) {
      const double dd = r + p.radius[q];
      if (norm2(p.x[q] - x) < dd * dd) {
        nb[i].push_back(q);
        nb[static_cast<std::size_t>(q)].push_back(static_cast<int>(i));
      }
      return true;
    });
    grid.insert(x, static_cast<int>(i));
  }
  std::vector<int> count(n);
  std::vector<char> gone(n, 0);
  for (std::size_t i = 0; i < n; ++i) count[i] = static_cast<int>(nb[i].size()) + walls[i];
  std::vector<int> stack;
  for (std::size_t i = 0; i < n; ++i)
    if (count[i] < 2) stack.push_back(static_cast<int>(i)), gone[i] = 1;
  while (!stack.empty()) {
    const int i = stack.back();
    stack.pop_back();
    for (int q : nb[static_cast<std::size_t>(i)])
      if (!gone[static_cast<std::size_t>(q)] && --count[static_cast<std::size_t>(q)] < 2) {
        gone[static_cast<std::size_t>(q)] = 1;
        stack.push_back(q);
      }
  }
  double sum = 0, kept = 0;
  for (std::size_t i = 0; i < n; ++i)
    if (!gone[i]) sum += count[i], kept += 1;
  return {kept > 0 ? sum / kept : 0.0, n > 0 ? 1.0 - kept / static_cast<double>(n) : 0.0};
}

}  // namespace

std::pair<double, double> coordination_without_rattlers(const Particles& p, double diameter,
                                                        double length) {
  return without_rattlers(p, diameter, length);
}

double fabric_anisotropy(const Particles& p, double diameter, double length) {
  double r_max = 0;
  for (double r : p.radius) r_max = std::max(r_max, r);
  if (p.size() == 0) return 0;
  CellGrid grid(2 * r_max, diameter / 2, length);
  double sum_nz2 = 0;
  std::size_t contacts = 0;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const Vec3& x = p.x[i];
    grid.visit(x, [&](int q) {
      const double dd = p.radius[i] + p.radius[q];
      const Vec3 d = p.x[q] - x;
      const double dist2 = norm2(d);
      if (dist2 < dd * dd && dist2 > 0) {
        sum_nz2 += d.z * d.z / dist2;
        ++contacts;
      }
      return true;
    });
    grid.insert(x, static_cast<int>(i));
  }
  if (contacts == 0) return 0;
  const double phi_zz = sum_nz2 / static_cast<double>(contacts);
  return 0.5 * (3 * phi_zz - 1);  // phi_zz - (phi_xx + phi_yy) / 2, the trace being 1
}

// Census of the final state: coordination (with and without walls and rattlers), largest
// overlap, and the contact-virial mean stress the grains would carry with Hertz contacts
// (rigid Hertz walls), the law of the SHPB runs (Sec. 4.3); then the grains are put at rest
// and the porosity is taken from the final radii.
void take_census(PackingResult& res, const PackingParams& in) {
  const double L = in.length;
  const double volume = psd::cylinder_volume(in.diameter, L);
  double mean_r = 0;
  for (double r : res.particles.radius) mean_r += r;
  mean_r /= static_cast<double>(res.particles.size());
  {
    const Particles& q = res.particles;
    const double E = in.material.youngs_modulus, nu = in.material.poisson_ratio;
    const double e_pair = E / (2 * (1 - nu * nu)), e_wall = E / (1 - nu * nu);
    const Census c = contact_census(
        q, in.diameter, L,
        [&](double delta, double ri, double rj) {
          return hertz_normal_force(e_pair, ri * rj / (ri + rj), delta);
        },
        [&](double delta, double r) {
          return hertz_normal_force(e_wall, r, delta);
        });
    const double nn = static_cast<double>(q.size());
    res.coordination = 2.0 * static_cast<double>(c.pairs) / nn;
    res.coordination_with_walls = (2.0 * static_cast<double>(c.pairs) + static_cast<double>(c.walls)) / nn;
    res.mean_stress_hertz = c.virial / (3 * volume);
    const auto [z, frac] = without_rattlers(q, in.diameter, L);
    res.coordination_no_rattlers = z;
    res.rattler_fraction = frac;
    res.max_overlap = max_packing_overlap(q, in.diameter, L) / mean_r;
  }
  Particles& out = res.particles;
  double solid = 0;
  for (std::size_t i = 0; i < out.size(); ++i) {
    out.v[i] = {};
    out.omega[i] = {};
    out.f[i] = {};
    out.torque[i] = {};
    out.material[i] = in.material_index;
    solid += 4.0 / 3.0 * std::numbers::pi * std::pow(out.radius[i], 3);
  }
  res.count = out.size();
  res.porosity = 1 - solid / volume;
}

}  // namespace kolsky::dem
