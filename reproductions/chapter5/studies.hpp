// The three tests of Chapter 5 as studies, each in three steps: plan (every case and chain it
// runs, decided from the cases file and the printed values before any run), its members in the
// set's ensemble (set.hpp: phase A the independent cases, phase B the chains that need phase A's
// results), and measure (its targets.json ids ch5.*, its plots and its part of the report's
// preamble, from the results alone).
#pragma once
#include <array>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "chapter5/backcalc.hpp"
#include "chapter5/ch5.hpp"
#include "chapter5/set.hpp"
#include "harness/report.hpp"
#include "harness/targets.hpp"

namespace kolsky::ch5 {

struct Study {
  bool smoke = false;
  std::string dir, cache;        ///< reproductions/chapter5, <out>/packing_cache
  nlohmann::json cases;          ///< cases_<scale>.json
  nlohmann::json reported;       ///< data/digitized/chapter5/reported.json
  harness::Measurements* m = nullptr;
  std::vector<harness::Plot>* plots = nullptr;
  std::string markdown;          ///< appended to the report's preamble
  unsigned perturb_seed = 0;     ///< --perturb-ulp
  const harness::TargetSet* targets = nullptr;       ///< this scale's targets file
  const harness::TargetSet* full_targets = nullptr;  ///< targets.json (the same at full scale)
  double printed(const std::string& id) const;
  /// A trend's threshold (harness::threshold) from this scale's targets file; a target the
  /// smoke file leaves out (measured and gated there, not scored) keeps targets.json's.
  double threshold(const std::string& id, const std::string& key) const;
  CaseRunner runner() const { return {dir, cache, perturb_seed}; }
};

// ---- Wang et al. (2018), Sec. 5.3.1 and 5.3.4 (wang_plan.cpp, wang.cpp, wang_companions.cpp)

/// A back-calculation of sigma_lim0 at one N: its settings and its candidate case (each
/// evaluation runs it at its sigma_lim0).
struct BackCalcPlan {
  double n = 0;
  BackCalcSettings settings;
  CaseSpec candidate;
};
/// One N of speed against error: the reference itself, a back-calculation's best run, or a run
/// at Eq. 5.17's sigma_lim0; and the packing seeds run at that run's sigma_lim0.
struct SpeedPlan {
  double n = 0;
  bool is_ref = false;
  long backcalc = -1;         ///< index into WangPlan::backcalcs whose best run it takes
  CaseSpec eq517;             ///< the run when there is no best run
  std::vector<long> seeds;
};
struct WangPlan {
  double n_ref = 0, n_pair = 0, sig1 = 0, sig15 = 0, sig_ref = 0, sig_pair = 0, end = 0;
  double m1 = 3;              ///< scene_wang.json's, the exponent of Eq. 5.17
  bool until = false;         ///< cases "load_until": the pair loaded until a stress
  // The pass rules' numbers (targets files), read before any run so that a missing one fails fast.
  double pair_low_rms = 0, pair_high_frac = 0, variants_rms = 0, nobreak_ratio = 0, clim0_ratio = 0, clim0_breaks = 0;
  CaseSpec ref, pair;
  double n_twin = 0, sig_twin = 0;
  bool twin_is_pair = true, has_twin = false;
  CaseSpec twin_ref;          ///< the twin's synthetic curve when it is not the pair's
  BackCalcPlan twin;
  double nv = 0, sig_v = 0;   ///< the variants' N and sigma_lim0
  CaseSpec base_rerun, nobreak, clim0;  ///< base_rerun only with until
  bool has_companions = false;
  CaseSpec end_count, ref_nobreak;      ///< the companions' runs (wang_companions.cpp)
  std::vector<BackCalcPlan> backcalcs;
  std::vector<SpeedPlan> speed;
};
struct WangRuns {
  CaseResult ref, pair, twin_ref, base_rerun, nobreak, clim0, end_count, ref_nobreak;
  bool twin_ran = false;
  BackCalcResult twin;
  std::vector<BackCalcResult> backcalcs;       ///< per plan.backcalcs; empty when the reference failed
  std::vector<std::vector<CaseResult>> speed;  ///< per plan.speed: its run, then its seeds that ran
  /// Each back-calculation's first three evaluations (first_evaluations), run in phase A beside
  /// the reference: per plan.backcalcs, and the twin's.
  std::vector<std::array<CaseResult, 3>> backcalc_first;
  std::array<CaseResult, 3> twin_first;
  const CaseResult& base(const WangPlan& p) const;  ///< the variants' c_lim = 8 run
};
WangPlan wang_plan(const Study& s);
/// Phase A: the reference, the pair, the twin's curve, the variants, and the first three
/// evaluations of every back-calculation.
void wang_cases(const WangPlan& p, const CaseRunner& r, SetEnsemble& e, WangRuns& runs);
/// Phase B, on phase A's results: the twin's and the N's back-calculations (each followed by its
/// N's speed runs), the other N's speed runs, the companions' runs.
void wang_chains(const WangPlan& p, const CaseRunner& r, SetEnsemble& e, WangRuns& runs);
void wang_measure(Study& s, const WangPlan& p, const WangRuns& runs);
/// Issue 31's companions of the known deviations (full scale: the cases file's wang.companions).
void wang_companions(Study& s, const WangPlan& p, const WangRuns& runs, std::string& md);

// ---- Huang et al. (2013), Sec. 5.3.2, and Song et al. (2009), Sec. 5.3.3 (huang_song.cpp)
CaseSpec huang_plan(const Study& s);
void huang_measure(Study& s, const CaseResult& c);
struct SongPlan {
  double same_rms_frac = 0, softer_k = 0, softer_mean = 0;  ///< the pass rules' numbers
  CaseSpec breakage, no_breakage;
};
SongPlan song_plan(const Study& s);
void song_measure(Study& s, const SongPlan& p, const CaseResult& brk, const CaseResult& nob);

/// The wanted studies ("wang", "huang", "song") as the set's ensemble: each planned, phase A
/// run (their independent cases), phase B run (Wang's chains, on phase A's results), then, on
/// rank 0 only, each measured, in the fixed order Wang, Huang, Song. Returns false on the
/// other ranks (they have nothing to report). Throws what planning throws (a missing printed
/// value or threshold).
bool run_studies(Study& s, SetEnsemble& e, const std::function<bool(const std::string&)>& wanted);

/// A figure and a line with every member set (the aggregates warn when left partly empty).
inline harness::Plot figure(std::string file, std::string title, std::string x, std::string y) {
  harness::Plot p;
  p.file = std::move(file), p.title = std::move(title), p.xlabel = std::move(x), p.ylabel = std::move(y);
  return p;
}
inline harness::PlotSeries series(std::string label, std::vector<double> x = {}, std::string style = "lines") {
  harness::PlotSeries p;
  p.label = std::move(label), p.x = std::move(x), p.style = std::move(style);
  return p;
}

}  // namespace kolsky::ch5
