#include "chapter4/ch4.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <stdexcept>

#include "dem/wall_layer.hpp"

namespace kolsky::ch4 {

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

std::string apply_scene_overrides(harness::Case& c, const char* overrides) {
  if (!overrides || !*overrides) return "";
  std::string note, all = overrides;
  while (!all.empty()) {
    const auto semi = all.find(';');
    const std::string item = all.substr(0, semi);
    all = semi == std::string::npos ? "" : all.substr(semi + 1);
    if (item.empty()) continue;
    c.changes.push_back(harness::parse_change(item, "KOLSKY_CH4_SET"));
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

CaseResult run_case(const harness::Case& base, double k, const std::string& label) {
  CaseResult c;
  static_cast<harness::CaseOutputs&>(c) = harness::run_case(base.with("specimen.rolling_factor", k, label));
  c.rolling_factor = k;
  if (c.ok && !c.analysis_failure.empty()) {  // no sigma_t(strain): nothing of Sec. 4.4 to measure
    c.ok = false;
    c.failure = c.analysis_failure;
    c.faces = {};
  }
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
  if (!c.ok || c.history.t.empty()) return m;
  const auto& h = c.history;
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
  const long j_lo = first_at_least(c.faces.back, lo_stress);
  long j_end = first_at_least(c.faces.back, limit);
  j_end = j_end < 0 ? static_cast<long>(c.faces.back.size()) : j_end + 1;
  if (j_lo >= 0 && j_end - j_lo >= 3) {
    std::vector<double> avg(c.faces.back.size());
    for (size_t k = 0; k < avg.size(); ++k) avg[k] = 0.5 * (c.faces.front[k] + c.faces.back[k]);
    m.modulus_back_if = shpb::fitted_slope(c.faces.strain, c.faces.back, j_lo, j_end);
    m.modulus_avg_if = shpb::fitted_slope(c.faces.strain, avg, j_lo, j_end);
  }
  if (!c.faces.back.empty()) {
    const long j = first_at_least(c.faces.back, c.faces.back.front() + 0.2e6);
    if (j >= 0) m.back_arrival = c.faces.t[j];
  }
  return m;
}

}  // namespace kolsky::ch4
