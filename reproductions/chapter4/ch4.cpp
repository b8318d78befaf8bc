#include "chapter4/ch4.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <stdexcept>

#include "common/scene_override.hpp"
#include "dem/wall_layer.hpp"
#include "scene/scene.hpp"

namespace kolsky::ch4 {

dem::CachedPacking pack_scene(const nlohmann::json& j, const std::string& scene_path,
                              const std::string& dir, const std::string& label) {
  const auto sc = scene::parse_scene(j, scene_path, dir);
  const auto& dp = std::get<dem::DemSpecimenParams>(sc.spec.specimen);
  dem::PackingParams p = dp.packing;
  p.on_progress = [label](const dem::PackingProgress& q) {
    const std::string phase = q.phase;
    const bool staged = phase == "growth" || phase == "compaction" || phase == "settle";
    if (q.done % (staged ? 10 : 20) != 0 && q.done != q.most) return;
    std::printf("%s: %s %d (of at most %d), %s %.3g", label.c_str(), q.phase, q.done, q.most,
                phase == "growth"    ? "radius scale"
                : phase == "compaction" ? "wall gap / length"
                : phase == "settle"  ? "largest overlap / mean radius"
                : phase == "relax"   ? "kinetic / initial elastic energy"
                                     : "wall mean stress (Pa)",
                q.value);
    if (phase != "prestress" && std::isfinite(q.wall_stress))
      std::printf(", wall mean stress %.3g Pa", q.wall_stress);
    if (std::isfinite(q.coordination)) std::printf(", Z %.2f", q.coordination);
    std::printf("\n");
  };
  return dem::cached_packing(p, dp.packing_store);
}

WallLayer wall_layer(const nlohmann::json& j, const dem::Particles& p) {
  WallLayer w;
  if (p.size() == 0) return w;
  const double r_min = *std::min_element(p.radius.begin(), p.radius.end());
  const double r_max = *std::max_element(p.radius.begin(), p.radius.end());
  const auto prof = dem::wall_layer_profile(p, j.at("specimen").at("diameter").get<double>(),
                                            j.at("specimen").at("length").get<double>(), r_min / 3,
                                            r_max / 5);
  w.whole = prof.fraction_beyond(0);
  w.core = prof.fraction_beyond(2 * r_max);
  w.core_share = prof.volume_share_beyond(2 * r_max);
  return w;
}

nlohmann::json read_json(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot read " + path);
  return nlohmann::json::parse(f);
}

std::vector<double> parse_list(const std::string& text) {
  std::vector<double> out;
  for (std::string all = text; !all.empty();) {
    const auto comma = all.find(',');
    const std::string v = all.substr(0, comma);
    all = comma == std::string::npos ? "" : all.substr(comma + 1);
    if (!v.empty()) out.push_back(std::stod(v));
  }
  return out;
}

std::string apply_scene_overrides(nlohmann::json& scene, const char* overrides) {
  if (!overrides || !*overrides) return "";
  std::string note, all = overrides;
  while (!all.empty()) {
    const auto semi = all.find(';');
    const std::string item = all.substr(0, semi);
    all = semi == std::string::npos ? "" : all.substr(semi + 1);
    if (item.empty()) continue;
    if (!repro::set_scene_key(scene, item))
      throw std::runtime_error("KOLSKY_CH4_SET: '" + item + "' has no '='");
    note += (note.empty() ? "" : ", ") + std::string("`") + item + "`";
  }
  return note.empty() ? "" : "**Diagnostic run: scene keys overridden by KOLSKY_CH4_SET: " + note + ".**\n\n";
}

std::vector<double> scaled(const std::vector<double>& v, double f, long n) {
  const long m = n < 0 ? static_cast<long>(v.size()) : std::min<long>(n, v.size());
  std::vector<double> out(m);
  for (long k = 0; k < m; ++k) out[k] = v[k] * f;
  return out;
}

double reference_value(const nlohmann::json& targets, const std::string& id) {
  for (const auto& t : targets.at("targets"))
    if (t.at("id") == id) return t.at("reference").at("value").get<double>();
  throw std::runtime_error("no reference value for " + id);
}

CaseResult run_case(nlohmann::json j, const std::string& scene_path, const std::string& dir,
                    double k, const std::string& label) {
  CaseResult c;
  c.label = label;
  c.rolling_factor = k;
  const auto start = std::chrono::steady_clock::now();
  try {
    j["specimen"]["rolling_factor"] = k;
    const auto sc = scene::parse_scene(j, scene_path, dir);
    shpb::SimulatedShpb sim(sc.spec);
    sim.require_analysable_end();
    c.run = sim.run();
    c.dt = c.run.dt;
    c.steps = c.run.steps;
    const dem::DemSpecimen& dem = *sim.dem_specimen();  // a DEM scene by construction
    c.held_steps = dem.held_calls();
    c.grains = dem.system().particles().size();
    if (!c.run.complete) {
      c.failure = c.run.failure;
    } else {
      const auto setup = sim.analysis_setup();
      const auto waves =
          c.run.face_waves(setup.incident.youngs_modulus, setup.transmission.youngs_modulus);
      c.h = shpb::analyze(waves, setup);
      const auto& fr = c.run.probe("stress_front").value;
      const auto& bk = c.run.probe("stress_back").value;
      const auto& st = c.run.probe("specimen_strain").value;
      for (size_t i = 0; i < c.run.t.size(); ++i) {
        if (c.run.t[i] < c.run.arrival_time - 1e-12) continue;
        c.t_if.push_back(c.run.t[i] - c.run.arrival_time);
        c.front_if.push_back(fr[i]);
        c.back_if.push_back(bk[i]);
        c.strain_if.push_back(st[i]);
      }
      c.ok = true;
    }
  } catch (const std::exception& e) {
    c.failure = e.what();
  }
  c.wall_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return c;
}

namespace {
long first_at_least(const std::vector<double>& v, double level, long from = 0) {
  for (long k = from; k < static_cast<long>(v.size()); ++k)
    if (v[k] >= level) return k;
  return -1;
}
}  // namespace

Measures measure(const CaseResult& c, double lo_stress, double mid_stress, double limit) {
  Measures m;
  if (!c.ok || c.h.t.empty()) return m;
  const auto& h = c.h;
  const long n = static_cast<long>(h.t.size());
  for (double s : h.stress_back) m.max_back = std::max(m.max_back, s);
  m.i_lo = first_at_least(h.stress_back, lo_stress);
  const long i_lim = first_at_least(h.stress_back, limit);
  m.reached_limit = i_lim >= 0;
  m.i_end = m.reached_limit ? i_lim + 1 : n;
  if (m.reached_limit) m.time_at_limit = h.t[i_lim];
  if (m.i_lo >= 0 && m.i_end - m.i_lo >= 3) {
    const long i_mid = std::max(m.i_lo + 3, first_at_least(h.stress_back, mid_stress, m.i_lo) + 1);
    const long i_late = first_at_least(h.stress_back, 0.7 * limit, m.i_lo);
    m.modulus_initial = shpb::fitted_slope(h.strain, h.stress_back, m.i_lo, std::min(i_mid, m.i_end));
    if (m.reached_limit && i_late >= 0 && m.i_end - i_late >= 3)
      m.modulus_late = shpb::fitted_slope(h.strain, h.stress_back, i_late, m.i_end);
    m.modulus_back = shpb::fitted_slope(h.strain, h.stress_back, m.i_lo, m.i_end);
    m.modulus_avg = shpb::fitted_slope(h.strain, h.stress_avg, m.i_lo, m.i_end);
    // alpha (Eq. 4.15 from the bar waves) over the comparison window.
    std::vector<double> a;
    for (long k = m.i_lo; k < m.i_end; ++k)
      if (std::isfinite(h.alpha[k])) a.push_back(h.alpha[k]);
    if (a.size() >= 6) {
      m.alpha_min = *std::min_element(a.begin(), a.end());
      const size_t third = a.size() / 3;
      double s0 = 0, s1 = 0, s = 0;
      for (size_t k = 0; k < third; ++k) s0 += a[k], s1 += a[a.size() - 1 - k];
      for (double x : a) s += x;
      m.alpha_first = s0 / third;
      m.alpha_last = s1 / third;
      m.alpha_mean = s / a.size();
    }
  }
  // Interface probes: the same stress window on the wall stresses.
  const long j_lo = first_at_least(c.back_if, lo_stress);
  long j_end = first_at_least(c.back_if, limit);
  j_end = j_end < 0 ? static_cast<long>(c.back_if.size()) : j_end + 1;
  if (j_lo >= 0 && j_end - j_lo >= 3) {
    std::vector<double> avg(c.back_if.size());
    for (size_t k = 0; k < avg.size(); ++k) avg[k] = 0.5 * (c.front_if[k] + c.back_if[k]);
    m.modulus_back_if = shpb::fitted_slope(c.strain_if, c.back_if, j_lo, j_end);
    m.modulus_avg_if = shpb::fitted_slope(c.strain_if, avg, j_lo, j_end);
  }
  if (!c.back_if.empty()) {
    const long j = first_at_least(c.back_if, c.back_if.front() + 0.2e6);
    if (j >= 0) m.back_arrival = c.t_if[j];
  }
  return m;
}

}  // namespace kolsky::ch4
