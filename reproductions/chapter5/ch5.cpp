#include "chapter5/ch5.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <stdexcept>

#include "common/perturb.hpp"
#include "harness/case_pipeline.hpp"
#include "scene/scene.hpp"
#include "shpb/simulation.hpp"

namespace kolsky::ch5 {

nlohmann::json read_json(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot read " + path);
  return nlohmann::json::parse(f);
}

nlohmann::json case_scene(const CaseSpec& spec, const std::string& dir, const std::string& cache,
                          unsigned perturb_seed) {
  auto j = repro::read_scene_json(dir + "/" + spec.scene, perturb_seed);
  auto& s = j["specimen"];
  if (spec.upscale > 0) s["upscale"] = spec.upscale;
  s["packing_cache"] = cache;
  const double n = s["upscale"].get<double>();
  if (!spec.breakage) {
    s.erase("breakage");
    // The scenes' safety factor 1.0 is for the up-front step of the smallest possible daughter
    // (README, 'Time step'). Without breakage the step is the initial grains' own, where the
    // Rayleigh step can bind and the no-breakage specimen reaches hundreds of MPa (stiffening
    // Hertz contacts): the Chapter 4 factor 0.3 there. These runs are the cheap ones.
    j["time"]["safety_factor"] = 0.3;
  } else {
    auto& b = s["breakage"];
    if (spec.sigma_lim0 > 0) b["sigma_lim0"] = spec.sigma_lim0;
    if (spec.coordination_limit >= 0) b["coordination_limit"] = spec.coordination_limit;
    // Eq. 5.16's d_min is a size of the original sand (Sec. 5.3.1: 7.5 um); the specimen's
    // fines are its upscaled image, so that downscaling by N gives the text's d_min back.
    if (spec.fines_d_min > 0) b["fines_d_min"] = spec.fines_d_min * n;
  }
  if (spec.end_time > 0) j["time"]["end"] = spec.end_time;
  if (!spec.loading_file.empty()) j["loading"]["file"] = spec.loading_file;
  if (spec.end_at_back_stress >= 0) j["loading"]["end_at_back_stress"] = spec.end_at_back_stress;
  if (spec.seed >= 0) s["seed"] = spec.seed;
  for (const std::string& item : spec.sets) harness::apply_change(j, harness::parse_change(item, spec.scene), spec.scene);
  return j;
}

namespace {

double interpolate(const std::vector<double>& x, const std::vector<double>& y, double at) {
  if (x.empty()) return NAN;
  if (at <= x.front()) return y.front();
  if (at >= x.back()) return y.back();
  const auto k = static_cast<std::size_t>(std::upper_bound(x.begin(), x.end(), at) - x.begin());
  const double f = (at - x[k - 1]) / (x[k] - x[k - 1]);
  return y[k - 1] + f * (y[k] - y[k - 1]);
}

}  // namespace

CaseResult run_case(const CaseSpec& spec, const std::string& dir, const std::string& cache, unsigned perturb_seed) {
  CaseResult c;
  c.spec = spec;
  const auto start = std::chrono::steady_clock::now();
  try {
    std::filesystem::create_directories(cache);
    const auto j = case_scene(spec, dir, cache, perturb_seed);
    c.upscale = j.at("specimen").at("upscale").get<double>();
    const auto sc = scene::parse_scene(j, dir + "/" + spec.scene, dir);
    shpb::SimulatedShpb sim(sc.spec);  // packs (or reads the packing cache)
    c.pack_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    sim.require_analysable_end();
    const double dt = sim.schedule().dt;
    shpb::RunControl control;
    control.snapshot_every = std::max(1L, std::lround(1e-6 / dt));  // a grain-size curve per us
    control.grain_size_curve = [&c](long, double t, const psd::GrainSizeCurve& g) { c.curves.push_back({t, g}); };
    // One progress line per tenth of the run: these runs take minutes to an hour.
    struct Tenths {
      std::string label;
      double end;
      int next = 1;
    } tenths{spec.label, sc.spec.time.end_time};
    const auto t0 = std::chrono::steady_clock::now();
    Progress quiet(sc.spec.time.end_time, false);
    control.progress_every = std::max(1L, sim.schedule().n_steps / 10);
    control.progress = [&tenths, t0](long, double t) {
      const double w = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
      std::printf("  %s: %.0f %% (t = %.1f us, %.0f s)\n", tenths.label.c_str(),
                  100.0 * t / tenths.end, t * 1e6, w);
    };
    const auto r = sim.run(&quiet, control);
    c.dt = r.dt;
    c.dt_final = r.dt_final;
    c.steps = r.steps;
    c.simulated_s = r.t.empty() ? 0 : r.t.back();
    c.arrival_time = r.arrival_time;
    c.ended_by = r.ended_by;
    if (!r.complete) throw std::runtime_error("run incomplete: " + r.failure);
    const auto a = sim.analyze(r);
    const auto& h = a.history;
    const double t_shift = sim.direct_analysis() ? 0.0 : r.arrival_time;
    c.t = h.t;
    c.strain = h.strain;
    c.stress_back = h.stress_back;
    c.stress_avg = h.stress_avg;
    if (r.has_probe("grain_count")) {
      auto on_history = [&](const std::string& name) {
        std::vector<double> out(h.t.size());
        for (std::size_t k = 0; k < h.t.size(); ++k)
          out[k] = interpolate(r.t, r.probe(name).value, h.t[k] + t_shift);
        return out;
      };
      c.grain_count = on_history("grain_count");
      c.broken_primary = on_history("broken_primary");
      c.broken_secondary = on_history("broken_secondary");
      c.relative_breakage = on_history("relative_breakage");
      // Curves on the history's clock, as the stresses.
      for (auto& g : c.curves) g.t -= t_shift;
      c.grains_initial = static_cast<std::size_t>(r.probe("grain_count").value.front());
      c.grains_final = static_cast<std::size_t>(r.probe("grain_count").value.back());
    }
    if (r.has_probe("incident_gauge_strain")) {
      const double e_i = sc.spec.incident.material.youngs_modulus,
                   e_t = sc.spec.transmission.material.youngs_modulus;
      c.gauge_t = r.t;
      for (double e : r.probe("incident_gauge_strain").value) c.gauge_incident.push_back(-e * e_i);
      for (double e : r.probe("transmission_gauge_strain").value) c.gauge_transmission.push_back(-e * e_t);
    }
    // Grain count and coordination of the specimen at the end (also without breakage).
    const dem::DemSpecimen* d = sim.dem_specimen();
    if (c.grains_final == 0) c.grains_initial = c.grains_final = d->system().particles().size();
    if (r.has_probe("coordination_number")) c.coordination_final = r.probe("coordination_number").value.back();
    c.ok = true;
  } catch (const std::exception& e) {
    c.failure = e.what();
  }
  c.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
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
  const std::vector<double> xb(strain_b.begin(), strain_b.begin() + top + 1);
  const std::vector<double> yb(stress_b.begin(), stress_b.begin() + top + 1);
  double sum = 0, worst = 0;
  for (std::size_t k = 0; k < strain_a.size(); ++k) {
    if (stress_a[k] < lo || stress_a[k] > hi) continue;
    if (strain_a[k] < xb.front() || strain_a[k] > xb.back()) continue;
    if (k > 0 && strain_a[k] < strain_a[k - 1]) break;  // a unloading
    const double e = interpolate(xb, yb, strain_a[k]) - stress_a[k];
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
  const auto it = std::min_element(c.curves.begin(), c.curves.end(), [t](const CurveAt& a, const CurveAt& b) {
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
