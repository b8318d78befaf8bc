#include "shpb/gauge_waves.hpp"

#include <cmath>
#include <limits>
#include <string>

namespace kolsky::shpb {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

std::vector<double>& values(RunResult& r, const std::string& name) {
  for (auto& p : r.probes)
    if (p.name == name) return p.value;
  throw std::out_of_range("no probe named '" + name + "'");
}

// Linear interpolation of the record g at time s; 0 before the first sample, NaN after the last.
double at(const std::vector<double>& t, const std::vector<double>& g, double s) {
  if (t.size() < 2 || s <= t.front()) return t.empty() || s < t.front() ? 0.0 : g.front();
  const double dt = t[1] - t[0];
  const double x = (s - t.front()) / dt;
  const auto i = static_cast<std::size_t>(x);
  if (i + 1 >= t.size()) return s <= t.back() + 1e-9 * dt ? g.back() : kNaN;
  const double w = x - static_cast<double>(i);
  return g[i] + w * (g[i + 1] - g[i]);
}

void cumulative_energy(const std::vector<double>& t, const std::vector<double>& s, double k,
                       std::vector<double>& w) {
  w.assign(t.size(), 0.0);
  for (std::size_t i = 1; i < t.size(); ++i)
    w[i] = w[i - 1] + 0.5 * (t[i] - t[i - 1]) * k * (s[i - 1] * s[i - 1] + s[i] * s[i]);
}

}  // namespace

void waves_from_gauges(RunResult& r, const BarSpec& incident, const BarSpec& transmission) {
  const auto& gi = r.probe("incident_gauge_strain").value;
  const auto& gt = r.probe("transmission_gauge_strain").value;
  const double ci = incident.material.wave_speed(), ct = transmission.material.wave_speed();
  const double ei = incident.material.youngs_modulus, et = transmission.material.youngs_modulus;
  const double di = incident.gauges.front(), dtr = transmission.gauges.front();
  const double arrival = incident.geometry.length / ci;
  std::vector<double> si(r.t.size()), sr(r.t.size()), st(r.t.size());
  for (std::size_t k = 0; k < r.t.size(); ++k) {
    const double t = r.t[k];
    si[k] = t < arrival + 2.0 * di / ci ? -ei * at(r.t, gi, t - di / ci) : 0.0;
    sr[k] = t >= arrival ? -ei * at(r.t, gi, t + di / ci) : 0.0;
    st[k] = -et * at(r.t, gt, t + dtr / ct);
  }
  values(r, "wave_incident") = si;
  values(r, "wave_reflected") = sr;
  values(r, "wave_transmitted") = st;
  const double ki = incident.geometry.area() / incident.material.specific_impedance();
  const double kt = transmission.geometry.area() / transmission.material.specific_impedance();
  cumulative_energy(r.t, si, ki, values(r, "w_incident"));
  cumulative_energy(r.t, sr, ki, values(r, "w_reflected"));
  cumulative_energy(r.t, st, kt, values(r, "w_transmitted"));
}

}  // namespace kolsky::shpb
