// The narrow pieces contact laws are composed of (architecture.md, "models are small value
// types"): normal (Hertz, linear), tangential (Mindlin, linear; both an incremental spring with
// a Coulomb limit), damping (Tsuji/LIGGGHTS from a restitution coefficient, fraction of
// critical) and rolling (constant rolling-friction moment, Eq. 3.4). Each piece holds its
// parameters as named fields and evaluates as a const function of a read-only ContactGeometry
// plus explicit per-contact history (the tangential displacement). SI units.
// Sign conventions: the normal n points from particle i toward j (or toward the wall), the
// overlap is positive in contact, "force" is the force on i (j receives the opposite).
#pragma once
#include <algorithm>
#include <cmath>

#include "dem/vec3.hpp"

namespace kolsky::dem {

/// Read-only kinematics of one contact at the current step.
struct ContactGeometry {
  double overlap = 0;  ///< delta > 0, m
  Vec3 normal;         ///< unit normal from i toward j (or the wall)
  Vec3 v_contact;      ///< velocity of j (or the wall) minus that of i at the contact point, m/s
  Vec3 omega_rel;      ///< omega_i - omega_j (rad/s), drives rolling resistance
  double r_eff = 0;    ///< R* = r_i r_j / (r_i + r_j) (r_i for a plane), m
  double m_eff = 0;    ///< m* = m_i m_j / (m_i + m_j) (m_i for a wall), kg
  double r_i = 0, r_j = 0;  ///< radii; r_j = +inf for a wall, m
};

/// R* = r_i r_j / (r_i + r_j) from two radii, m* = m_i m_j / (m_i + m_j) from two masses: one
/// expression, so that the per-pair constants formed once per list (ContactNetwork::pair_r_eff,
/// pair_m_eff) and the per-contact kernel have the same bits.
constexpr double pair_effective(double a, double b) { return a * b / (a + b); }

/// What a law's stable-step rule needs to know about the grains (every law of both families
/// has `double stable_dt(const LawLimits&) const`, contact_law.hpp; DemSystem fills it).
struct LawLimits {
  double lightest_mass = 0;   ///< smallest grain mass, kg
  double largest_radius = 0;  ///< largest grain radius, m
  double rayleigh_step = 0;   ///< smallest Rayleigh step of the grains, s (Li et al. 2005)
};

/// What one contact evaluation returns.
struct ContactResult {
  Vec3 force;                 ///< total contact force on i, N
  Vec3 rolling_torque;        ///< rolling-resistance moment on i (j gets the opposite), N m
  double normal_force = 0;    ///< normal force, repulsive positive, N
  double elastic_normal_force = 0;  ///< its elastic part (no dashpot), N: what Eq. 5.13 tests
  double elastic_energy = 0;  ///< energy stored in the normal and tangential springs, J
  double dissipated = 0;      ///< energy dissipated over the last dt (dashpots, sliding), J
};

/// Elastic part of a normal law: force, tangent stiffness dF/d(delta), stored energy, and the
/// Hertz contact radius a = sqrt(R* delta) (0 for a linear spring), which the Mindlin piece
/// reuses rather than taking the square root again.
struct NormalElastic {
  double force = 0, stiffness = 0, energy = 0, contact_radius = 0;
};

/// Hertz (1882): F = 4/3 E* sqrt(R*) delta^{3/2}; tangent stiffness S_n = 2 E* sqrt(R* delta);
/// energy 8/15 E* sqrt(R*) delta^{5/2} = 2/5 F delta.
struct HertzNormal {
  double e_star = 0;  ///< effective modulus E* = 1 / ((1-nu_i^2)/E_i + (1-nu_j^2)/E_j), Pa

  NormalElastic force(const ContactGeometry& g) const {
    const double a = std::sqrt(g.r_eff * g.overlap);  // contact radius
    const double f = (4.0 / 3.0) * e_star * a * g.overlap;
    return {f, 2.0 * e_star * a, 0.4 * f * g.overlap, a};
  }
};

/// Linear spring F = k delta (PFC linear model, LS-DYNA DES Eq. 3.1).
struct LinearNormal {
  double stiffness = 0;  ///< k_n, N/m

  NormalElastic force(const ContactGeometry& g) const {
    const double f = stiffness * g.overlap;
    return {f, stiffness, 0.5 * f * g.overlap, 0.0};
  }
};

/// Mindlin (1949) no-slip tangential stiffness k_t = 8 G* a, a = sqrt(R* delta) the Hertz
/// contact radius of the normal piece.
struct MindlinTangential {
  double g_star = 0;    ///< G* = 1 / (2(2-nu_i)(1+nu_i)/E_i + 2(2-nu_j)(1+nu_j)/E_j), Pa
  double friction = 0;  ///< Coulomb coefficient mu

  double stiffness_at(const NormalElastic& hertz) const {
    return 8.0 * g_star * hertz.contact_radius;
  }
};

/// Constant tangential stiffness (PFC linear k_s; LS-DYNA K_s = SHEARK K_n, Eq. 3.2).
struct LinearTangential {
  double stiffness = 0;  ///< k_s, N/m
  double friction = 0;   ///< Coulomb coefficient mu (Eq. 3.3)

  double stiffness_at(const NormalElastic&) const { return stiffness; }
};

/// Tsuji et al. (1992) / LIGGGHTS damping: c = 2 sqrt(5/6) beta sqrt(S m*), S the tangent
/// stiffness (normal or tangential). beta >= 0 comes from a restitution coefficient
/// (contact_damping.hpp); the sqrt(5/6) is LIGGGHTS' choice for the Hertz tangent stiffness.
struct TsujiDamping {
  double beta = 0;  ///< |ln e| / sqrt(ln^2 e + pi^2) or the exact Hertz calibration, -

  double coefficient(double stiffness, double m_eff) const {
    if (beta == 0) return 0;
    return 1.8257418583505538 * beta * std::sqrt(stiffness * m_eff);  // 2 sqrt(5/6)
  }
};

/// Viscous damping as a fraction of critical, c = 2 zeta sqrt(k m*) (LS-DYNA NDAMP/TDAMP,
/// PFC dp_nratio/dp_sratio). For a linear spring, e = exp(-zeta pi / sqrt(1 - zeta^2)).
struct CriticalDamping {
  double ratio = 0;  ///< zeta, fraction of critical damping, -

  double coefficient(double stiffness, double m_eff) const {
    if (ratio == 0) return 0;
    return 2.0 * ratio * std::sqrt(stiffness * m_eff);
  }
};

/// Constant rolling-friction moment, Eq. 3.4 (M_r = fricr F_N) with the lever arm R* that the
/// printed equation omits (a moment needs one; Ai et al. 2011, model A): M = -mu_r R* F_n w/|w|,
/// w the rolling part of omega_i - omega_j. Acts on i; j receives the opposite.
struct RollingFriction {
  double coefficient = 0;  ///< fricr (mu_r), -

  Vec3 torque(const ContactGeometry& g, double normal_force) const {
    if (coefficient == 0 || normal_force <= 0) return {};
    const Vec3 w = g.omega_rel - dot(g.omega_rel, g.normal) * g.normal;
    const double wn = norm(w);
    if (wn == 0) return {};
    return (-coefficient * g.r_eff * normal_force / wn) * w;
  }
};

/// Tangential spring-dashpot with Coulomb limit, shared by the Mindlin and linear pieces.
/// `history` is the tangential displacement xi of j relative to i at the contact point: it is
/// rotated onto the current tangent plane (magnitude kept, as LIGGGHTS does), then incremented
/// by v_t dt. If the spring force k_t xi exceeds the Coulomb limit L = mu F_el, the contact
/// slides: xi is scaled back to |k_t xi| = L, the slip dissipates L times the slip distance,
/// and the dashpot is idle. Otherwise it sticks and the dashpot c_t v_t is added, scaled down
/// if needed so that the total stays within L. Every term then dissipates (never creates)
/// energy. The limit uses the elastic normal force F_el (PFC's convention), not F_el plus the
/// dashpot: the normal dashpot coefficient depends on the overlap only, so its impulse over a
/// contact vanishes and the sliding tangential impulse is exactly mu times the normal impulse
/// (rigid-body theory); friction also does not vanish while the dashpot pulls at separation.
/// Returns the force on i; adds its stored and dissipated energy to `out`.
[[gnu::always_inline]] inline Vec3 tangential_force(const ContactGeometry& g, Vec3& history,
                                                    double dt, double k_t, double c_t,
                                                    double friction, double elastic_normal,
                                                    ContactResult& out) {
  const Vec3& n = g.normal;
  const double xn = dot(history, n);
  if (xn != 0) {
    const double before = norm2(history);
    history -= xn * n;
    const double after = norm2(history);
    if (after > 0) history *= std::sqrt(before / after);
  }
  const Vec3 vt = g.v_contact - dot(g.v_contact, n) * n;
  history += dt * vt;
  const double limit = friction * elastic_normal;
  Vec3 ft = k_t * history;
  const double spring2 = norm2(ft);
  if (spring2 > limit * limit) {  // sliding
    const double spring = std::sqrt(spring2);
    const double scale = limit / spring;
    history *= scale;
    ft *= scale;
    out.dissipated += limit * (spring - limit) / k_t;  // L x slip, slip = (|k xi| - L)/k
  } else if (c_t > 0) {  // sticking: add the dashpot, within the Coulomb limit
    const Vec3 damp = c_t * vt;
    double s = 1;
    const Vec3 total = ft + damp;
    if (norm2(total) > limit * limit) {
      // Largest s in [0, 1] with |ft + s damp| = L (|ft| <= L, so the root is >= 0).
      const double b2 = norm2(damp), ab = dot(ft, damp);
      s = (-ab + std::sqrt(std::max(0.0, ab * ab - b2 * (spring2 - limit * limit)))) / b2;
    }
    ft += s * damp;
    out.dissipated += s * c_t * norm2(vt) * dt;
  }
  out.elastic_energy += 0.5 * k_t * norm2(history);
  return ft;
}

/// Normal spring-dashpot: F_n = F_el + c_n d(delta)/dt (no clamp: the dashpot may pull near
/// separation, as LIGGGHTS' default and PFC's full-normal dashpot mode; the restitution closed
/// forms assume it). Force on i is -F_n n.
[[gnu::always_inline]] inline double normal_force(const ContactGeometry& g,
                                                  const NormalElastic& el, double c_n,
                                                  double dt, ContactResult& out) {
  const double vn = dot(g.v_contact, g.normal);  // < 0 while approaching
  out.elastic_energy += el.energy;
  out.elastic_normal_force = el.force;
  out.dissipated += c_n * vn * vn * dt;
  return el.force - c_n * vn;
}

}  // namespace kolsky::dem
