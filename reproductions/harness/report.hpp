// One call per reproduction driver: score the measurements against targets.json and write
// out_dir/results.json (machine-readable), out_dir/report.md (for people) and the plots.
// results.json: {"set", "scale", "git_commit", "wall_time_s", "targets": [{"id", "value", "lo",
// "hi", "reference", "unit", "source", "status", "pass"} + optional "unexpected_pass",
// "worst_point", "note"]}. Layout and scoring rules: docs/reproductions.md.
#pragma once
#include "harness/plot.hpp"
#include "harness/score.hpp"
#include "harness/targets.hpp"

#include <string>
#include <vector>

namespace kolsky::harness {

struct ReportInput {
  std::string set;           // must equal "set" in targets.json
  std::string scale;         // "smoke" | "full" (free text, reported as given)
  std::string targets_path;  // reproductions/<set>/targets.json
  std::string out_dir;       // created if missing
  std::string repo_root;     // curve reference files are relative to it
  double wall_time_s = 0.0;
  Measurements m;
  std::vector<Plot> plots;
  std::string preamble_markdown;  // shown right after the title
  std::string gnuplot = default_gnuplot();  // "" disables plotting
};

/// Writes results.json, report.md and the plots. Returns the number of expected_pass targets
/// that failed (0: the set passes); known deviations never count.
/// Throws kolsky::InputError for an invalid targets.json or a set name mismatch,
/// std::invalid_argument for malformed plots, std::runtime_error if a file cannot be written.
int write_report(const ReportInput& in);

/// Scores every target of `targets` (in file order) against m. Each Score points into
/// `targets`, which must outlive the result.
std::vector<Score> score_all(const TargetSet& targets, const Measurements& m);

}  // namespace kolsky::harness
