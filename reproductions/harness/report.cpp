// results.json and report.md for one reproduction set (formats in report.hpp). Both are written
// atomically after all scoring and plotting, so a crashed driver never leaves a report that looks
// complete.
#include "harness/report.hpp"

#include "harness/baseline.hpp"
#include "harness/gate.hpp"

#include "core/atomic_file.hpp"
#include "core/build_info.hpp"
#include "core/errors.hpp"

#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

namespace kolsky::harness {
namespace {

namespace fs = std::filesystem;
using Json = nlohmann::ordered_json;  // keeps the documented key order in results.json

Json number(std::optional<double> v) {
  return v && std::isfinite(*v) ? Json(*v) : Json(nullptr);
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return buf;
}

/// "[lo, hi]". Built by appending: GCC 12 at -O3 raises a false -Wrestrict on "[" + rvalue.
std::string interval(double lo, double hi) {
  std::string s = "[";
  s += fmt(lo);
  s += ", ";
  s += fmt(hi);
  s += "]";
  return s;
}

/// Table-cell safe text: a '|' would end the cell, a line break the row.
std::string cell(const std::string& s) {
  std::string out;
  for (char c : s) {
    if (c == '|') out += "\\|";
    else if (c == '\n' || c == '\r') out += ' ';
    else out += c;
  }
  return out;
}

Json worst_json(const WorstPoint& w) {
  Json j;
  j["x_ref"] = w.x_ref;
  j["y_ref"] = w.y_ref;
  j["x_nearest"] = number(w.x_nearest);
  j["y_nearest"] = number(w.y_nearest);
  j["error"] = number(w.error);
  j["allowed"] = w.allowed;
  if (w.outside) j["outside_measured_range"] = true;
  return j;
}

Json results_json(const ReportInput& in, const std::vector<Score>& scores) {
  Json r;
  r["set"] = in.set;
  r["scale"] = in.scale;
  r["git_commit"] = build_info::git_commit();
  r["wall_time_s"] = number(in.wall_time_s);
  r["targets"] = Json::array();
  for (const Score& s : scores) {
    const Target& t = *s.target;
    Json e;
    e["id"] = t.id;
    e["value"] = number(s.value);
    e["lo"] = number(s.lo);
    e["hi"] = number(s.hi);
    e["reference"] = Json::parse(t.reference.raw.dump());  // same content, ordered_json type
    e["unit"] = t.unit;
    e["source"] = t.reference.source;
    e["status"] = to_string(t.status);
    e["pass"] = s.pass;
    if (s.unexpected_pass) e["unexpected_pass"] = true;
    if (!t.companions.empty()) e["companions"] = t.companions;
    if (s.worst) e["worst_point"] = worst_json(*s.worst);
    if (!s.note.empty()) e["note"] = s.note;
    r["targets"].push_back(std::move(e));
  }
  return r;
}

std::string measured_text(const Score& s) {
  const Target& t = *s.target;
  if (!s.measured) return "not measured";
  if (!s.value) return s.worst && s.worst->outside ? "outside measured range" : "n/a";
  switch (t.kind) {
    case Kind::trend: return *s.value != 0.0 ? "holds" : "does not hold";
    case Kind::curve:
      return (s.worst && s.worst->y_ref == 0.0 ? "abs. err " : "rel. err ") + fmt(*s.value);
    case Kind::scalar: break;
  }
  return fmt(*s.value);
}

std::string band_text(const Score& s) {
  const Target& t = *s.target;
  if (t.kind == Kind::trend) return "must hold";
  std::string text;
  if (s.lo && s.hi) text = interval(*s.lo, *s.hi);
  if (t.tolerance) {
    std::string tol = "rtol " + fmt(t.tolerance->rtol) + ", atol " + fmt(t.tolerance->atol);
    if (t.kind == Kind::curve) tol += ", xtol " + fmt(t.tolerance->xtol);
    text += text.empty() ? tol : " (" + tol + ")";
  }
  return text;
}

std::string reference_text(const Target& t) {
  const Reference& r = t.reference;
  switch (t.kind) {
    case Kind::scalar:
      return r.value ? fmt(*r.value) : interval(r.range->lo, r.range->hi);
    case Kind::curve: {
      const std::string n = std::to_string(r.points.x.size()) + " points";
      return r.file.empty() ? n : "`" + r.file + "` (" + r.x_column + ", " + r.y_column + "), " + n;
    }
    case Kind::trend: return r.statement.empty() ? "-" : r.statement;
  }
  return "";
}

std::string result_text(const Score& s) {
  const Target& t = *s.target;
  if (t.status == Status::expected_pass)
    return s.pass ? "<span style=\"color:green\">PASS</span>"
                  : "<span style=\"color:red\">FAIL</span>";
  if (s.unexpected_pass)
    return "<span style=\"color:orange\">UNEXPECTED PASS</span>: remove the known_deviation note";
  std::string names;
  for (const std::string& id : t.companions) names += (names.empty() ? "" : ", ") + ("`" + id + "`");
  return "<span style=\"color:orange\">KNOWN DEVIATION</span>: " + t.reason +
         (names.empty() ? "" : " (companions: " + names + ")");
}

std::string report_markdown(const ReportInput& in, const std::vector<Score>& scores,
                            const std::vector<PlotResult>& plots, const BaselineComparison& base) {
  int n_pass = 0, n_fail = 0, n_known = 0, n_unexpected = 0;
  for (const Score& s : scores) {
    if (s.target->status == Status::known_deviation) {
      (s.unexpected_pass ? n_unexpected : n_known)++;
    } else {
      (s.pass ? n_pass : n_fail)++;
    }
  }
  std::string md = "# Reproduction report: " + in.set + "\n\n";
  if (!in.preamble_markdown.empty()) md += in.preamble_markdown + "\n\n";
  md += "- Scale: " + in.scale + "\n- Commit: `" + std::string(build_info::git_commit()) + "`\n";
  md += "- Wall time: " + fmt(in.wall_time_s) + " s\n- Targets: `" + in.targets_path + "`\n";
  md += "- Result: " +
        std::string(n_fail == 0 ? "<span style=\"color:green\">**PASS**</span>"
                                : "<span style=\"color:red\">**FAIL**</span>") +
        " (" + std::to_string(n_pass) + " passed, " + std::to_string(n_fail) +
        " failed, " + std::to_string(n_known) + " known deviations, " +
        std::to_string(n_unexpected) + " unexpected passes)\n";
  if (n_unexpected > 0)
    md += "- **Unexpected passes**: known_deviation targets that now pass; remove their "
          "known_deviation note in targets.json.\n";

  md += "\n## Targets\n\n| id | measured | band | vs baseline | reference | unit | source | status | result |\n"
        "|---|---|---|---|---|---|---|---|---|\n";
  for (const Score& s : scores) {
    const Target& t = *s.target;
    const GateRow* row = base.row(t.id);
    md += "| " + cell(t.id) + " | " + cell(measured_text(s)) + " | " + cell(band_text(s)) + " | " +
          (row ? cell(gate_cell(*row)) : std::string("-")) + " | " +
          cell(reference_text(t)) + " | " + cell(t.unit) + " | " + cell(t.reference.source) +
          " | " + to_string(t.status) + " | " + cell(result_text(s)) + " |\n";
  }
  std::string notes;
  for (const Score& s : scores)
    if (!s.note.empty()) notes += "- `" + s.target->id + "`: " + s.note + "\n";
  if (!notes.empty()) md += "\n### Notes\n\n" + notes;

  if (!in.plots.empty()) md += "\n## Plots\n";
  for (size_t i = 0; i < in.plots.size(); ++i) {
    const Plot& p = in.plots[i];
    md += "\n### " + p.title + "\n\n";
    md += plots[i].ok ? "![" + p.title + "](" + p.file + ")\n" : "*" + plots[i].message + "*\n";
  }

  std::string worst;
  for (const Score& s : scores) {
    if (!s.worst) continue;
    const WorstPoint& w = *s.worst;
    worst += "| " + cell(s.target->id) + " | " + fmt(w.x_ref) + " | " + fmt(w.y_ref) + " | " +
             (w.outside ? "outside measured range | - | -"
                        : fmt(w.y_nearest) + " (x = " + fmt(w.x_nearest) + ") | " + fmt(w.error) +
                              " | " + fmt(w.allowed)) +
             " | " + cell(s.target->unit) + " | " + (s.pass ? "pass" : "fail") + " |\n";
  }
  if (!worst.empty())
    md += "\n## Worst points of curve targets\n\n"
          "| id | x_ref | y_ref | nearest measured y | error | allowed | unit | |\n"
          "|---|---|---|---|---|---|---|---|\n" + worst;

  md += baseline_section_markdown(base, in.scale);

  std::set<std::string> ids;
  for (const Score& s : scores) ids.insert(s.target->id);
  std::string stray;
  for (const auto& [id, m] : in.m.all())
    if (!ids.count(id)) stray += "- `" + id + "` (" + to_string(m.kind) + ")\n";
  if (!stray.empty())
    md += "\n## Measurements without a target\n\nThe driver recorded these ids, but " +
          in.targets_path + " has no such target (a typo?):\n\n" + stray;
  return md;
}

}  // namespace

std::vector<Score> score_all(const TargetSet& targets, const Measurements& m) {
  std::vector<Score> scores;
  scores.reserve(targets.targets.size());
  for (const Target& t : targets.targets) scores.push_back(score_target(t, m));
  // A known deviation is only as explained as its companions: show their verdicts beside it.
  for (Score& s : scores) {
    std::string verdicts;
    for (const std::string& id : s.target->companions)
      for (const Score& c : scores)
        if (c.target->id == id)
          verdicts += (verdicts.empty() ? "" : ", ") + id + " " +
                      (c.pass ? "passes" : c.measured ? "FAILS (explanation refuted)" : "not measured");
    if (!verdicts.empty()) s.note += (s.note.empty() ? "" : "; ") + std::string("companions: ") + verdicts;
  }
  return scores;
}

int write_report(const ReportInput& in) {
  const TargetSet targets = load_targets(in.targets_path, in.repo_root);
  if (targets.set != in.set)
    throw InputError(in.targets_path, "set",
                     "is '" + targets.set + "' but the driver reports set '" + in.set + "'");
  fs::create_directories(in.out_dir);
  const std::vector<Score> scores = score_all(targets, in.m);

  std::set<std::string> files;
  std::vector<PlotResult> plots;
  for (const Plot& p : in.plots) {
    if (!files.insert(p.file).second)
      throw std::invalid_argument("two plots write " + p.file);
    plots.push_back(render_plot(p, in.out_dir, in.gnuplot));
  }

  const fs::path out(in.out_dir);
  write_file_atomic((out / "results.json").string(), results_json(in, scores).dump(2) + "\n");
  write_measurements(in.out_dir, in.set, in.scale, in.m);
  const BaselineComparison base = compare_with_committed(in.repo_root, in.set, in.scale, in.m);
  write_file_atomic((out / "report.md").string(), report_markdown(in, scores, plots, base));
  int n_failed = 0;
  for (const Score& s : scores) n_failed += s.fails_set() ? 1 : 0;
  return n_failed;
}

}  // namespace kolsky::harness
