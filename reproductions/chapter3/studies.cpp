#include "chapter3/studies.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

#include "common/format.hpp"
#include "harness/log_search.hpp"
#include "core/errors.hpp"

namespace kolsky::ch3 {

using repro::fmt;

harness::Case make_case(const Context& x, const std::string& label, const nlohmann::json& patch) {
  harness::Case c;
  c.label = label;
  c.scene_path = x.scene_path;
  c.scene = x.scene;
  c.changes = harness::changes_from_patch(patch);
  c.packing_cache = x.packing_cache;
  return c;
}

Measures measure(const Context& x, const CaseResult& c) {
  return ch3::measure(c, x.eps_lo, x.eps_hi, x.cutoff, x.ringing_time);
}

namespace {
std::string mpa(double pa) { return std::isfinite(pa) ? fmt("%.1f", pa / 1e6) : "-"; }
}  // namespace

std::map<std::string, double> level_speedups(const Context& x, const harness::TargetSet& targets) {
  std::map<std::string, double> out;
  for (const auto& lv : x.studies.at("levels").at("reduced")) {
    const std::string id = lv.at("id"), target = "ch3.level." + id + ".faster";
    if (targets.find(target) != nullptr) out[id] = harness::threshold(targets, target, "min_speedup");
  }
  return out;
}

void model_levels(Context& x, const CaseResult& full, const Measures& full_m) {
  std::string md = "\n### Model levels: speed against error (original curve)\n\n"
                   "| level | run time (s, time loop only) | steps | slope 2-6 % (MPa) | slope - full (MPa) | RMS of the stress difference to the full model, 2-6 % strain (MPa) | status |\n"
                   "|---|---|---|---|---|---|---|\n";
  md += "| " + x.studies.at("levels").at("full_label").get<std::string>() + " | " + fmt("%.1f", full.run_s) + " | " +
        std::to_string(full.run.steps) + " | " + mpa(full_m.slope) + " | 0 | 0 | " + (full.ok ? "ran" : "failed: " + full.failure) +
        " |\n";
  harness::Plot lp{"model_levels.png", "Back-face stress vs strain to 13 MPa: model levels (original curve)", "strain (-)",
                   "stress (MPa)", {}, {}, {}};
  auto add_series = [&](const std::string& label, const CaseResult& c, const Measures& m) {
    const auto cv = curve_to_cutoff(c, m);
    harness::PlotSeries s{label, cv.x, {}, "lines"};
    for (double y : cv.y) s.y.push_back(y / 1e6);
    lp.series.push_back(s);
  };
  add_series("full model", full, full_m);
  for (const auto& lv : x.studies.at("levels").at("reduced")) {
    const std::string id = lv.at("id"), label = lv.at("label");
    const harness::Case spec = make_case(x, label, lv.at("patch"));
    try {
      harness::validate(spec);
    } catch (const InputError& e) {
      // Not supported by the solver: reported as such, never run another way instead.
      md += "| " + label + " | - | - | - | - | - | refused by the scene reader: `" + std::string(e.what()) + "` |\n";
      x.m->trend("ch3.level." + id + ".refused", true, std::string("refused: ") + e.what());
      continue;
    }
    const CaseResult c = ch3::run_case(spec);
    const Measures m = measure(x, c);
    const double d_slope = m.slope - full_m.slope;
    const double rms = curve_rms_difference(c, m, full, full_m, x.eps_lo, x.eps_hi);
    std::printf("level %s: slope %s MPa (full %s), RMS %s MPa, run %.1f s\n", id.c_str(), mpa(m.slope).c_str(),
                mpa(full_m.slope).c_str(), mpa(rms).c_str(), c.run_s);
    md += "| " + label + " | " + fmt("%.1f", c.run_s) + " | " + std::to_string(c.run.steps) + " | " + mpa(m.slope) + " | " +
          mpa(d_slope) + " | " + mpa(rms) + " | " + (c.ok ? "ran" : "failed: " + c.failure) + " |\n";
    // Relative to the full model's slope; wall times stay in the table (they are not
    // reproducible numbers, so the regression gate never sees them), except for the levels
    // the targets file expects to be clearly faster (a trend; its threshold min_speedup).
    x.m->scalar("ch3.level." + id + ".slope_difference", std::abs(d_slope) / full_m.slope);
    x.m->note("ch3.level." + id + ".slope_difference",
              "slope " + mpa(m.slope) + " MPa against the full model's " + mpa(full_m.slope) + " MPa; " +
                  fmt("%.1f s", c.run_s) + " against " + fmt("%.1f s", full.run_s) + " of time loop; RMS of the stress difference " +
                  mpa(rms) + " MPa");
    if (x.min_speedup.count(id)) {
      const double k = x.min_speedup.at(id);
      x.m->trend("ch3.level." + id + ".faster", k * c.run_s < full.run_s,
                 fmt("%.1f s", c.run_s) + " against the full model's " + fmt("%.1f s", full.run_s) + " of time loop (needs x " + fmt("%g", k) + ")");
    }
    if (c.ok) add_series(label, c, m);
  }
  x.plots->push_back(lp);
  x.markdown += md;
}

// ------------------------------------------------------------------ back-calculation

BackCalcResult back_calculate(const std::function<double(double)>& slope_of, double target, double guess,
                              double factor, double rel_tol, int max_evaluations) {
  BackCalcResult r;
  const double log_target = std::log(target);
  auto objective = [&](double k) {
    const double s = slope_of(k);
    r.evaluated[k] = s;
    std::printf("  back-calculation: NORMK %.5g -> slope %.1f MPa\n", k, s / 1e6);
    return std::isfinite(s) && s > 0 ? std::pow(std::log(s) - log_target, 2) : 1e30;
  };
  const double step = std::log(factor);
  const double mid = std::log(guess);
  const harness::LogSearchResult q =
      harness::log_brent_search(objective, {mid - step, mid, mid + step, step, rel_tol, max_evaluations});
  // Best: the slope nearest the target in ln (a failed run, NaN, never); the search's own best
  // would take the 1e30 it is handed for a failed run.
  for (const auto& [k, s] : r.evaluated)
    if (std::isfinite(s) && s > 0 &&
        (!std::isfinite(r.slope) || std::abs(std::log(s) - log_target) < std::abs(std::log(r.slope) - log_target)))
      r.slope = s, r.normk = k;
  r.bracket_lo = q.bracket_lo;
  r.bracket_hi = q.bracket_hi;
  r.evaluations = static_cast<int>(q.evaluated.size());
  r.converged = q.converged;
  r.note = q.note;
  return r;
}

void normk_studies(Context& x, double slope_full_at_printed) {
  const auto& bc = x.studies.at("backcalc");
  const nlohmann::json level_patch = bc.at("level_patch");
  const double printed = bc.at("normk_printed"), factor = bc.at("bracket_factor"), tol = bc.at("rel_tol");
  const int cap = bc.at("max_evaluations");
  std::string md = "\n### NORMK back-calculation (Sec. 3.4, Table 3.2)\n\nLevel: " +
                   bc.at("level_label").get<std::string>() + ". GSL Brent minimiser of (ln slope - ln target)^2 over ln NORMK.\n\n";
  std::map<double, double> slopes;  // every evaluation of this level, shared by the studies
  auto slope_of = [&](double normk) {
    if (auto it = slopes.find(normk); it != slopes.end()) return it->second;
    nlohmann::json p = level_patch;
    p["specimen"]["normk"] = normk;
    const CaseResult c = ch3::run_case(make_case(x, "NORMK " + fmt("%.5g", normk), p));
    const double s = measure(x, c).slope;
    slopes[normk] = s;
    return s;
  };
  auto row = [&](const std::string& what, const BackCalcResult& r) {
    return "| " + what + " | " + fmt("%.5g", r.normk) + " | " + mpa(r.slope) + " | [" + fmt("%.4g", r.bracket_lo) + ", " +
           fmt("%.4g", r.bracket_hi) + "] | " + std::to_string(r.evaluations) + " | " + (r.converged ? "yes" : "no") +
           (r.note.empty() ? "" : " (" + r.note + ")") + " |\n";
  };
  md += "| search | NORMK found | slope there (MPa) | final bracket | runs | converged |\n|---|---|---|---|---|---|\n";
  // Twin experiment: the slope of a known NORMK is the target; the finder, started at the
  // printed value, must recover it.
  const double k_true = bc.at("twin_normk");
  const double s_syn = slope_of(k_true);
  const BackCalcResult twin = back_calculate(slope_of, s_syn, printed, factor, tol, cap);
  md += row("twin: synthetic slope " + mpa(s_syn) + " MPa of NORMK " + fmt("%.4g", k_true), twin);
  x.m->scalar("ch3.twin_normk_ratio", twin.normk / k_true);
  x.m->note("ch3.twin_normk_ratio", "recovered NORMK " + fmt("%.5g", twin.normk) + " of the true " + fmt("%.4g", k_true) +
                                        " (synthetic slope " + mpa(s_syn) + " MPa)");
  // The real problem: the text's 235 MPa (Sec. 3.4, original curve, 2-6 %).
  const double target = bc.at("target_slope");
  const BackCalcResult real = back_calculate(slope_of, target, printed, factor, tol, cap);
  md += row("target " + mpa(target) + " MPa (Sec. 3.4)", real);
  x.m->scalar("ch3.normk_backcalculated", real.normk);
  x.m->note("ch3.normk_backcalculated", "E read as 70 GPa (Table 3.2's 'MPa' taken as a misprint); slope there " +
                                            mpa(real.slope) + " MPa; " + std::to_string(real.evaluations) + " runs");
  // The printed reading, E = 70 MPa: K_n of Eq. 3.1 is proportional to NORMK E, so the same
  // slope needs NORMK x 1000 there; one run as printed shows what 0.07 gives.
  const double e_ratio = bc.at("printed_modulus_ratio");
  nlohmann::json pp = level_patch;
  pp.merge_patch(bc.at("printed_modulus_patch"));
  const CaseResult pc = ch3::run_case(make_case(x, "E = 70 MPa as printed", pp));
  const Measures pm = measure(x, pc);
  md += "\nAs printed (E = 70 MPa, NORMK 0.07, same level): " +
        (pc.ok ? "slope " + mpa(pm.slope) + " MPa, " + (pm.reached_cutoff ? "reaches" : "never reaches") +
                     " 13 MPa (largest back-face stress " + mpa(*std::max_element(pc.history.stress_back.begin(), pc.history.stress_back.end())) + " MPa)"
               : "run failed: " + pc.failure) +
        ". Under that reading the back-calculation would return NORMK x " + fmt("%.0f", 1 / e_ratio) + " = " +
        fmt("%.4g", real.normk / e_ratio) + " (Eq. 3.1: K_n depends on NORMK E only).\n";
  x.m->scalar("ch3.normk_printed_reading", real.normk / e_ratio);
  x.m->note("ch3.normk_printed_reading", "NORMK the same slope needs with E = 70 MPa: the GPa result x 1000 (Eq. 3.1)");
  x.m->scalar("ch3.slope_printed_modulus", pm.slope / 1e6);
  if (pc.ok) {  // companion of both printed-modulus deviations: as printed, 13 MPa is out of reach
    x.m->scalar("ch3.printed_modulus_peak_stress",
                *std::max_element(pc.history.stress_back.begin(), pc.history.stress_back.end()) / 1e6);
    x.m->note("ch3.printed_modulus_peak_stress", "largest back-face stress over the run, E = 70 MPa and NORMK 0.07 as printed");
  }
  x.m->note("ch3.slope_printed_modulus", pc.ok ? "E = 70 MPa, NORMK 0.07 on the " + bc.at("level_label").get<std::string>()
                                               : "run failed: " + pc.failure);
  md += "Full model at the printed NORMK (70 GPa reading): slope " + mpa(slope_full_at_printed) + " MPa.\n";
  // Companion of the slope known deviations: a network's stiffness does not depend on N, the
  // compaction of a specimen without one does (README, "What the slope's N-dependence is made
  // of"); the same level and NORMK at a coarser N.
  if (x.studies.contains("companions")) {
    const auto& cp = x.studies.at("companions").at("n_dependence");
    nlohmann::json p6 = level_patch;
    p6.merge_patch(cp.at("patch"));
    p6["specimen"]["normk"] = printed;
    const CaseResult c6 = ch3::run_case(make_case(x, cp.at("label").get<std::string>(), p6));
    const double s6 = measure(x, c6).slope, s3 = slope_of(printed);
    x.m->scalar("ch3.slope_n_dependence", s6 / s3);
    x.m->note("ch3.slope_n_dependence", cp.at("label").get<std::string>() + ": " + mpa(s6) + " MPa against " + mpa(s3) +
                                            " MPa at the set's N, NORMK " + fmt("%.4g", printed) + ", " +
                                            bc.at("level_label").get<std::string>());
    md += "Same level and NORMK, " + cp.at("label").get<std::string>() + ": slope " + mpa(s6) + " MPa (" +
          std::to_string(c6.dem.grains) + " grains) against " + mpa(s3) + " MPa.\n";
  }
  // The finder's path, for the plot.
  harness::Plot cp{"normk_backcalc.png", "Slope 2-6 % vs NORMK (" + bc.at("level_label").get<std::string>() + ")", "NORMK (-)",
                   "slope (MPa)", {}, {}, {}};
  harness::PlotSeries s{"evaluated", {}, {}, "points"};
  for (const auto& [k, v] : slopes)
    if (std::isfinite(v)) s.x.push_back(k), s.y.push_back(v / 1e6);
  cp.series.push_back(s);
  cp.series.push_back({"target 235 MPa", {s.x.empty() ? 0.01 : s.x.front(), s.x.empty() ? 1 : s.x.back()}, {target / 1e6, target / 1e6}, "dashed"});
  cp.logx = true;
  x.plots->push_back(cp);
  x.markdown += md;
}

}  // namespace kolsky::ch3
