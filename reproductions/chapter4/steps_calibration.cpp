// Steps 3, 7 and 12 of the Chapter 4 recipe: the rotational factor back-calculated. Sec. 4.3
// says its k was calibrated without saying against what; the set takes the text's initial
// modulus, 220 MPa (Sec. 4.4.1), as the target (calibration.hpp says how and why on x).
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <utility>

#include "chapter4/recipe.hpp"

namespace kolsky::ch4 {

using repro::fmt;

// 3. The twin experiment: the back-calculation procedure recovers a known k from synthetic data
// (the initial modulus of a case run at that k) on a cheap specimen before it is trusted on
// the real one.
void twin_experiment(Recipe& r) {
  if (!study_on("twin")) return;
  auto& m = r.m();
  const auto& tw = r.studies.at("twin");
  const double n_twin = tw.at(r.smoke ? "upscale_smoke" : "upscale_full").get<double>();
  const double k_true = tw.at("k_true").get<double>();
  const harness::Case jt = r.set_case.with("specimen.upscale", n_twin, "twin packing N = " + fmt("%g", n_twin));
  harness::pack(jt);
  auto eval_twin = [&](double k) { return run_point(r, jt, k, "twin N = " + fmt("%g", n_twin) + ", k = " + fmt("%.10g", k)); };
  const CalPoint truth = eval_twin(k_true);  // the synthetic "measurement"
  const double x_true = x_of_k(k_true);
  Calibration& twin = r.twin;
  twin = calibrate(eval_twin, truth.value, r.cal_set);
  const double allowed = tw.at("allowed_multiple").get<double>() * twin.dx;
  std::printf("twin: k_true %.8g (x %.3f), synthetic M %.1f MPa -> k %.8g (x %.3f +- %.3f), %s\n", k_true, x_true,
              truth.value / 1e6, twin.k, twin.x, twin.dx, twin.status.c_str());
  if (twin.converged) {
    m.scalar("ch4.calibration_twin_recovery", std::abs(twin.x - x_true) / allowed);
    m.note("ch4.calibration_twin_recovery",
           "N = " + fmt("%g", n_twin) + ": k_true " + fmt("%.8g", k_true) + " per ns (x = " + fmt("%.3f", x_true) +
               "), synthetic M 1-3 MPa " + mpa(truth.value) + "; recovered k " + fmt("%.8g", twin.k) + " (x = " +
               fmt("%.3f", twin.x) + "), |dx| = " + fmt("%.3f", std::abs(twin.x - x_true)) + " decades against " +
               fmt("%.3f", allowed) + " allowed (2 x " + fmt("%.0f %%", 100 * r.cal_set.resolution_rtol) +
               " of M over the bracket slope " + fmt("%.1f MPa/decade", twin.slope / 1e6) + "); " + twin.status);
  } else {
    m.note("ch4.calibration_twin_recovery", twin.status);
  }
  r.twin_md = "\n\n**Twin experiment of the back-calculation** (N = " + fmt("%g", n_twin) + ": synthetic target = the initial modulus "
              "of a case at k_true = " + fmt("%.8g", k_true) + " per ns, x = " + fmt("%.3f", x_true) + ", " + mpa(truth.value) +
              "): recovered k = " + fmt("%.8g", twin.k) + " (x = " + fmt("%.3f", twin.x) + " +- " + fmt("%.3f", twin.dx) +
              "), error " + fmt("%.3f", std::abs(twin.x - x_true)) + " decades, allowed " + fmt("%.3f", allowed) +
              "; " + twin.status + ".\n\n" + calibration_table(twin);
}

namespace {

// The calibrated variant's measures beside the printed k's (Sec. 4.4.1's 220, 228 and 300 MPa).
void record_variant(Recipe& r, const CalPoint& v, const std::string& printed_note) {
  auto& m = r.m();
  const Calibration& cal = r.cal;
  const Measures& b = r.printed_m();
  m.scalar("ch4.calibrated_k_log10", cal.x);
  m.note("ch4.calibrated_k_log10", "k = " + fmt("%.8g", cal.k) + " per ns = 1 - 10^" + fmt("%.3f", cal.x) + " (+- " +
                                       fmt("%.3f", cal.dx) + " decades: k in [" + fmt("%.6g", k_of_x(cal.x - cal.dx)) +
                                       ", " + fmt("%.6g", k_of_x(cal.x + cal.dx)) + "]) against the " + printed_note +
                                       "; " + cal.status);
  m.scalar("ch4.calibrated_variant_modulus_initial", v.value / 1e6);
  m.note("ch4.calibrated_variant_modulus_initial", "circular: the quantity the calibration fits (a check that the finder "
                                                   "stopped within its resolution); M 1-10 MPa " + mpa(v.m.modulus_back));
  m.scalar("ch4.calibrated_variant_modulus_stiffened", v.m.modulus_late / 1e6);
  m.note("ch4.calibrated_variant_modulus_stiffened", "calibrated variant k = " + fmt("%.8g", cal.k) + ", fit over back stress "
                                                     "7-10 MPa; M 1-10 MPa " + mpa(v.m.modulus_back) + " (the printed k: " +
                                                     mpa(b.modulus_late) + ", " + mpa(b.modulus_back) + ")");
  m.scalar("ch4.calibrated_variant_modulus_overall", v.m.modulus_back / 1e6);
  m.note("ch4.calibrated_variant_modulus_overall", "calibrated variant, fit over back stress 1-10 MPa (the printed k: " +
                                                   mpa(b.modulus_back) + ")");
  if (std::isfinite(v.m.modulus_avg))
    m.trend("ch4.calibrated_variant_trend_average_softer", v.m.modulus_avg < v.m.modulus_back,
            "sigma_avg " + mpa(v.m.modulus_avg) + " vs sigma_t " + mpa(v.m.modulus_back));
}

// The calibrated variant's row beside the printed k's; alpha of the printed case over its own
// 1-10 MPa window, like the root's (b_own), not over the family's common window.
std::string variant_table(const Recipe& r, const CalPoint& v, const Measures& b_own) {
  const Measures& b = r.printed_m();
  return "\n**Calibrated variant** (the set's specimen with k = " + fmt("%.8g", r.cal.k) + " per ns; labelled as such, the "
         "printed k stays the reproduction):\n\n| k per 1 ns | M 1-3 MPa (220 / 228) | M 7-10 MPa (300) | M 1-10 MPa (300) | "
         "sigma_avg M 1-10 MPa | mean alpha 1-10 MPa | t at 10 MPa (us) |\n|---|---|---|---|---|---|---|\n| " +
         fmt("%.8g", r.cal.k) + " (calibrated) | " + mpa(v.value) + " | " + mpa(v.m.modulus_late) + " | " +
         mpa(v.m.modulus_back) + " | " + mpa(v.m.modulus_avg) + " | " + fmt("%.3f", v.m.alpha_mean) + " | " +
         fmt("%.1f", v.m.time_at_limit * 1e6) + " |\n| " + fmt("%.8g", r.k_cal) + " (printed) | " + mpa(b.modulus_initial) +
         " | " + mpa(b.modulus_late) + " | " + mpa(b.modulus_back) + " | " + mpa(b.modulus_avg) + " | " +
         fmt("%.3f", b_own.alpha_mean) + " | " + fmt("%.1f", b.time_at_limit * 1e6) + " |\n";
}

}  // namespace

// 7. The k per 1 ns whose initial modulus on this (printed) specimen is the text's 220 MPa;
// start points reused from the family of step 4. Its root case is the calibrated variant,
// reported beside the printed k (which stays the reproduction).
void back_calculate_k(Recipe& r) {
  if (!study_on("calibration")) return;
  const auto& rc = r.studies.at("rotational_calibration");
  const double target = reference_value(r.targets, rc.at("target_id").get<std::string>()) * 1e6;
  auto eval_set = [&](double k) {
    for (size_t i = 0; i < r.cases.size(); ++i)
      if (r.cases[i].rolling_factor == k) return cal_point(r.cases[i], r.ms[i], true);
    return run_point(r, r.set_case, k, "calibration, k = " + fmt("%.10g", k));
  };
  Calibration& cal = r.cal;
  cal = calibrate(eval_set, target, r.cal_set);
  const Measures b_own = measure(r.printed(), 1e6, 3e6, r.limit);
  std::printf("calibration: target %.1f MPa -> k %.10g per ns (x %.3f +- %.3f), %s\n", target / 1e6, cal.k, cal.x,
              cal.dx, cal.status.c_str());
  const CalPoint* v = cal.root();
  const std::string printed_note = "printed k = " + fmt("%.8g", r.k_cal) + " per ns (x = " + fmt("%.3f", x_of_k(r.k_cal)) + ")";
  if (v != nullptr) {
    record_variant(r, *v, printed_note);
  } else {
    for (const char* id : {"ch4.calibrated_k_log10", "ch4.calibrated_variant_modulus_initial",
                           "ch4.calibrated_variant_modulus_stiffened", "ch4.calibrated_variant_modulus_overall",
                           "ch4.calibrated_variant_trend_average_softer"})
      r.m().note(id, cal.status);
  }
  r.cal_md = "\n\n**The rotational factor back-calculated** (Brent on x = log10(1 - k), k per 1 ns, target: the initial modulus "
             "(1-3 MPa) = " + mpa(target) + "; start points the family's k; stop when |M - target| <= " +
             fmt("%.0f %%", 100 * r.cal_set.resolution_rtol) + " of the target, the run-to-run resolution, studies.json): " +
             (v != nullptr ? "**k = " + fmt("%.8g", cal.k) + " per ns** (x = " + fmt("%.3f", cal.x) + " +- " + fmt("%.3f", cal.dx) +
                                 " decades, from the resolution over the bracket slope " + fmt("%.1f MPa/decade", cal.slope / 1e6) +
                                 ") against the " + printed_note + "; " + cal.status
                           : cal.status) + ".\n\n" + calibration_table(cal);
  if (v != nullptr) r.cal_md += variant_table(r, *v, b_own);
}

// 12. Back-calculation plots: M 1-3 MPa against x = log10(1 - k) with the target, and sigma_t of
// the printed specimen, its calibrated variant and the jammed diagnostic one.
void calibration_plots(Recipe& r) {
  if (!r.cal.points.empty() || !r.twin.points.empty()) {
    harness::Plot cp{"calibration.png", "Initial modulus (1-3 MPa) vs rotational factor: back-calculation and twin",
                     "x = log10(1 - k), k per 1 ns", "M 1-3 MPa (MPa)", {}, {}, {}};
    auto add = [&](const Calibration& c, const std::string& what) {
      std::vector<std::pair<double, double>> v;
      for (const auto& p : c.points)
        if (std::isfinite(p.x) && std::isfinite(p.value)) v.push_back({p.x, p.value / 1e6});
      std::sort(v.begin(), v.end());
      harness::PlotSeries ps{what, {}, {}, "linespoints"};
      for (auto [x, y] : v) ps.x.push_back(x), ps.y.push_back(y);
      if (!ps.x.empty()) cp.series.push_back(ps);
      if (std::isfinite(c.target) && !ps.x.empty())
        cp.series.push_back({what + ": target", {ps.x.front(), ps.x.back()}, {c.target / 1e6, c.target / 1e6}, "dashed"});
    };
    add(r.cal, "N = " + fmt("%g", r.upscale) + " (the set's specimen)");
    add(r.twin, "twin (synthetic target)");
    if (!cp.series.empty()) r.rep.plots.push_back(cp);
  }
  if (r.cal.root() == nullptr && r.jam.empty()) return;
  const auto& h = r.printed().history;
  const long n = r.printed_end();
  const double e_max = n > 0 ? h.strain[n - 1] : 0.05;
  harness::Plot sv{"specimens.png", "sigma_t vs strain: printed, calibrated variant, jammed diagnostic",
                   "strain (-)", "stress (MPa)", {}, {}, {}};
  sv.series.push_back({"printed (n 0.44, k " + fmt("%.8g", r.k_cal) + ")", scaled(h.strain, 1, n), scaled(h.stress_back, 1e-6, n)});
  if (const CalPoint* v = r.cal.root())
    sv.series.push_back({"calibrated variant (k " + fmt("%.6g", v->k) + ")", v->strain, scaled(v->stress, 1e-6)});
  for (size_t i = 0; i < r.jam.size(); ++i) {
    if (!r.jam[i].ok) continue;
    const long ni = r.jam_m[i].i_end > 0 ? r.jam_m[i].i_end : static_cast<long>(r.jam[i].history.t.size());
    sv.series.push_back({"jammed n " + fmt("%.2f", r.jam_porosity) + ", k " + fmt("%.8g", r.jam[i].rolling_factor),
                         scaled(r.jam[i].history.strain, 1, ni), scaled(r.jam[i].history.stress_back, 1e-6, ni), "dashed"});
  }
  sv.bands = {{"220 MPa (Sec. 4.4.1) +-5 %", {0, e_max}, {0, 0.220e3 * e_max * 0.95}, {0, 0.220e3 * e_max * 1.05}}};
  r.rep.plots.push_back(sv);
}

}  // namespace kolsky::ch4
