// Particle breakage in a running DemSystem (Sec. 5.2.3; docs/breakage.md): which grains break
// (find_breaks) and their replacement by the 14 daughters of Table 5.3 (apply_breaks), between
// two steps. The model pieces are pure (breakage_model.hpp, apollonian.hpp, breakage_ledger.hpp);
// this file holds the per-grain state they need and keeps it aligned with the particles through
// DemSystem::edit's index map (which includes a locality re-sort).
// Determinism: the decision reads the contacts in DemSystem::for_each_touching_contact's fixed order
// and the grains' own strengths, drawn from (seed, grain id) only; replacements go in
// ascending parent index. No thread count, check order or restart enters either.
#pragma once
#include <cstdint>
#include <vector>

#include "dem/breakage_ledger.hpp"
#include "dem/breakage_model.hpp"
#include "dem/dem_system.hpp"
#include "psd/grain_size_curve.hpp"

namespace kolsky::dem {

/// Per-grain breakage state, index-aligned with DemSystem::particles(), plus the ledger.
struct BreakageState {
  BreakageParams params;
  std::uint64_t seed = 0;
  double d50_initial = 0.0;   ///< m, mass-weighted d50 of the grains as generated (upscaled)
  std::vector<std::uint64_t> id;          ///< grain ids: initial grains 0..n-1, daughters daughter_id()
  std::vector<double> strength;           ///< sigma_lim of each grain, Eq. 5.13 with its own var, Pa
  std::vector<unsigned char> generation;  ///< 0: initial grain; a daughter: its parent's + 1 (capped)
  BreakageLedger ledger;
  psd::GrainSizeCurve initial_curve;  ///< the grains as generated, on `sizes`
  std::vector<double> sizes;          ///< m, where the curves are tabulated (docs/breakage.md)
  /// Energy of the replacements (J; both also inside DemEnergy::edited): kinetic energy that
  /// left with the lost 46.6 % of the mass, and the rest, the stored contact energy that the
  /// replacement takes out of the assembly (insertion: the parents' contact energy minus the
  /// daughters'; positive when energy is released, as DemEnergy::edited books what edits remove).
  double kinetic_removed = 0.0, insertion_energy = 0.0;
};

/// d50 of the grains by mass (m): the smallest diameter whose grains, with every smaller one,
/// hold at least half the volume.
double mass_d50(const Particles& p);

/// The state of a specimen's grains before any break: ids 0..n-1 in index order, strengths
/// drawn from (seed, id), d50 and the initial curve of these grains. Throws InputError for bad
/// parameters (validate, validate_against_d50) at path "specimen.breakage".
BreakageState start_breakage(const BreakageParams& p, std::uint64_t seed, const Particles& grains);

/// Smallest radius breakage can create for these grains (m): half smallest_daughter_diameter
/// of the comminution limit, for DemOptions::smallest_radius_to_come.
double smallest_radius_to_come(const BreakageParams& p, const Particles& grains);

struct BreakEvent {
  int grain = 0;
  Vec3 axis;  ///< direction of the grain's largest contact force (unit)
};

/// Grains that break in the current state, ascending: some contact of the grain has an elastic
/// normal force F >= F_crit (Eq. 5.13 closed form with that contact's r' and E'), its counted
/// coordination is below c_lim (or c_lim = 0) and it is not below the comminution limit.
/// F: for a grain pair the Hertz elastic force (4/3) E' sqrt(r') delta^1.5 of the overlap (the
/// criterion is one on the Hertz contact pressure; a dashpot force has no contact area); for a
/// wall contact the wall law's normal force, with r' = the grain's radius (plane) and E' of the
/// grain against a rigid wall. Requires the forces of the current state.
std::vector<BreakEvent> find_breaks(const DemSystem& sys, const BreakageState& s);

/// Grains of the initial specimen (generation 0) that the coordination limit keeps whole now:
/// their load ratio is >= 1 and they are above the comminution limit, but their counted
/// coordination is >= c_lim (both zero when c_lim = 0). `primary_at_limit`: those of them with
/// exactly c_lim contacts, the grains a "not more than c_lim" reading of Sec. 5.2.3 ("lower
/// than a specified limit") would break. A diagnostic of the same pass as find_breaks (the
/// same loads, the same counts); it changes nothing (issue 31, Huang's count at 42.5 MPa).
struct HeldByCoordination {
  std::size_t primary = 0, primary_at_limit = 0;
};
HeldByCoordination held_by_coordination(const DemSystem& sys, const BreakageState& s);

/// Replaces each event's grain by its 14 daughters (place_daughters about the event's axis,
/// turned by the grain's own spin angle), daughters moving with the parent's velocity and spin
/// (docs/breakage.md), through one DemSystem::edit; records the breaks and the lost mass in the
/// ledger and realigns the per-grain state. Returns the number of grains replaced.
std::size_t apply_breaks(DemSystem& sys, BreakageState& s, const std::vector<BreakEvent>& events);

/// The specimen's grain-size curve now (simulated grains plus fines) on s.sizes, and Hardin's
/// B_r of it against the initial curve (threshold params.hardin_threshold: 75 um x N).
psd::GrainSizeCurve current_grain_size_curve(const BreakageState& s, const Particles& grains);
double relative_breakage(const BreakageState& s, const Particles& grains);

}  // namespace kolsky::dem
