// Steps 10 and 11 of the Chapter 4 recipe: speed against error of the upscaling factor N
// (upscaling.hpp; the text upscales the PSD by N = 2, Sec. 4.3) and the scatter between packing
// seeds (seeds.hpp), which tells which Sec. 4.4 comparisons one packing can resolve.
#include <omp.h>

#include <cmath>
#include <cstdlib>

#include "chapter4/recipe.hpp"
#include "chapter4/seeds.hpp"
#include "chapter4/upscaling.hpp"

namespace kolsky::ch4 {

using repro::fmt;

namespace {

void upscaling_plots(Recipe& r, const std::vector<UpscalingRow>& rows, const FinestComparison& finest) {
  const auto& h = r.printed().history;
  const long n = r.printed_end();
  harness::Plot uc{"upscaling_curves.png", "sigma_t vs strain for upscaling factors N", "strain (-)", "stress (MPa)", {}, {}, {}};
  harness::Plot ue{"upscaling_cost.png", "Cost vs deviation of sigma_t(strain)", "case wall time (s)", "RMS deviation of sigma_t (MPa)", {}, {}, {}};
  uc.series.push_back({"N = " + fmt("%g", r.upscale), scaled(h.strain, 1, n), scaled(h.stress_back, 1e-6, n)});
  std::vector<double> cost, dev, cost_f, dev_f;
  if (std::isfinite(finest.reference_rms)) cost_f.push_back(r.printed().wall_s), dev_f.push_back(finest.reference_rms / 1e6);
  for (const auto& row : rows) {
    if (!row.ok) continue;
    uc.series.push_back({"N = " + fmt("%g", row.n), scaled(row.strain, 1, row.i_end), scaled(row.stress, 1e-6, row.i_end)});
    cost.push_back(row.case_s);
    dev.push_back(row.rms / 1e6);
    if (row.n != finest.n && std::isfinite(row.rms_finest)) cost_f.push_back(row.case_s), dev_f.push_back(row.rms_finest / 1e6);
  }
  ue.series.push_back({"from N = " + fmt("%g", r.upscale) + " (1-10 MPa)", cost, dev, "linespoints"});
  if (!cost_f.empty())
    ue.series.push_back({"from N = " + fmt("%g", finest.n) + " (1-" + fmt("%.1f", finest.top / 1e6) + " MPa)",
                         cost_f, dev_f, "linespoints"});
  ue.logx = true;
  r.rep.plots.push_back(uc);
  r.rep.plots.push_back(ue);
}

}  // namespace

// 10. The calibrated case at other N against this scale's N; at full scale one finer N, 1.5,
// shows whether N = 2 is converged. KOLSKY_CH4_NS="2.5,3" overrides the list ("" skips).
void upscaling(Recipe& r) {
  std::vector<double> ns = r.smoke ? std::vector<double>{8.0} : std::vector<double>{1.5, 2.5, 3.0, 4.0};
  if (const char* env = std::getenv("KOLSKY_CH4_NS")) ns = parse_list(env);
  if (ns.empty()) return;
  auto rows = upscaling_study(r.set_case, r.k_cal, r.printed(), r.printed_m(), ns, 1e6, r.limit);
  const FinestComparison finest = compare_with_finest(rows, r.printed(), r.upscale, 1e6);
  r.upscaling_md = "\n\n**Speed against error of the upscaling factor N** (calibrated k; deviation of sigma_t(strain) "
                   "from the N = " + fmt("%g", r.upscale) + " curve between back stresses of 1 and 10 MPa on it, and from the "
                   "finest N's curve up to its largest stress; wall times "
                   "on this machine with " + std::to_string(omp_get_max_threads()) + " OpenMP thread(s)):\n\n" +
                   upscaling_table(r.printed(), r.printed_m(), wall_layer(harness::final_scene(r.set_case), r.packing.result.particles),
                                   r.upscale, rows, finest);
  upscaling_plots(r, rows, finest);
}

namespace {

// Companion of "k = 1 softest": the N-scale difference between the calibrated k and k = 1
// against the seed-to-seed scatter of that same difference (README, "Scatter between packing
// seeds"). The scatter is measured at the seed study's N and scaled to this N's grain count
// by sqrt(grains_seed / grains) (a packing average over more grains scatters less): the
// stricter reading, since the unscaled scatter would allow more.
void free_within_scatter(Recipe& r, const std::vector<SeedCase>& sc_cases, double seed_n) {
  const FreeScatter fs = calibrated_vs_free(sc_cases, r.k_cal);
  if (!(r.i1 >= 0 && fs.d.size() >= 2 && std::isfinite(fs.sd) && fs.sd > 0)) return;
  const double d = r.printed_m().modulus_back / r.ms[r.i1].modulus_back - 1;
  const double sd = fs.sd * std::sqrt(fs.grains / static_cast<double>(r.printed().dem.grains));
  r.m().scalar("ch4.rotation_k1_vs_calibrated_within_seed_scatter", std::abs(d) / (2 * sd));
  std::string per;
  for (double x : fs.d) per += (per.empty() ? "" : ", ") + fmt("%+.2f %%", 100 * x);
  r.m().note("ch4.rotation_k1_vs_calibrated_within_seed_scatter",
             "|M(k_cal)/M(1) - 1| = " + fmt("%.2f %%", 100 * std::abs(d)) + " at N = " + fmt("%g", r.upscale) + " against 2 x " +
                 fmt("%.2f %%", 100 * sd) + " (seed sd " + fmt("%.2f %%", 100 * fs.sd) + " at N = " + fmt("%g", seed_n) + " over " +
                 std::to_string(fs.d.size()) + " seeds: " + per + ", x sqrt(" + fmt("%.0f", fs.grains) + " / " +
                 std::to_string(r.printed().dem.grains) + " grains))");
}

}  // namespace

// 11. The whole rotational family on packings that differ only in their seed, at a coarser N
// where a packing costs minutes: N = 3 at full scale, N = 8 with two k at the smoke scale.
// KOLSKY_CH4_SEED_N and KOLSKY_CH4_SEEDS ("" skips) override.
void seed_scatter(Recipe& r) {
  double seed_n = r.smoke ? 8.0 : 3.0;
  if (const char* env = std::getenv("KOLSKY_CH4_SEED_N")) seed_n = std::stod(env);
  const double seed0 = harness::final_scene(r.set_case)["specimen"]["seed"].get<double>();
  std::vector<double> seeds;
  for (int s = 0; s < (r.smoke ? 2 : 5); ++s) seeds.push_back(seed0 + s);
  if (const char* env = std::getenv("KOLSKY_CH4_SEEDS")) seeds = parse_list(env);
  std::vector<double> seed_ks{r.k_cal};
  for (double k : r.smoke ? std::vector<double>{1.0} : std::vector<double>{0.0, 0.999, 1.0}) seed_ks.push_back(k);
  if (seeds.empty()) return;
  const auto sc_cases = seed_study(r.set_case, seed_n, seeds, seed_ks, r.limit);
  r.scatter_md = "\n\n**Scatter between packing seeds** (N = " + fmt("%g", seed_n) +
                 ", the same scene with specimen.seed changed; windows as above):\n\n" + seed_table(sc_cases, seed_ks, r.k_cal);
  harness::Plot sp{"seed_curves.png", "sigma_t vs strain, calibrated k, packing seeds at N = " + fmt("%g", seed_n),
                   "strain (-)", "stress (MPa)", {}, {}, {}};
  for (const auto& c : sc_cases)
    if (c.ok && c.k == r.k_cal) sp.series.push_back({"seed " + fmt("%g", c.seed), c.strain, scaled(c.stress, 1e-6)});
  r.rep.plots.push_back(sp);
  free_within_scatter(r, sc_cases, seed_n);
}

}  // namespace kolsky::ch4
