// Raw strain-gauge records -> face-referred waves (gauge_processing.hpp; rules and thresholds in
// docs/analysis.md): pre-trigger offset and noise, incident start detection, incident/reflected
// window separation at the incident gauge, and the gauge-to-face shift (pure delay, or the first
// Pochhammer-Chree mode correction of dispersion.hpp). Inputs compression negative (as
// measured), outputs compression positive. SI units.
#include "shpb/gauge_processing.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>

#include "core/errors.hpp"
#include "shpb/dispersion.hpp"

namespace kolsky::shpb {
namespace {

constexpr long min_pretrigger = 8;  // fewer samples give no usable mean/sigma

std::string num(double v) {
  std::ostringstream os;
  os.precision(6);
  os << v;
  return os.str();
}

/// Checks sizes, finiteness and uniform spacing; returns the mean step.
double validated_dt(const GaugeRecord& rec) {
  const std::size_t n = rec.t.size();
  if (rec.incident.size() != n || rec.transmitted.size() != n)
    throw std::invalid_argument("process_gauges: t, incident and transmitted lengths differ (" +
                                std::to_string(n) + ", " + std::to_string(rec.incident.size()) +
                                ", " + std::to_string(rec.transmitted.size()) + ")");
  if (n < 4 * min_pretrigger)
    throw std::invalid_argument("process_gauges: record too short (" + std::to_string(n) +
                                " samples, need " + std::to_string(4 * min_pretrigger) + ")");
  for (std::size_t i = 0; i < n; ++i)
    if (!std::isfinite(rec.t[i]) || !std::isfinite(rec.incident[i]) ||
        !std::isfinite(rec.transmitted[i]))
      throw GaugeRowError(i, "non-finite value (time, incident or transmitted strain)");
  const double dt = (rec.t.back() - rec.t.front()) / static_cast<double>(n - 1);
  if (!(dt > 0)) throw std::invalid_argument("process_gauges: time must increase");
  for (std::size_t i = 1; i < n; ++i) {
    const double step = rec.t[i] - rec.t[i - 1];
    // Uniform clock: the FFT and the index shifts need it. A record written with ~10
    // significant digits jitters by ~1e-6 of a step late in the record, so allow 1e-4 of a step
    // (100x that rounding, and far below anything that would move a sample).
    if (std::abs(step - dt) > 1e-4 * dt)
      throw GaugeRowError(i, "non-uniform time step (t = " + num(rec.t[i]) + " s, step " +
                                 num(step) + " s, mean step " + num(dt) + " s)");
  }
  return dt;
}

struct Stats {
  double mean = 0, sigma = 0;
};

/// Mean and population standard deviation of v[0, end).
Stats stats(const std::vector<double>& v, long end) {
  Stats s;
  for (long k = 0; k < end; ++k) s.mean += v[k];
  s.mean /= static_cast<double>(end);
  for (long k = 0; k < end; ++k) s.sigma += (v[k] - s.mean) * (v[k] - s.mean);
  s.sigma = std::sqrt(s.sigma / static_cast<double>(end));
  return s;
}

/// First-pass baseline of v[0, end), robust to a pulse that starts inside the window: the
/// median, and sigma from first differences (white noise: var(diff) = 2 sigma^2), which a
/// smooth pulse barely raises.
Stats robust_stats(const std::vector<double>& v, long end) {
  std::vector<double> w(v.begin(), v.begin() + end);
  std::nth_element(w.begin(), w.begin() + end / 2, w.end());
  Stats s;
  s.mean = w[end / 2];
  for (long k = 1; k < end; ++k) s.sigma += (v[k] - v[k - 1]) * (v[k] - v[k - 1]);
  s.sigma = std::sqrt(s.sigma / (2.0 * static_cast<double>(end - 1)));
  return s;
}

struct Detection {
  long start = 0;          ///< sample index of the pulse start
  double level = 0;        ///< detection level (strain magnitude above the offset)
  double walk_level = 0;   ///< level the walk back stops at
};

/// Rule (docs/analysis.md): level = max(threshold_fraction * peak, noise_sigmas * sigma), peak =
/// max |s - offset| over the whole incident-gauge record (the incident is the largest pulse of a
/// passive test, |e_r| <= e_i); the first sample above it is the crossing; from there walk back
/// to the last sample with |s - offset| <= max(2 sigma, 0.02 level), which is the start.
Detection detect_start(const std::vector<double>& s, Stats base, const GaugeOptions& opt) {
  double peak = 0;
  for (double v : s) peak = std::max(peak, std::abs(v - base.mean));
  // Finite strains whose squares overflow (1e160) leave an infinite noise sigma: the record is
  // beyond what double arithmetic can process, a numerical failure of the processing.
  if (!std::isfinite(base.sigma) || !std::isfinite(base.mean))
    throw NumericalError("process_gauges: the incident gauge's pre-trigger noise sigma is not "
                         "finite (" + num(base.sigma) + "): the strains are too large to process", 0.0);
  Detection d;
  d.level = std::max(opt.threshold_fraction * peak, opt.noise_sigmas * base.sigma);
  long crossing = -1;
  for (long k = 0; k < static_cast<long>(s.size()) && peak > 0; ++k)
    if (std::abs(s[k] - base.mean) > d.level) {
      crossing = k;
      break;
    }
  if (crossing < 0)
    throw std::invalid_argument(
        "process_gauges: no incident pulse found (no sample exceeds " + num(d.level) +
        " = max(threshold_fraction * peak, noise_sigmas * sigma), peak " + num(peak) +
        ", sigma " + num(base.sigma) + "; check pretrigger_fraction if the pulse starts early)");
  d.walk_level = std::max(2.0 * base.sigma, 0.02 * d.level);
  d.start = crossing;
  while (d.start > 0 && std::abs(s[d.start] - base.mean) > d.walk_level) --d.start;
  return d;
}

/// Samples kept clear of the rising edge when averaging the pre-trigger window.
long margin_samples(long start) { return std::max(4L, start / 20); }

/// Linear interpolation at fractional index x; zero outside the record.
double sample_at(const std::vector<double>& v, double x) {
  const long n = static_cast<long>(v.size());
  if (x < 0 || x > static_cast<double>(n - 1)) return 0.0;
  const long k = std::min(static_cast<long>(x), n - 2);
  const double w = x - static_cast<double>(k);
  return (1 - w) * v[k] + w * v[k + 1];
}

void check_options(const AnalysisSetup& setup, const GaugeOptions& opt) {
  for (const AnalysisBar* b : {&setup.incident, &setup.transmission})
    if (!(b->youngs_modulus > 0 && b->density > 0 && b->diameter > 0 && b->gauge_distance >= 0))
      throw std::invalid_argument(
          "process_gauges: bars need youngs_modulus, density, diameter > 0, gauge_distance >= 0");
  if (!(setup.incident.gauge_distance > 0))
    throw std::invalid_argument(
        "process_gauges: incident gauge_distance must be > 0 (incident and reflected waves "
        "cannot be separated at the face)");
  if (!(opt.threshold_fraction > 0 && opt.threshold_fraction < 1) || !(opt.noise_sigmas >= 0) ||
      !(opt.pretrigger_fraction > 0 && opt.pretrigger_fraction < 1) || !(opt.duration >= 0))
    throw std::invalid_argument(
        "process_gauges: need 0 < threshold_fraction < 1, noise_sigmas >= 0, "
        "0 < pretrigger_fraction < 1, duration >= 0");
}

/// The start of the incident wave and the baselines (offset, noise) of both channels.
struct Baselines {
  Detection det;
  Stats incident, transmitted;
};

// Pass 1 takes a robust baseline of the first pretrigger_fraction of the record; later passes
// use mean and sigma of the samples before the detected start minus a margin, until the start
// stops moving.
Baselines find_baselines(const std::vector<double>& s_i, const std::vector<double>& s_t, const GaugeOptions& opt,
                         GaugeReport& rep) {
  const long n = static_cast<long>(s_i.size());
  Baselines b;
  long pre_end = std::max(min_pretrigger, static_cast<long>(opt.pretrigger_fraction * n));
  b.incident = robust_stats(s_i, pre_end);
  b.det = detect_start(s_i, b.incident, opt);
  bool have_baseline = true;
  for (int pass = 0; pass < 4; ++pass) {
    pre_end = b.det.start - margin_samples(b.det.start);
    if (pre_end < min_pretrigger) {
      have_baseline = false;
      break;
    }
    b.incident = stats(s_i, pre_end);
    const Detection next = detect_start(s_i, b.incident, opt);
    const bool settled = next.start == b.det.start;
    b.det = next;
    if (settled) break;
  }
  if (have_baseline) {
    // The transmitted wave reaches its gauge after the incident reaches its own, so the same
    // pre-trigger window is clean on both channels.
    b.transmitted = stats(s_t, pre_end);
  } else {
    rep.warnings.push_back("fewer than " + std::to_string(min_pretrigger) +
                           " pre-trigger samples before the incident start: offsets not removed");
    b.incident = {};
    b.det = detect_start(s_i, b.incident, opt);
  }
  return b;
}

/// The incident gauge's record split into the incident and the reflected wave.
struct IncidentSplit {
  std::vector<double> incident, reflected;
  double pulse_length = 0;  ///< s, incident start to the end of its pulse
};

// The reflected wave reaches the incident gauge 2 d_I / c_I after the incident start. The
// incident pulse ends at the first sample after its peak back at the walk level; the record
// is split midway through the quiet gap between the two, so the incident's dispersed tail and
// the reflected wave's precursor (and a toe missed by a late start) stay whole.
IncidentSplit split_incident(const std::vector<double>& s_i, const Detection& det, double dt, double d_i,
                             double c_i, GaugeReport& rep) {
  const long n = static_cast<long>(s_i.size());
  const long i_s = det.start;
  const double arrival_r = static_cast<double>(i_s) + 2.0 * d_i / (c_i * dt);  // fractional
  long i_peak = i_s;
  for (long k = i_s; k < n && static_cast<double>(k) < arrival_r; ++k)
    if (std::abs(s_i[k]) > std::abs(s_i[i_peak])) i_peak = k;
  long i_end = i_peak;
  while (i_end < n && static_cast<double>(i_end) < arrival_r && std::abs(s_i[i_end]) > det.walk_level) ++i_end;
  double split = arrival_r;
  if (static_cast<double>(i_end) >= arrival_r)
    rep.warnings.push_back("incident pulse still above " + num(det.walk_level) +
                           " when the reflected wave arrives: it is longer than 2 d_I / c_I = " +
                           num(2 * d_i / c_i) + " s and overlaps the reflected wave at the gauge");
  else
    split = 0.5 * (static_cast<double>(i_end) + arrival_r);
  IncidentSplit w;
  w.pulse_length = static_cast<double>(i_end - i_s) * dt;
  w.incident.assign(s_i.size(), 0.0);
  w.reflected.assign(s_i.size(), 0.0);
  for (long k = 0; k < n; ++k) (static_cast<double>(k) < split ? w.incident : w.reflected)[k] = s_i[k];
  return w;
}

}  // namespace

FaceWaves process_gauges(const GaugeRecord& rec, const AnalysisSetup& setup,
                         const GaugeOptions& opt, GaugeReport* report) {
  check_options(setup, opt);
  const double dt = validated_dt(rec);
  const long n = static_cast<long>(rec.t.size());
  GaugeReport rep;

  // Compression positive from here on.
  std::vector<double> s_i(rec.incident.size()), s_t(rec.transmitted.size());
  for (long k = 0; k < n; ++k) s_i[k] = -rec.incident[k], s_t[k] = -rec.transmitted[k];
  const Baselines base = find_baselines(s_i, s_t, opt, rep);
  for (long k = 0; k < n; ++k) s_i[k] -= base.incident.mean, s_t[k] -= base.transmitted.mean;

  const AnalysisBar& bi = setup.incident;
  const AnalysisBar& bt = setup.transmission;
  const double c_i = bi.wave_speed(), c_t = bt.wave_speed();
  const double d_i = bi.gauge_distance, d_t = bt.gauge_distance;
  const long i_s = base.det.start;
  const IncidentSplit win = split_incident(s_i, base.det, dt, d_i, c_i, rep);

  // Output sample k is face time k dt: record index i_s + k + d_I/(c_I dt) for every face signal.
  const double face0 = static_cast<double>(i_s) + d_i / (c_i * dt);
  const double last_r = static_cast<double>(n - 1) - (face0 + d_i / (c_i * dt));
  const double last_t = static_cast<double>(n - 1) - (face0 + d_t / (c_t * dt));
  const long n_avail = static_cast<long>(std::floor(std::min(last_r, last_t))) + 1;
  if (n_avail < 2)
    throw std::invalid_argument("process_gauges: record ends before the reflected and "
                                "transmitted waves reach their gauges");
  // Automatic window: the incident pulse length plus 25 % (covers the specimen transit and the
  // tails of the reflected and transmitted waves), or what the record holds.
  const double wanted = opt.duration > 0 ? opt.duration : 1.25 * win.pulse_length;
  long n_out = static_cast<long>(std::llround(wanted / dt)) + 1;
  if (n_out > n_avail) {
    rep.warnings.push_back("record ends before the analysis window: window cut from " +
                           num(wanted) + " s to " + num(static_cast<double>(n_avail - 1) * dt) +
                           " s");
    n_out = n_avail;
  }

  FaceWaves w;
  w.t.resize(n_out);
  w.eps_i.resize(n_out);
  w.eps_r.resize(n_out);
  w.eps_t.resize(n_out);
  if (opt.dispersion_correction) {
    const double r_i = 0.5 * bi.diameter, r_t = 0.5 * bt.diameter;
    const auto inc = propagate_dispersive(win.incident, dt, d_i, c_i, r_i, bi.poisson_ratio);
    const auto ref = propagate_dispersive(win.reflected, dt, -d_i, c_i, r_i, bi.poisson_ratio);
    const auto tr = propagate_dispersive(s_t, dt, -d_t, c_t, r_t, bt.poisson_ratio);
    for (long k = 0; k < n_out; ++k) {
      const double x = face0 + static_cast<double>(k);
      w.eps_i[k] = sample_at(inc, x);
      w.eps_r[k] = sample_at(ref, x);
      w.eps_t[k] = sample_at(tr, x);
    }
  } else {
    // One interpolation per channel: the gauge-to-face delay and the clock shift combined.
    for (long k = 0; k < n_out; ++k) {
      const double x = static_cast<double>(i_s + k);
      w.eps_i[k] = win.incident[i_s + k];
      w.eps_r[k] = sample_at(win.reflected, x + 2.0 * d_i / (c_i * dt));
      w.eps_t[k] = sample_at(s_t, x + (d_i / c_i + d_t / c_t) / dt);
    }
  }
  for (long k = 0; k < n_out; ++k) w.t[k] = static_cast<double>(k) * dt;

  rep.offset_incident = -base.incident.mean;  // as measured (compression negative)
  rep.offset_transmitted = -base.transmitted.mean;
  rep.noise_incident = base.incident.sigma;
  rep.noise_transmitted = base.transmitted.sigma;
  rep.start_time = rec.t[i_s];
  rep.detection_level = base.det.level;
  rep.window = static_cast<double>(n_out - 1) * dt;
  if (report) *report = std::move(rep);
  return w;
}

}  // namespace kolsky::shpb
