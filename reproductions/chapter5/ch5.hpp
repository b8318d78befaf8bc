// Chapter 5 reproduction helpers: one breakage case (a scene of this folder with the driver's
// changes: upscaling factor, sigma_lim0, coordination limit, breakage on or off) as a case of
// the one pipeline (harness/case_pipeline.hpp), what the set reads off its outputs
// (stress-strain, grain counts, broken parents, B_r, grain-size curves over time), and the
// comparisons Sec. 5.3 makes on such cases (curves at equal strain, downscaled grain-size
// curves at equal stress).
#pragma once
#include <cmath>
#include <cstdio>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "harness/case_pipeline.hpp"
#include "psd/grain_size_curve.hpp"

namespace kolsky::ch5 {

/// printf into a std::string (any arguments; the drivers' repro::fmt takes one double).
template <class... A>
std::string fmt(const char* f, A... a) {
  const int n = std::snprintf(nullptr, 0, f, a...);
  std::string s(n > 0 ? n : 0, '\0');
  if (n > 0) std::snprintf(s.data(), s.size() + 1, f, a...);
  return s;
}

/// What a driver says about a case: the changes of its scene (a negative / empty value keeps
/// the scene's); make_case turns it into the pipeline's changes.
struct CaseSpec {
  std::string label;
  std::string scene;          ///< file name in reproductions/chapter5/
  double upscale = -1;        ///< specimen.upscale
  double sigma_lim0 = -1;     ///< specimen.breakage.sigma_lim0, Pa
  int coordination_limit = -1;
  bool breakage = true;       ///< false: the breakage block is removed
  double end_time = -1;       ///< time.end, s
  double fines_d_min = -1;    ///< m in the *original* sand (x N in the specimen)
  // Loading, seed and overrides (issue 31: H2 / H3 studies, the full set's load_until and speed seeds):
  std::string loading_file;   ///< loading.file, relative to reproductions/chapter5/
  double end_at_back_stress = -1;  ///< loading.end_at_back_stress, Pa
  long seed = -1;                  ///< specimen.seed (the packing's)
  std::vector<std::string> sets;   ///< "dotted.key=JSON" changes (harness/case_pipeline.hpp)
};

struct CaseResult {
  CaseSpec spec;
  bool ok = false;
  std::string failure;
  double upscale = 1, wall_s = 0, pack_s = 0, dt = 0, simulated_s = 0;
  double dt_final = 0;  // s: below dt when breaks refined the step (docs/breakage.md, "Time step")
  long steps = 0;
  std::size_t grains_initial = 0, grains_final = 0;
  // The stress-strain record (strain-rate walls: the walls; bars: the classic analysis, t = 0
  // at the arrival): strain (Eq. 5.1 / 1.1), back-face (TB) and average stress, Pa.
  std::vector<double> t, strain, stress_back, stress_avg;
  // Probes of the breakage on the same samples as t (empty without breakage).
  std::vector<double> grain_count, broken_primary, broken_secondary, relative_breakage;
  // Initial grains at or past their force criterion that c_lim keeps whole at each sample, and
  // those of them with exactly c_lim contacts (dem::held_by_coordination; empty when c_lim = 0).
  std::vector<double> held_primary, held_primary_at_limit;
  std::vector<harness::CurveAt> curves;  ///< every microsecond of a breakage run, on t's clock
  harness::GaugeRecord gauges;  ///< bar runs only: on the run's clock
  double arrival_time = 0;
  double coordination_final = NAN;  ///< grain contacts per grain at the end
  std::string ended_by;  ///< set when loading.end_at_back_stress ended the run
};

/// The pipeline's case for `spec`: the scene file `dir`/spec.scene (perturb_seed > 0 moves
/// every float of it by one ulp first, common/perturb.hpp, for `make rebaseline`), the spec's
/// changes, a grain-size curve every microsecond, a progress line per tenth of the run, and
/// the packings cached in `cache`. Throws what reading the scene file throws.
harness::Case make_case(const CaseSpec& spec, const std::string& dir, const std::string& cache,
                        unsigned perturb_seed = 0);

/// The set's record of a case from the pipeline's outputs: the history (strain-rate walls: the
/// walls; bars: the classic analysis, t = 0 at the arrival) with the breakage probes and the
/// curves on its clock. A run that completed but could not be analysed is a failure.
CaseResult case_result(const CaseSpec& spec, double upscale, const harness::CaseOutputs& out);

/// Runs `spec` through the pipeline (make_case, harness::run_case); never throws (a failure is
/// ok = false with its reason).
CaseResult run_case(const CaseSpec& spec, const std::string& dir, const std::string& cache, unsigned perturb_seed = 0);

/// Where a set's cases run from: the scenes' folder, the packing cache, the --perturb-ulp seed.
struct CaseRunner {
  std::string dir, cache;
  unsigned perturb_seed = 0;
  harness::Case make(const CaseSpec& spec) const { return make_case(spec, dir, cache, perturb_seed); }
  /// run_case, with a line when it starts and its one-line summary when it ends.
  CaseResult run(const CaseSpec& spec) const;
};

/// Back stress of c at strain e on its loading branch (up to its largest strain), linear
/// between samples; NaN outside it.
double stress_at_strain(const CaseResult& c, double e);

/// The largest value of v (NaN for none).
double max_of(const std::vector<double>& v);

/// Index of the first sample with v >= level, or -1.
long first_at_least(const std::vector<double>& v, double level);

/// RMS and largest difference of b's stress from a's at a's strains where both are defined and
/// a's stress lies in [lo, hi] (Pa); NaN when fewer than 3 points compare.
struct CurveDifference {
  double rms = NAN, max = NAN;
  int points = 0;
};
CurveDifference stress_difference(const std::vector<double>& strain_a, const std::vector<double>& stress_a,
                                  const std::vector<double>& strain_b, const std::vector<double>& stress_b,
                                  double lo, double hi);

/// The case's grain-size curve at the first sample whose back stress reaches `stress`,
/// downscaled by the case's N (diameters / N); empty curve if it never does.
psd::GrainSizeCurve curve_at_stress(const CaseResult& c, double stress, double* time = nullptr);

/// RMS difference (percentage points) of two curves' percent passing, over log-spaced sizes
/// in [lo, hi] (m) where both are defined.
double passing_difference(const psd::GrainSizeCurve& a, const psd::GrainSizeCurve& b, double lo, double hi);

/// Broken parents (primary + secondary) at the first sample with back stress >= s; NaN if never.
double broken_at_stress(const CaseResult& c, double stress);

nlohmann::json read_json(const std::string& path);

/// m1 of a scene's breakage (specimen.breakage.m1; 3 in every scene of this folder): the
/// exponent of Eq. 5.17 (dem::sigma_lim0_between), read from the scene file as written.
double scene_m1(const std::string& dir, const std::string& scene);

/// Yield stress of a broken-count curve on a semi-log plot (Fig. 5.12): the intersection of the
/// two straight lines (count against log10 stress) that fit it best with one break point, the
/// construction used for yield on e-log p curves; NaN with fewer than 6 points above zero count.
double bilinear_yield(const std::vector<double>& stress, const std::vector<double>& count);


}  // namespace kolsky::ch5
