#include "chapter4/upscaling.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>

#include "common/format.hpp"

namespace kolsky::ch4 {

namespace {

// sigma_t at strain e on the curve (strain, stress), linear between samples; the strain is
// made monotone by its running maximum (it may dip by round-off before the arrival).
double stress_at(const std::vector<double>& strain, const std::vector<double>& stress, double e) {
  double prev_e = -1e300, prev_s = 0;
  for (std::size_t i = 0; i < strain.size(); ++i) {
    const double ei = std::max(strain[i], prev_e);
    if (ei >= e) {
      if (i == 0 || ei == prev_e) return stress[i];
      return prev_s + (stress[i] - prev_s) * (e - prev_e) / (ei - prev_e);
    }
    prev_e = ei, prev_s = stress[i];
  }
  return NAN;  // beyond the curve
}

// |sigma(strain) - ref_stress| at the strains of the samples [i0, i1) of a reference curve,
// where the curve (strain, stress) has data: RMS and largest (NaN, 0 without any).
struct Deviation {
  double rms = NAN, max = 0;
};
Deviation deviation(const std::vector<double>& strain, const std::vector<double>& stress,
                    const std::vector<double>& ref_strain, const std::vector<double>& ref_stress,
                    long i0, long i1) {
  Deviation d;
  double sum = 0;
  long cnt = 0;
  for (long i = i0; i < i1; ++i) {
    const double s = stress_at(strain, stress, ref_strain[i]);
    if (!std::isfinite(s)) continue;
    const double e = std::abs(s - ref_stress[i]);
    sum += e * e, ++cnt;
    d.max = std::max(d.max, e);
  }
  if (cnt > 0) d.rms = std::sqrt(sum / cnt);
  return d;
}

}  // namespace

std::vector<UpscalingRow> upscaling_study(const harness::Case& base, double k,
                                          const CaseResult& reference, const Measures& ref_m,
                                          const std::vector<double>& ns, double lo, double limit) {
  std::vector<UpscalingRow> rows;
  const auto& rh = reference.history;
  for (double n : ns) {
    UpscalingRow row;
    row.n = n;
    const harness::Case jn = base.with("specimen.upscale", n, "packing N = " + repro::fmt("%g", n));
    try {
      const auto t0 = std::chrono::steady_clock::now();
      const dem::CachedPacking pk = harness::pack(jn);
      row.pack_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      row.packed_now = !pk.from_cache;
      row.layer = wall_layer(harness::final_scene(jn), pk.result.particles);
    } catch (const std::exception& e) {
      row.failure = e.what();
      rows.push_back(row);
      continue;
    }
    const CaseResult c = run_case(jn, k, "N = " + repro::fmt("%g", n));
    row.grains = c.dem.grains;
    row.case_s = c.wall_s;
    row.dt = c.run.dt;
    row.ok = c.ok;
    row.failure = c.failure;
    if (c.ok && ref_m.i_lo >= 0 && ref_m.i_end > ref_m.i_lo) {
      const Measures m = measure(c, lo, 3e6, limit);
      row.modulus = m.modulus_back;
      if (m.i_lo >= 0) row.toe_strain = c.history.strain[m.i_lo];
      row.i_end = m.i_end > 0 ? m.i_end : static_cast<long>(c.history.t.size());
      row.strain = c.history.strain;
      row.stress = c.history.stress_back;
      const Deviation d = deviation(c.history.strain, c.history.stress_back, rh.strain, rh.stress_back,
                                    ref_m.i_lo, ref_m.i_end);
      row.rms = d.rms, row.max = d.max;
    }
    std::printf("upscaling N = %g: %zu grains, %s, case %.1f s, packing %.1f s%s, RMS deviation %.2f MPa, "
                "solid fraction %.4f (core %.4f), strain at 1 MPa %.4f\n",
                n, row.grains, row.ok ? "ok" : row.failure.c_str(), row.case_s, row.pack_s,
                row.packed_now ? " (generated)" : " (cache)", row.rms / 1e6, row.layer.whole,
                row.layer.core, row.toe_strain);
    rows.push_back(row);
  }
  return rows;
}

FinestComparison compare_with_finest(std::vector<UpscalingRow>& rows, const CaseResult& reference,
                                     double reference_n, double lo) {
  FinestComparison out;
  const UpscalingRow* f = nullptr;
  for (const auto& r : rows)
    if (r.ok && r.n < reference_n && (!f || r.n < f->n)) f = &r;
  if (!f || f->stress.empty()) return out;
  out.n = f->n;
  const long i_top = static_cast<long>(
      std::max_element(f->stress.begin(), f->stress.end()) - f->stress.begin());
  out.top = f->stress[i_top];
  long i0 = 0;
  while (i0 <= i_top && f->stress[i0] < lo) ++i0;
  auto rms_against = [&](const std::vector<double>& strain, const std::vector<double>& stress) {
    return deviation(strain, stress, f->strain, f->stress, i0, i_top + 1).rms;
  };
  out.reference_rms = rms_against(reference.history.strain, reference.history.stress_back);
  const double finest_n = f->n;  // f points into rows
  for (auto& r : rows)
    if (r.ok) r.rms_finest = r.n == finest_n ? 0.0 : rms_against(r.strain, r.stress);
  return out;
}

std::string upscaling_table(const CaseResult& reference, const Measures& ref_m,
                            const WallLayer& ref_layer, double reference_n,
                            const std::vector<UpscalingRow>& rows, const FinestComparison& finest) {
  using repro::fmt;
  // The core's solid fraction when the back face first carries 1 MPa, if the core takes the
  // specimen's mean axial strain (uniaxial strain: the axial strain is the volume change).
  auto layer_cells = [](const WallLayer& w, double toe) {
    return " | " + fmt("%.2f %%", 100 * toe) + " | " + fmt("%.4f", w.whole) + " / " + fmt("%.4f", w.core) + " (" +
           fmt("%.0f %%", 100 * w.core_share) + ") | " + fmt("%.3f", w.core / (1 - toe)) + " |\n";
  };
  std::string t =
      "| N | grains | dt (ns) | case wall (s) | packing wall (s) | M 1-10 MPa | RMS dev. | max dev. | " +
      (std::isfinite(finest.n) ? "RMS dev. from N = " + fmt("%g", finest.n) + " (1 to " +
                                     fmt("%.1f", finest.top / 1e6) + " MPa on it) | "
                               : std::string("RMS dev. from the finest | ")) +
      "strain at 1 MPa | solid fraction whole / core (core's volume share) | core at 1 MPa |\n"
      "|---|---|---|---|---|---|---|---|---|---|---|---|\n";
  auto dev_cell = [&](double v) {
    return std::isfinite(v) ? " | " + fmt("%.2f MPa", v / 1e6) : std::string(" | -");
  };
  const double ref_toe = ref_m.i_lo >= 0 ? reference.history.strain[ref_m.i_lo] : NAN;
  t += "| " + fmt("%g", reference_n) + " (reference) | " + std::to_string(reference.dem.grains) + " | " +
       fmt("%.2f", reference.run.dt * 1e9) + " | " + fmt("%.1f", reference.wall_s) + " | - | " +
       fmt("%.1f MPa", ref_m.modulus_back / 1e6) + " | 0 | 0" + dev_cell(finest.reference_rms) +
       layer_cells(ref_layer, ref_toe);
  for (const auto& r : rows) {
    if (!r.ok) {
      t += "| " + fmt("%g", r.n) + " | failed: " + r.failure + " | | | | | | | | | | |\n";
      continue;
    }
    t += "| " + fmt("%g", r.n) + " | " + std::to_string(r.grains) + " | " + fmt("%.2f", r.dt * 1e9) +
         " | " + fmt("%.1f", r.case_s) + " | " + fmt("%.1f", r.pack_s) + (r.packed_now ? "" : " (cache)") +
         " | " + fmt("%.1f MPa", r.modulus / 1e6) + " | " + fmt("%.2f MPa", r.rms / 1e6) + " | " +
         fmt("%.2f MPa", r.max / 1e6) + dev_cell(r.rms_finest) + layer_cells(r.layer, r.toe_strain);
  }
  return t;
}

}  // namespace kolsky::ch4
