// Speed against error of the upscaling factor N (Ch. 5 studies the same effect): the Ch. 4
// case with the calibrated rotational resistance repeated at other N, each against the set's
// own N (the reference), as the deviation of the sigma_t-strain curve up to the reference's
// 10 MPa point and the wall time of the case and of its packing. A finer N than the reference
// tells whether the reference is converged; coarser ones what their savings cost.
#pragma once
#include <string>
#include <vector>

#include "chapter4/ch4.hpp"

namespace kolsky::ch4 {

struct UpscalingRow {
  double n = 0;              ///< upscaling factor
  std::size_t grains = 0;
  double pack_s = 0;         ///< wall time of the packing (0 when read from the cache)
  bool packed_now = false;
  double case_s = 0;         ///< wall time of the SHPB case
  double dt = 0;             ///< DEM step, s
  double modulus = 0;        ///< Pa, sigma_t fit over back stress 1-10 MPa
  double rms = 0, max = 0;   ///< |sigma_t(N) - sigma_t(ref)| over the reference's strain range, Pa
  double toe_strain = NAN;   ///< strain at the first back stress >= lo (the end of the toe)
  WallLayer layer;           ///< solid fractions of the packing (whole, core)
  std::vector<double> strain, stress;  ///< sigma_t(strain) to the first 10 MPa sample, Pa
  bool ok = false;
  std::string failure;
};

/// Runs the calibrated case at each factor in `ns` (the scene `j` with specimen.upscale = n)
/// and compares its sigma_t(strain) with `reference` (already run, at the scene's own N)
/// between back stresses of lo and limit on the reference curve.
std::vector<UpscalingRow> upscaling_study(const nlohmann::json& j, const std::string& scene_path,
                                          const std::string& dir, double k,
                                          const CaseResult& reference, const Measures& ref_m,
                                          const std::vector<double>& ns, double lo, double limit);

/// Markdown table of the study (the reference, whose packing has `ref_layer`, first).
std::string upscaling_table(const CaseResult& reference, const Measures& ref_m,
                            const WallLayer& ref_layer, double reference_n,
                            const std::vector<UpscalingRow>& rows);

}  // namespace kolsky::ch4
