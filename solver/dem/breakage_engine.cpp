#include "dem/breakage_engine.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <variant>

#include "dem/apollonian.hpp"
#include "dem/dem_system.hpp"
#include "dem/hertz.hpp"

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

double strength_of(const BreakageParams& p, double diameter, std::uint64_t seed, std::uint64_t id) {
  return std::visit([&](const auto& c) { return grain_strength(c, diameter, seed, id); }, p.criterion);
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
    s.strength.push_back(strength_of(p, 2.0 * grains.radius[i], seed, i));
    s.generation.push_back(0);
  }
  s.sizes = curve_sizes(p, grains);
  s.initial_curve = current_curve(s.ledger, diameters(grains), s.sizes);
  return s;
}

namespace {

// What one pass over the contacts knows of each grain: its load ratio (the criterion's largest
// over its contacts), the orienting contact of its largest force and its contact counts.
struct GrainLoads {
  std::vector<double> ratio;
  std::vector<int> partner;  // -1: the largest force is a wall's (wall_axis), or no contact
  std::vector<Vec3> wall_axis;
  std::vector<int> grain_contacts, wall_contacts;
};

// One pass over the touching contacts with criterion C (breakage_criterion.hpp), resolved once
// per check rather than per contact. A grain's load ratio is the largest over its contacts;
// the largest contact force orients the daughter set. Forces are compared squared,
// F^2 = (16/9) E'^2 r' delta^3 for a pair (hertz.hpp's force, squared to spare the roots): this
// pass runs at every check, so it is kept to a few multiplications per touching contact.
template <class C>
GrainLoads scan_loads(const C& criterion, const DemSystem& sys, const BreakageState& s) {
  const Particles& p = sys.particles();
  const auto& mat = sys.materials();
  const std::size_t n = p.size(), n_mat = mat.size();
  std::vector<double> e_pair(n_mat * n_mat), c_pair(n_mat * n_mat), e_wall(n_mat);
  for (std::size_t a = 0; a < n_mat; ++a) {
    for (std::size_t b = 0; b < n_mat; ++b) {
      const double e = effective_modulus(mat[a].youngs_modulus, mat[a].poisson_ratio, mat[b].youngs_modulus,
                                         mat[b].poisson_ratio);
      e_pair[a * n_mat + b] = e;
      c_pair[a * n_mat + b] = pair_constant(criterion, e);
    }
    e_wall[a] = wall_modulus(criterion,
                             effective_modulus(mat[a].youngs_modulus, mat[a].poisson_ratio,
                                               std::numeric_limits<double>::infinity(), 0.0),
                             e_pair[a * n_mat + a]);
  }
  // The orienting contact of each grain: its partner (axis from the positions, computed only
  // for the grains that break) or, for a wall (partner -1), the wall's normal.
  GrainLoads out{std::vector<double>(n, 0.0), std::vector<int>(n, -1), std::vector<Vec3>(n), std::vector<int>(n, 0),
                 std::vector<int>(n, 0)};
  std::vector<double>& ratio = out.ratio;
  std::vector<int>&partner = out.partner, &grain_contacts = out.grain_contacts, &wall_contacts = out.wall_contacts;
  std::vector<Vec3>& wall_axis = out.wall_axis;
  std::vector<double> inv_r(n), grain_c(n), largest2(n, 0.0);
  for (std::size_t i = 0; i < n; ++i) {
    inv_r[i] = 1.0 / p.radius[i];
    grain_c[i] = grain_constant(criterion, s.strength[i], 2.0 * p.radius[i]);
  }
  sys.for_each_touching_contact(
      [&](int i, int j, const Vec3&, double dist) {
        const auto a = static_cast<std::size_t>(i), b = static_cast<std::size_t>(j);
        const std::size_t m = static_cast<std::size_t>(p.material[a]) * n_mat + static_cast<std::size_t>(p.material[b]);
        const double delta = p.radius[a] + p.radius[b] - dist;
        const double inv_r_eff = inv_r[a] + inv_r[b];
        ratio[a] = std::max(ratio[a], pair_ratio(criterion, delta, inv_r_eff, c_pair[m], grain_c[a]));
        ratio[b] = std::max(ratio[b], pair_ratio(criterion, delta, inv_r_eff, c_pair[m], grain_c[b]));
        // F^2 > largest2 without a division: (16/9) E'^2 delta^3 > largest2 / r'.
        const double k = 16.0 / 9.0 * e_pair[m] * e_pair[m] * delta * delta * delta;
        if (k > largest2[a] * inv_r_eff) largest2[a] = k / inv_r_eff, partner[a] = j;
        if (k > largest2[b] * inv_r_eff) largest2[b] = k / inv_r_eff, partner[b] = i;
        ++grain_contacts[a];
        ++grain_contacts[b];
      },
      [&](int i, int, const Vec3& normal, double, double force) {
        // A wall: r' = the grain's radius (a plane) and the wall law's elastic normal force (no
        // Hertz overlap relation for a linear wall spring; without the dashpot, as for grain
        // pairs: docs/breakage.md).
        const auto a = static_cast<std::size_t>(i);
        const double e = e_wall[static_cast<std::size_t>(p.material[a])];
        ratio[a] = std::max(ratio[a], wall_ratio(criterion, force, p.radius[a], e, s.strength[a]));
        if (force * force > largest2[a]) largest2[a] = force * force, partner[a] = -1, wall_axis[a] = normal;
        ++wall_contacts[a];
      });
  return out;
}

GrainLoads scan_loads(const DemSystem& sys, const BreakageState& s) {
  return std::visit([&](const auto& c) { return scan_loads(c, sys, s); }, s.params.criterion);
}

int coordination_of(const BreakageState& s, const GrainLoads& l, std::size_t g) {
  return counted_coordination(s.params, l.grain_contacts[g], l.wall_contacts[g]);
}

}  // namespace

std::vector<BreakEvent> find_breaks(const DemSystem& sys, const BreakageState& s) {
  const Particles& p = sys.particles();
  const GrainLoads l = scan_loads(sys, s);
  std::vector<BreakEvent> events;
  for (std::size_t g = 0; g < p.size(); ++g) {
    if (!grain_breaks(s.params, 2.0 * p.radius[g], s.d50_initial, coordination_of(s, l, g), l.ratio[g])) continue;
    Vec3 axis = l.wall_axis[g];
    if (l.partner[g] >= 0) {
      const Vec3 d = p.x[static_cast<std::size_t>(l.partner[g])] - p.x[g];
      axis = (1.0 / std::sqrt(dot(d, d))) * d;
    }
    events.push_back({static_cast<int>(g), axis});
  }
  return events;
}

HeldByCoordination held_by_coordination(const DemSystem& sys, const BreakageState& s) {
  HeldByCoordination held;
  if (s.params.coordination_limit == 0) return held;
  const Particles& p = sys.particles();
  const GrainLoads l = scan_loads(sys, s);
  for (std::size_t g = 0; g < p.size(); ++g) {
    if (s.generation[g] != 0 || l.ratio[g] < 1.0) continue;
    if (!above_comminution_limit(s.params, 2.0 * p.radius[g], s.d50_initial)) continue;
    const int coordination = coordination_of(s, l, g);
    if (coordination_allows_break(s.params, coordination)) continue;
    ++held.primary;
    if (coordination == s.params.coordination_limit) ++held.primary_at_limit;
  }
  return held;
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
      strengths.push_back(strength_of(s.params, 2.0 * daughters[k].radius, s.seed, id));
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
