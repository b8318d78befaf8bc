// Packing generator for DEM specimens: a cylinder of given diameter and length filled with
// spheres whose mass distribution follows a grain-size curve (already upscaled by N) at a target
// porosity n. Procedure (docs/dem.md, "Packing"):
//   1. diameters: psd::sample_diameters(curve, V (1 - n), seed) (sorted descending), so the
//      porosity 1 - sum(pi d^3/6)/V is met up to half the largest grain's volume and the sample's
//      curve matches the input within psd::max_passing_deviation_bound;
//   2. placement: random sequential addition (largest first) of the spheres shrunk by
//      s0 = (initial_solid_fraction / (1 - n))^(1/3), entirely inside the cylinder, no overlap;
//   3. growth: the radii grow linearly from s0 r to r over `growth_stages` stages of
//      `steps_per_stage` steps each, with frictionless, damped linear contacts (grains and
//      rigid walls; k_n = E r_mean, which only sets the time scale) and the velocities scaled by `velocity_quench` at each stage;
//   4. settling: stages at full size until the largest overlap (grain or wall) is below
//      `overlap_tolerance` x mean radius, or `max_settle_stages` is reached; then v = omega = 0.
// Deterministic for a seed (xoshiro256**, and DemSystem is bitwise the same for any thread
// count). Porosities below the frictionless jamming limit (solid fraction ~0.64) settle to a
// nearly overlap-free state with few contacts. With `jam` (opt-in), steps 3-4 use frictional
// contacts and a quenched settling instead, ending in a frictional contact network (Z ~ 4
// without rattlers) at the same porosity. With initial_stress > 0 the settled grains are then
// pre-stressed to that mean stress (prestress.hpp): the radii grow by a factor s - 1 ~ 1e-4,
// so the porosity drops by ~3 (s - 1)(1 - n) (reported). SI units.
#pragma once
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <functional>
#include <utility>

#include "core/specimen_geometry.hpp"
#include "dem/particles.hpp"
#include "psd/grain_size_curve.hpp"

namespace kolsky::dem {

/// A packing's progress, reported through PackingParams::on_progress.
struct PackingProgress {
  const char* phase = "";  ///< "growth" (or "compaction": the servo walls' gap / L), "settle",
                           ///< "prestress" or "relax" (make_dem_specimen's
                           ///< relaxation to rest: check windows, value = kinetic / initial elastic)
  int done = 0;            ///< stages (pre-stress: servo intervals) done in this phase
  int most = 0;            ///< the most this phase can take (it may end earlier)
  double value = 0;        ///< settle: largest overlap / mean radius; prestress: wall mean
                           ///< stress, Pa; growth: the radius scale s
  // Diagnostics of the frictional (jammed) growth and settling and of the pre-stress; NaN
  // where not reported (the loose packing's stages, and kinetic_to_elastic while pre-stressing).
  double wall_stress = NAN;         ///< wall mean stress (s_zz + 2 s_rr) / 3, Pa
  double coordination = NAN;        ///< 2 x touching grain pairs / grains (walls excluded)
  double kinetic_to_elastic = NAN;  ///< kinetic over elastic energy of the assembly
};

/// Steps per jamming stage with density scaling: the growth then stays fast against the
/// grains' motion, so they lock into a frictional network (docs/dem.md, "Packing").
inline constexpr int kJamScaledStepsPerStage = 60;

struct PackingParams {
  psd::GrainSizeCurve curve;       ///< grain sizes of the specimen (already upscaled), m
  double porosity = 0.44;          ///< target n = 1 - V_solid / V, in (0, 1)
  double diameter = kSpecimenDiameter; ///< cylinder diameter, m
  double length = kSpecimenLength;     ///< cylinder length (z from 0 to length), m
  std::uint64_t seed = 1;
  Material material;               ///< grain material (E, nu, rho) used while packing
  int material_index = 0;          ///< material index written into the particles
  double initial_solid_fraction = 0.25;  ///< RSA fill before growth, -
  int growth_stages = 30;
  int steps_per_stage = 50;
  double velocity_quench = 0.8;     ///< v, omega *= this at every stage, -
  double damping_ratio = 0.3;       ///< normal dashpot, fraction of critical, -
  double overlap_tolerance = 1e-3;  ///< settled when max overlap < this x mean radius, -
  int max_settle_stages = 200;
  int max_rsa_attempts = 20000;     ///< per sphere, before the placement throws
  // Jamming (docs/dem.md "Packing"). jam = false: the loose frictionless packing (steps 3-4
  // above). jam = true: growth with frictional linear contacts (stiffness = Hertz secant at
  // jam_overlap, walls frictionless), then settling at full size with v = omega = 0 at every
  // stage until the largest overlap < overlap_tolerance (at most max_settle_stages);
  // growth_stages, damping_ratio, overlap_tolerance and max_settle_stages apply to both.
  bool jam = false;
  double jam_friction = 0.3;          ///< grain-grain friction while packing (mu_pack), -
  double jam_overlap = 1e-4;          ///< design overlap / mean radius for the stiffness, -
  int jam_steps_per_stage = 200;      ///< kJamScaledStepsPerStage with jam_mass_scaling
  double jam_velocity_quench = 0.5;   ///< v, omega *= this at every growth stage, -
  /// Density scaling while jamming: no grain lighter than the mean grain (the end state is
  /// static; the step grows by sqrt(m_mean / m_min)); the result has the grains' own masses.
  /// Off by default, so existing scenes keep their packings (scene key
  /// specimen.packing_density_scaling; docs/dem.md, "Packing").
  bool jam_mass_scaling = false;
  /// Servo-wall compaction instead of growth (scene "packing": "servo_walls"; docs/dem.md,
  /// "Packing"): the grains placed at full size in a cylinder of length L (1 - n) /
  /// initial_solid_fraction, the end walls closing symmetrically to L over growth_stages stages
  /// of jam_steps_per_stage steps under the jammed packing's law (jam_friction, jam_overlap,
  /// jam_velocity_quench, jam_mass_scaling), then quenched settling. Overrides jam.
  bool servo_walls = false;
  /// Grains do not rotate while the jammed growth or the servo-wall compaction runs (k = 0 of
  /// Eqs. 4.12-4.14; scene key specimen.packing_lock_rotation). The pre-stress has its own
  /// (prestress_lock_rotation).
  bool packing_lock_rotation = false;
  // Pre-stress (prestress.hpp; docs/dem.md "Pre-stress"), after the settling; off at 0: all
  // radii scaled by one servo-controlled factor until the wall mean stress under damped
  // Hertz-Mindlin grain contacts (rigid frictionless Hertz walls) is initial_stress.
  double initial_stress = 0;            ///< target isotropic mean stress, Pa (0: none)
  double prestress_friction = 0.5;      ///< grain friction while pre-stressing (the test's), -
  double prestress_restitution = 0.1;   ///< Tsuji damping while pre-stressing, -
  double prestress_tolerance = 0.05;    ///< relative band on the servo's stress window
  int prestress_servo_interval = 50;    ///< steps between radius updates
  int prestress_max_steps = 40000;
  bool prestress_lock_rotation = true;  ///< grains do not rotate while pre-stressing (prestress.cpp)
  /// Walls while pre-stressing: frictionless linear springs k_n, k_s (N/m; the test's walls),
  /// or rigid frictionless Hertz walls when k_n = 0.
  double prestress_wall_normal_stiffness = 0;
  double prestress_wall_shear_stiffness = 0;
  /// Called after every growth and settling stage and every pre-stress servo interval (a
  /// progress report: packings take minutes to tens of minutes). It only observes: it is not
  /// part of the result or of the cache key. Empty: silent.
  std::function<void(const PackingProgress&)> on_progress;
};

struct PackingResult {
  Particles particles;            ///< at rest (v = omega = 0), material index as requested
  double porosity = 0;            ///< 1 - sum(4/3 pi r^3) / (pi D^2 L / 4), -
  double target_porosity = 0;
  std::size_t count = 0;
  double expected_count = 0;      ///< psd::expected_particle_count(curve, V, n)
  double coordination = 0;        ///< 2 x touching grain pairs / count, -
  double coordination_with_walls = 0;  ///< (2 x pairs + wall contacts) / count, -
  double max_overlap = 0;         ///< largest grain-grain or grain-wall overlap / mean radius
  double curve_deviation = 0;     ///< max |sample passing - curve passing|, percentage points
  double curve_deviation_bound = 0;  ///< psd::max_passing_deviation_bound, percentage points
  double kinetic_energy = 0;      ///< at the end of settling, before zeroing, J
  int steps = 0;                  ///< DEM steps taken (growth + settling)
  bool settled = false;           ///< overlap tolerance reached within max_settle_stages
  int stages = 0;                 ///< growth and settling stages run
  double coordination_no_rattlers = 0;  ///< (contacts incl. walls) / grain after removing,
                                        ///< repeatedly, grains with < 2 contacts, -
  double rattler_fraction = 0;    ///< fraction of grains removed as rattlers, -
  double mean_stress = 0;         ///< wall mean stress (s_zz + 2 s_rr)/3, packing law, end, Pa
  double mean_stress_hertz = 0;   ///< contact-virial mean stress of the final positions with
                                  ///< Hertz contacts (rigid Hertz walls), Pa
  double packing_friction = 0;    ///< friction used while packing (0 without jam), -
  double prestress_scale = 1;     ///< radius factor of the pre-stress (1: none), -
  int prestress_stages = 0;       ///< pre-stress servo intervals run (0: none)
  bool prestress_converged = false;  ///< pre-stress reached initial_stress within tolerance
};

/// Generates the packing. Throws kolsky::InputError("", "dem.packing...", rule) on bad
/// parameters or when RSA finds no place for a sphere (lower initial_solid_fraction), and
/// psd::InvalidCurve for an invalid curve.
PackingResult generate_packing(const PackingParams& params);

/// Pre-stresses a packing generated with in.initial_stress = 0 to in.initial_stress
/// (prestress.hpp) and retakes its census (coordination, stresses, porosity); generate_packing
/// does this itself when initial_stress > 0, the packing cache uses it to reuse the unstressed
/// packing.
void prestress_result(PackingResult& res, const PackingParams& in);

/// Largest overlap of grain pairs (brute force over a cell grid) and with the cylinder of
/// diameter D around the z axis and the planes z = 0 and z = L, in m.
double max_packing_overlap(const Particles& p, double diameter, double length);

/// The load-bearing network of grains in that cylinder: (contacts including walls per grain
/// after removing, repeatedly, grains with fewer than 2 contacts; fraction of grains removed
/// as rattlers). A contact is a geometric overlap (PackingResult::coordination_no_rattlers).
std::pair<double, double> coordination_without_rattlers(const Particles& p, double diameter,
                                                        double length);

/// Deviatoric fabric of the grain contacts about the cylinder axis: phi_zz - (phi_xx + phi_yy)/2
/// of the fabric tensor phi = <n n> over touching pairs (Satake 1982; Oda 1982): 0 for isotropic
/// contact normals, > 0 with more of them along z (at most 1), < 0 with more across (at least
/// -1/2). Walls are not counted.
double fabric_anisotropy(const Particles& p, double diameter, double length);

/// Porosity of the interior of the specimen cylinder (diameter, length): the part farther than
/// `margin` from the tube and from both end walls, estimated from `samples` points drawn
/// uniformly in it (xoshiro256**, `seed`): 1 - the fraction inside a grain. The standard error
/// is sqrt(n (1 - n) / samples). Grains pack looser against a wall (a layer about half a
/// diameter thick), so a specimen's interior is denser than its whole volume: issue 31, H1,
/// "porosity counted over the whole sleeve". Throws std::invalid_argument when the margin
/// leaves no interior or samples < 1.
double interior_porosity(const Particles& p, double diameter, double length, double margin,
                         long samples = 1000000, std::uint64_t seed = 1);

}  // namespace kolsky::dem
