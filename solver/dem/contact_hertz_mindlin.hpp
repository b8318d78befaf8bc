// Hertz-Mindlin contact (JSON "hertz_mindlin"): Hertz normal force, Mindlin no-slip tangential
// stiffness with an incremental displacement history and a Coulomb limit, optional Tsuji
// damping from a restitution coefficient (LIGGGHTS "hertz" + "history"). Dissertation Sec. 4.3
// Eqs. 4.10/4.11 print a PFC secant form, k_n = 2G sqrt(2 R_bar)/(3(1-nu)) sqrt(U), which equals
// F/U of this law when R_bar = 2R* (targets.md 4d) and whose Eq. 4.11 is misprinted (4e.6);
// docs/dem.md relates the two. Also the closed forms of Hertz impact (Johnson 1985, Sec. 11.4)
// and the Rayleigh time step (Li et al. 2005) the tests and the dt policy use. SI units.
#pragma once
#include <string>
#include <vector>

#include "dem/contact_pieces.hpp"
#include "dem/hertz.hpp"
#include "dem/particles.hpp"

namespace kolsky::dem {

/// E* of two materials; a material with E = +inf (rigid wall) contributes nothing.
double effective_modulus(const Material& a, const Material& b);
/// G* = 1 / (2(2-nu_a)(1+nu_a)/E_a + 2(2-nu_b)(1+nu_b)/E_b) (Mindlin; as LIGGGHTS).
double effective_shear_modulus(const Material& a, const Material& b);

/// Interaction parameters shared by all material pairs of a Hertz-Mindlin law.
struct HertzMindlinParams {
  double friction = 0.5;     ///< Coulomb coefficient mu, -
  double restitution = 1.0;  ///< e in (0, 1]; 1 = undamped
};

/// Throws kolsky::InputError (path.friction, path.restitution) unless friction >= 0 and
/// restitution in (0, 1].
void validate(const HertzMindlinParams& p, const std::string& path = "dem.contact_law");

/// The pieces of one material pair; force() evaluates one contact.
struct HertzMindlinPair {
  HertzNormal normal;
  MindlinTangential tangential;
  TsujiDamping damping;
  double tangential_damping_scale = 0;  ///< derived: sqrt(4 G* / E*) = sqrt(k_t / S_n)

  /// Total force on i for geometry g; `history` is the tangential displacement (m), updated
  /// for the displacement over dt (s).
  [[gnu::always_inline]] ContactResult force(const ContactGeometry& g, Vec3& history,
                                             double dt) const {
    ContactResult r;
    const NormalElastic el = normal.force(g);
    const double c_n = damping.coefficient(el.stiffness, g.m_eff);
    const double fn = normal_force(g, el, c_n, dt, r);
    const double kt = tangential.stiffness_at(el);
    // k_t / S_n = 4 G*/E* is fixed per pair, so c_t = c_n sqrt(k_t / S_n) needs no root.
    const Vec3 ft = tangential_force(g, history, dt, kt, c_n * tangential_damping_scale,
                                     tangential.friction, el.force, r);
    r.normal_force = fn;
    r.force = ft - fn * g.normal;
    return r;
  }
};

/// Makes the pair of materials a and b (b may be a rigid wall: E = +inf).
HertzMindlinPair make_hertz_mindlin_pair(const Material& a, const Material& b,
                                         const HertzMindlinParams& p);

/// Grain-grain law: a table over material pairs, looked up by the particles' material indices.
/// The law interface of contact_law.hpp: params(), pair(a, b).force(...), stable_dt, fits,
/// validate.
class HertzMindlin {
 public:
  using Params = HertzMindlinParams;
  HertzMindlin(const std::vector<Material>& materials, const HertzMindlinParams& p);
  const HertzMindlinPair& pair(int a, int b) const { return table_[a * n_ + b]; }
  const HertzMindlinParams& params() const { return params_; }
  int n_materials() const { return n_; }
  bool fits(int n_materials) const { return n_materials == n_; }
  void validate(const std::string& path) const { dem::validate(params_, path); }
  /// A Hertz contact stiffens with its overlap without bound, so no spring period limits
  /// the step; the Rayleigh wave crossing the smallest grain does (Li et al. 2005).
  double stable_dt(const LawLimits& l) const { return l.rayleigh_step; }

 private:
  HertzMindlinParams params_;
  int n_;
  std::vector<HertzMindlinPair> table_;
};

/// Hertz-Mindlin between grains and a wall of material `wall` (E = +inf: rigid plane; the
/// wall's radius is infinite through the contact geometry, so R* = r for a plane).
class HertzMindlinWall {
 public:
  using Params = HertzMindlinParams;
  HertzMindlinWall(const std::vector<Material>& materials, const Material& wall,
                   const HertzMindlinParams& p);
  const HertzMindlinPair& pair(int particle_material) const { return table_[particle_material]; }
  const HertzMindlinParams& params() const { return params_; }
  bool fits(int n_materials) const { return n_materials == static_cast<int>(table_.size()); }
  void validate(const std::string& path) const { dem::validate(params_, path); }
  /// As HertzMindlin: the Rayleigh step of the smallest grain.
  double stable_dt(const LawLimits& l) const { return l.rayleigh_step; }

 private:
  HertzMindlinParams params_;
  std::vector<HertzMindlinPair> table_;
};

/// Closed forms of an undamped Hertz impact at relative normal speed v (Johnson 1985, 11.4).
struct HertzImpact {
  double e_star, r_eff, m_eff, speed;
  /// delta_max = (15 m* v^2 / (16 E* sqrt(R*)))^{2/5}
  double max_overlap() const;
  /// F_max = 4/3 E* sqrt(R*) delta_max^{3/2}
  double peak_force() const;
  /// t_c = 2 (delta_max / v) int_0^1 (1 - x^{5/2})^{-1/2} dx = 2.9432 delta_max / v
  /// = 2.8683 (m*^2 / (R* E*^2 v))^{1/5}; the integral is B(2/5, 1/2) / (5/2).
  double contact_time() const;
};

/// Rayleigh time step of a sphere, pi r sqrt(rho/G) / (0.1631 nu + 0.8766) (Li et al. 2005).
double rayleigh_time_step(double radius, const Material& m);

}  // namespace kolsky::dem
