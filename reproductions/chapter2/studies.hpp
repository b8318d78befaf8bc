// The two Chapter 2 parametric studies on top of the calibrated dry EOS:
//   equilibrium study (Sec. 2.4.2): L/d 0.48, 0.75, 1 x friction 0, 0.2, alpha(t) (Eq. 2.15);
//   water-content study (Secs. 2.3.5-2.4.1): three-phase EOS tables (solver/eos) as the FE
//   compaction EOS at 0-20 % water, ~400/s, slopes, EOS components and dissipation at 8 %.
// Each records its measurements (target ids as in targets.json) and appends its plots.
#pragma once
#include <string>
#include <vector>

#include "chapter2/ch2.hpp"
#include "harness/plot.hpp"
#include "harness/score.hpp"
#include "harness/targets.hpp"

namespace kolsky::ch2 {

struct StudyContext {
  const BaseScene* base = nullptr;
  const nlohmann::json* targets = nullptr;   ///< the full targets.json (reference values)
  const nlohmann::json* reported = nullptr;  ///< data/digitized/chapter2/reported.json (SI)
  harness::Measurements* m = nullptr;
  std::vector<harness::Plot>* plots = nullptr;
  std::string* summary = nullptr;  ///< markdown lines appended for the report preamble
  TubeSpec steel;
  std::string repo_root, out_dir;
  const harness::TargetSet* target_set = nullptr;  ///< targets.json validated: trend thresholds
};

/// Sec. 2.4.2 with the calibrated dry EOS `eos` and the steel tube.
void equilibrium_study(const StudyContext& ctx, const Table1D& eos);

/// Secs. 2.3.5-2.4.1 for the given water contents (fractions).
void water_content_study(const StudyContext& ctx, const std::vector<double>& water_contents);

}  // namespace kolsky::ch2
