// Breakage criteria (docs/breakage.md, "Criteria"): whether a grain is loaded past its strength.
// A criterion is a small value type beside the contact law. The engine (breakage_engine.cpp)
// draws each grain's strength once (grain_strength), then at every check hands the criterion,
// for each touching contact of the grain, what the Hertz law already has: the overlap, 1/r' and
// E' of a grain pair, or the elastic normal force of a wall contact. The criterion answers a
// load ratio, >= 1 where it holds; the grain's ratio is the largest over its contacts. The
// coordination and comminution limits belong to no criterion (breakage_model.hpp, may_break).
//
// The members are split in a per-pair and a per-grain constant so that the pass, run at every
// check over every contact, costs a few multiplications per contact (no root, no division).
// Adding a criterion: a struct with the functions below, its name in kBreakageCriterionNames
// and default_criterion, and its keys in scene/dem_keys.cpp. SI units: Pa, m, N.
#pragma once
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <variant>

namespace kolsky::dem {

/// Eq. 5.13, the Hertzian-contact criterion (HC) of Ciantia et al. (2015) the text uses
/// (Sec. 5.2.3; corrected form targets.md 5e.5): a grain breaks when the mean Hertz pressure
/// F / (pi a^2) of one of its contacts reaches its strength
/// sigma_lim = sigma_lim0 (d/d0)^(-3/m1) var, var = (U - b)/a (Eq. 5.15).
struct HertzianContactCriterion {
  double sigma_lim0 = 2.7e9;  ///< Pa, strength of a d0 grain: Song, N = 2 (Sec. 5.3.3)
  double d0 = 0.002;          ///< m, reference diameter of sigma_lim0 (Sec. 5.2.3)
  double m1 = 3.0;            ///< Weibull modulus of the size effect (silica, Sec. 5.2.3)
  double var_a = -1.22;       ///< Eq. 5.15 slope a (Hanley et al. 2015, silica)
  double var_b = 1.67;        ///< Eq. 5.15 intercept b
  /// Eq. 5.13 at a wall contact: false (default) takes the grain on a rigid plane, r' = r and
  /// E' = E/(1 - nu^2); true takes E' of two alike grains, E/(2(1 - nu^2)) (the single-material
  /// formula, with r' = r still), which makes F_crit four times larger there. The text's walls
  /// are linear springs with no modulus, so it leaves this open (targets.md 5d).
  bool wall_as_grain = false;
};

/// A constant characteristic stress (McDowell and Bolton 1998, whose grain strength is the
/// characteristic tensile stress F / d^2 of a grain crushed between platens): a grain of
/// diameter d breaks when the elastic normal force of one of its contacts reaches
/// characteristic_stress x d^2. No size effect and no scatter: every grain alike. No chapter
/// uses it; it is the simplest criterion beside Eq. 5.13, for comparison.
struct ConstantStressCriterion {
  double characteristic_stress = 50e6;  ///< Pa (silica sand grains: tens of MPa, McDowell 1998)
};

using BreakageCriterion = std::variant<HertzianContactCriterion, ConstantStressCriterion>;
/// Scene names (specimen.breakage.criterion), in the variant's order.
inline constexpr std::array<std::string_view, 2> kBreakageCriterionNames = {"hertzian_contact",
                                                                          "constant_stress"};
/// The criterion named `name` with its default parameters; throws std::invalid_argument for
/// an unknown name.
BreakageCriterion default_criterion(std::string_view name);

/// Throws kolsky::InputError("", path + "." + key, rule) on the first broken rule.
/// HC: sigma_lim0, d0, m1 finite and > 0; var_a finite and != 0; var_b finite, with both ends
/// of Eq. 5.15's range, var(U = 0) = -b/a and var(U = 1) = (1-b)/a, > 0 (else named at var_b).
/// Constant stress: characteristic_stress finite and > 0.
void validate(const HertzianContactCriterion& c, const std::string& path);
void validate(const ConstantStressCriterion& c, const std::string& path);

// --- HC (Eq. 5.13) ---

/// sigma_lim = sigma_lim0 (d/d0)^(-3/m1) var (Pa; Eq. 5.13 size effect). d in m, var > 0.
double strength_limit(const HertzianContactCriterion& c, double diameter, double var);
/// Eq. 5.15: var = (U - b)/a with U = strength_uniform(seed, grain_id) (breakage_model.hpp).
double strength_variability(const HertzianContactCriterion& c, std::uint64_t seed,
                            std::uint64_t grain_id);

/// The grain's strength, drawn once: sigma_lim with its own var (Pa).
double grain_strength(const HertzianContactCriterion& c, double diameter, std::uint64_t seed,
                      std::uint64_t grain_id);
/// (4 E' / (3 pi))^2 for a pair of effective modulus E'.
double pair_constant(const HertzianContactCriterion& c, double e_eff);
/// 1 / sigma_lim^2.
double grain_constant(const HertzianContactCriterion& c, double strength, double diameter);
/// delta / delta_crit with critical_overlap's delta_crit = r' (3 pi sigma_lim / (4 E'))^2, as
/// delta (4 E' / (3 pi))^2 (1/r') / sigma_lim^2: the mean Hertz pressure over sigma_lim, squared.
inline double pair_ratio(const HertzianContactCriterion&, double overlap, double inv_r_eff,
                         double pair_c, double grain_c) {
  return overlap * pair_c * inv_r_eff * grain_c;
}
/// F / F_crit with critical_force(sigma_lim, r, E'_wall): r' = r on a plane.
double wall_ratio(const HertzianContactCriterion& c, double force, double radius, double e_wall,
                  double strength);
/// E' at a wall contact: that of the grain against a rigid plane, or of two alike grains when
/// wall_as_grain.
inline double wall_modulus(const HertzianContactCriterion& c, double e_rigid_plane, double e_alike) {
  return c.wall_as_grain ? e_alike : e_rigid_plane;
}

// --- Constant characteristic stress ---

double grain_strength(const ConstantStressCriterion& c, double diameter, std::uint64_t seed,
                      std::uint64_t grain_id);
/// E' itself: the force is the Hertz force of the pair.
double pair_constant(const ConstantStressCriterion& c, double e_eff);
/// 1 / (sigma_c d^2).
double grain_constant(const ConstantStressCriterion& c, double strength, double diameter);
/// hertz_normal_force(E', r', delta) / (sigma_c d^2).
double pair_ratio(const ConstantStressCriterion& c, double overlap, double inv_r_eff, double pair_c,
                  double grain_c);
/// F / (sigma_c d^2), d = 2 r.
double wall_ratio(const ConstantStressCriterion& c, double force, double radius, double e_wall,
                  double strength);
inline double wall_modulus(const ConstantStressCriterion&, double e_rigid_plane, double) {
  return e_rigid_plane;  // unused: the wall law gives the force
}

}  // namespace kolsky::dem
