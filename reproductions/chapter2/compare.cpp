#include "chapter2/compare.hpp"
#include "common/format.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>

namespace kolsky::ch2 {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
// Measurement definitions shared with the driver and studies.cpp (not reference values).
constexpr double kSlopeLo = 0.02, kSlopeHi = 0.10;  // stress-strain slope window
constexpr double kLoadingEnd = 350e-6;              // end of the Sec. 2.3.4 plateau window

using repro::fmt;

// Index one past the loading branch: up to the peak strain among t <= t_end.
long branch_end(const shpb::SpecimenHistory& h, double t_end) {
  long peak = 0;
  for (long k = 0; k < static_cast<long>(h.t.size()) && h.t[k] <= t_end; ++k)
    if (h.strain[k] > h.strain[peak]) peak = k;
  return peak + 1;
}

harness::PlotSeries curve(const std::string& label, const shpb::SpecimenHistory& h, double t_end,
                          const std::string& style = "lines") {
  const long end = branch_end(h, t_end);
  return {label, {h.strain.begin(), h.strain.begin() + end},
          scaled({h.stress_back.begin(), h.stress_back.begin() + end}, 1e-6), style};
}

}  // namespace

double stress_at_strain(const shpb::SpecimenHistory& h, double e, double t_end) {
  const long end = branch_end(h, t_end);
  for (long k = 1; k < end; ++k) {
    const double e0 = h.strain[k - 1], e1 = h.strain[k];
    if (e0 <= e && e <= e1 && e1 > e0)
      return h.stress_back[k - 1] + (e - e0) / (e1 - e0) * (h.stress_back[k] - h.stress_back[k - 1]);
  }
  return kNaN;
}

void bar_model_comparison(const StudyContext& ctx, CaseSpec spec, const BarComparisonSettings& s) {
  auto& m = *ctx.m;
  spec.bars = "characteristic";
  const auto one_d = run_case(*ctx.base, spec);
  // Meshed bars: the face waves come from the gauges, so the run lasts until the reflected wave
  // of the loading window has reached the incident gauge: t_a + window + d_I/c0 (+ 20 us).
  const auto& bars = ctx.base->json.at("bars");
  const auto& inc = bars.at("incident");
  const double c0 = std::sqrt(inc.at("youngs_modulus").get<double>() / inc.at("density").get<double>());
  const double d_i = inc.at("gauges").at(0).get<double>();
  spec.bars = "meshed";
  spec.bar_mesh_radial = s.mesh_radial;
  spec.bar_element_length = s.element_length;
  spec.end_time = (inc.at("length").get<double>() + d_i) / c0 + kLoadingEnd + 20e-6;
  const auto meshed = run_case(*ctx.base, spec);
  if (!one_d.ok || !meshed.ok) {
    std::fprintf(stderr, "chapter2: bar comparison failed: %s %s\n", one_d.failure.c_str(), meshed.failure.c_str());
    return;
  }
  // Stress difference at equal strain over the slope window (1-D strains as the abscissa).
  double max_d = 0, sum2 = 0, sum_s = 0;
  long n = 0;
  const long end = branch_end(one_d.h, kLoadingEnd);
  for (long k = 0; k < end; ++k) {
    const double e = one_d.h.strain[k];
    if (e < kSlopeLo || e > kSlopeHi) continue;
    const double d = stress_at_strain(meshed.h, e, kLoadingEnd) - one_d.h.stress_back[k];
    if (!std::isfinite(d)) continue;
    max_d = std::max(max_d, std::fabs(d)), sum2 += d * d, sum_s += one_d.h.stress_back[k], ++n;
  }
  const double rms = n > 0 ? std::sqrt(sum2 / static_cast<double>(n)) : kNaN;
  const double mean_s = n > 0 ? sum_s / static_cast<double>(n) : kNaN;
  const double slope_1d = loading_slope(one_d.h, kSlopeLo, kSlopeHi, kLoadingEnd);
  const double slope_m = loading_slope(meshed.h, kSlopeLo, kSlopeHi, kLoadingEnd);
  const double slope_diff = 100.0 * (slope_m / slope_1d - 1.0);
  m.scalar("ch2.bars_meshed_slope_difference", slope_m / slope_1d - 1.0);
  m.note("ch2.bars_meshed_slope_difference",
         "slope " + fmt("%.1f", slope_m / 1e6) + " MPa (meshed) vs " + fmt("%.1f", slope_1d / 1e6) +
             " MPa (1-D); stress difference at equal strain max " + fmt("%.2f", max_d / 1e6) + " MPa, RMS " +
             fmt("%.2f", rms / 1e6) + " MPa");
  *ctx.summary +=
      "\n\n**Bar model: 1-D characteristic vs meshed bars** (" + spec.label + ", calibrated dry EOS; meshed: " +
      std::to_string(s.mesh_radial) + " radial elements, " + fmt("%.1f", s.element_length * 1e3) +
      " mm axially, face waves from the surface gauges by the 1-D shift; strain window " + fmt("%.2f", kSlopeLo) +
      "-" + fmt("%.2f", kSlopeHi) + ", t <= 350 us)\n\n"
      "| bars | slope (MPa) | dt (s) | steps | wall (s) |\n|---|---|---|---|---|\n"
      "| characteristic | " + fmt("%.1f", slope_1d / 1e6) + " | " + fmt("%.3g", one_d.dt) + " | " +
      std::to_string(one_d.steps) + " | " + fmt("%.1f", one_d.wall_s) + " |\n"
      "| meshed | " + fmt("%.1f", slope_m / 1e6) + " | " + fmt("%.3g", meshed.dt) + " | " +
      std::to_string(meshed.steps) + " | " + fmt("%.1f", meshed.wall_s) + " |\n\n"
      "Stress difference at equal strain (meshed - 1-D): max " + fmt("%.3f", max_d / 1e6) + " MPa, RMS " +
      fmt("%.3f", rms / 1e6) + " MPa (mean stress in the window " + fmt("%.2f", mean_s / 1e6) +
      " MPa); slope difference " + fmt("%+.2f", slope_diff) + " %.\n";
  harness::Plot p{"bars_meshed_vs_1d.png", "Bar model: 1-D characteristic vs meshed bars (" + spec.label + ")",
                  "strain (-)", "stress (MPa)", {}, {}, {}};
  p.series = {curve("characteristic (1-D) bars", one_d.h, kLoadingEnd),
              curve("meshed bars (gauges, 1-D shift)", meshed.h, kLoadingEnd, "dashed")};
  ctx.plots->push_back(p);
}

void rate_independence(const StudyContext& ctx, const shpb::SpecimenHistory& h480,
                       const shpb::SpecimenHistory& h900) {
  // "Similar" as the text uses it: it calls slopes of 200 and 208 MPa (4 % apart) similar
  // results, so stresses within 5 % are similar in its sense. The 900/s curve rings about the
  // 480/s one (strain period ~0.03 at 900/s); as in the harness's curve scoring, a strain
  // tolerance absorbs that: a 480/s point is matched if the 900/s curve comes within 5 % of its
  // stress somewhere within +-0.01 strain (a shift below what Fig. 2.4's scale resolves).
  constexpr double kSimilar = 0.05, kStrainTol = 0.01;
  const double t_all = std::numeric_limits<double>::infinity();  // the whole loading branch
  const long end = branch_end(h480, t_all), end900 = branch_end(h900, t_all);
  double limit = kNaN, worst = 0, worst_strain = kNaN, plain = 0, plain_strain = kNaN;
  bool diverged = false;
  for (long k = 0; k < end && !diverged; ++k) {
    const double e = h480.strain[k], s = h480.stress_back[k];
    if (e < kSlopeLo) continue;
    const double d0 = std::fabs(stress_at_strain(h900, e, t_all) / s - 1.0);  // no strain shift
    if (std::isfinite(d0) && d0 > plain) plain = d0, plain_strain = e;
    // Range of the 900/s polyline over [e - tol, e + tol]: its ends and the samples between.
    double lo = stress_at_strain(h900, e - kStrainTol, t_all), hi = stress_at_strain(h900, e + kStrainTol, t_all);
    if (!std::isfinite(lo) || !std::isfinite(hi) || !(s > 0)) break;  // the 900/s branch ends
    if (lo > hi) std::swap(lo, hi);
    for (long j = 0; j < end900; ++j)
      if (std::fabs(h900.strain[j] - e) <= kStrainTol)
        lo = std::min(lo, h900.stress_back[j]), hi = std::max(hi, h900.stress_back[j]);
    const double rel = (std::max(0.0, lo - s) + std::max(0.0, s - hi)) / s;
    if (rel > kSimilar) diverged = true;
    else limit = std::isfinite(limit) ? std::max(limit, s) : s;
    if (rel > worst) worst = rel, worst_strain = e;
  }
  auto& m = *ctx.m;
  m.scalar("ch2.rate_independence_limit", limit / 1e6);
  m.note("ch2.rate_independence_limit",
         std::string(diverged ? "the curves part beyond this stress" : "no divergence along the compared branch") +
             "; largest stress difference within +-0.01 strain " + fmt("%.1f", 100 * worst) + " %" +
             (worst > 0 ? " (at strain " + fmt("%.3f", worst_strain) + ")" : std::string()) +
             "; at equal strain without the shift " + fmt("%.1f", 100 * plain) + " % (at strain " +
             fmt("%.3f", plain_strain) + "); compared from strain " + fmt("%.2f", kSlopeLo) +
             " to the end of the 480/s loading branch");
  harness::Plot p{"rate_independence.png", "Polycarbonate tube, 480/s vs 900/s (calibrated EOS)", "strain (-)",
                  "stress (MPa)", {}, {}, {}};
  p.series = {curve("480/s", h480, t_all), curve("900/s", h900, t_all, "dashed")};
  if (std::isfinite(limit)) p.series.push_back({"agreement limit", {0, 0.3}, {limit / 1e6, limit / 1e6}, "dashed"});
  ctx.plots->push_back(p);
}

void mesh_refinement_study(const StudyContext& ctx, CaseSpec spec, const std::vector<std::pair<int, int>>& meshes) {
  struct Row { int n_r, n_z; double dt, wall, slope; long steps; };
  std::vector<Row> rows;
  for (const auto& [n_r, n_z] : meshes) {
    spec.n_radial = n_r;
    spec.n_axial = n_z;
    const auto r = run_case(*ctx.base, spec);
    if (!r.ok) {
      std::fprintf(stderr, "chapter2: mesh %d x %d failed: %s\n", n_r, n_z, r.failure.c_str());
      continue;
    }
    rows.push_back({n_r, n_z, r.dt, r.wall_s, loading_slope(r.h, kSlopeLo, kSlopeHi, kLoadingEnd), r.steps});
  }
  if (rows.empty()) return;
  const double finest = rows.back().slope;
  const double length = ctx.base->json.at("specimen").at("length").get<double>();
  std::string table = "\n\n**Mesh refinement** (" + spec.label + ", calibrated dry EOS; specimen mesh halved per "
                      "level, tube mesh fixed; slope over strain " + fmt("%.2f", kSlopeLo) + "-" + fmt("%.2f", kSlopeHi) +
                      ", t <= 350 us; wall time of the whole SHPB run on one core)\n\n"
                      "| level | mesh | elements | h_z (mm) | dt (s) | steps | wall (s) | slope (MPa) | deviation from finest (%) |\n"
                      "|---|---|---|---|---|---|---|---|---|\n";
  harness::Plot p{"mesh_refinement.png", "Mesh refinement: slope deviation from the finest mesh vs wall time",
                  "wall time per run (s)", "|slope - slope_finest| / slope_finest (%)", {}, {}, {}};
  harness::PlotSeries dev{"deviation (finest level not plotted)", {}, {}, "linespoints"};
  for (std::size_t i = 0; i < rows.size(); ++i) {
    const auto& r = rows[i];
    const double d = 100.0 * (r.slope / finest - 1.0);
    table += "| " + std::to_string(i) + " | " + std::to_string(r.n_r) + " x " + std::to_string(r.n_z) + " | " +
             std::to_string(r.n_r * r.n_z) + " | " + fmt("%.3f", length / r.n_z * 1e3) + " | " + fmt("%.3g", r.dt) +
             " | " + std::to_string(r.steps) + " | " + fmt("%.2f", r.wall) + " | " + fmt("%.2f", r.slope / 1e6) +
             " | " + fmt("%+.3f", d) + " |\n";
    if (i + 1 < rows.size()) dev.x.push_back(r.wall), dev.y.push_back(std::max(std::fabs(d), 1e-4));
  }
  p.series = {dev};
  p.logx = p.logy = true;
  ctx.plots->push_back(p);
  if (rows.size() >= 3) {
    // Observed order from the last three levels (h halved each time) and the Richardson
    // estimate of the converged slope.
    const double s0 = rows[rows.size() - 3].slope, s1 = rows[rows.size() - 2].slope, s2 = finest;
    const double order = std::log2((s1 - s0) / (s2 - s1));
    const double limit = s2 + (s2 - s1) / (std::pow(2.0, order) - 1.0);
    table += "\nObserved order of convergence (last three levels) " + fmt("%.2f", order) +
             "; Richardson estimate of the converged slope " + fmt("%.2f", limit / 1e6) + " MPa (level 1, the scene's calibration mesh, " +
             "lies " + fmt("%.2f", 100.0 * (rows[std::min<std::size_t>(1, rows.size() - 1)].slope / limit - 1.0)) +
             " % from it).\n";
  }
  *ctx.summary += table;
}

}  // namespace kolsky::ch2
