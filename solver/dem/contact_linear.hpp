// Linear contact laws, composed of the pieces of contact_pieces.hpp:
//   LinearSpring ("linear"): PFC-style constant k_n, k_s, friction (walls, Table 4.1).
//   LsDynaLinear ("ls_dyna_linear"): LS-DYNA DES contact, Sec. 3.3, Eqs. 3.1-3.4:
//     K_n = NORMK k_1 r_1 k_2 r_2 / (k_1 r_1 + k_2 r_2), k_i = E_i / (1 - 2 nu_i) as printed,
//     K_s = SHEARK K_n, Coulomb FRIC, rolling moment FRICR R* F_n, NDAMP/TDAMP as fractions of
//     critical damping. Stable step sqrt(m/k) (sqrt(1 + z^2) - z), with 3.5 k_s for the
//     tangential spring (a solid sphere's contact point responds with mass m/3.5).
#pragma once
#include <limits>
#include <string>
#include <vector>

#include "dem/contact_pieces.hpp"
#include "dem/particles.hpp"

namespace kolsky::dem {

/// The shared evaluation of a linear spring-dashpot-slider (+ rolling friction) contact.
[[gnu::always_inline]] inline ContactResult linear_contact_force(const LinearNormal& normal,
                                          const LinearTangential& tangential,
                                          const CriticalDamping& damping_normal,
                                          const CriticalDamping& damping_tangential,
                                          const RollingFriction& rolling,
                                          const ContactGeometry& g, Vec3& history, double dt,
                                          double rolling_inverse_inertia = 0) {
  ContactResult r;
  const NormalElastic el = normal.force(g);
  const double fn =
      normal_force(g, el, damping_normal.coefficient(el.stiffness, g.m_eff), dt, r);
  const double kt = tangential.stiffness_at(el);
  const Vec3 ft = tangential_force(g, history, dt, kt,
                                   damping_tangential.coefficient(kt, g.m_eff),
                                   tangential.friction, el.force, r);
  r.normal_force = fn;
  r.force = ft - fn * g.normal;
  r.rolling_torque = rolling.torque(g, fn);
  if (rolling_inverse_inertia > 0) {
    // Model A's constant moment flips the rolling part w of omega_i - omega_j every step once
    // the rolling has nearly stopped, and each flip feeds (M dt)^2 / (2 I) into the spins
    // (Chapter 3 README, 'Rolling friction': at N = 2 that grew the SHPB's energy by 5 % of
    // the pulse's work past 13 MPa). So |M| is capped at kStick |w| / (dt (1/I_i + 1/I_j)):
    // below that rolling speed the moment is a rotational dashpot that removes at most kStick
    // of w per step. kStick = 0.1 keeps the sum over a grain's contacts stable (explicit
    // dashpots: sum of c dt / I < 2) up to 20 contacts of equal spheres; a large grain among
    // small ones has its partners' inertia in 1/I_i + 1/I_j and stays far inside the bound.
    constexpr double kStick = 0.1;
    const Vec3 w = g.omega_rel - dot(g.omega_rel, g.normal) * g.normal;
    double m = norm(r.rolling_torque);
    const double cap = kStick * norm(w) / (dt * rolling_inverse_inertia);
    if (m > cap) r.rolling_torque = (cap / m) * r.rolling_torque, m = cap;
    // Booked at the step's mean w, w - M dt / (2 I): M w dt - (M dt)^2 / (2 I), exact for one
    // moment (the step-start w alone books (M dt)^2 / (2 I) too much each step).
    r.dissipated += -dot(r.rolling_torque, g.omega_rel) * dt - 0.5 * m * m * dt * dt * rolling_inverse_inertia;
  } else if (rolling.coefficient != 0) {
    r.dissipated -= dot(r.rolling_torque, g.omega_rel) * dt;
  }
  return r;
}

/// Stable step of a single linear contact of stiffness k (N/m) and damping ratio zeta on a
/// particle of mass m (kg): sqrt(m/k) (sqrt(1 + zeta^2) - zeta).
double linear_contact_time_step(double mass, double stiffness, double zeta);

/// Parameters of a LinearSpring. The initialisers are the one linear contact the dissertation
/// prints, the wall-specimen interface of Table 4.1 (k_n = 2.6e6 N/m, k_s = 1.6e6 N/m,
/// ball-interface friction 0.3, no dashpot): every wall's default, and the scene's defaults
/// for the walls and for the grain law "linear" (no grain-grain value is printed).
struct LinearParams {
  double normal_stiffness = 2.6e6;  ///< k_n, N/m
  double shear_stiffness = 1.6e6;   ///< k_s, N/m
  double friction = 0.3;            ///< Coulomb coefficient mu, -
  double damping_ratio = 0;         ///< both dashpots, fraction of critical damping, -
};

/// PFC-style linear contact; the same parameters for every material pair (and every wall).
/// The law interface of contact_law.hpp (pair(...).force, stable_dt, fits, validate).
struct LinearSpring {
  using Params = LinearParams;
  LinearNormal normal;
  LinearTangential tangential;
  CriticalDamping damping_normal, damping_tangential;
  RollingFriction rolling;

  const LinearSpring& pair(int, int) const { return *this; }
  const LinearSpring& pair(int) const { return *this; }
  ContactResult force(const ContactGeometry& g, Vec3& history, double dt) const {
    return linear_contact_force(normal, tangential, damping_normal, damping_tangential, rolling,
                                g, history, dt);
  }
  /// Smallest stable step over the normal and tangential springs for particle mass m (kg).
  double stable_dt(double mass) const;
  /// The same for the lightest grain: the stiffest spring on the smallest mass.
  double stable_dt(const LawLimits& l) const { return stable_dt(l.lightest_mass); }
  bool fits(int) const { return true; }  // one parameter set for every material
  void validate(const std::string& path) const;
};

/// A LinearSpring from k_n, k_s (N/m), friction and damping ratios (fractions of critical).
LinearSpring linear_spring(double k_n, double k_s, double friction, double damping_normal = 0,
                           double damping_tangential = 0);
/// The LinearSpring of p, damping_ratio on both dashpots.
LinearSpring linear_spring(const LinearParams& p);
/// Throws kolsky::InputError (path.<field>) unless normal_stiffness > 0, shear_stiffness >= 0
/// (both finite), friction >= 0 and damping_ratio in [0, 1).
void validate(const LinearParams& p, const std::string& path);
/// Throws kolsky::InputError (path.<field>: normal_stiffness, shear_stiffness, friction,
/// damping_normal, damping_tangential, rolling_friction) unless k_n > 0, k_s >= 0,
/// friction >= 0, damping ratios in [0, 1) and rolling coefficient >= 0.
void validate(const LinearSpring& s, const std::string& path);

/// Table 3.2 parameters of the LS-DYNA DES contact (defaults as printed there; TDAMP, which
/// Table 3.2 lists without a source, as NDAMP).
struct LsDynaParams {
  double normk = 0.07;  ///< NORMK, scale of the normal stiffness, -
  double sheark = 1.0;  ///< SHEARK = K_s / K_n, -
  double fric = 0.56;   ///< Coulomb coefficient FRIC, -
  double fricr = 0.1;   ///< rolling-friction coefficient FRICR (moment FRICR R* F_n), -
  double ndamp = 0.1;   ///< normal damping, fraction of critical, -
  double tdamp = 0.1;   ///< tangential damping, fraction of critical, -
};

/// Throws kolsky::InputError (path.<field>) unless NORMK > 0, SHEARK, FRIC, FRICR >= 0 and
/// NDAMP, TDAMP in [0, 1).
void validate(const LsDynaParams& p, const std::string& path);

/// One material pair of the LS-DYNA law: K_n depends on the two radii (Eq. 3.1).
struct LsDynaPair {
  double k_a = 0, k_b = 0;  ///< E_i / (1 - 2 nu_i), Pa
  LsDynaParams p;

  /// Eq. 3.1: NORMK k_a r_i k_b r_j / (k_a r_i + k_b r_j), N/m.
  double normal_stiffness(double r_i, double r_j) const {
    const double a = k_a * r_i, b = k_b * r_j;
    return p.normk * a * b / (a + b);
  }
  ContactResult force(const ContactGeometry& g, Vec3& history, double dt) const {
    const double kn = normal_stiffness(g.r_i, g.r_j);
    return linear_contact_force(LinearNormal{kn}, LinearTangential{p.sheark * kn, p.fric},
                                CriticalDamping{p.ndamp}, CriticalDamping{p.tdamp},
                                RollingFriction{p.fricr}, g, history, dt,
                                p.fricr > 0 ? rolling_inverse_inertia(g) : 0.0);
  }
  /// 1/I_i + 1/I_j of the two solid spheres (I = 0.4 m r^2) from m* and the radii, the two
  /// grains of one density (m ~ r^3: m_i = m* (r_i^3 + r_j^3) / r_j^3); a wall: 1/I_i.
  static double rolling_inverse_inertia(const ContactGeometry& g) {
    if (!(g.r_j < std::numeric_limits<double>::infinity())) return 1 / (0.4 * g.m_eff * g.r_i * g.r_i);
    const double a = g.r_i * g.r_i * g.r_i, b = g.r_j * g.r_j * g.r_j;
    const double m_i = g.m_eff * (a + b) / b, m_j = g.m_eff * (a + b) / a;
    return 1 / (0.4 * m_i * g.r_i * g.r_i) + 1 / (0.4 * m_j * g.r_j * g.r_j);
  }
};

/// Grain-grain LS-DYNA DES law over the material table (the law interface of contact_law.hpp).
class LsDynaLinear {
 public:
  using Params = LsDynaParams;
  /// Throws kolsky::InputError ("dem.contact_law.<field>") for parameters validate() refuses.
  LsDynaLinear(const std::vector<Material>& materials, const LsDynaParams& p);
  const LsDynaPair& pair(int a, int b) const { return table_[a * n_ + b]; }
  const LsDynaParams& params() const { return params_; }
  int n_materials() const { return n_; }
  bool fits(int n_materials) const { return n_materials == n_; }
  void validate(const std::string& path) const { dem::validate(params_, path); }
  /// Smallest stable step for particles of mass >= m_min (kg) and radius <= r_max (m).
  double stable_dt(double m_min, double r_max) const;
  /// The same for the lightest grain and the largest radius (K_n grows with both radii).
  double stable_dt(const LawLimits& l) const {
    return stable_dt(l.lightest_mass, l.largest_radius);
  }

 private:
  LsDynaParams params_;
  int n_;
  std::vector<LsDynaPair> table_;
};

}  // namespace kolsky::dem
