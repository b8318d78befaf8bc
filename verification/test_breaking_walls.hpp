// The small strain-rate-walls specimen whose grains break within the first 20 us, shared by
// the tests of the time-step refinement (test_dt_refine.cpp) and of the loop's after_forces
// hook (test_after_forces.cpp).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

namespace kolsky::testing {

// The small walls specimen of test_strain_rate_walls (~250 grains, N = 5) with a low strength
// and no coordination limit, at 1200/s: grains break within the first 20 us.
inline nlohmann::json breaking_walls_scene(const std::string& rate_csv, double end) {
  return nlohmann::json{{"loading", {{"kind", "strain_rate"}, {"file", rate_csv}}},
          {"specimen", {{"model", "dem"},
                        {"grain_size_curve", std::string(KOLSKY_SOURCE_DIR) +
                                                 "/data/digitized/chapter4/song2009_psd_reconstructed.csv"},
                        {"upscale", 5.0}, {"seed", 7}, {"length", 0.006}, {"diameter", 0.008},
                        {"wall_friction", 0.3},
                        {"breakage", {{"sigma_lim0", 1.0e9}, {"coordination_limit", 0}}}}},
          {"time", {{"end", end}}},
          {"output", {{"interval", 1e-6}}}};
}

}  // namespace kolsky::testing
