// What `kolsky run` and `kolsky analyze` check and report before their work starts, beyond
// the scene itself: that every output can be written and overwrites no input, the expected
// size of the probes, and the DEM packing's initial wall stress against the pulse.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

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

/// An output a command will write, and the option that names it (for the error).
struct OutputPath {
  std::string option, path;
};

/// Throws InputError(option, "", rule) unless every output can be written: its folder exists
/// and is writable, it is not itself a folder, it is none of `inputs` (the same file under any
/// name: `kolsky run s.json -o s.json` would replace the scene), and no two outputs are the
/// same file. Called before any work, so a bad path costs nothing.
void check_outputs(const std::vector<OutputPath>& outputs, const std::vector<std::string>& inputs);

/// The input files a scene names (the scene itself and every CSV table it reads).
std::vector<std::string> scene_inputs(const scene::Scene& sc);

/// Above this many bytes of probe data (memory during the run, and the run file) `kolsky run`
/// warns with the expected size before it starts: beyond what a workstation holds comfortably.
inline constexpr double kProbeBytesWarning = 1024.0 * 1024.0 * 1024.0;

/// The expected probe data of the run (probes x samples x 16 bytes: time and value), with a
/// warning on stderr above kProbeBytesWarning. Returns the estimate in bytes.
double warn_probe_size(const shpb::SimulatedShpb& sim, const std::string& out);

/// A DEM specimen's initial end-wall stresses on stderr (unless quiet), a warning above
/// kInitialWallStressWarning x the pulse's peak stress (always), and the same numbers for the
/// run file's /meta ({"front": Pa, "back": Pa}); null for other specimens.
nlohmann::json report_initial_wall_stress(const shpb::SimulatedShpb& sim, const scene::Scene& sc,
                                          bool quiet);

}  // namespace kolsky::app
