// Wang et al. (2018), Sec. 5.3.1 and 5.3.4: the original and the 1.5x specimen with their own
// sigma_lim0, the breakage-criterion variants (Fig. 5.8), the automated back-calculation of
// sigma_lim0(N) against Eq. 5.17 (Fig. 5.16), and speed against error of N.
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "chapter5/backcalc.hpp"
#include "chapter5/studies.hpp"
#include "common/stats.hpp"
#include "dem/breakage_model.hpp"

namespace kolsky::ch5 {

namespace {

harness::PlotSeries stress_series(const CaseResult& c, const std::string& label) {
  harness::PlotSeries p = series(label);
  for (std::size_t k = 0; k < c.t.size(); ++k) {
    p.x.push_back(c.strain[k]);
    p.y.push_back(c.stress_back[k] / 1e6);
  }
  return p;
}

harness::PlotSeries curve_series(const psd::GrainSizeCurve& g, const std::string& label, const std::string& style) {
  harness::PlotSeries p = series(label, {}, style);
  for (std::size_t k = 0; k < g.size(); ++k)
    if (g.percent_passing[k] > 0) {
      p.x.push_back(g.diameter[k] * 1e3);
      p.y.push_back(g.percent_passing[k]);
    }
  return p;
}

std::string case_row(const CaseResult& c) {
  if (!c.ok) return "| " + c.spec.label + " | failed: " + c.failure + " | | | | | |\n";
  return fmt("| %s | %g | %zu -> %zu | %.0f | %.2f | %.1f MPa | %.0f s |\n", c.spec.label.c_str(), c.upscale,
             c.grains_initial, c.grains_final, c.broken_primary.empty() ? 0.0 : c.broken_primary.back() + c.broken_secondary.back(),
             c.relative_breakage.empty() ? 0.0 : c.relative_breakage.back(), max_of(c.stress_back) / 1e6, c.wall_s);
}

}  // namespace

void wang_measure(Study& s, const WangPlan& p, const WangRuns& runs) {
  const double n_ref = p.n_ref, n_pair = p.n_pair, sig1 = p.sig1, sig15 = p.sig15, sig_ref = p.sig_ref;
  const CaseResult &ref = runs.ref, &pair = runs.pair;
  auto& m = *s.m;
  if (runs.twin_ran) {  // the twin experiment: its synthetic curve's sigma_lim0 recovered
    const BackCalcResult& r = runs.twin;
    m.scalar("ch5.backcalc.twin_recovered", r.sigma / p.sig_twin);
    m.note("ch5.backcalc.twin_recovered", fmt("N = %g: truth %.4g GPa, start %.4g GPa, recovered %.4g GPa (bracket %.4g-%.4g) "
                                              "in %zu runs; %s", p.n_twin, p.sig_twin / 1e9, p.twin.settings.guess / 1e9,
                                              r.sigma / 1e9, r.bracket_lo / 1e9, r.bracket_hi / 1e9, r.evaluated.size(),
                                              r.note.c_str()));
  }
  const double to1 = std::pow(n_ref, 3), to15 = std::pow(n_pair / 1.5, 3);  // counts scale as N^-3
  std::string md = "## Wang et al. (2018): strain-rate walls, 5 x 15 mm, porosity 0.41\n\n";
  md += "| case | N | grains | broken parents | B_r at end | largest back stress | wall time |\n|---|---|---|---|---|---|---|\n";
  md += case_row(ref) + case_row(pair);
  if (ref.ok) {
    m.scalar("ch5.wang.count_final_ref", ref.grains_final * to1);
    m.note("ch5.wang.count_final_ref", fmt("%zu -> %zu grains at N = %g (x N^3 = %g to N = 1); the initial count is circular "
                                            "(the PSD was fitted to it)", ref.grains_initial, ref.grains_final, n_ref, to1));
    m.scalar("ch5.wang.growth_ratio_ref", double(ref.grains_final) / ref.grains_initial);
    m.scalar("ch5.wang.relative_breakage_end", ref.relative_breakage.back());
  }
  if (pair.ok) {
    m.scalar("ch5.wang.count_final_pair", pair.grains_final * to15);
    m.note("ch5.wang.count_final_pair", fmt("%zu -> %zu grains at N = %g (x (N/1.5)^3 = %g)", pair.grains_initial,
                                             pair.grains_final, n_pair, to15));
  }
  if (ref.ok && pair.ok) {
    const double g_ref = double(ref.grains_final) / ref.grains_initial, g_pair = double(pair.grains_final) / pair.grains_initial;
    m.scalar("ch5.wang.growth_ratio_same", g_pair / g_ref);
    m.note("ch5.wang.growth_ratio_same", fmt("growth %.3f (N = %g) / %.3f (N = %g)", g_pair, n_pair, g_ref, n_ref));
    const auto low = stress_difference(ref.strain, ref.stress_back, pair.strain, pair.stress_back, 1e6, 20e6);
    m.trend("ch5.wang.pair_coincide_low", low.rms <= p.pair_low_rms,
            fmt("RMS %.2f MPa (largest %.2f) over back stress 1-20 MPa, %d points; <= %g MPa", low.rms / 1e6, low.max / 1e6, low.points,
                p.pair_low_rms / 1e6));
    const double top = max_of(ref.stress_back);
    const auto high = stress_difference(ref.strain, ref.stress_back, pair.strain, pair.stress_back, 20e6, top);
    m.trend("ch5.wang.pair_close_high", high.rms <= p.pair_high_frac * top,
            fmt("RMS %.2f MPa over back stress 20-%.0f MPa (%d points); <= %g %% of %.0f MPa", high.rms / 1e6, top / 1e6,
                high.points, 100 * p.pair_high_frac, top / 1e6));
    harness::Plot psd = figure("wang_psd.png", "Wang: grain-size curves, N = " + fmt("%g", n_ref) + " and N = " + fmt("%g", n_pair) +
                                          " downscaled (Fig. 5.7)", "diameter (mm, original sand)", "percent passing");
    psd.logx = true;
    for (const char* id : {"ch5.wang.psd_stress_1", "ch5.wang.psd_stress_2"}) {
      const double st = s.printed(id);
      double t_ref = NAN, t_pair = NAN;
      const auto a = curve_at_stress(ref, st, &t_ref), b = curve_at_stress(pair, st, &t_pair);
      const std::string key = std::string("ch5.wang.psd_match_") + (st < 50e6 ? "43" : "72");
      if (a.size() > 1 && b.size() > 1) {
        m.scalar(key, passing_difference(a, b, 75e-6, std::min(a.diameter.back(), b.diameter.back())));
        m.note(key, fmt("curves at %.1f us (N = %g) and %.1f us (N = %g, downscaled), RMS of percent passing over "
                        "75 um to the largest grain", t_ref * 1e6, n_ref, t_pair * 1e6, n_pair));
        psd.series.push_back(curve_series(a, fmt("N = %g at %.0f MPa", n_ref, st / 1e6), "lines"));
        psd.series.push_back(curve_series(b, fmt("N = %g at %.0f MPa, downscaled", n_pair, st / 1e6), "dashed"));
      } else {
        m.note(key, fmt("back stress %.0f MPa not reached (largest %.1f / %.1f MPa)", st / 1e6, max_of(ref.stress_back) / 1e6,
                        max_of(pair.stress_back) / 1e6));
      }
    }
    if (ref.curves.size() > 0) psd.series.push_back(curve_series(psd::downscale(ref.curves.front().curve, n_ref), "initial", "dashed"));
    s.plots->push_back(psd);
  }
  harness::Plot ss = figure("wang_stress_strain.png", "Wang: back-face stress against strain (Fig. 5.6)", "strain (Eq. 5.1)", "stress (MPa)");
  for (const auto* c : {&ref, &pair})
    if (c->ok) ss.series.push_back(stress_series(*c, fmt("N = %g, sigma_lim0 %.3g GPa", c->upscale, c->spec.sigma_lim0 / 1e9)));
  s.plots->push_back(ss);

  // The breakage-criterion variants (Fig. 5.8), at the same sigma_lim0, at variants_n.
  const double nv = p.nv, sig_v = p.sig_v;
  const CaseResult &base = runs.base(p), &nobreak = runs.nobreak, &clim0 = runs.clim0;
  md += case_row(nobreak) + case_row(clim0) + "\n";
  if (base.ok && nobreak.ok && clim0.ok) {
    const auto a = stress_difference(base.strain, base.stress_back, nobreak.strain, nobreak.stress_back, 1e6, 10e6);
    const auto b = stress_difference(base.strain, base.stress_back, clim0.strain, clim0.stress_back, 1e6, 10e6);
    m.trend("ch5.wang.variants_coincide_low", a.rms <= p.variants_rms && b.rms <= p.variants_rms,
            fmt("RMS from c_lim = 8 over back stress 1-10 MPa: no breakage %.2f MPa, c_lim = 0 %.2f MPa; <= %g MPa", a.rms / 1e6, b.rms / 1e6,
                p.variants_rms / 1e6));
    // At the largest strain all three reach (high stress).
    const double e = std::min({max_of(base.strain), max_of(nobreak.strain), max_of(clim0.strain)}) * 0.98;
    const double sb = stress_at_strain(base, e), sn = stress_at_strain(nobreak, e), sc = stress_at_strain(clim0, e);
    m.trend("ch5.wang.nobreak_stiffer_high", sn > p.nobreak_ratio * sb,
            fmt("at strain %.3f: no breakage %.1f MPa, c_lim = 8 %.1f MPa (> %g %% higher)", e, sn / 1e6, sb / 1e6,
                100 * (p.nobreak_ratio - 1)));
    m.trend("ch5.wang.clim0_much_softer", sc < p.clim0_ratio * sb,
            fmt("at strain %.3f: c_lim = 0 %.1f MPa, c_lim = 8 %.1f MPa (< %g %%)", e, sc / 1e6, sb / 1e6, 100 * p.clim0_ratio));
    const double kb = base.broken_primary.back() + base.broken_secondary.back();
    const double k0 = clim0.broken_primary.back() + clim0.broken_secondary.back();
    m.trend("ch5.wang.clim0_breaks_more", k0 > p.clim0_breaks * kb,
            fmt("broken parents at the end: c_lim = 0 %.0f, c_lim = 8 %.0f (> %gx); grain contacts per grain at the end %.2f "
                "(c_lim = 8) and %.2f (c_lim = 0)", k0, kb, p.clim0_breaks, base.coordination_final, clim0.coordination_final));
  }
  // The companions of the known deviations (issue 31): full scale only (cases "companions").
  if (p.has_companions && ref.ok && base.ok && nobreak.ok && clim0.ok) wang_companions(s, p, runs, md);
  harness::Plot vs = figure("wang_variants.png", fmt("Wang N = %g: breakage criteria at sigma_lim0 %.3g GPa (Fig. 5.8)", nv, sig_v / 1e9),
                   "strain (Eq. 5.1)", "stress (MPa)");
  for (const auto* c : {&base, &nobreak, &clim0})
    if (c->ok) vs.series.push_back(stress_series(*c, c->spec.label));
  s.plots->push_back(vs);

  // The back-calculations' table, and speed against error.
  if (!ref.ok) {
    s.markdown += md;
    return;
  }
  md += "### sigma_lim0 back-calculated against N = " + fmt("%g", n_ref) + " (Sec. 5.3.4, Fig. 5.16)\n\n";
  md += "| N | Eq. 5.17 | back-calculated | / Eq. 5.17 | bracket | RMS stress difference | runs |\n|---|---|---|---|---|---|---|\n";
  std::vector<double> bn, bs;
  for (std::size_t k = 0; k < p.backcalcs.size(); ++k) {
    const double n = p.backcalcs[k].n;
    const BackCalcSettings& bc = p.backcalcs[k].settings;
    const BackCalcResult& r = runs.backcalcs[k];
    md += fmt("| %g | %.3f GPa | %.3f GPa | %.3f | %.3f-%.3f GPa%s | %.2f MPa | %zu |\n", n, bc.guess / 1e9, r.sigma / 1e9,
              r.sigma / bc.guess, r.bracket_lo / 1e9, r.bracket_hi / 1e9, r.converged ? "" : " (not converged)", r.score / 1e6,
              r.evaluated.size());
    bn.push_back(n);
    bs.push_back(r.sigma);
    if (bn.size() == 1) {
      m.scalar("ch5.backcalc.ratio_to_eq517_pair", r.sigma / bc.guess);
      m.note("ch5.backcalc.ratio_to_eq517_pair", fmt("N = %g: %.3f GPa against Eq. 5.17's %.3f GPa (text's 2.37 / 2.295 = 1.033); %s",
                                                      n, r.sigma / 1e9, bc.guess / 1e9, r.note.c_str()));
    }
  }
  bool grows = bs.size() >= 2;
  for (std::size_t k = 1; k < bs.size(); ++k) grows = grows && bs[k] > bs[k - 1];
  if (bs.size() >= 2)
    m.trend("ch5.backcalc.grows_with_n", grows, "sigma_lim0 at N = " + fmt("%g", bn.front()) + "..." + fmt("%g", bn.back()) +
                                                    ": increasing in N");
  harness::Plot sn = figure("sigma_vs_n.png", "sigma_lim0 against the upscaling factor (Fig. 5.16)", "N", "sigma_lim0 (GPa)");
  harness::PlotSeries law = series("Eq. 5.17 from N = " + fmt("%g", n_ref), {}, "dashed");
  for (double n = 1; n <= 3.0001; n += 0.1) law.x.push_back(n), law.y.push_back(dem::sigma_lim0_between(sig_ref, n_ref, n, p.m1) / 1e9);
  sn.series.push_back(law);
  harness::PlotSeries got = series("back-calculated", bn, "linespoints");
  for (double v : bs) got.y.push_back(v / 1e9);
  sn.series.push_back(got);
  sn.reference_points.push_back({"text (Wang N = 1, 1.5)", {1, 1.5}, {sig1 / 1e9, sig15 / 1e9}, {}, {}});
  s.plots->push_back(sn);

  // Speed against error: every N with its back-calculated sigma (Eq. 5.17's where none), its
  // cost with and without the packing, and the seed scatter of its error over the packing
  // seeds of speed_seeds (each packs afresh, so its wall time holds a true packing's cost).
  const bool seeds = s.cases.at("wang").contains("speed_seeds") && !s.cases.at("wang").at("speed_seeds").empty();
  md += "\n### Speed against error of N (Wang specimen; reference N = " + fmt("%g", n_ref) + ")\n\n";
  md += fmt("Cost per simulated us without the packing (run) and with it (the longest packing time among the seeds: "
            "a packing read from the cache takes under a second); the stress RMS over packing seed 1%s.\n\n",
            !seeds ? "" : " and the seeds of speed_seeds (mean +- sample standard deviation)");
  md += "| N | sigma_lim0 | grains start -> end | run per simulated us | with packing | stress RMS vs ref | seeds | PSD RMS at 43 MPa |\n"
        "|---|---|---|---|---|---|---|---|\n";
  harness::Plot se = figure("speed_vs_error.png", "Wang: cost against deviation from N = " + fmt("%g", n_ref) +
                                                      " (bars: packing-seed scatter)",
                            "wall time per simulated us (s)", "RMS stress difference (MPa)");
  se.logx = se.logy = true;
  harness::PlotPoints run_only{"run (packing excluded), each point labelled with its N", {}, {}, {}, {}};
  harness::PlotPoints packed{"the same run with a fresh packing", {}, {}, {}, {}};
  for (std::size_t i = 0; i < p.speed.size(); ++i) {
    const double n = p.speed[i].n;
    const bool is_ref = p.speed[i].is_ref;
    // The case (its back-calculation's best run, or the run at Eq. 5.17's sigma_lim0), then its
    // seeds that ran (wang_plan.cpp, speed_runs).
    const std::vector<CaseResult>& members = runs.speed[i];
    if (members.empty() || !members.front().ok) continue;
    const CaseResult& c = members.front();
    // The packing's cost: the largest packing time among the members (the extra seeds pack
    // afresh; seed 1's packing may have been read from the cache in under a second).
    std::vector<double> rms, run_cost;
    double pack_s = 0;
    for (const CaseResult& r : members) {
      run_cost.push_back((r.wall_s - r.pack_s) / (r.simulated_s * 1e6));
      pack_s = std::max(pack_s, r.pack_s);
      const auto d = stress_difference(ref.strain, ref.stress_back, r.strain, r.stress_back, 1e6, max_of(ref.stress_back));
      if (std::isfinite(d.rms)) rms.push_back(d.rms / 1e6);
    }
    const repro::SampleStat err = repro::sample_stat(rms), cost = repro::sample_stat(run_cost);
    const double err_sd = std::isfinite(err.sd) ? err.sd : 0.0;  // one seed: no bar
    const auto a = curve_at_stress(ref, 43e6), b = curve_at_stress(c, 43e6);
    const double pd = passing_difference(a, b, 75e-6, 1.0);
    // Under a second the packing was read from the cache: its cost is not known here.
    const bool packed_here = pack_s >= 1.0;
    const double packed_cost = cost.mean + pack_s / (c.simulated_s * 1e6);
    const std::string error = is_ref        ? "-"
                              : rms.size() > 1 ? fmt("%.2f +- %.2f MPa", err.mean, err_sd)
                                               : fmt("%.2f MPa", err.mean);
    md += fmt("| %g | %.3f GPa | %zu -> %zu | %.3f s | %s | %s | %zu | %.2f points |\n", n, c.spec.sigma_lim0 / 1e9,
              c.grains_initial, c.grains_final, cost.mean,
              packed_here ? fmt("%.3f s (packing %.0f s)", packed_cost, pack_s).c_str() : "- (packing cached)",
              error.c_str(), members.size(), pd);
    if (is_ref || rms.empty()) continue;
    run_only.x.push_back(cost.mean);
    run_only.y.push_back(err.mean);
    run_only.yerr.push_back(err_sd);
    run_only.point_labels.push_back(fmt("N = %g", n));
    if (!packed_here) continue;
    packed.x.push_back(packed_cost);
    packed.y.push_back(err.mean);
    packed.yerr.push_back(err_sd);
  }
  se.reference_points = {run_only, packed};
  s.plots->push_back(se);
  s.markdown += md + "\n";
}

}  // namespace kolsky::ch5
