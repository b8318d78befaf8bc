// The regression gate: a run's measurements against the committed baseline, value by value.
// `kolsky_gate check` (inside `make test`) fails on any row whose verdict fails; write_report
// shows the rows beside the dissertation bands. docs/reproductions.md, "Regression gate".
#pragma once
#include "harness/baseline.hpp"

#include <string>
#include <vector>

namespace kolsky::harness {

enum class Verdict {
  same,     // bitwise equal
  within,   // moved, but no more than its tolerance
  moved,    // moved more than its tolerance: fails
  missing,  // in the baseline, not measured now: fails
  added,    // measured now, not in the baseline: fails (rebaseline to accept it)
  ungated,  // the baseline says round-off alone changes it: shown, never fails
};
std::string to_string(Verdict v);

struct GateRow {
  std::string set, id;
  Kind kind = Kind::scalar;
  std::string baseline, now;  // as text; a curve: its worst point
  double difference = 0.0;    // |now - baseline| (a curve: at its worst point)
  double allowed = 0.0;       // tolerance there
  std::string why;            // the baseline's reason for the tolerance, or what is wrong
  Verdict verdict = Verdict::same;

  bool fails() const;
};

/// One row per id of the baseline or the measurements, in baseline order, new ids last.
std::vector<GateRow> compare_to_baseline(const Baseline& b, const Measurements& m);

/// Fixed-width table for a terminal: set, id, baseline, now, difference, tolerance, verdict, why.
std::string gate_table_text(const std::vector<GateRow>& rows);
/// Same table in Markdown (report.md).
std::string gate_table_markdown(const std::vector<GateRow>& rows);
/// One cell for the targets table of report.md: "= baseline", "+3e-16 (tol 1e-12)", "MOVED ...".
std::string gate_cell(const GateRow& r);

/// A run against the committed baseline of its set and scale, as the reports show it.
struct BaselineComparison {
  std::string path;     // the baseline file looked for
  std::string problem;  // why there is no comparison (no baseline, unreadable); empty otherwise
  Baseline baseline;
  std::vector<GateRow> rows;
  const GateRow* row(const std::string& id) const;  // nullptr when absent
};
BaselineComparison compare_with_committed(const std::string& repo_root, const std::string& set,
                                          const std::string& scale, const Measurements& m);
/// "## Against the baseline" for report.md: what moved, with tolerances and their reasons. At
/// full scale a move is reported, never a failure (the dissertation band decides there).
std::string baseline_section_markdown(const BaselineComparison& c, const std::string& scale);

/// True when the log (reproductions/BASELINES.md) has an entry for this set, scale and digest.
bool log_has_entry(const std::string& log_text, const Baseline& b);

}  // namespace kolsky::harness
