#include "chapter3/ch3.hpp"

#include <algorithm>
#include <cmath>
#include <exception>
#include <fstream>
#include <stdexcept>

#include "core/table.hpp"

namespace kolsky::ch3 {

namespace {

long first_at_least(const std::vector<double>& v, double level, long from = 0) {
  for (long k = from; k < static_cast<long>(v.size()); ++k)
    if (v[k] >= level) return k;
  return -1;
}

}  // namespace

nlohmann::json read_json(const std::string& path) {
  std::ifstream f(path);
  if (!f) throw std::runtime_error("cannot read " + path);
  return nlohmann::json::parse(f);
}

CaseResult run_case(const harness::Case& spec) {
  CaseResult c;
  static_cast<harness::CaseOutputs&>(c) = harness::run_case(spec);
  if (c.refusal) std::rethrow_exception(c.refusal);  // InputError: exit 2
  if (c.run.has_probe("off_axis_fraction") && !c.run.probe("off_axis_fraction").value.empty())
    c.off_axis = c.run.probe("off_axis_fraction").value.back();
  if (c.ok && c.dem.grains > 0 && c.run.has_probe("applied_stress")) {
    const auto scene = harness::final_scene(spec);
    const auto impedance = [&](const char* bar) {
      const auto& b = scene.at("bars").at(bar);
      return std::sqrt(b.at("youngs_modulus").get<double>() * b.at("density").get<double>());
    };
    c.mass_per_area = scene.at("specimen").at("grain_density").get<double>() * c.dem.grain_volume / c.dem.face_area;
    c.z_incident = impedance("incident"), c.z_transmission = impedance("transmission");
    // The pulse is applied at the incident bar's far end from t = 0 and reaches the face one
    // transit later (the arrival), so the face sees at faces.t = x what was applied at run time x.
    const Table1D applied{c.run.t, c.run.probe("applied_stress").value};
    for (double x : c.faces.t) c.incident_if.push_back(applied(x));
  }
  if (c.ok) {
    // Energy balance (docs/coupling.md, "Energy"): what the specimen and the bars hold against
    // the work delivered at the incident bar's far end, on the face records' samples.
    try {
      const auto held = harness::from_arrival(c.run, "energy_held");
      c.delivered_if = harness::from_arrival(c.run, "energy_delivered");
      for (std::size_t i = 0; i < held.size(); ++i) c.energy_error_if.push_back(held[i] - c.delivered_if[i]);
    } catch (const std::out_of_range& e) {  // a model without an energy ledger: nothing to measure
      c.ok = false;
      c.failure = e.what();
      c.faces = {};
      c.delivered_if.clear();
    }
  }
  return c;
}

namespace {
// Least-squares slope of y vs x over the samples with x in [lo, hi] before index `end` (the
// strain rises monotonically while the specimen is loaded, so that is one run of samples).
double window_slope(const std::vector<double>& x, const std::vector<double>& y, long end, double lo, double hi,
                    long* points = nullptr) {
  long a = -1, b = -1;
  for (long k = 0; k < end; ++k) {
    if (x[k] >= lo && a < 0) a = k;
    if (x[k] <= hi && a >= 0) b = k + 1;
    if (x[k] > hi) break;
  }
  if (points) *points = a >= 0 ? b - a : 0;
  return a >= 0 && b - a >= 3 ? shpb::fitted_slope(x, y, a, b) : NAN;
}
}  // namespace

std::vector<double> face_inertia_gap(const CaseResult& c, double half_width) {
  const auto& t = c.faces.t;
  std::vector<double> gap(t.size(), NAN);
  if (c.incident_if.size() != t.size() || !std::isfinite(c.mass_per_area)) return gap;
  for (std::size_t k = 0; k < t.size(); ++k) {
    std::size_t a = k, b = k;
    while (a > 0 && t[k] - t[a] < half_width) --a;
    while (b + 1 < t.size() && t[b] - t[k] < half_width) ++b;
    if (a == k || b == k) continue;
    const double dt = t[b] - t[a];
    const double rate_i = (c.incident_if[b] - c.incident_if[a]) / dt, rate_f = (c.faces.front[b] - c.faces.front[a]) / dt,
                 rate_b = (c.faces.back[b] - c.faces.back[a]) / dt;
    gap[k] = 0.5 * c.mass_per_area * ((2 * rate_i - rate_f) / c.z_incident + rate_b / c.z_transmission);
  }
  return gap;
}

Measures measure(const CaseResult& c, double eps_lo, double eps_hi, double cutoff, double ringing_time) {
  Measures m;
  if (!c.ok || c.faces.back.empty()) return m;
  // The specimen's own record: the transmission-face stress (summed grain contact forces over
  // the area, = sigma_t of Eq. 1.2 for a 1-D bar) against the strain of the two faces'
  // displacements. Sec. 3.3: "terminated at a stress of 13 MPa".
  const long n = static_cast<long>(c.faces.back.size());
  const long i_cut = first_at_least(c.faces.back, cutoff);
  m.reached_cutoff = i_cut >= 0;
  m.i_end = m.reached_cutoff ? i_cut + 1 : n;
  if (m.reached_cutoff) m.strain_at_cutoff = c.faces.strain[i_cut], m.time_at_cutoff = c.faces.t[i_cut];
  // Energy balance (docs/coupling.md, "Energy") up to the cut-off: largest |held - delivered|
  // so far over the work delivered by then.
  double worst = 0;
  for (long k = 0; k < m.i_end; ++k) worst = std::max(worst, std::abs(c.energy_error_if[k]));
  m.energy_error = worst / c.delivered_if[m.i_end - 1];
  m.slope = window_slope(c.faces.strain, c.faces.back, m.i_end, eps_lo, eps_hi, &m.slope_points);
  // Mean strain rate over the window: strain gained over the time it took.
  long a = -1, b = -1;
  for (long k = 0; k < m.i_end; ++k) {
    if (c.faces.strain[k] >= eps_lo && a < 0) a = k;
    if (c.faces.strain[k] <= eps_hi && a >= 0) b = k;
  }
  if (a >= 0 && b > a) m.strain_rate = (c.faces.strain[b] - c.faces.strain[a]) / (c.faces.t[b] - c.faces.t[a]);
  // The same slope from the bar gauges by the classic analysis (Eqs. 1.1-1.2), where the
  // gauge records reach the window (the reflected wave needs d_I / c0 after the face).
  if (!c.history.t.empty()) {
    const long g_cut = first_at_least(c.history.stress_back, cutoff);
    m.slope_gauges = window_slope(c.history.strain, c.history.stress_back, g_cut < 0 ? static_cast<long>(c.history.t.size()) : g_cut + 1,
                                  eps_lo, eps_hi);
  }
  // Fig. 3.4: front and back face stresses after the ringing time (studies_*.json, README
  // "The face stresses"), up to the cut-off.
  const long j0 = first_at_least(c.faces.t, ringing_time);
  if (j0 >= 0 && m.i_end > j0) {
    m.ringing_end = c.faces.t[j0];
    m.stress_at_ringing_end = c.faces.back[j0];
    double gap = 0, alpha = 0;
    for (long k = j0; k < m.i_end; ++k) {
      const double d = std::abs(c.faces.front[k] - c.faces.back[k]);
      gap = std::max(gap, d);
      alpha = std::max(alpha, d / (0.5 * (c.faces.front[k] + c.faces.back[k])));  // Eq. 4.15's form
    }
    m.face_gap_max = gap;
    m.face_alpha_max = alpha;
  }
  // Before it: is the gap the specimen's momentum rate while the pulse still rises? Rates over
  // +-5 us: a tenth of the 125 us rise, wide enough to average the force chains' flicker.
  const std::vector<double> need = face_inertia_gap(c, 5e-6);
  double top = 0, measured = 0, predicted = 0;
  for (std::size_t k = 0; k < need.size() && c.faces.t[k] < ringing_time; ++k)
    if (std::isfinite(need[k])) top = std::max(top, need[k]);
  for (std::size_t k = 0; k < need.size() && c.faces.t[k] < ringing_time; ++k)
    if (top > 0 && need[k] >= 0.5 * top) measured += c.faces.front[k] - c.faces.back[k], predicted += need[k];
  if (predicted > 0) m.face_inertia_ratio = measured / predicted, m.face_inertia_gap_max = top;
  return m;
}

harness::Curve curve_to_cutoff(const CaseResult& c, const Measures& m) {
  harness::Curve out;
  for (long k = 0; k < m.i_end && k < static_cast<long>(c.faces.back.size()); ++k) {
    out.x.push_back(c.faces.strain[k]);
    out.y.push_back(c.faces.back[k]);
  }
  return out;
}

namespace {
// sigma_t at strain e on a curve whose strain rises (first crossing), NaN outside it.
double stress_at(const harness::Curve& cv, double e) {
  for (std::size_t k = 1; k < cv.x.size(); ++k)
    if (cv.x[k - 1] <= e && e <= cv.x[k] && cv.x[k] > cv.x[k - 1])
      return cv.y[k - 1] + (cv.y[k] - cv.y[k - 1]) * (e - cv.x[k - 1]) / (cv.x[k] - cv.x[k - 1]);
  return NAN;
}
}  // namespace

double curve_rms_difference(const CaseResult& a, const Measures& ma, const CaseResult& b, const Measures& mb,
                            double lo, double hi) {
  const harness::Curve ca = curve_to_cutoff(a, ma), cb = curve_to_cutoff(b, mb);
  if (ca.x.empty() || cb.x.empty()) return NAN;
  // Over the strain both reach before their cut-off (a stiff curve hits 13 MPa before 6 %).
  hi = std::min({hi, *std::max_element(ca.x.begin(), ca.x.end()), *std::max_element(cb.x.begin(), cb.x.end())});
  if (!(hi > lo)) return NAN;
  constexpr int kPoints = 41;  // 0.1 % strain apart over 2-6 %: finer than the 1 us samples' ~0.05 %
  double s = 0;
  for (int k = 0; k < kPoints; ++k) {
    // The last point exactly at hi: lo + (hi - lo) may round above a curve's largest strain.
    const double e = k == kPoints - 1 ? hi : lo + (hi - lo) * k / (kPoints - 1);
    const double d = stress_at(ca, e) - stress_at(cb, e);
    if (!std::isfinite(d)) return NAN;
    s += d * d;
  }
  return std::sqrt(s / kPoints);
}

}  // namespace kolsky::ch3
