#include "chapter4/seeds.hpp"

#include <cmath>
#include <cstdio>

#include "common/format.hpp"
#include "common/stats.hpp"

namespace kolsky::ch4 {

using repro::fmt;

std::vector<SeedCase> seed_study(const harness::Case& base, double n, const std::vector<double>& seeds,
                                 const std::vector<double>& ks, double limit) {
  std::vector<SeedCase> out;
  for (double seed : seeds) {
    const std::string packing = "packing N = " + fmt("%g", n) + ", seed " + fmt("%g", seed);
    const harness::Case js = base.with("specimen.upscale", n, packing).with("specimen.seed", static_cast<long>(seed), packing);
    double porosity = NAN;
    std::string failure;
    try {  // pack once (the cases then read the cache)
      porosity = harness::pack(js).result.porosity;
    } catch (const std::exception& e) {
      failure = e.what();
    }
    for (double k : ks) {
      SeedCase s;
      s.seed = seed, s.k = k, s.porosity = porosity;
      if (!failure.empty()) {
        s.failure = failure;
        out.push_back(s);
        continue;
      }
      const CaseResult c = run_case(js, k, fmt("seed %g, ", seed) + fmt("k = %.8g", k));
      s.grains = c.dem.grains, s.case_s = c.wall_s, s.ok = c.ok, s.failure = c.failure;
      if (c.ok) {
        s.m = measure(c, 1e6, 3e6, limit);
        const long end = s.m.i_end > 0 ? s.m.i_end : static_cast<long>(c.history.t.size());
        s.strain.assign(c.history.strain.begin(), c.history.strain.begin() + end);
        s.stress.assign(c.history.stress_back.begin(), c.history.stress_back.begin() + end);
      }
      std::printf("seeds N = %g, seed %g, k = %.8g: %s, %.1f s, M 1-10 MPa %.1f MPa\n", n, seed, k,
                  s.ok ? "ok" : s.failure.c_str(), s.case_s, s.m.modulus_back / 1e6);
      out.push_back(s);
    }
  }
  return out;
}

namespace {

using Stat = repro::SampleStat;
Stat stat(const std::vector<double>& v) { return repro::sample_stat(v); }
std::string pm(const Stat& s, double scale, const char* f) {
  return fmt(f, s.mean * scale) + " ± " + fmt(f, s.sd * scale);
}

}  // namespace

FreeScatter calibrated_vs_free(const std::vector<SeedCase>& cases, double k_calibrated) {
  FreeScatter f;
  double g = 0;
  for (const auto& c : cases) {
    if (c.k != k_calibrated || !c.ok) continue;
    for (const auto& o : cases)
      if (o.seed == c.seed && o.k == 1.0 && o.ok) {
        f.d.push_back(c.m.modulus_back / o.m.modulus_back - 1);
        g += static_cast<double>(c.grains);
      }
  }
  if (f.d.empty()) return f;
  const Stat s = stat(f.d);
  f.mean = s.mean, f.sd = s.sd, f.grains = g / f.d.size();
  return f;
}

std::string seed_table(const std::vector<SeedCase>& cases, const std::vector<double>& ks,
                       double k_calibrated) {
  std::string t =
      "| seed | k per 1 ns | grains | porosity | case wall (s) | M 1-3 MPa | M 7-10 MPa | M 1-10 MPa | "
      "M 1-10 MPa, sigma_avg | back arrival (us) | mean alpha 1-10 MPa |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& c : cases) {
    if (!c.ok) {
      t += "| " + fmt("%g", c.seed) + " | " + fmt("%.8g", c.k) + " | failed: " + c.failure + " | | | | | | | | |\n";
      continue;
    }
    t += "| " + fmt("%g", c.seed) + " | " + fmt("%.8g", c.k) + " | " + std::to_string(c.grains) + " | " +
         fmt("%.4f", c.porosity) + " | " + fmt("%.1f", c.case_s) + " | " + fmt("%.1f", c.m.modulus_initial / 1e6) +
         " | " + fmt("%.1f", c.m.modulus_late / 1e6) + " | " + fmt("%.1f", c.m.modulus_back / 1e6) + " | " +
         fmt("%.1f", c.m.modulus_avg / 1e6) + " | " + fmt("%.1f", c.m.back_arrival * 1e6) + " | " +
         fmt("%.3f", c.m.alpha_mean) + " |\n";
  }
  // Per k: mean ± standard deviation over the seeds.
  t += "\nMean ± standard deviation over the seeds (moduli in MPa):\n\n"
       "| k per 1 ns | seeds | M 1-3 MPa | M 7-10 MPa | M 1-10 MPa | M 1-10 MPa, sigma_avg | back arrival (us) | mean alpha |\n"
       "|---|---|---|---|---|---|---|---|\n";
  auto column = [&](double k, auto get) {
    std::vector<double> v;
    for (const auto& c : cases)
      if (c.k == k && c.ok) v.push_back(get(c.m));
    return v;
  };
  for (double k : ks) {
    const Stat mi = stat(column(k, [](const Measures& m) { return m.modulus_initial; }));
    t += "| " + fmt("%.8g", k) + " | " + std::to_string(mi.n) + " | " + pm(mi, 1e-6, "%.1f") + " | " +
         pm(stat(column(k, [](const Measures& m) { return m.modulus_late; })), 1e-6, "%.1f") + " | " +
         pm(stat(column(k, [](const Measures& m) { return m.modulus_back; })), 1e-6, "%.1f") + " | " +
         pm(stat(column(k, [](const Measures& m) { return m.modulus_avg; })), 1e-6, "%.1f") + " | " +
         pm(stat(column(k, [](const Measures& m) { return m.back_arrival; })), 1e6, "%.2f") + " | " +
         pm(stat(column(k, [](const Measures& m) { return m.alpha_mean; })), 1, "%.3f") + " |\n";
  }
  // Orderings of Sec. 4.4, seed by seed (strict: no tie allowance).
  std::vector<double> seeds;
  for (const auto& c : cases)
    if (seeds.empty() || seeds.back() != c.seed) seeds.push_back(c.seed);
  auto find = [&](double seed, double k) -> const SeedCase* {
    for (const auto& c : cases)
      if (c.seed == seed && c.k == k && c.ok) return &c;
    return nullptr;
  };
  struct Order {
    std::string what;
    int holds = 0, seen = 0;
  };
  Order o_avg{"sigma_avg softer than sigma_t (calibrated k, M 1-10 MPa)"}, o_k0{"k = 0 stiffest (M 1-10 MPa)"},
      o_k1{"k = 1 softest (M 1-10 MPa)"}, o_arr{"k = 0 earliest back arrival"},
      o_eq{"k = 0 lowest mean alpha (own 1-10 MPa window)"};
  std::vector<double> d_cal;  // M(calibrated) / M(k = 1) - 1 per seed
  for (double seed : seeds) {
    const SeedCase* c0 = find(seed, 0.0);
    const SeedCase* c1 = find(seed, 1.0);
    const SeedCase* cc = find(seed, k_calibrated);
    if (cc) {
      ++o_avg.seen;
      o_avg.holds += cc->m.modulus_avg < cc->m.modulus_back;
    }
    if (c1 && cc) d_cal.push_back(cc->m.modulus_back / c1->m.modulus_back - 1);
    bool all = true;
    for (double k : ks) all = all && find(seed, k);
    if (!all || ks.size() < 2) continue;
    bool k0s = c0 != nullptr, k1s = c1 != nullptr, k0a = c0 != nullptr, k0e = c0 != nullptr;
    for (double k : ks) {
      const Measures& m = find(seed, k)->m;
      if (c0 && k != 0.0) {
        k0s = k0s && c0->m.modulus_back > m.modulus_back;
        k0a = k0a && c0->m.back_arrival < m.back_arrival;
        k0e = k0e && c0->m.alpha_mean < m.alpha_mean;
      }
      if (c1 && k != 1.0) k1s = k1s && c1->m.modulus_back < m.modulus_back;
    }
    if (c0) ++o_k0.seen, ++o_arr.seen, ++o_eq.seen;
    if (c1) ++o_k1.seen;
    o_k0.holds += k0s, o_arr.holds += k0a, o_eq.holds += k0e, o_k1.holds += k1s;
  }
  t += "\nSec. 4.4 comparisons, seed by seed (strict inequalities):\n\n| comparison | holds in |\n|---|---|\n";
  for (const Order* o : {&o_avg, &o_k0, &o_k1, &o_arr, &o_eq})
    if (o->seen > 0) t += "| " + o->what + " | " + std::to_string(o->holds) + " of " + std::to_string(o->seen) + " seeds |\n";
  if (!d_cal.empty()) {
    const Stat d = stat(d_cal);
    t += "\nM 1-10 MPa of the calibrated k relative to k = 1, per seed: ";
    for (size_t i = 0; i < d_cal.size(); ++i) t += (i ? ", " : "") + fmt("%+.2f %%", 100 * d_cal[i]);
    t += " (mean " + fmt("%+.2f %%", 100 * d.mean) + ", sd " + fmt("%.2f %%", 100 * d.sd) + ").\n";
  }
  return t;
}

}  // namespace kolsky::ch4
