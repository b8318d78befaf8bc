// Value-by-value comparison with a baseline (gate.hpp). Curves are compared point by point, x
// and y each against its own tolerance; the row shows the point that used most of its allowance.
#include "harness/gate.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <set>

namespace kolsky::harness {
namespace {

std::string g(double v, const char* f = "%.10g") {
  if (std::isnan(v)) return "not finite";
  char b[48];
  std::snprintf(b, sizeof b, f, v);
  return b;
}

/// Sets difference/allowed/verdict for one number; returns the share of the allowance used.
double judge(GateRow& r, double base, double now, const GateTolerance& tol) {
  r.allowed = tol.allowed(base);
  if (same_number(base, now)) {
    r.difference = 0.0;
    return 0.0;
  }
  r.difference = std::fabs(now - base);
  if (!std::isfinite(r.difference)) return INFINITY;
  return r.allowed > 0 ? r.difference / r.allowed : INFINITY;
}

GateRow scalar_row(const BaselineValue& v, const Measurement& m) {
  GateRow r;
  r.baseline = g(v.value);
  r.now = g(m.value);
  const double used = judge(r, v.value, m.value, v.tol);
  r.verdict = r.difference == 0.0 && same_number(v.value, m.value) ? Verdict::same
              : used <= 1.0                                         ? Verdict::within
                                                                    : Verdict::moved;
  return r;
}

GateRow curve_row(const BaselineValue& v, const Measurement& m) {
  GateRow r;
  const Curve& b = v.curve;
  const Curve& c = m.curve;
  if (b.x.size() != c.x.size()) {
    r.baseline = std::to_string(b.x.size()) + " points";
    r.now = std::to_string(c.x.size()) + " points";
    r.difference = INFINITY;
    r.verdict = Verdict::moved;
    return r;
  }
  double worst = 0.0;
  bool bitwise = true;
  r.baseline = r.now = std::to_string(b.x.size()) + " points, unchanged";
  for (size_t i = 0; i < b.x.size(); ++i) {
    for (int axis = 0; axis < 2; ++axis) {
      const double vb = axis ? b.y[i] : b.x[i], vn = axis ? c.y[i] : c.x[i];
      if (same_number(vb, vn)) continue;
      bitwise = false;
      GateRow p;
      const double used = judge(p, vb, vn, axis ? v.tol : v.tol_x);
      if (used > worst || r.difference == 0.0) {
        worst = used;
        r.difference = p.difference;
        r.allowed = p.allowed;
        const std::string at = std::string(axis ? "y" : "x") + "[" + std::to_string(i) + "] = ";
        r.baseline = at + g(vb);
        r.now = at + g(vn);
      }
    }
  }
  if (bitwise) r.allowed = v.tol.allowed(0.0);
  r.verdict = bitwise ? Verdict::same : worst <= 1.0 ? Verdict::within : Verdict::moved;
  return r;
}

std::string pad(const std::string& s, size_t w) {
  return s.size() >= w ? s : s + std::string(w - s.size(), ' ');
}

}  // namespace

std::string to_string(Verdict v) {
  switch (v) {
    case Verdict::same: return "same";
    case Verdict::within: return "within";
    case Verdict::moved: return "MOVED";
    case Verdict::missing: return "MISSING";
    case Verdict::added: return "NEW";
    case Verdict::ungated: return "ungated";
  }
  return "?";
}

bool GateRow::fails() const {
  return verdict == Verdict::moved || verdict == Verdict::missing || verdict == Verdict::added;
}

std::vector<GateRow> compare_to_baseline(const Baseline& b, const Measurements& m) {
  std::vector<GateRow> rows;
  std::set<std::string> seen;
  for (const BaselineValue& v : b.values) {
    seen.insert(v.id);
    const Measurement* now = m.find(v.id);
    GateRow r;
    if (!now || now->kind != v.kind) {
      r.baseline = to_string(v.kind);
      r.now = now ? "measured as " + to_string(now->kind) : "not measured";
      r.verdict = Verdict::missing;
    } else if (v.kind == Kind::trend) {
      r.baseline = v.holds ? "holds" : "does not hold";
      r.now = now->holds ? "holds" : "does not hold";
      r.difference = v.holds == now->holds ? 0.0 : 1.0;
      r.verdict = v.holds == now->holds ? Verdict::same : Verdict::moved;
    } else {
      r = v.kind == Kind::scalar ? scalar_row(v, *now) : curve_row(v, *now);
    }
    if (!v.gated && r.verdict != Verdict::missing) r.verdict = Verdict::ungated;
    r.set = b.set;
    r.id = v.id;
    r.kind = v.kind;
    r.why = v.why;
    rows.push_back(std::move(r));
  }
  for (const auto& [id, now] : m.all()) {
    if (seen.count(id)) continue;
    GateRow r;
    r.set = b.set;
    r.id = id;
    r.kind = now.kind;
    r.baseline = "-";
    // The value a rebaseline records (the log's reader sees it, not just its kind).
    r.now = now.kind == Kind::scalar  ? g(now.value)
            : now.kind == Kind::trend ? (now.holds ? "holds" : "does not hold")
                                      : "curve of " + std::to_string(now.curve.x.size()) + " points";
    r.verdict = Verdict::added;
    r.why = "not in the baseline: `make rebaseline` records it (with a reason)";
    rows.push_back(std::move(r));
  }
  return rows;
}

std::string gate_table_text(const std::vector<GateRow>& rows) {
  std::vector<std::vector<std::string>> cells{
      {"set", "id", "baseline", "now", "difference", "tolerance", "verdict", "why"}};
  for (const auto& r : rows)
    cells.push_back({r.set, r.id, r.baseline, r.now, g(r.difference, "%.3g"), g(r.allowed, "%.3g"),
                     to_string(r.verdict), r.why});
  std::vector<size_t> w(cells[0].size(), 0);
  for (const auto& row : cells)
    for (size_t i = 0; i + 1 < row.size(); ++i) w[i] = std::max(w[i], row[i].size());
  std::string out;
  for (const auto& row : cells) {
    for (size_t i = 0; i + 1 < row.size(); ++i) out += pad(row[i], w[i]) + "  ";
    out += row.back() + "\n";
  }
  return out;
}

std::string gate_table_markdown(const std::vector<GateRow>& rows) {
  std::string md = "| id | baseline | now | difference | tolerance | verdict | why this tolerance |\n"
                   "|---|---|---|---|---|---|---|\n";
  for (const auto& r : rows) {
    const std::string verdict = r.fails() ? "<span style=\"color:red\">" + to_string(r.verdict) + "</span>"
                                          : to_string(r.verdict);
    md += "| " + r.id + " | " + r.baseline + " | " + r.now + " | " + g(r.difference, "%.3g") +
          " | " + g(r.allowed, "%.3g") + " | " + verdict + " | " + r.why + " |\n";
  }
  return md;
}

std::string gate_cell(const GateRow& r) {
  switch (r.verdict) {
    case Verdict::same: return "= baseline";
    case Verdict::within: return g(r.difference, "%.2g") + " (tol " + g(r.allowed, "%.2g") + ")";
    case Verdict::ungated: return "ungated: " + g(r.difference, "%.2g");
    case Verdict::added: return "not in baseline";
    case Verdict::missing:
    case Verdict::moved:
      return "<span style=\"color:red\">moved " + g(r.difference, "%.2g") + " (tol " +
             g(r.allowed, "%.2g") + ")</span>";
  }
  return "";
}

const GateRow* BaselineComparison::row(const std::string& id) const {
  for (const auto& r : rows)
    if (r.id == id) return &r;
  return nullptr;
}

BaselineComparison compare_with_committed(const std::string& repo_root, const std::string& set,
                                          const std::string& scale, const Measurements& m) {
  BaselineComparison c;
  c.path = baseline_path(repo_root, set, scale);
  if (!std::filesystem::exists(c.path)) {
    c.problem = "no baseline for this scale yet (`make rebaseline SET=" + set + " SCALE=" + scale +
                " REASON=\"...\"` records one)";
    return c;
  }
  try {
    c.baseline = load_baseline(c.path);
    c.rows = compare_to_baseline(c.baseline, m);
  } catch (const std::exception& e) {  // a broken baseline must not cost the report
    c.problem = std::string("baseline unreadable: ") + e.what();
  }
  return c;
}

std::string baseline_section_markdown(const BaselineComparison& c, const std::string& scale) {
  std::string md = "\n## Against the baseline\n\n";
  if (!c.problem.empty()) return md + c.problem + "\n";
  int n_fail = 0, n_same = 0;
  for (const auto& r : c.rows) {
    n_fail += r.fails() ? 1 : 0;
    n_same += r.verdict == Verdict::same ? 1 : 0;
  }
  md += "`" + std::filesystem::path(c.path).filename().string() + "` (commit " +
        c.baseline.git_commit + ", " + c.baseline.created + "; " + c.baseline.method + "): " +
        std::to_string(c.rows.size()) + " values, " + std::to_string(n_same) + " bitwise equal, " +
        std::to_string(n_fail) + " moved beyond their tolerance.";
  md += scale == "smoke" ? " In `make test` the regression gate fails on any move beyond tolerance.\n\n"
                         : " At full scale a move is reported here, not failed: the dissertation band "
                           "decides pass or fail.\n\n";
  return md + gate_table_markdown(c.rows);
}

bool log_has_entry(const std::string& log_text, const Baseline& b) {
  // Entry heading (written by `kolsky_gate rebaseline`): "## <date> · <set> · <scale> · ... digest <hex>"
  const std::string key = " · " + b.set + " · " + b.scale + " · ";
  const std::string digest = "digest " + baseline_digest(b);
  size_t pos = 0;
  while ((pos = log_text.find("\n## ", pos)) != std::string::npos) {
    const size_t end = log_text.find('\n', pos + 1);
    const std::string line = log_text.substr(pos + 1, end == std::string::npos ? end : end - pos - 1);
    if (line.find(key) != std::string::npos && line.find(digest) != std::string::npos) return true;
    pos = pos + 1;
  }
  return false;
}

}  // namespace kolsky::harness
