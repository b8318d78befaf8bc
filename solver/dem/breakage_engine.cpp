#include "dem/breakage_engine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <numeric>

#include "dem/apollonian.hpp"
#include "dem/dem_contacts.hpp"

namespace kolsky::dem {

namespace {

constexpr int kCurvePoints = 64;            // log-spaced rows of the tracked curves

std::vector<double> diameters(const Particles& p) {
  std::vector<double> d(p.size());
  for (std::size_t i = 0; i < p.size(); ++i) d[i] = 2.0 * p.radius[i];
  return d;
}

// Rows from d_min of the fines to the largest grain, log-spaced, with the Hardin threshold.
std::vector<double> curve_sizes(const BreakageParams& p, const Particles& grains) {
  const double lo = p.fines_d_min;
  const double hi = 2.0 * *std::max_element(grains.radius.begin(), grains.radius.end());
  std::vector<double> s;
  for (int k = 0; k < kCurvePoints; ++k)
    s.push_back(lo * std::pow(hi / lo, static_cast<double>(k) / (kCurvePoints - 1)));
  s.back() = hi;
  if (p.hardin_threshold > lo && p.hardin_threshold < hi) s.push_back(p.hardin_threshold);
  std::sort(s.begin(), s.end());
  s.erase(std::unique(s.begin(), s.end()), s.end());
  return s;
}

template <class T>
std::vector<T> realigned(const std::vector<T>& old, const EditMap& m, std::size_t n_new,
                         const std::vector<T>& added) {
  std::vector<T> out(n_new);
  for (std::size_t i = 0; i < old.size(); ++i)
    if (m.old_to_new[i] >= 0) out[static_cast<std::size_t>(m.old_to_new[i])] = old[i];
  for (std::size_t k = 0; k < added.size(); ++k) out[static_cast<std::size_t>(m.added_at[k])] = added[k];
  return out;
}

double kinetic(const Particles& p, std::size_t i) {
  return 0.5 * p.mass[i] * dot(p.v[i], p.v[i]) + 0.5 * p.inertia[i] * dot(p.omega[i], p.omega[i]);
}

}  // namespace

double mass_d50(const Particles& p) {
  std::vector<std::size_t> order(p.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::sort(order.begin(), order.end(), [&](std::size_t a, std::size_t b) { return p.radius[a] < p.radius[b]; });
  double total = 0.0;
  for (double r : p.radius) total += r * r * r;
  double sum = 0.0;
  for (std::size_t i : order) {
    sum += p.radius[i] * p.radius[i] * p.radius[i];
    if (sum >= 0.5 * total) return 2.0 * p.radius[i];
  }
  return 0.0;
}

double smallest_radius_to_come(const BreakageParams& p, const Particles& grains) {
  return 0.5 * smallest_daughter_diameter(p, mass_d50(grains));
}

BreakageState start_breakage(const BreakageParams& p, std::uint64_t seed, const Particles& grains) {
  validate(p);
  BreakageState s;
  s.params = p;
  s.seed = seed;
  s.d50_initial = mass_d50(grains);
  validate_against_d50(p, s.d50_initial);
  for (std::size_t i = 0; i < grains.size(); ++i) {
    s.id.push_back(i);
    s.strength.push_back(strength_limit(p, 2.0 * grains.radius[i], strength_variability(p, seed, i)));
    s.generation.push_back(0);
  }
  s.sizes = curve_sizes(p, grains);
  s.initial_curve = current_curve(s.ledger, diameters(grains), s.sizes);
  return s;
}

std::vector<BreakEvent> find_breaks(const DemSystem& sys, const BreakageState& s) {
  // Eq. 5.13 in overlap form for a Hertz pair (critical_overlap): grain i's criterion holds when
  // delta >= r' (3 pi sigma_i / (4 E'))^2, i.e. ratio = delta (4 E' / (3 pi))^2 (1/r') / sigma_i^2
  // >= 1: no root, no power, 1/r' = 1/r_i + 1/r_j. The largest contact force orients the set;
  // forces are compared squared, F^2 = (16/9) E'^2 r' delta^3 for a pair. This pass runs at
  // every check, so it is kept to a few multiplications per touching contact.
  const Particles& p = sys.particles();
  const auto& mat = sys.materials();
  const std::size_t n = p.size(), n_mat = mat.size();
  std::vector<double> e_pair(n_mat * n_mat), c_pair(n_mat * n_mat), e_wall(n_mat);
  for (std::size_t a = 0; a < n_mat; ++a) {
    for (std::size_t b = 0; b < n_mat; ++b) {
      const double e = effective_modulus(mat[a].youngs_modulus, mat[a].poisson_ratio, mat[b].youngs_modulus,
                                         mat[b].poisson_ratio);
      e_pair[a * n_mat + b] = e;
      c_pair[a * n_mat + b] = std::pow(4.0 * e / (3.0 * std::numbers::pi), 2);
    }
    // wall_as_grain: the wall as a grain of the same material (E' of the alike pair).
    e_wall[a] = s.params.wall_as_grain ? e_pair[a * n_mat + a]
                                       : effective_modulus(mat[a].youngs_modulus, mat[a].poisson_ratio,
                                                           std::numeric_limits<double>::infinity(), 0.0);
  }
  std::vector<double> inv_r(n), inv_s2(n), ratio(n, 0.0), largest2(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    inv_r[i] = 1.0 / p.radius[i];
    inv_s2[i] = 1.0 / (s.strength[i] * s.strength[i]);
  }
  // The orienting contact of each grain: its partner (axis from the positions, computed only
  // for the grains that break) or, for a wall (partner -1), the wall's normal.
  std::vector<int> partner(n, -1);
  std::vector<Vec3> wall_axis(n);
  std::vector<int> grain_contacts(n, 0), wall_contacts(n, 0);
  sys.for_each_touching_contact(
      [&](int i, int j, const Vec3&, double dist) {
        const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>(j);
        const std::size_t m = static_cast<std::size_t>(p.material[a]) * n_mat + static_cast<std::size_t>(p.material[b]);
        const double delta = p.radius[a] + p.radius[b] - dist;
        const double inv_r_eff = inv_r[a] + inv_r[b];
        const double q = delta * c_pair[m] * inv_r_eff;
        ratio[a] = std::max(ratio[a], q * inv_s2[a]);
        ratio[b] = std::max(ratio[b], q * inv_s2[b]);
        // F^2 > largest2 without a division: (16/9) E'^2 delta^3 > largest2 / r'.
        const double k = 16.0 / 9.0 * e_pair[m] * e_pair[m] * delta * delta * delta;
        if (k > largest2[a] * inv_r_eff) largest2[a] = k / inv_r_eff, partner[a] = j;
        if (k > largest2[b] * inv_r_eff) largest2[b] = k / inv_r_eff, partner[b] = i;
        ++grain_contacts[a];
        ++grain_contacts[b];
      },
      [&](int i, int, const Vec3& normal, double, double force) {
        // A wall: r' = the grain's radius (a plane), E' of the grain against a rigid wall, and the
        // wall law's elastic normal force (no Hertz overlap relation for a linear wall spring;
        // without the dashpot, as for grain pairs: docs/breakage.md).
        const auto a = static_cast<std::size_t>(i);
        const double f_crit = critical_force(s.strength[a], p.radius[a], e_wall[static_cast<std::size_t>(p.material[a])]);
        ratio[a] = std::max(ratio[a], force / f_crit);
        if (force * force > largest2[a]) largest2[a] = force * force, partner[a] = -1, wall_axis[a] = normal;
        ++wall_contacts[a];
      });
  std::vector<BreakEvent> events;
  for (std::size_t g = 0; g < n; ++g) {
    if (!(ratio[g] >= 1.0)) continue;
    const int coordination = counted_coordination(s.params, grain_contacts[g], wall_contacts[g]);
    if (!may_break(s.params, 2.0 * p.radius[g], s.d50_initial, coordination)) continue;
    Vec3 axis = wall_axis[g];
    if (partner[g] >= 0) {
      const Vec3 d = p.x[static_cast<std::size_t>(partner[g])] - p.x[g];
      axis = (1.0 / std::sqrt(dot(d, d))) * d;
    }
    events.push_back({static_cast<int>(g), axis});
  }
  return events;
}

std::size_t apply_breaks(DemSystem& sys, BreakageState& s, const std::vector<BreakEvent>& events) {
  if (events.empty()) return 0;
  const Particles& p = sys.particles();
  ParticleEdit edit;
  std::vector<std::uint64_t> ids;
  std::vector<double> strengths;
  std::vector<unsigned char> generations;
  double kinetic_parents = 0.0;
  for (const BreakEvent& e : events) {
    const auto g = static_cast<std::size_t>(e.grain);
    edit.removed.push_back(e.grain);
    kinetic_parents += kinetic(p, g);
    const auto daughters =
        place_daughters(p.x[g], p.radius[g], e.axis, replacement_spin_angle(s.seed, s.id[g]));
    for (unsigned k = 0; k < daughters.size(); ++k) {
      edit.added.add(daughters[k].centre, daughters[k].radius, p.material[g], sys.materials(),
                     daughter_velocity(p.v[g]), p.omega[g]);
      const std::uint64_t id = daughter_id(s.id[g], k);
      ids.push_back(id);
      strengths.push_back(strength_limit(s.params, 2.0 * daughters[k].radius, strength_variability(s.params, s.seed, id)));
      generations.push_back(static_cast<unsigned char>(std::min(254, s.generation[g] + 1)));
    }
    record_break(s.ledger, s.params, p.radius[g], s.generation[g]);
  }
  double kinetic_daughters = 0.0;
  for (std::size_t k = 0; k < edit.added.size(); ++k) kinetic_daughters += kinetic(edit.added, k);
  const double edited_before = sys.energy().edited;
  const EditMap map = sys.edit(edit);
  const std::size_t n_new = sys.particles().size();
  s.id = realigned(s.id, map, n_new, ids);
  s.strength = realigned(s.strength, map, n_new, strengths);
  s.generation = realigned(s.generation, map, n_new, generations);
  const double moved = sys.energy().edited - edited_before;
  s.kinetic_removed += kinetic_parents - kinetic_daughters;
  s.insertion_energy += moved - (kinetic_parents - kinetic_daughters);
  return events.size();
}

psd::GrainSizeCurve current_grain_size_curve(const BreakageState& s, const Particles& grains) {
  return current_curve(s.ledger, diameters(grains), s.sizes);
}

double relative_breakage(const BreakageState& s, const Particles& grains) {
  return hardin_br(s.initial_curve, current_grain_size_curve(s, grains), s.params.hardin_threshold);
}

}  // namespace kolsky::dem
