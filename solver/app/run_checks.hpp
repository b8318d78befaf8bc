// What `kolsky run` checks and reports before the simulation starts, beyond the scene itself:
// the DEM packing's initial wall stress against the pulse.
#pragma once
#include <nlohmann/json.hpp>

#include "scene/scene.hpp"
#include "shpb/simulation.hpp"

namespace kolsky::app {

/// Above this fraction of the pulse's peak stress, a packing's initial end-wall stress is
/// warned about. The bars carry it from t = 0 (unless specimen.preload_on_supports), so it is
/// an offset of the whole stress-strain record, and its release while the grains rearrange is
/// energy the check judges against a still small injected pulse: at 5 % the offset is already
/// larger than the scatter the equilibrium indices resolve. A deliberate pre-stress
/// (specimen.initial_stress > 0) is reported, not warned about.
inline constexpr double kInitialWallStressWarning = 0.05;

/// A DEM specimen's initial end-wall stresses on stderr (unless quiet), a warning above
/// kInitialWallStressWarning x the pulse's peak stress (always), and the same numbers for the
/// run file's /meta ({"front": Pa, "back": Pa}); null for other specimens.
nlohmann::json report_initial_wall_stress(const shpb::SimulatedShpb& sim, const scene::Scene& sc,
                                          bool quiet);

}  // namespace kolsky::app
