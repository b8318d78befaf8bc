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
  double rms_finest = NAN;   ///< the same against the finest N's curve (compare_with_finest)
  std::vector<double> strain, stress;  ///< sigma_t(strain), the whole run, Pa
  long i_end = 0;            ///< samples up to the first at the limit (10 MPa), or all
  bool ok = false;
  std::string failure;
};

/// Runs the calibrated case at each factor in `ns` (the set's case `base` with
/// specimen.upscale = n) and compares its sigma_t(strain) with `reference` (already run, at
/// the scene's own N) between back stresses of lo and limit on the reference curve.
std::vector<UpscalingRow> upscaling_study(const harness::Case& base, double k,
                                          const CaseResult& reference, const Measures& ref_m,
                                          const std::vector<double>& ns, double lo, double limit);

/// The deviation of every curve from the finest N's, as the issue asks for ("against the
/// finest N you can afford"), when a row is finer than the reference: RMS |sigma_t(N) -
/// sigma_t(finest)| at equal strain over the finest curve's samples from back stress `lo` up
/// to its largest stress (the finest specimens may not reach 10 MPa within the pulse), where
/// the other curve has data. Sets each row's rms_finest.
struct FinestComparison {
  double n = NAN;              ///< the finest N (NaN: the reference is the finest)
  double top = NAN;            ///< Pa, the largest back stress of its curve (window's end)
  double reference_rms = NAN;  ///< Pa, the reference's deviation from it
};
FinestComparison compare_with_finest(std::vector<UpscalingRow>& rows, const CaseResult& reference,
                                     double reference_n, double lo);

/// Markdown table of the study (the reference, whose packing has `ref_layer`, first).
std::string upscaling_table(const CaseResult& reference, const Measures& ref_m,
                            const WallLayer& ref_layer, double reference_n,
                            const std::vector<UpscalingRow>& rows, const FinestComparison& finest);

}  // namespace kolsky::ch4
