// The three tests of Chapter 5 as studies: each runs its cases, records its measurements
// (targets.json ids ch5.*), adds its plots and writes its part of the report's preamble.
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "chapter5/ch5.hpp"
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
  /// Runs a case and prints its one-line summary.
  CaseResult run(const CaseSpec& spec) const;
};

/// Sec. 5.3.1 and 5.3.4: the N pair, the variants, the back-calculation, speed against error.
void wang_study(Study& s);
/// What the Wang study hands its companions of the known deviations (wang_companions.cpp).
struct WangCompanionCases {
  CaseSpec pair_until;    ///< the pair as the set runs it (loaded until a stress, cases "load_until")
  CaseSpec ref_nobreak;   ///< the reference N without breakage, on the variants' history
  const CaseResult* pair_nobreak = nullptr;  ///< the variants' run without breakage
  const CaseResult* clim8 = nullptr;         ///< the variants' base (c_lim = 8)
  const CaseResult* clim0 = nullptr;         ///< the variants' c_lim = 0
};
/// Issue 31's companions: the cases file's wang.companions says what they run.
void wang_companions(Study& s, const WangCompanionCases& c, std::string& md);
/// Sec. 5.3.2.
void huang_study(Study& s);
/// Sec. 5.3.3.
void song_study(Study& s);

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
