// Pre-stress of a packed specimen (see prestress.hpp).
#include "dem/prestress.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <vector>

#include "dem/contact_damping.hpp"
#include "dem/contact_hertz_mindlin.hpp"
#include "dem/contact_linear.hpp"
#include "dem/dem_system.hpp"
#include "dem/packing_internal.hpp"
#include "dem/packing_walls.hpp"

namespace kolsky::dem {

namespace {

// Radii s r0, masses and inertias to match.
void scale_grains(Particles& q, const std::vector<double>& r0, double s, double rho) {
  for (std::size_t i = 0; i < q.size(); ++i) {
    const double r = s * r0[i];
    q.radius[i] = r;
    q.mass[i] = sphere_mass(r, rho);
    q.inertia[i] = 0.4 * q.mass[i] * r * r;
  }
}

// First step of the servo: the radius increase that gives mean grains the Hertz overlap of the
// target stress, with the contact force from the virial p = sum(f l) / (3V) for Z = 4 and
// l = 2 r_mean, E* = E / (2(1 - nu^2)), R* = r_mean / 2; each grain grows by half the overlap.
double first_step(const PackingParams& in, const std::vector<double>& r0) {
  double r_mean = 0;
  for (double r : r0) r_mean += r;
  r_mean /= static_cast<double>(r0.size());
  const double volume = std::numbers::pi * 0.25 * in.diameter * in.diameter * in.length;
  const double contacts = 2.0 * static_cast<double>(r0.size());  // Z = 4
  const double f = 3 * in.initial_stress * volume / (contacts * 2 * r_mean);
  const double nu = in.material.poisson_ratio;
  const double e_star = in.material.youngs_modulus / (2 * (1 - nu * nu));
  const double delta = std::pow(f / (4.0 / 3.0 * e_star * std::sqrt(0.5 * r_mean)), 2.0 / 3.0);
  return 0.5 * delta / r_mean;
}

}  // namespace

PrestressOutcome prestress_packing(Particles& p, const PackingParams& in) {
  const double R = in.diameter / 2, L = in.length, target = in.initial_stress;
  const std::vector<Material> materials{in.material};
  const HertzMindlinParams grains{in.prestress_friction, in.prestress_restitution};
  std::vector<double> r0(p.radius);
  const std::vector<int> material_index = p.material;
  Particles q = p;
  std::fill(q.material.begin(), q.material.end(), 0);  // the one material of `materials`
  // Rotations locked (k = 0, Eqs. 4.12-4.14) unless asked otherwise: at n = 0.44 (solid
  // fraction 0.56) freely rotating spheres with mu = 0.5 are below their jamming fraction
  // (~0.58-0.59, Silbert 2010, Soft Matter 6:2918), so under any isotropic stress they roll
  // and compact: the servo then grows the radii without end (measured: s + 0.6 % at N = 6,
  // + 2.6 % at N = 2, stress stuck at 15-50 kPa). Without rotation the network is stable.
  DemOptions opt;
  opt.rolling.factor_per_reference_step = in.prestress_lock_rotation ? 0.0 : 1.0;
  DemSystem sys(std::move(q), materials, HertzMindlin(materials, grains), opt);
  // Frictionless walls, as while jamming (wall friction would hold the wall zone looser): the
  // test's linear springs when given, damped like the grains, so the wall layer is in
  // equilibrium with the walls it will meet in the test. Against rigid Hertz walls a grain sits
  // at another overlap, and the Table 4.1 springs (2.6e6 N/m) then pushed the wall layer with
  // 4-5x the target stress (test_dem_prestress; -0.28 MPa interface jump at the N = 2 release).
  if (in.prestress_wall_normal_stiffness > 0) {
    add_packing_walls(sys, R, L,
                      linear_spring(in.prestress_wall_normal_stiffness,
                                    in.prestress_wall_shear_stiffness, 0.0,
                                    damping_ratio_from_restitution(in.prestress_restitution), 0.0));
  } else {
    Material rigid = in.material;
    rigid.youngs_modulus = std::numeric_limits<double>::infinity();
    add_packing_walls(sys, R, L,
                      HertzMindlinWall(materials, rigid, {0.0, in.prestress_restitution}));
  }

  PrestressOutcome out;
  // Servo (as PFC's servo walls, on the radii): every `interval` steps the radius factor moves
  // by ds = gain (1 - p / p_target), p the wall mean stress averaged over the interval. The
  // gain is 3 % of the Hertz estimate of the whole target overlap (first_step): near the
  // target a Hertz network changes p by ~1.5 x 2 r ds / delta ~ 5 % per interval, slow enough
  // for the damped grains to follow (a jump in s makes the frictional network collapse and
  // creep, so stress then depends on the waiting time). Converged when the mean of the last
  // `window` intervals is within the tolerance and none of them is off by more than twice it.
  const int interval = in.prestress_servo_interval;
  const int window = 20;
  const double gain = 0.03 * first_step(in, r0);
  std::vector<double> history;
  double s = 1;
  sys.compute_forces();
  // The Rayleigh step scales with r, a wall spring's sqrt(m/k) with r^1.5: 0.98 of the step at
  // s = 1 stays stable down to s = 0.99 (0.99^1.5 = 0.985), and the servo keeps s within 1 %
  // of 1 (Hertz overlaps at kPa-MPa are ~1e-4 r).
  const double dt = 0.98 * (kDemStepFraction * sys.stable_dt());
  while (!out.converged && out.steps < in.prestress_max_steps) {
    double sum = 0;
    for (int k = 0; k < interval; ++k) {
      sys.step(dt);
      sum += wall_mean_stress(sys, R, L);
    }
    out.steps += interval;
    const double p_now = sum / interval;
    history.push_back(p_now);
    if (history.size() >= static_cast<std::size_t>(window)) {
      double mean = 0, worst = 0;
      for (auto it = history.end() - window; it != history.end(); ++it) {
        mean += *it / window;
        worst = std::max(worst, std::abs(*it / target - 1));
      }
      out.converged = std::abs(mean / target - 1) <= in.prestress_tolerance &&
                      worst <= 2 * in.prestress_tolerance;
      out.mean_stress = mean;
    }
    if (in.on_progress) {
      PackingProgress q{"prestress", static_cast<int>(history.size()),
                        in.prestress_max_steps / interval, p_now};
      q.wall_stress = p_now;
      q.coordination = 2.0 * static_cast<double>(sys.n_contacts()) / static_cast<double>(r0.size());
      progress(in, q);
    }
    if (out.converged) break;
    s = std::clamp(s + gain * (1 - p_now / target), 0.99, 1.01);
    scale_grains(sys.mutable_particles(), r0, s, in.material.density);
  }
  out.scale = s;
  out.stages = static_cast<int>(history.size());
  p = sys.particles();
  p.material = material_index;
  for (std::size_t i = 0; i < p.size(); ++i) p.v[i] = p.omega[i] = Vec3{};
  return out;
}

}  // namespace kolsky::dem
