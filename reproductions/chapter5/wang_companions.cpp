// The companions of the Wang targets that are known deviations (issue 31, item 3; README
// "The red Wang targets settled"). Each tests the cause a deviation's reason names and can fail:
// - the counts at 72 MPa: the text's "end of simulation" lies past 72 MPa (H5), so the pair
//   loaded on to the text's final count must show the text's B_r there;
// - the pair apart at 1-20 MPa: the N = 1 specimen breaks earlier, so without breakage the two
//   N must coincide there;
// - c_lim = 0 breaking fewer parents by the end: it breaks excessively while the stress is low,
//   softens, and by the end of the equal-strain history has fewer but larger broken parents; so
//   at half the smaller peak it must have broken at least twice the parents of c_lim = 8, and at
//   the end its B_r must be the larger. (A first explanation, "at 0.9 x the smaller peak more
//   than twice", was refuted at 1.40 and is kept as a measurement.)
#include <algorithm>
#include <cmath>

#include "chapter5/studies.hpp"

namespace kolsky::ch5 {

void wang_companions(Study& s, const WangPlan& p, const WangRuns& runs, std::string& md) {
  auto& m = *s.m;
  const auto& w = s.cases.at("wang");
  const auto& spec = w.at("companions");
  md += "\n### Companions of the known deviations (issue 31; README \"The red Wang targets settled\")\n\n";

  // H5: the pair loaded on (peak rate held) until the back stress passes end_count.back_stress;
  // B_r read at the first sample with the text's final count, scaled from N = 1.5 by N^-3.
  {
    const auto& e = spec.at("end_count");
    const CaseSpec& sp = p.end_count;
    const CaseResult& r = runs.end_count;
    const double count = e.at("count").get<double>() * std::pow(1.5 / sp.upscale, 3);
    const char* id = "ch5.wang.relative_breakage_at_end_count";
    const long k = r.ok ? first_at_least(r.grain_count, count) : -1;
    if (k >= 0) {
      const double broken = r.broken_primary[k] + r.broken_secondary[k];
      m.scalar(id, r.relative_breakage[k]);
      m.note(id, fmt("N = %g reaches %.0f grains (the text's %.0f at N = 1.5, x (1.5/N)^3) at back stress %.1f MPa, "
                     "t = %.1f us, strain %.3f: growth %.3f, %.0f broken parents, B_r %.3f",
                     sp.upscale, r.grain_count[k], e.at("count").get<double>(), r.stress_back[k] / 1e6, r.t[k] * 1e6,
                     r.strain[k], r.grain_count[k] / r.grains_initial, broken, r.relative_breakage[k]));
      md += fmt("- The pair loaded on: %.0f grains (growth %.3f) at back stress %.1f MPa, %.0f broken parents, B_r %.3f "
                "(text at its end: 40,000 / 12,824 grains, about 2,090 broken parents, B_r 0.28); %.0f s.\n",
                r.grain_count[k], r.grain_count[k] / r.grains_initial, r.stress_back[k] / 1e6, broken,
                r.relative_breakage[k], r.wall_s);
    } else {
      m.note(id, r.ok ? fmt("the count %.0f was not reached (largest %.0f grains, back stress %.1f MPa)", count,
                            max_of(r.grain_count), max_of(r.stress_back) / 1e6)
                      : "run failed: " + r.failure);
      md += "- The pair loaded on: the text's final count not reached.\n";
    }
  }

  // Without breakage the reference N and the pair must coincide where, with it, they part.
  {
    const char* id = "ch5.wang.pair_coincide_low_nobreak";
    const double lo = spec.at("nobreak_low").at(0).get<double>(), hi = spec.at("nobreak_low").at(1).get<double>();
    const CaseResult& r = runs.ref_nobreak;
    const CaseResult& pair_nobreak = runs.nobreak;
    if (r.ok && pair_nobreak.ok) {
      const auto d = stress_difference(r.strain, r.stress_back, pair_nobreak.strain, pair_nobreak.stress_back, lo, hi);
      const double rule = s.threshold(id, "max_rms_pa");
      m.trend(id, d.rms <= rule,
              fmt("without breakage, N = %g against N = %g: RMS %.2f MPa (largest %.2f) over back stress %.0f-%.0f MPa, %d "
                  "points; <= %g MPa", r.upscale, pair_nobreak.upscale, d.rms / 1e6, d.max / 1e6, lo / 1e6, hi / 1e6,
                  d.points, rule / 1e6));
      md += fmt("- Without breakage, N = %g against N = %g over back stress %.0f-%.0f MPa: RMS %.2f MPa (with breakage the "
                "target's pair is compared over the same window); %.0f s.\n",
                r.upscale, pair_nobreak.upscale, lo / 1e6, hi / 1e6, d.rms / 1e6, r.wall_s);
    } else {
      m.note(id, "a run failed: " + (r.ok ? pair_nobreak.failure : r.failure));
    }
  }

  // c_lim = 0 against c_lim = 8 at equal back stress: 0.9 x the smaller of their largest. It was
  // the first companion of clim0_breaks_more and failed (ratio 1.40 <= 2, README): recorded
  // without a target. Then the two companions of the explanation that held on a second seed.
  {
    const CaseResult &base = runs.base(p), &clim0 = runs.clim0;
    if (base.ok && clim0.ok) {
      const double low = spec.at("low_stress_fraction").get<double>() *
                         std::min(max_of(base.stress_back), max_of(clim0.stress_back));
      const double lb = broken_at_stress(base, low), l0 = broken_at_stress(clim0, low);
      const double min_ratio = s.threshold("ch5.wang.clim0_breaks_more_low_stress", "min_broken_ratio");
      m.trend("ch5.wang.clim0_breaks_more_low_stress", l0 > min_ratio * lb,
              fmt("broken parents at back stress %.1f MPa (%.2f x the smaller peak): c_lim = 0 %.0f, c_lim = 8 %.0f "
                  "(ratio %.2f; > %g)", low / 1e6, spec.at("low_stress_fraction").get<double>(), l0, lb, l0 / lb, min_ratio));
      const double rb = base.relative_breakage.back(), r0 = clim0.relative_breakage.back();
      m.trend("ch5.wang.clim0_more_broken_mass", r0 > rb,
              fmt("B_r at the end of the equal-strain history: c_lim = 0 %.3f (%.0f parents), c_lim = 8 %.3f (%.0f parents)", r0,
                  clim0.broken_primary.back() + clim0.broken_secondary.back(), rb,
                  base.broken_primary.back() + base.broken_secondary.back()));
      const double level = spec.at("equal_stress_fraction").get<double>() *
                           std::min(max_of(base.stress_back), max_of(clim0.stress_back));
      const double kb = broken_at_stress(base, level), k0 = broken_at_stress(clim0, level);
      m.scalar("ch5.wang.clim0_broken_ratio_equal_stress", k0 / kb);
      m.note("ch5.wang.clim0_broken_ratio_equal_stress",
             fmt("broken parents at back stress %.1f MPa: c_lim = 0 %.0f, c_lim = 8 %.0f", level / 1e6, k0, kb));
      md += fmt("- At equal back stress (%.1f MPa) c_lim = 0 has broken %.0f parents, c_lim = 8 %.0f (ratio %.2f).\n",
                level / 1e6, k0, kb, k0 / kb);
    }
  }
}

}  // namespace kolsky::ch5
