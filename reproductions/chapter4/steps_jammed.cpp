// Step 8 of the Chapter 4 recipe: the jammed diagnostic specimen (studies.json "jammed":
// porosity 0.41, at the jamming density of mu = 0.5 spheres; README, "A specimen that starts
// jammed"), the companions of the known deviations. If the printed specimen misses because it
// is below jamming and rolls, the text's 220 MPa (Sec. 4.4.1) lies between it and the jammed
// one, and the jammed one has the Sec. 4.4 orderings the printed one lacks (sigma_avg softer,
// k = 0 closest to equilibrium).
#include <chrono>
#include <cmath>
#include <cstdio>

#include "chapter4/recipe.hpp"

namespace kolsky::ch4 {

using repro::fmt;

namespace {

// The companions, read on the jammed cases at the printed k and at k = 0.
void jammed_companions(Recipe& r, double n_j, bool jcommon, double ja, double jb) {
  auto& m = r.m();
  const Measures& b = r.printed_m();
  auto jfind = [&](double k) -> const Measures* {
    for (size_t i = 0; i < r.jam.size(); ++i)
      if (r.jam[i].rolling_factor == k && r.jam[i].ok) return &r.jam_m[i];
    return nullptr;
  };
  const double target = reference_value(r.targets, "ch4.confined_modulus_initial_dem");
  const Measures* jc = jfind(r.k_cal);
  if (jc == nullptr) return;
  const double lo = b.modulus_initial / 1e6, hi = jc->modulus_initial / 1e6;
  m.scalar("ch4.jammed_brackets_initial_modulus", (target - lo) / (hi - lo));
  m.note("ch4.jammed_brackets_initial_modulus",
         "(220 - M_printed) / (M_jammed - M_printed) with M 1-3 MPa at the printed k: printed n = 0.44 " + fmt("%.1f", lo) +
             " MPa, jammed n = " + fmt("%g", n_j) + " " + fmt("%.1f MPa", hi) + "; in [0, 1] iff 220 MPa lies between them");
  if (std::isfinite(jc->modulus_avg))
    m.trend("ch4.jammed_trend_average_softer", jc->modulus_avg < jc->modulus_back,
            "jammed n = " + fmt("%g", n_j) + ", printed k: sigma_avg " + mpa(jc->modulus_avg) + " vs sigma_t " +
                mpa(jc->modulus_back) + " (printed specimen: " + mpa(b.modulus_avg) + " vs " + mpa(b.modulus_back) + ")");
  if (const Measures* j0 = jfind(0.0))
    m.trend("ch4.jammed_trend_k0_closest_equilibrium", j0->alpha_mean < jc->alpha_mean,
            "jammed n = " + fmt("%g", n_j) + ", mean alpha " +
                (jcommon ? "over t = " + fmt("%.1f", ja * 1e6) + "-" + fmt("%.1f us", jb * 1e6)
                         : std::string("over each case's own window")) +
                ": k = 0 " + fmt("%.3f", j0->alpha_mean) + " vs k = " + fmt("%.8g", r.k_cal) + " " + fmt("%.3f", jc->alpha_mean));
}

std::string jammed_table(const Recipe& r, double n_j, const dem::CachedPacking& pj, double pj_s) {
  std::string md = "\n\n**Jammed diagnostic specimen** (clearly not the text's: porosity " + fmt("%g", n_j) + ", packed " +
                   fmt("%.4f", r.jam_porosity) + ", " + std::to_string(pj.result.count) + " grains, " +
                   (pj.from_cache ? "packing read from the cache" : fmt("packed in %.0f s", pj_s)) +
                   "; everything else as the set's scene):\n\n"
                   "| k per 1 ns | M 1-3 MPa | M 7-10 MPa | M 1-10 MPa | sigma_avg M 1-10 MPa | back arrival (us) | mean alpha (common window) | t at 10 MPa (us) | wall (s) |\n"
                   "|---|---|---|---|---|---|---|---|---|\n";
  for (size_t i = 0; i < r.jam.size(); ++i) {
    const Measures& q = r.jam_m[i];
    md += "| " + fmt("%.8g", r.jam[i].rolling_factor) + " | " + mpa(q.modulus_initial) + " | " + mpa(q.modulus_late) +
          " | " + mpa(q.modulus_back) + " | " + mpa(q.modulus_avg) + " | " + fmt("%.1f", q.back_arrival * 1e6) + " | " +
          fmt("%.3f", q.alpha_mean) + " | " + fmt("%.1f", q.time_at_limit * 1e6) + " | " + fmt("%.1f", r.jam[i].wall_s) +
          " |" + (r.jam[i].ok ? "" : " failed: " + r.jam[i].failure) + "\n";
  }
  return md;
}

}  // namespace

// 8. The jammed specimen: the set's case at the studies file's porosity, its packing timed,
// each of its k run and measured like the family.
void jammed_specimen(Recipe& r) {
  if (!study_on("jammed")) return;
  const auto& js = r.studies.at("jammed");
  const double n_j = js.at("porosity").get<double>();
  const harness::Case jj = r.set_case.with("specimen.porosity", n_j, "jammed packing n = " + fmt("%g", n_j));
  const auto t0 = std::chrono::steady_clock::now();
  const dem::CachedPacking pj = harness::pack(jj);
  const double pj_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  r.jam_porosity = pj.result.porosity;
  for (double k : js.at("ks").get<std::vector<double>>()) {
    r.jam.push_back(run_case(jj, k, "jammed n = " + fmt("%g", n_j) + " (diagnostic), k = " + fmt("%.8g", k)));
    r.jam_m.push_back(measure(r.jam.back(), 1e6, 3e6, r.limit));
    std::printf("%s: %s, %.1f s, M 1-3 MPa %.1f MPa\n", r.jam.back().label.c_str(),
                r.jam.back().ok ? "ok" : r.jam.back().failure.c_str(), r.jam.back().wall_s,
                r.jam_m.back().modulus_initial / 1e6);
  }
  double ja = 0, jb = 0;
  const bool jcommon = common_window_alpha(r.jam, r.jam_m, ja, jb);
  jammed_companions(r, n_j, jcommon, ja, jb);
  r.jam_md = jammed_table(r, n_j, pj, pj_s);
}

}  // namespace kolsky::ch4
