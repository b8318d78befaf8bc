// The Hertzian-contact (HC) breakage criterion of Ciantia et al. as the dissertation uses it
// (Sec. 5.2.3; parameters and misprints in targets.md 5a/5e): pure functions of a grain and one
// of its contacts, for the engine to call between steps.
//   Eq. 5.13 (corrected, 5e.5): break when F >= F_crit = sigma_lim^3 pi^3 (3 r'/(4 E'))^2, i.e.
//     when the mean Hertz contact pressure F/(pi a^2) reaches sigma_lim, with
//     sigma_lim = sigma_lim0 (d/d0)^(-3/m1) var;
//   Eq. 5.15 (5e.7): var = (U - b)/a, U uniform on [0, 1), one draw per grain from a
//     counter-based stream keyed by (seed, grain id);
//   Eq. 5.17: sigma_lim0 of an N-times upscaled specimen = sigma_lim0(1) N^(3/m1);
//   coordination limit (strictly fewer than c_lim contacts; 0 = off, 5e.9) and comminution
//   limit (d >= comminution_factor x d50 of the initial curve).
// docs/breakage.md says which force enters F and every other choice the text leaves open.
// SI units: Pa, m, N.
#pragma once
#include <cstdint>
#include <string>

#include "dem/vec3.hpp"

namespace kolsky::dem {

/// Parameters of the breakage model (scene keys: the field names, under specimen.breakage).
struct BreakageParams {
  double sigma_lim0 = 2.7e9;  ///< Pa, strength of a d0 grain: Song, N = 2 (Sec. 5.3.3)
  double d0 = 0.002;          ///< m, reference diameter of sigma_lim0 (Sec. 5.2.3)
  double m1 = 3.0;            ///< Weibull modulus of the size effect (silica, Sec. 5.2.3)
  double var_a = -1.22;       ///< Eq. 5.15 slope a (Hanley et al. 2015, silica)
  double var_b = 1.67;        ///< Eq. 5.15 intercept b
  /// c_lim: a grain may break only with fewer than this many contacts (c_lim = 8, Secs.
  /// 5.3.1-5.3.3); 0 switches the criterion off (targets.md 5e.9).
  int coordination_limit = 8;
  /// Whether wall contacts count towards the coordination number. The text leaves it open.
  /// Default true: c_lim stands for the confinement a grain gets from its load-bearing
  /// contacts (Lobo-Guerrero and Vallejo 2005a), and a platen or the tube confines a grain at
  /// least as well as a neighbour does; PFC3D 5.0 (the dissertation's code), as far as we know,
  /// counts ball-facet contacts in a ball's contact count unless told to filter them.
  bool count_wall_contacts = true;
  /// Eq. 5.13 at a wall contact: false (default) takes the grain on a rigid plane, r' = r and
  /// E' = E/(1 - nu^2); true takes E' of two alike grains, E/(2(1 - nu^2)) (the single-material
  /// formula, with r' = r still), which makes F_crit four times larger there. The text's walls
  /// are linear springs with no modulus, so it leaves this open (targets.md 5d).
  bool wall_as_grain = false;
  double comminution_factor = 0.22;  ///< grains below this x d50 never break (Sec. 5.2.3)
  double fines_fractal_dimension = 2.6;  ///< alpha of the lost mass, Eq. 5.16
  double fines_d_min = 7.5e-6;       ///< m, d_min of Eq. 5.16 (Wang et al. 2018)
  /// Hardin's size threshold at the specimen's scale (m): 75 um (Sec. 5.3.1) times the
  /// upscaling factor, so that B_r of the upscaled curves equals B_r of the curves shifted
  /// back by N (B_r is an area in log d). Set by the scene from specimen.upscale.
  double hardin_threshold = 75e-6;
};

/// Throws kolsky::InputError("", path + "." + key, rule) on the first broken rule:
/// sigma_lim0, d0, m1 finite and > 0; var_a finite and != 0; var_b finite, with both ends of
/// Eq. 5.15's range, var(U = 0) = -b/a and var(U = 1) = (1-b)/a, > 0 (else named at var_b);
/// coordination_limit >= 0; comminution_factor in (0, 1); fines_fractal_dimension finite, > 0 (alpha >= 3
/// is allowed: psd::fractal_passing_fraction takes it, alpha = 3 as the log limit); fines_d_min
/// finite and > 0.
void validate(const BreakageParams& p, const std::string& path = "specimen.breakage");

/// The rules that need the specimen's initial d50 (m): the fines of the smallest grain that
/// may break must have d_max = 2 x 0.2240 x R > d_min, i.e. fines_d_min < 0.224 x
/// comminution_factor x d50 (else Eq. 5.16 is empty). Throws InputError at path.fines_d_min.
void validate_against_d50(const BreakageParams& p, double d50_initial,
                          const std::string& path = "specimen.breakage");

/// sigma_lim = sigma_lim0 (d/d0)^(-3/m1) var (Pa; Eq. 5.13 size effect). d in m, var > 0.
double strength_limit(const BreakageParams& p, double diameter, double var);

/// Eq. 5.17: sigma_lim0 for an N-times upscaled specimen from that of the original (N = 1).
double upscaled_sigma_lim0(double sigma_lim0_original, double upscaling_factor, double m1);

/// F_crit = sigma_lim^3 pi^3 (3 r_eff / (4 e_eff))^2 (N): the force at which the mean Hertz
/// pressure F / (pi a(F)^2), a = (3 F r_eff / (4 e_eff))^(1/3), equals sigma_lim (Eq. 5.13
/// solved for F in closed form; no iteration). Pa, m, Pa.
double critical_force(double sigma_lim, double r_eff, double e_eff);

/// The same criterion for a Hertz contact in overlap form: the elastic Hertz force
/// (4/3) E' sqrt(r') delta^(3/2) reaches critical_force at delta_crit = r' (3 pi sigma_lim /
/// (4 E'))^2 (m), where the mean pressure (4 E' / (3 pi)) sqrt(delta / r') equals sigma_lim. Lets
/// a sweep that already has the overlap test a Hertz contact without its force.
double critical_overlap(double sigma_lim, double r_eff, double e_eff);

/// Mean Hertz contact pressure F / (pi a^2) at normal force F (Pa), the left side of the
/// criterion in pressure form; equals sigma_lim exactly at critical_force.
double mean_hertz_pressure(double force, double r_eff, double e_eff);

/// r' = (1/r1 + 1/r2)^-1 (m); r2 = +inf (a plane wall) gives r1 exactly.
double effective_radius(double r1, double r2);
/// E' = ((1 - nu1^2)/E1 + (1 - nu2^2)/E2)^-1 (Pa); E2 = +inf (rigid wall) drops its term.
double effective_modulus(double e1, double nu1, double e2, double nu2);

/// Eq. 5.15: var = (U - b)/a with U in [0, 1) the grain's own uniform draw: a function of
/// (seed, grain_id) only, so the same grain gets the same var whatever the thread count, the
/// order grains are checked in, or a restart. In ((1-b)/a, -b/a] for a < 0.
double strength_variability(const BreakageParams& p, std::uint64_t seed, std::uint64_t grain_id);

/// The U of Eq. 5.15 for (seed, grain_id): output grain_id + 1 of the SplitMix64 stream keyed
/// by (seed, purpose "kolsky.breakage.var"), top 53 bits, in [0, 1). Pure: no state.
double strength_uniform(std::uint64_t seed, std::uint64_t grain_id);

/// Rotation of the daughter set about the force axis, uniform in [0, 2 pi) (rad), from the
/// grain's stream with purpose "kolsky.breakage.spin" (independent of its var).
double replacement_spin_angle(std::uint64_t seed, std::uint64_t grain_id);

/// Id of daughter k (0..13, the Table 5.3 index) of parent_id: SplitMix64's bijective mixer
/// applied to parent_id ^ K_k with 14 distinct pseudo-random 64-bit keys K_k. For a fixed k the
/// map is a bijection (distinct parents, distinct daughters); for a fixed parent the 14 ids are
/// distinct. Across parents ids are not collision-free by construction (no 64-bit scheme can
/// be, for unbounded generations): they behave as random 64-bit values, so n ids collide with
/// probability ~ n^2 / 2^65 (5e-10 for the 1.3e5 grains of a Chapter-5 run). A collision would
/// only make two grains share var and spin angle. Throws std::out_of_range for k > 13.
std::uint64_t daughter_id(std::uint64_t parent_id, unsigned k);

/// Coordination number the limit is tested on: grain contacts plus, if count_wall_contacts,
/// wall contacts (both counts of contacts that carry force).
int counted_coordination(const BreakageParams& p, int n_grain_contacts, int n_wall_contacts);
/// Coordination limit: true if coordination_limit == 0 (off) or coordination < c_lim.
bool coordination_allows_break(const BreakageParams& p, int coordination);
/// Smallest diameter that may break: comminution_factor x d50 of the initial curve (m).
double comminution_diameter(const BreakageParams& p, double d50_initial);
/// Comminution limit: true unless diameter < comminution_factor x d50_initial.
bool above_comminution_limit(const BreakageParams& p, double diameter, double d50_initial);
/// Both limits together: the grain may break if its force criterion holds.
bool may_break(const BreakageParams& p, double diameter, double d50_initial, int coordination);
/// The whole decision for one grain: may_break(...) and force >= f_crit, where force and f_crit
/// (critical_force with that contact's r' and E') belong to the grain's most critical contact.
bool grain_breaks(const BreakageParams& p, double diameter, double d50_initial, int coordination,
                  double force, double f_crit);
/// Smallest grain breakage can ever create (m): the smallest daughter (0.2240 R) of the
/// smallest grain that may break, 0.224 x comminution_factor x d50. For a dt fixed up front.
double smallest_daughter_diameter(const BreakageParams& p, double d50_initial);

/// Daughters move with the parent's translational velocity (Sec. 5.2.3: "the same ...
/// velocities as the parent"): v_k = v, so sum m_k v_k = (retained fraction) m v exactly, i.e.
/// momentum per unit retained mass is preserved. (v + omega x r_k would carry the rounded
/// table's centroid error and is not what the text says; docs/breakage.md.)
inline Vec3 daughter_velocity(const Vec3& parent_velocity) { return parent_velocity; }

}  // namespace kolsky::dem
