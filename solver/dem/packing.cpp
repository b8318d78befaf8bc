// Packing generator: sample, place small (RSA), grow with damped frictionless contacts, settle
// (see packing.hpp).
#include "dem/packing.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <optional>
#include <string>
#include <vector>

#include "core/errors.hpp"
#include "core/rng.hpp"
#include "dem/contact_linear.hpp"
#include "dem/dem_system.hpp"
#include "dem/packing_internal.hpp"
#include "dem/packing_walls.hpp"
#include "dem/prestress.hpp"
#include "dem/spatial_sort.hpp"
#include "psd/sampling.hpp"

namespace kolsky::dem {

namespace {

constexpr double kPi = std::numbers::pi;


void check(bool ok, const std::string& field, const std::string& rule) {
  if (!ok) throw InputError("", "dem.packing." + field, rule);
}

void set_scale(Particles& q, const std::vector<double>& target, double scale, double rho,
               double quench, double mass_floor = 0) {
  for (std::size_t i = 0; i < q.size(); ++i) {
    set_radius(q, i, scale * target[i], rho, mass_floor);
    q.v[i] = quench * q.v[i];
    q.omega[i] = quench * q.omega[i];
  }
}

// Random sequential addition of the grains d (sorted descending) at `scale` times their size,
// each entirely inside the cylinder of radius D/2 and the given length, then a spatial sort;
// `target` gets each particle's full radius, in particle order.
Particles place_rsa(const PackingParams& in, const std::vector<double>& d, double scale,
                    double length, std::vector<double>& target) {
  const double R = in.diameter / 2, L = length;
  const std::vector<Material> materials{in.material};
  Xoshiro256ss rng(in.seed ^ 0x5deece66dULL);
  Particles p;
  p.reserve(d.size());
  target.reserve(d.size());
  {
    CellGrid grid(scale * d.front(), R, L);
    for (std::size_t s = 0; s < d.size(); ++s) {
      const double r = scale * d[s] / 2;
      bool placed = false;
      for (int attempt = 0; attempt < in.max_rsa_attempts && !placed; ++attempt) {
        const double rho = (R - r) * std::sqrt(rng.uniform_open());
        const double phi = 2 * kPi * rng.uniform_open();
        const Vec3 c{rho * std::cos(phi), rho * std::sin(phi), r + (L - 2 * r) * rng.uniform_open()};
        const bool free = grid.visit(c, [&](int q) {
          const double dd = r + p.radius[q];
          return norm2(p.x[q] - c) >= dd * dd;
        });
        if (!free) continue;
        grid.insert(c, static_cast<int>(p.size()));
        p.add(c, r, 0, materials);
        target.push_back(d[s] / 2);
        placed = true;
      }
      // The scene has no initial_solid_fraction (dem_keys.cpp names this after the grains).
      check(placed, "initial_solid_fraction",
            "random sequential addition found no place for grain " + std::to_string(s + 1) +
                " of " + std::to_string(d.size()) + " (" + std::to_string(d[s]) +
                " m) after " + std::to_string(in.max_rsa_attempts) +
                " tries: the grains are too coarse for the cylinder; smaller grains, a larger "
                "specimen or another seed");
    }
  }
  // Spatial order for memory locality; the target radii follow the permutation.
  const std::size_t n = p.size();
  for (std::size_t i = 0; i < n; ++i) p.f[i] = {target[i], 0, 0};  // carry target through
  sort_spatially(p, scale * d.front());
  for (std::size_t i = 0; i < n; ++i) {
    target[i] = p.f[i].x;
    p.f[i] = {};
  }
  return p;
}

// Loose packing (jam = false): growth and settling with frictionless damped linear contacts.
void loose_stage(const PackingParams& in, Particles p, const std::vector<double>& target,
                 double s0, double mean_r, PackingResult& res) {
  const double R = in.diameter / 2, L = in.length;
  const std::vector<Material> materials{in.material};
  // Linear, not Hertz: a Hertz contact softens as the overlap vanishes, so the last overlaps
  // would relax ever more slowly. The stiffness only sets the time scale (the step follows it).
  const LinearSpring law = linear_spring(in.material.youngs_modulus * mean_r, 0.0, 0.0,
                                         in.damping_ratio, 0.0);
  DemSystem sys(std::move(p), materials, law, DemOptions{});
  add_packing_walls(sys, R, L, law);
  // The lightest grain only grows, so the step of the shrunk state stays stable throughout.
  const double dt = kDemStepFraction * sys.stable_dt();
  auto stage = [&](double scale) {
    set_scale(sys.mutable_particles(), target, scale, in.material.density, in.velocity_quench);
    for (int k = 0; k < in.steps_per_stage; ++k) sys.step(dt);
    res.steps += in.steps_per_stage;
    ++res.stages;
  };
  for (int g = 1; g <= in.growth_stages; ++g) {
    const double scale = s0 + (1 - s0) * static_cast<double>(g) / in.growth_stages;
    stage(scale);
    progress(in, {"growth", g, in.growth_stages, scale});
  }
  double overlap = max_packing_overlap(sys.particles(), in.diameter, L) / mean_r;
  for (int k = 0; k < in.max_settle_stages && overlap >= in.overlap_tolerance; ++k) {
    stage(1.0);
    overlap = max_packing_overlap(sys.particles(), in.diameter, L) / mean_r;
    progress(in, {"settle", k + 1, in.max_settle_stages, overlap});
  }
  res.settled = overlap < in.overlap_tolerance;
  res.kinetic_energy = sys.particles().kinetic_energy();
  sys.compute_forces();
  res.mean_stress = wall_mean_stress(sys, R, L);
  res.particles = sys.particles();
}

// Jammed packing (jam = true): growth with frictional linear contacts whose stiffness is the
// Hertz secant stiffness at the design overlap, then quenched settling at full size with the
// friction kept, so the grains come to rest in a frictional contact network at the target
// porosity (docs/dem.md, "Packing").
void jam_stage(const PackingParams& in, Particles p, const std::vector<double>& target,
               double s0, double mean_r, PackingResult& res) {
  const double R = in.diameter / 2, L = in.length;
  const std::vector<Material> materials{in.material};
  const double n = static_cast<double>(target.size());
  const double mass_floor = jam_mass_floor(in, target);
  for (std::size_t i = 0; i < p.size(); ++i)
    set_radius(p, i, p.radius[i], in.material.density, mass_floor * s0 * s0 * s0);
  std::optional<DemSystem> sys;
  sys.emplace(std::move(p), materials, jam_law(in, mean_r, in.jam_friction), packing_options(in));
  // Frictionless walls, so the wall zone is not held looser than the core by wall friction.
  add_packing_walls(*sys, R, L, jam_law(in, mean_r, 0.0));
  const double dt = kDemStepFraction * sys->stable_dt();
  const int sps = in.jam_steps_per_stage;
  auto stage = [&](double scale, double quench) {
    set_scale(sys->mutable_particles(), target, scale, in.material.density, quench,
              mass_floor * scale * scale * scale);
    for (int j = 0; j < sps; ++j) sys->step(dt);
    res.steps += sps;
    ++res.stages;
  };
  // The stage's diagnostics for the progress hook (computed only when one is set).
  auto report = [&](const char* phase, int done, int most, double value) {
    if (!in.on_progress) return;
    PackingProgress q{phase, done, most, value};
    const DemEnergy e = sys->energy();
    q.wall_stress = wall_mean_stress(*sys, R, L);
    q.coordination = 2.0 * static_cast<double>(sys->n_contacts()) / n;
    q.kinetic_to_elastic = e.kinetic / std::max(e.elastic, 1e-300);
    progress(in, q);
  };
  // Growth with friction: the grains lock into a frictional network as they touch.
  for (int g = 1; g <= in.growth_stages; ++g) {
    const double scale = s0 + (1 - s0) * static_cast<double>(g) / in.growth_stages;
    stage(scale, in.jam_velocity_quench);
    report("growth", g, in.growth_stages, scale);
  }
  // Settling at full size with quenched dynamics (v = omega = 0 at every stage, friction and
  // contact histories kept): the over-compressed frictional network relaxes by sliding and
  // rolling (its stress decays roughly geometrically) until the largest overlap is below
  // overlap_tolerance x mean radius.
  double overlap = max_packing_overlap(sys->particles(), in.diameter, L) / mean_r;
  for (int k = 0; k < in.max_settle_stages && overlap >= in.overlap_tolerance; ++k) {
    stage(1.0, 0.0);
    overlap = max_packing_overlap(sys->particles(), in.diameter, L) / mean_r;
    report("settle", k + 1, in.max_settle_stages, overlap);
  }
  res.packing_friction = in.jam_friction;
  res.kinetic_energy = sys->particles().kinetic_energy();
  sys->compute_forces();
  res.mean_stress = wall_mean_stress(*sys, R, L);
  res.particles = sys->particles();
  for (std::size_t i = 0; i < res.particles.size(); ++i)  // the grains' own masses again
    set_radius(res.particles, i, res.particles.radius[i], in.material.density);
  res.settled = overlap < in.overlap_tolerance;
}

}  // namespace

void prestress_result(PackingResult& res, const PackingParams& in) {
  const PrestressOutcome o = prestress_packing(res.particles, in);
  res.prestress_scale = o.scale;
  res.prestress_stages = o.stages;
  res.prestress_converged = o.converged;
  res.mean_stress = o.mean_stress;
  res.steps += o.steps;
  res.stages += o.stages;
  take_census(res, in);
}

PackingResult generate_packing(const PackingParams& in) {
  in.curve.validate();
  check(in.porosity > 0 && in.porosity < 1, "porosity", "must be in (0, 1)");
  check(in.diameter > 0 && std::isfinite(in.diameter), "diameter", "must be finite and > 0");
  check(in.length > 0 && std::isfinite(in.length), "length", "must be finite and > 0");
  check(in.initial_solid_fraction > 0 && in.initial_solid_fraction < 1 - in.porosity,
        "initial_solid_fraction", "must be in (0, 1 - porosity)");
  check(in.growth_stages >= 1, "growth_stages", "must be >= 1");
  check(in.steps_per_stage >= 1, "steps_per_stage", "must be >= 1");
  check(in.velocity_quench >= 0 && in.velocity_quench <= 1, "velocity_quench",
        "must be in [0, 1]");
  check(in.damping_ratio >= 0 && in.damping_ratio < 1, "damping_ratio", "must be in [0, 1)");
  check(in.overlap_tolerance > 0, "overlap_tolerance", "must be > 0");
  check(in.max_settle_stages >= 0, "max_settle_stages", "must be >= 0");
  check(in.material_index >= 0, "material_index", "must be >= 0");
  check(in.jam_friction >= 0, "jam_friction", "must be >= 0");
  check(in.jam_overlap > 0 && in.jam_overlap < 0.1, "jam_overlap", "must be in (0, 0.1)");
  check(in.jam_steps_per_stage >= 1, "jam_steps_per_stage", "must be >= 1");
  check(in.jam_velocity_quench >= 0 && in.jam_velocity_quench <= 1, "jam_velocity_quench",
        "must be in [0, 1]");
  // Spheres pack no denser than ~0.64 at random (0.74 ordered); walls closing on a denser
  // target would press the grains into one another instead of packing them.
  check(!in.servo_walls || 1 - in.porosity <= 0.64, "porosity",
        "servo-wall compaction cannot reach a solid fraction above random close packing (0.64): "
        "porosity must be >= 0.36");
  check(in.initial_stress >= 0 && std::isfinite(in.initial_stress), "initial_stress",
        "must be finite and >= 0");
  check(in.prestress_friction >= 0, "prestress_friction", "must be >= 0");
  check(in.prestress_restitution > 0 && in.prestress_restitution <= 1, "prestress_restitution",
        "must be in (0, 1]");
  check(in.prestress_tolerance > 0 && in.prestress_tolerance < 1, "prestress_tolerance",
        "must be in (0, 1)");
  check(in.prestress_servo_interval >= 1, "prestress_servo_interval", "must be >= 1");
  check(in.prestress_max_steps >= 1, "prestress_max_steps", "must be >= 1");
  check(in.prestress_wall_normal_stiffness >= 0, "prestress_wall_normal_stiffness", "must be >= 0");
  check(in.prestress_wall_shear_stiffness >= 0, "prestress_wall_shear_stiffness", "must be >= 0");
  const std::vector<Material> materials{in.material};
  validate(materials);
  if (in.initial_stress > 0) {  // the unstressed packing, then the pre-stress
    PackingParams base = in;
    base.initial_stress = 0;
    PackingResult res = generate_packing(base);
    prestress_result(res, in);
    return res;
  }

  const double L = in.length;
  const double volume = psd::cylinder_volume(in.diameter, L);
  const std::vector<double> d = psd::sample_diameters(in.curve, volume * (1 - in.porosity),
                                                      in.seed);
  check(!d.empty(), "diameter", "the cylinder's solid volume holds no grain of the curve");  // d.front()
  check(2 * d.front() < std::min(in.diameter, L), "curve",
        "largest grain does not fit twice across the cylinder");

  PackingResult res;
  res.target_porosity = in.porosity;
  res.expected_count = psd::expected_particle_count(in.curve, volume, in.porosity);
  res.curve_deviation = psd::max_passing_deviation(in.curve, d);
  res.curve_deviation_bound = psd::max_passing_deviation_bound(in.curve, volume * (1 - in.porosity));

  // 2. RSA, largest first: the spheres shrunk by s0 in the cylinder (growth), or at full size
  // in a cylinder long enough for the same initial solid fraction (servo-wall compaction).
  const double s0 = in.servo_walls ? 1.0 : std::cbrt(in.initial_solid_fraction / (1 - in.porosity));
  const double place_length = in.servo_walls ? servo_initial_length(in) : L;
  std::vector<double> target;  // full radius, in particle order
  Particles p = place_rsa(in, d, s0, place_length, target);

  double mean_r = 0;
  for (double r : target) mean_r += r;
  mean_r /= static_cast<double>(target.size());
  if (in.servo_walls) {
    servo_wall_stage(in, std::move(p), target, mean_r, res);
  } else if (in.jam) {
    jam_stage(in, std::move(p), target, s0, mean_r, res);
  } else {
    loose_stage(in, std::move(p), target, s0, mean_r, res);
  }
  take_census(res, in);
  return res;
}

}  // namespace kolsky::dem
