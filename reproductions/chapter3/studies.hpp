// The Chapter 3 studies on top of the printed cases: the model-level comparison (speed against
// error, issue 16), the NORMK back-calculation with its twin experiment (GSL Brent on ln NORMK),
// and the printed grain modulus E = 70 MPa run as written (targets.md 3e.11).
#pragma once
#include <functional>
#include <map>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "chapter3/ch3.hpp"
#include "harness/plot.hpp"
#include "harness/score.hpp"

namespace kolsky::ch3 {

/// What every study needs: the scene, the studies file, the windows, where results go.
struct Context {
  nlohmann::json scene;          ///< the scale's base scene (as perturbed)
  std::string scene_path;        ///< its file
  std::string packing_cache;     ///< folder of the packing cache, next to the report
  nlohmann::json studies;        ///< studies_<scale>.json
  double eps_lo = 0.02, eps_hi = 0.06, cutoff = 13e6, ringing_time = 125e-6;
  harness::Measurements* m = nullptr;
  std::vector<harness::Plot>* plots = nullptr;
  std::string markdown;          ///< appended to the report preamble
  std::map<std::string, double> min_speedup;  ///< level id -> its ".faster" trend's threshold
};

/// For each reduced level of x.studies with a trend "ch3.level.<id>.faster" in `targets`, the
/// speed-up it must reach (its threshold "min_speedup"), read before any run so that a missing
/// one fails fast; a level without such a target records no speed trend.
std::map<std::string, double> level_speedups(const Context& x, const harness::TargetSet& targets);

/// base with `patch` merged in (RFC 7386 merge patch), as a case: the patch's leaves are its
/// changes (harness::changes_from_patch).
harness::Case make_case(const Context& x, const std::string& label, const nlohmann::json& patch);
Measures measure(const Context& x, const CaseResult& c);

/// Model levels: the full model (already run: `full`, `full_m`) against each reduced level of
/// studies.levels; refused combinations are reported as refused (the scene reader's message).
void model_levels(Context& x, const CaseResult& full, const Measures& full_m);

struct BackCalcResult {
  double normk = NAN;            ///< best evaluated
  double slope = NAN;            ///< Pa, there
  double bracket_lo = NAN, bracket_hi = NAN;
  bool converged = false;
  int evaluations = 0;
  std::map<double, double> evaluated;  ///< NORMK -> slope (Pa)
  std::string note;
};

/// NORMK whose slope (2-6 % strain) is `target` Pa: GSL Brent minimiser of
/// (ln slope - ln target)^2 over ln NORMK, after a bracketing walk from `guess`.
/// `slope_of(normk)` runs one case and returns its slope (NaN for a failed run).
BackCalcResult back_calculate(const std::function<double(double)>& slope_of, double target, double guess,
                              double factor, double rel_tol, int max_evaluations);

/// The twin experiment, the back-calculation against the text's 235 MPa, and the printed
/// modulus reading, on the level studies.backcalc.level names.
void normk_studies(Context& x, double slope_full_at_printed);

}  // namespace kolsky::ch3
