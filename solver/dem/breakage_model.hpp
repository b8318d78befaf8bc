// The breakage model of Ciantia et al. as the dissertation uses it (Sec. 5.2.3; parameters and
// misprints in targets.md 5a/5e): pure functions of a grain and one of its contacts, for the
// engine to call between steps. The criterion itself is a type of breakage_criterion.hpp
// (Eq. 5.13 by default); here the closed forms it rests on and what every criterion shares:
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

#include "dem/breakage_criterion.hpp"
#include "dem/vec3.hpp"

namespace kolsky::dem {

/// How often the engine checks for breaks (docs/breakage.md, "Checks").
struct BreakageCadence {
  /// Steps between checks (>= 1). 50: a check costs about one step of the force sweep
  /// (bench_dem BM_DemBreakageIdle), so every 50 steps it costs ~2 %; on the example scene
  /// intervals 1, 10, 20 and 50 gave 39, 41, 40 and 39 breaks and B_r 0.443, 0.448, 0.437,
  /// 0.443, the scatter of a chaotic DEM run (docs/breakage.md). 50 steps of a Chapter-5 dt
  /// (~2e-9 s) are 0.1 us of a ~100 us loading.
  int check_interval = 50;
  /// Simulated time between checks (s); 0: every check_interval steps. For a run whose dt is
  /// refined after breaks, where a step count is no fixed time (docs/breakage.md).
  double check_period = 0.0;
};

/// Parameters of the breakage model (scene keys: the field names, under specimen.breakage;
/// the criterion's under specimen.breakage too, selected by specimen.breakage.criterion).
struct BreakageParams {
  /// Which grains are loaded past their strength: Eq. 5.13 (the text's) by default.
  BreakageCriterion criterion = HertzianContactCriterion{};
  /// c_lim: a grain may break only with fewer than this many contacts (c_lim = 8, Secs.
  /// 5.3.1-5.3.3); 0 switches the criterion off (targets.md 5e.9).
  int coordination_limit = 8;
  /// Whether wall contacts count towards the coordination number. The text leaves it open.
  /// Default true: c_lim stands for the confinement a grain gets from its load-bearing
  /// contacts (Lobo-Guerrero and Vallejo 2005a), and a platen or the tube confines a grain at
  /// least as well as a neighbour does; PFC3D 5.0 (the dissertation's code), as far as we know,
  /// counts ball-facet contacts in a ball's contact count unless told to filter them.
  bool count_wall_contacts = true;
  double comminution_factor = 0.22;  ///< grains below this x d50 never break (Sec. 5.2.3)
  double fines_fractal_dimension = 2.6;  ///< alpha of the lost mass, Eq. 5.16
  double fines_d_min = 7.5e-6;       ///< m, d_min of Eq. 5.16 (Wang et al. 2018)
  /// Hardin's size threshold at the specimen's scale (m): 75 um (Sec. 5.3.1) times the
  /// upscaling factor, so that B_r of the upscaled curves equals B_r of the curves shifted
  /// back by N (B_r is an area in log d). Set by the scene from specimen.upscale.
  double hardin_threshold = 75e-6;
  BreakageCadence cadence;
};

/// Throws kolsky::InputError("", path + "." + key, rule) on the first broken rule: the
/// criterion's (breakage_criterion.hpp), then coordination_limit >= 0; comminution_factor in (0, 1); fines_fractal_dimension finite, > 0 (alpha >= 3
/// is allowed: psd::fractal_passing_fraction takes it, alpha = 3 as the log limit); fines_d_min
/// finite and > 0; cadence.check_interval >= 1, cadence.check_period finite and >= 0.
void validate(const BreakageParams& p, const std::string& path = "specimen.breakage");

/// The rules that need the specimen's initial d50 (m): the fines of the smallest grain that
/// may break must have d_max = 2 x 0.2240 x R > d_min, i.e. fines_d_min < 0.224 x
/// comminution_factor x d50 (else Eq. 5.16 is empty). Throws InputError at path.fines_d_min.
void validate_against_d50(const BreakageParams& p, double d50_initial,
                          const std::string& path = "specimen.breakage");

/// Eq. 5.17: sigma_lim0 for an N-times upscaled specimen from that of the original (N = 1).
double upscaled_sigma_lim0(double sigma_lim0_original, double upscaling_factor, double m1);

/// Eq. 5.17 between two upscaling factors: sigma_lim0 at N from its value at N_ref,
/// sigma_ref (N / N_ref)^(3/m1), evaluated as sigma_ref N^(3/m1) / N_ref^(3/m1). With m1 = 3
/// (every Chapter 5 scene) pow(x, 1) is x exactly, so this is sigma_ref N / N_ref to the bit.
double sigma_lim0_between(double sigma_ref, double n_ref, double n, double m1);

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
/// The whole decision for one grain (what the engine calls): may_break(...) and load_ratio >= 1,
/// where load_ratio is the criterion's largest over the grain's contacts (breakage_criterion.hpp;
/// for Eq. 5.13, F / F_crit of the grain's most critical contact).
bool grain_breaks(const BreakageParams& p, double diameter, double d50_initial, int coordination,
                  double load_ratio);
/// Smallest grain breakage can ever create (m): the smallest daughter (0.2240 R) of the
/// smallest grain that may break, 0.224 x comminution_factor x d50. For a dt fixed up front.
double smallest_daughter_diameter(const BreakageParams& p, double d50_initial);

/// Daughters move with the parent's translational velocity (Sec. 5.2.3: "the same ...
/// velocities as the parent"): v_k = v, so sum m_k v_k = (retained fraction) m v exactly, i.e.
/// momentum per unit retained mass is preserved. (v + omega x r_k would carry the rounded
/// table's centroid error and is not what the text says; docs/breakage.md.)
inline Vec3 daughter_velocity(const Vec3& parent_velocity) { return parent_velocity; }

}  // namespace kolsky::dem
