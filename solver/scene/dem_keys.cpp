// The DEM specimen's contact-law keys and the physics-to-scene names (see dem_keys.hpp).
#include "scene/dem_keys.hpp"

#include "scene/schema_builder.hpp"

namespace kolsky::scene {

using namespace table;

const std::vector<LawKey<dem::HertzMindlinParams>>& law_keys(const dem::HertzMindlinParams&) {
  using P = dem::HertzMindlinParams;
  static const std::vector<LawKey<P>> keys = {
      {"grain_friction", &P::friction, "friction", "-", kNonNegative,
       "Grain-grain Coulomb friction (Table 4.1: 0.5)"},
      {"restitution", &P::restitution, "restitution", "-", kHalfOpenUnitUpper,
       "Grain-grain restitution through Tsuji viscous damping (docs/dem.md); 1 = undamped"}};
  return keys;
}

const std::vector<LawKey<dem::LinearParams>>& law_keys(const dem::LinearParams&) {
  using P = dem::LinearParams;
  static const std::vector<LawKey<P>> keys = {
      {"linear_normal_stiffness", &P::normal_stiffness, "normal_stiffness", "N/m", kPositive,
       "Grain-grain k_n of the linear law (PFC linear model; no grain value is printed: the "
       "default is Table 4.1's linear wall contact)"},
      {"linear_shear_stiffness", &P::shear_stiffness, "shear_stiffness", "N/m", kNonNegative,
       "Grain-grain k_s of the linear law (default: Table 4.1's wall contact)"},
      {"linear_friction", &P::friction, "friction", "-", kNonNegative,
       "Grain-grain Coulomb friction of the linear law (default: Table 4.1's wall contact)"},
      {"linear_damping_ratio", &P::damping_ratio, "damping_ratio", "-", kHalfOpenUnitLower,
       "Normal and tangential dashpots of the linear law, fraction of critical damping"}};
  return keys;
}

const std::vector<LawKey<dem::LsDynaParams>>& law_keys(const dem::LsDynaParams&) {
  using P = dem::LsDynaParams;
  static const std::vector<LawKey<P>> keys = {
      {"normk", &P::normk, "normk", "-", kPositive,
       "NORMK: K_n = NORMK k_1 r_1 k_2 r_2 / (k_1 r_1 + k_2 r_2), k_i = E_i / (1 - 2 nu_i) "
       "(Eq. 3.1; Table 3.2: 0.07, back-calculated)"},
      {"sheark", &P::sheark, "sheark", "-", kNonNegative,
       "SHEARK: K_s = SHEARK K_n (Eq. 3.2; Table 3.2: 1, Wang and Leung 2008)"},
      {"fric", &P::fric, "fric", "-", kNonNegative,
       "FRIC: grain-grain Coulomb friction F_tr = FRIC F_N (Eq. 3.3; Table 3.2: 0.56, Henrych "
       "1979)"},
      {"fricr", &P::fricr, "fricr", "-", kNonNegative,
       "FRICR: rolling-resistance moment FRICR R* F_N (Eq. 3.4, with the lever arm R*; "
       "Table 3.2: 0.1, Flores-Johnson et al. 2015)"},
      {"ndamp", &P::ndamp, "ndamp", "-", kHalfOpenUnitLower,
       "NDAMP: normal damping, fraction of critical (Table 3.2: 0.1, Kermani et al. 2015)"},
      {"tdamp", &P::tdamp, "tdamp", "-", kHalfOpenUnitLower,
       "TDAMP: tangential damping, fraction of critical (Table 3.2: 0.1, no source given)"}};
  return keys;
}

const std::vector<LawKey<dem::LinearParams>>& wall_keys() {
  using P = dem::LinearParams;
  static const std::vector<LawKey<P>> keys = {
      {"wall_normal_stiffness", &P::normal_stiffness, "normal_stiffness", "N/m", kPositive,
       "Linear wall contact k_n, ends and tube (Table 4.1)"},
      {"wall_shear_stiffness", &P::shear_stiffness, "shear_stiffness", "N/m", kPositive,
       "Linear wall contact k_s (Table 4.1)"},
      {"wall_friction", &P::friction, "friction", "-", kNonNegative,
       "Wall-grain Coulomb friction (Table 4.1: 0.3)"}};
  return keys;
}

const std::vector<BreakageKey<dem::HertzianContactCriterion>>& breakage_keys(
    const dem::HertzianContactCriterion&) {
  using P = dem::HertzianContactCriterion;
  static const std::vector<BreakageKey<P>> keys = {
      {"sigma_lim0", &P::sigma_lim0, "Pa", kPositive,
       "Strength of a d0 grain, Eq. 5.13 (Song N = 2: 2.7e9; Wang 1.53e9 / 2.37e9, Huang 3.6e9, "
       "Sec. 5.3); grows with the upscaling factor, Eq. 5.17"},
      {"d0", &P::d0, "m", kPositive, "Reference diameter of sigma_lim0 (Sec. 5.2.3: 2 mm)"},
      {"m1", &P::m1, "-", kPositive, "Weibull modulus of the size effect (Sec. 5.2.3: 3, silica)"},
      {"var_a", &P::var_a, "-", kNoRange,
       "Eq. 5.15 slope a of var = (U - b)/a (Sec. 5.2.3: -1.22); must not be 0"},
      {"var_b", &P::var_b, "-", kNoRange,
       "Eq. 5.15 intercept b (Sec. 5.2.3: 1.67); var must stay > 0 over U in [0, 1)"},
      {"wall_as_grain", &P::wall_as_grain, "-", kNoRange,
       "Eq. 5.13 at a wall contact takes E' of two alike grains, E/(2(1 - nu^2)), instead of the "
       "grain on a rigid plane, E/(1 - nu^2): F_crit four times larger (the text leaves it open; "
       "docs/breakage.md)"}};
  return keys;
}

const std::vector<BreakageKey<dem::ConstantStressCriterion>>& breakage_keys(
    const dem::ConstantStressCriterion&) {
  using P = dem::ConstantStressCriterion;
  static const std::vector<BreakageKey<P>> keys = {
      {"characteristic_stress", &P::characteristic_stress, "Pa", kPositive,
       "A grain of diameter d breaks when one contact's elastic normal force reaches this x d^2 "
       "(McDowell and Bolton 1998; no size effect, no scatter; docs/breakage.md)"}};
  return keys;
}

const std::vector<BreakageKey<dem::BreakageParams>>& breakage_limit_keys() {
  using P = dem::BreakageParams;
  static const std::vector<BreakageKey<P>> keys = {
      {"coordination_limit", &P::coordination_limit, "-", kNonNegative,
       "c_lim: only grains with fewer contacts break (Secs. 5.3.1-5.3.3: 8); 0 = no limit "
       "(targets.md 5e.9)"},
      {"count_wall_contacts", &P::count_wall_contacts, "-", kNoRange,
       "Wall contacts count towards the coordination number (the text leaves it open; "
       "docs/breakage.md)"},
      {"comminution_factor", &P::comminution_factor, "-", kOpenUnit,
       "Grains below this x d50 of the initial grains never break (Sec. 5.2.3: 0.22)"},
      {"fines_fractal_dimension", &P::fines_fractal_dimension, "-", kPositive,
       "alpha of Eq. 5.16 for the lost mass (Sec. 5.2.3: 2.6)"},
      {"fines_d_min", &P::fines_d_min, "m", kPositive,
       "d_min of Eq. 5.16, the smallest size of the fines (Wang: 7.5e-6)"}};
  return keys;
}

const std::vector<BreakageKey<dem::BreakageCadence>>& breakage_cadence_keys() {
  using P = dem::BreakageCadence;
  static const std::vector<BreakageKey<P>> keys = {
      {"check_interval", &P::check_interval, "-", Range{1.0, kInf, false, false},
       "Steps between breakage checks (a check costs about one step; 1: every step; "
       "docs/breakage.md)"},
      {"check_period", &P::check_period, "s", kNonNegative,
       "Simulated time between breakage checks; 0 = every check_interval steps. Set it where dt "
       "is refined after breaks (time.refine_after_breaks), so the checks keep their cadence in "
       "time (docs/breakage.md 'Checks')"}};
  return keys;
}

namespace {
template <class P>
void add_names(std::vector<dem::InputName>& out, const std::vector<LawKey<P>>& keys,
               const std::string& internal) {
  for (const LawKey<P>& k : keys)
    out.push_back({internal + "." + k.physics_name, "specimen." + k.key});
}
}  // namespace

std::vector<dem::InputName> dem_input_names(const dem::ContactLawParams& law) {
  // The longest internal prefix wins, so the catch-alls ("dem.contact_law", "dem") only
  // take what the finer names leave.
  std::vector<dem::InputName> n = {
      {"dem", "specimen"},  // anything else: the DEM specimen as a whole
      {"dem.contact_law", "specimen.contact_law"},
      {"dem.walls", "specimen"},
      {"dem.walls.cylinder.radius", "specimen.diameter"},
      {"dem.specimen.length", "specimen.length"},
      {"dem.specimen.radius", "specimen.diameter"},
      {"dem.materials[0].youngs_modulus", "specimen.grain_shear_modulus"},
      {"dem.materials[0].poisson_ratio", "specimen.grain_poisson_ratio"},
      {"dem.materials[0].density", "specimen.grain_density"},
      {"dem.rolling.factor", "specimen.rolling_factor"},
      {"dem.packing", "specimen.packing"},
      {"dem.packing.curve", "specimen.upscale"},  // the upscaled curve's largest grain
      {"dem.packing.porosity", "specimen.porosity"},
      {"dem.packing.initial_solid_fraction", "specimen.upscale"},  // RSA found no room: coarse grains
      {"dem.packing.diameter", "specimen.diameter"},
      {"dem.packing.length", "specimen.length"},
      {"dem.packing.initial_stress", "specimen.initial_stress"},
      {"dem.packing.prestress_friction", "specimen.grain_friction"},
      {"dem.packing.prestress_wall_normal_stiffness", "specimen.wall_normal_stiffness"},
      {"dem.packing.prestress_wall_shear_stiffness", "specimen.wall_shear_stiffness"},
      {"dem.rest", "specimen.relax_to_rest"},
      {"dem.dt", "time.dt"}};
  std::visit([&](const auto& p) { add_names(n, law_keys(p), "dem.contact_law"); }, law);
  add_names(n, wall_keys(), "dem.walls.plane.law");
  add_names(n, wall_keys(), "dem.walls.cylinder.law");
  return n;
}

}  // namespace kolsky::scene
