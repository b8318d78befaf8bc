#include "chapter5/ch5.hpp"

#include <algorithm>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "common/perturb.hpp"
#include "core/table.hpp"

namespace kolsky::ch5 {

nlohmann::json read_json(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot read " + path);
  return nlohmann::json::parse(f);
}

double scene_m1(const std::string& dir, const std::string& scene) {
  return read_json(dir + "/" + scene).at("specimen").at("breakage").at("m1").get<double>();
}

harness::Case make_case(const CaseSpec& spec, const std::string& dir, const std::string& cache, unsigned perturb_seed) {
  harness::Case c;
  c.label = spec.label;
  c.scene_path = dir + "/" + spec.scene;
  c.scene = repro::read_scene_json(c.scene_path, perturb_seed);
  c.packing_cache = cache;
  c.grain_size_curve_every = 1e-6;
  c.progress_lines = 10;  // these runs take minutes to an hour
  auto& ch = c.changes;
  if (spec.upscale > 0) ch.push_back({"specimen.upscale", spec.upscale});
  const double n = spec.upscale > 0 ? spec.upscale : c.scene.at("specimen").at("upscale").get<double>();
  if (!spec.breakage) {
    ch.push_back({"specimen.breakage", nullptr});
    // The scenes' safety factor 1.0 is for the up-front step of the smallest possible daughter
    // (README, 'Time step'). Without breakage the step is the initial grains' own, where the
    // Rayleigh step can bind and the no-breakage specimen reaches hundreds of MPa (stiffening
    // Hertz contacts): the Chapter 4 factor 0.3 there. These runs are the cheap ones.
    ch.push_back({"time.safety_factor", 0.3});
  } else {
    if (spec.sigma_lim0 > 0) ch.push_back({"specimen.breakage.sigma_lim0", spec.sigma_lim0});
    if (spec.coordination_limit >= 0) ch.push_back({"specimen.breakage.coordination_limit", spec.coordination_limit});
    // Eq. 5.16's d_min is a size of the original sand (Sec. 5.3.1: 7.5 um); the specimen's
    // fines are its upscaled image, so that downscaling by N gives the text's d_min back.
    if (spec.fines_d_min > 0) ch.push_back({"specimen.breakage.fines_d_min", spec.fines_d_min * n});
  }
  if (spec.end_time > 0) ch.push_back({"time.end", spec.end_time});
  if (!spec.loading_file.empty()) ch.push_back({"loading.file", spec.loading_file});
  if (spec.end_at_back_stress >= 0) ch.push_back({"loading.end_at_back_stress", spec.end_at_back_stress});
  if (spec.seed >= 0) ch.push_back({"specimen.seed", spec.seed});
  for (const std::string& item : spec.sets) ch.push_back(harness::parse_change(item, spec.scene));
  return c;
}

CaseResult case_result(const CaseSpec& spec, double upscale, const harness::CaseOutputs& out) {
  CaseResult c;
  c.spec = spec;
  c.upscale = upscale;
  c.wall_s = out.wall_s;
  c.pack_s = out.build_s;
  const shpb::RunResult& r = out.run;
  c.dt = r.dt;
  c.dt_final = r.dt_final;
  c.steps = r.steps;
  c.simulated_s = r.t.empty() ? 0 : r.t.back();
  c.arrival_time = r.arrival_time;
  c.ended_by = r.ended_by;
  if (!out.ok || !out.analysis_failure.empty()) {
    c.failure = !r.complete ? "run incomplete: " + out.failure : out.ok ? out.analysis_failure : out.failure;
    return c;
  }
  const auto& h = out.history;
  c.t = h.t;
  c.strain = h.strain;
  c.stress_back = h.stress_back;
  c.stress_avg = h.stress_avg;
  c.curves = out.curves;
  for (auto& g : c.curves) g.t -= r.arrival_time;  // on the history's clock, as the stresses
  if (r.has_probe("grain_count")) {
    c.grain_count = harness::on_history(out, "grain_count");
    c.broken_primary = harness::on_history(out, "broken_primary");
    c.broken_secondary = harness::on_history(out, "broken_secondary");
    c.relative_breakage = harness::on_history(out, "relative_breakage");
    if (r.has_probe("primary_held_by_coordination")) {
      c.held_primary = harness::on_history(out, "primary_held_by_coordination");
      c.held_primary_at_limit = harness::on_history(out, "primary_held_at_limit");
    }
    c.grains_initial = static_cast<std::size_t>(r.probe("grain_count").value.front());
    c.grains_final = static_cast<std::size_t>(r.probe("grain_count").value.back());
  }
  c.gauges = out.gauges;
  // Grain count and coordination of the specimen at the end (also without breakage).
  if (c.grains_final == 0) c.grains_initial = c.grains_final = out.dem.grains;
  if (r.has_probe("coordination_number")) c.coordination_final = r.probe("coordination_number").value.back();
  c.ok = true;
  return c;
}

CaseResult run_case(const CaseSpec& spec, const std::string& dir, const std::string& cache, unsigned perturb_seed) {
  try {
    const harness::Case c = make_case(spec, dir, cache, perturb_seed);
    const double upscale = harness::final_scene(c).at("specimen").at("upscale").get<double>();
    return case_result(spec, upscale, harness::run_case(c));
  } catch (const std::exception& e) {  // the scene file or a change could not be read
    CaseResult c;
    c.spec = spec;
    c.failure = e.what();
    return c;
  }
}

CaseResult CaseRunner::run(const CaseSpec& spec) const {
  std::printf("%s: starting\n", spec.label.c_str());
  CaseResult c = run_case(spec, dir, cache, perturb_seed);
  if (c.ok)
    std::printf("%s: %zu -> %zu grains, %ld steps of %.3g ns (%.3g ns at the end), %.0f s (packing %.0f s)\n",
                spec.label.c_str(), c.grains_initial, c.grains_final, c.steps, c.dt * 1e9, c.dt_final * 1e9, c.wall_s,
                c.pack_s);
  else
    std::printf("%s: FAILED: %s\n", spec.label.c_str(), c.failure.c_str());
  return c;
}

double stress_at_strain(const CaseResult& c, double e) {
  const long top = std::max_element(c.strain.begin(), c.strain.end()) - c.strain.begin();
  for (long k = 1; k <= top; ++k)
    if (c.strain[k] >= e && c.strain[k - 1] <= e) {
      const double f = (e - c.strain[k - 1]) / std::max(1e-300, c.strain[k] - c.strain[k - 1]);
      return c.stress_back[k - 1] + f * (c.stress_back[k] - c.stress_back[k - 1]);
    }
  return NAN;
}

double max_of(const std::vector<double>& v) { return v.empty() ? NAN : *std::max_element(v.begin(), v.end()); }

long first_at_least(const std::vector<double>& v, double level) {
  for (std::size_t k = 0; k < v.size(); ++k)
    if (v[k] >= level) return static_cast<long>(k);
  return -1;
}

CurveDifference stress_difference(const std::vector<double>& strain_a, const std::vector<double>& stress_a,
                                  const std::vector<double>& strain_b, const std::vector<double>& stress_b,
                                  double lo, double hi) {
  CurveDifference d;
  if (strain_b.size() < 2) return d;
  // b's strain is monotonic only while loading: compare up to b's largest strain.
  const auto top = std::max_element(strain_b.begin(), strain_b.end()) - strain_b.begin();
  const Table1D b_at{{strain_b.begin(), strain_b.begin() + top + 1}, {stress_b.begin(), stress_b.begin() + top + 1}};
  const std::vector<double>& xb = b_at.x;
  double sum = 0, worst = 0;
  for (std::size_t k = 0; k < strain_a.size(); ++k) {
    if (stress_a[k] < lo || stress_a[k] > hi) continue;
    if (strain_a[k] < xb.front() || strain_a[k] > xb.back()) continue;
    if (k > 0 && strain_a[k] < strain_a[k - 1]) break;  // a unloading
    const double e = b_at(strain_a[k]) - stress_a[k];
    sum += e * e;
    worst = std::max(worst, std::abs(e));
    ++d.points;
  }
  if (d.points >= 3) {
    d.rms = std::sqrt(sum / d.points);
    d.max = worst;
  }
  return d;
}

psd::GrainSizeCurve curve_at_stress(const CaseResult& c, double stress, double* time) {
  const long k = first_at_least(c.stress_back, stress);
  if (k < 0 || c.curves.empty()) return {};
  const double t = c.t[k];
  const auto it = std::min_element(c.curves.begin(), c.curves.end(), [t](const harness::CurveAt& a, const harness::CurveAt& b) {
    return std::abs(a.t - t) < std::abs(b.t - t);
  });
  if (time) *time = it->t;
  return psd::downscale(it->curve, c.upscale);
}

double passing_difference(const psd::GrainSizeCurve& a, const psd::GrainSizeCurve& b, double lo, double hi) {
  if (a.size() < 2 || b.size() < 2) return NAN;
  const double from = std::max({lo, a.diameter.front(), b.diameter.front()});
  const double to = std::min({hi, a.diameter.back(), b.diameter.back()});
  if (!(to > from)) return NAN;
  constexpr int kPoints = 40;
  double sum = 0;
  for (int k = 0; k < kPoints; ++k) {
    const double d = from * std::pow(to / from, k / (kPoints - 1.0));
    const double e = psd::passing_at(a, d) - psd::passing_at(b, d);
    sum += e * e;
  }
  return std::sqrt(sum / kPoints);
}

double broken_at_stress(const CaseResult& c, double stress) {
  const long k = first_at_least(c.stress_back, stress);
  if (k < 0 || c.broken_primary.empty()) return NAN;
  return c.broken_primary[k] + c.broken_secondary[k];
}

double bilinear_yield(const std::vector<double>& stress, const std::vector<double>& count) {
  std::vector<double> x, y;
  for (std::size_t k = 0; k < stress.size(); ++k)
    if (stress[k] > 0 && count[k] > 0 && (x.empty() || std::log10(stress[k]) > x.back()))
      x.push_back(std::log10(stress[k])), y.push_back(count[k]);
  const std::size_t n = x.size();
  if (n < 6) return NAN;
  auto fit = [&](std::size_t a, std::size_t b, double& slope, double& icpt) {  // least squares on [a, b)
    double sx = 0, sy = 0, sxx = 0, sxy = 0;
    const double m = b - a;
    for (std::size_t k = a; k < b; ++k) sx += x[k], sy += y[k], sxx += x[k] * x[k], sxy += x[k] * y[k];
    const double den = m * sxx - sx * sx;
    slope = den != 0 ? (m * sxy - sx * sy) / den : 0;
    icpt = (sy - slope * sx) / m;
    double r = 0;
    for (std::size_t k = a; k < b; ++k) r += std::pow(y[k] - slope * x[k] - icpt, 2);
    return r;
  };
  double best = INFINITY, yield = NAN;
  for (std::size_t j = 3; j + 3 <= n; ++j) {
    double s1, i1, s2, i2;
    const double r = fit(0, j, s1, i1) + fit(j, n, s2, i2);
    if (r < best && s2 != s1) {
      best = r;
      yield = std::pow(10.0, (i1 - i2) / (s2 - s1));
    }
  }
  return yield;
}

}  // namespace kolsky::ch5
