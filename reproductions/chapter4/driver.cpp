// Reproduction set "chapter4": the dissertation's Ch. 4 DEM-only SHPB (PFC3D in the text) on
// kolsky's DEM specimen between sphere-chain bars (216/108 balls, Table 4.1): the Song et al.
// (2009) dry sand, upscaled PSD (N = 2 full, N = 6 smoke), jammed packing at porosity 0.44,
// Hertz-Mindlin grains, Table 4.1 linear walls, the reconstructed 480/s pulse. Measured, up
// to a back-face stress of 10 MPa (Sec. 4.4.1): the confined modulus (initial and stiffened),
// alpha(t), the average-face vs back-face response, and the rotational-resistance family
// (Sec. 4.4.2). Reference values and bands live in targets.json (full) / targets_smoke.json.
// The set is a recipe of numbered steps (recipe.hpp); each step's file says why it measures
// what it does, citing the text.
#include <chrono>
#include <cstdio>

#include "chapter4/recipe.hpp"
#include "core/errors.hpp"

using namespace kolsky;

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // progress lines reach a log file as they happen
  const auto args = repro::parse_driver_args(argc, argv, "chapter4");
  const auto start = std::chrono::steady_clock::now();
  try {
    // 1. Inputs: targets, the text's printed values, the set's scene with its packing cache
    //    and any diagnostic overrides.
    ch4::Recipe r = ch4::read_inputs(args);
    // 2. The packing (Sec. 4.3), timed here, through the cache every later case hits.
    ch4::pack_specimen(r);
    // 3. The twin experiment: the back-calculation recovers a known k on a cheap specimen
    //    before it is trusted on the real one.
    ch4::twin_experiment(r);
    // 4. The cases: the printed k, then the rotational family k = 0, 0.999, 1 (Sec. 4.4.2).
    ch4::run_family(r);
    // 5. Sec. 4.4.1 on the printed case: confined moduli, stiffening, alpha, sigma_avg.
    ch4::measure_printed(r);
    // 6. Sec. 4.4.2: the orderings of the rotational family.
    ch4::rotation_orderings(r);
    // 7. The rotational factor back-calculated against the text's 220 MPa.
    ch4::back_calculate_k(r);
    // 8. The jammed diagnostic specimen, companion of the known deviations.
    ch4::jammed_specimen(r);
    // 9. Plots of the printed case and of the family.
    ch4::case_plots(r);
    // 10. Speed against error of the upscaling factor N.
    ch4::upscaling(r);
    // 11. Scatter between packing seeds.
    ch4::seed_scatter(r);
    // 12. Plots of the back-calculation and of the specimens side by side.
    ch4::calibration_plots(r);
    // 13. The report, scored against targets(_smoke).json.
    return ch4::write_report(r, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
  } catch (const InputError& e) {  // a scene, a KOLSKY_CH4_SET item or a targets file refused
    std::fprintf(stderr, "reproduce_chapter4: %s\n", e.what());
    return kExitInputError;
  }
}
