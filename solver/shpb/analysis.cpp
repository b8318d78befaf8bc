// Classic SHPB analysis of face-referred bar waves (Gama 2004; dissertation Eqs. 1.1-1.4,
// 2.11-2.13, 2.15/4.15, 4.16, 5.1) and the equilibrium indices of open SHPB tools
// (DynaMat-Platform FBC/SEQI; SHPB_Processing.py strain difference). docs/analysis.md has the
// formulas with their sources. Bar strains and specimen stress/strain compression positive;
// SI units (Pa, s, m, J).
#include "shpb/analysis.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <string>

namespace kolsky::shpb {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();

/// Cumulative trapezoid integral of y on a uniform step dt, starting from 0.
std::vector<double> cumulative_trapezoid(const std::vector<double>& y, double dt) {
  std::vector<double> out(y.size(), 0.0);
  for (std::size_t i = 1; i < y.size(); ++i) out[i] = out[i - 1] + 0.5 * dt * (y[i - 1] + y[i]);
  return out;
}

double max_abs(const std::vector<double>& v) {
  double m = 0;
  for (double x : v) m = std::max(m, std::abs(x));
  return m;
}

void check_bar(const AnalysisBar& b, const char* name) {
  if (!(b.youngs_modulus > 0 && b.density > 0 && b.diameter > 0))
    throw std::invalid_argument(std::string("analyze: ") + name +
                                " bar needs youngs_modulus, density and diameter > 0");
}

/// Uniform clock spacing of a FaceWaves (the t vector may be empty of meaning for n < 2).
double face_dt(const FaceWaves& w) {
  const std::size_t n = w.t.size();
  if (w.eps_i.size() != n || w.eps_r.size() != n || w.eps_t.size() != n)
    throw std::invalid_argument("analyze: t, eps_i, eps_r, eps_t must have the same length");
  if (n < 2) throw std::invalid_argument("analyze: need at least 2 samples");
  const double dt = (w.t.back() - w.t.front()) / static_cast<double>(n - 1);
  if (!(dt > 0)) throw std::invalid_argument("analyze: t must increase");
  return dt;
}

void check_range(long begin, long end, std::size_t n, const char* who) {
  if (begin < 0 || end > static_cast<long>(n) || begin >= end)
    throw std::invalid_argument(std::string(who) + ": need 0 <= begin < end <= " +
                                std::to_string(n) + ", got [" + std::to_string(begin) + ", " +
                                std::to_string(end) + ")");
}

/// Eq. 2.15 on every sample, NaN below the floor: a fraction of the record's peak |stress_avg|
/// (docs/analysis.md, "Alpha floor"). Needs stress_front, stress_back, stress_avg filled.
void fill_alpha(SpecimenHistory& h, const AnalysisOptions& o) {
  const double floor = o.alpha_floor_fraction * max_abs(h.stress_avg);
  h.alpha.resize(h.stress_avg.size());
  for (std::size_t k = 0; k < h.alpha.size(); ++k)
    h.alpha[k] = stress_nonuniformity(h.stress_front[k], h.stress_back[k], floor);
}
}  // namespace

double AnalysisBar::wave_speed() const { return std::sqrt(youngs_modulus / density); }
double AnalysisBar::area() const { return 0.25 * std::numbers::pi * diameter * diameter; }
double AnalysisSetup::specimen_area() const {
  return 0.25 * std::numbers::pi * specimen_diameter * specimen_diameter;
}

std::vector<double> strain_from_strain_rate(const std::vector<double>& rate, double dt) {
  return cumulative_trapezoid(rate, dt);
}

std::vector<double> wave_energy(const std::vector<double>& sigma, double dt, double area,
                                double density, double wave_speed) {
  std::vector<double> sq(sigma.size());
  for (std::size_t i = 0; i < sigma.size(); ++i) sq[i] = sigma[i] * sigma[i];
  std::vector<double> w = cumulative_trapezoid(sq, dt);
  const double k = area / (density * wave_speed);  // Eqs. 2.11-2.13: A_o / (rho_o c_o)
  for (double& x : w) x *= k;
  return w;
}

double stress_nonuniformity(double stress_front, double stress_back, double floor) {
  const double avg = 0.5 * (stress_front + stress_back);
  if (std::abs(avg) < floor || avg == 0) return nan;  // ratio of noise to noise below the floor
  return std::abs(stress_front - stress_back) / std::abs(avg);
}

SpecimenHistory analyze(const FaceWaves& w, const AnalysisSetup& s, const AnalysisOptions& o) {
  const double dt = face_dt(w);
  check_bar(s.incident, "incident");
  check_bar(s.transmission, "transmission");
  if (!(s.specimen_length > 0 && s.specimen_diameter > 0))
    throw std::invalid_argument("analyze: specimen_length and specimen_diameter must be > 0");
  const std::size_t n = w.t.size();
  const double c_i = s.incident.wave_speed(), c_t = s.transmission.wave_speed();
  const double a_s = s.specimen_area(), l_s = s.specimen_length;
  const double front_k = s.incident.youngs_modulus * s.incident.area() / a_s;
  const double back_k = s.transmission.youngs_modulus * s.transmission.area() / a_s;

  SpecimenHistory h;
  h.t = w.t;
  h.strain_rate.resize(n);
  h.strain_rate_three_wave.resize(n);
  h.stress_front.resize(n);
  h.stress_back.resize(n);
  h.stress_avg.resize(n);
  std::vector<double> sigma_i(n), sigma_r(n), sigma_t(n);
  for (std::size_t k = 0; k < n; ++k) {
    h.strain_rate[k] = -2.0 * c_i * w.eps_r[k] / l_s;  // Eq. 1.3
    // Face velocities: v_front = c_I (e_i - e_r), v_back = c_T e_t (compression positive,
    // the reflected wave travels away from the specimen); rate = (v_front - v_back) / L_s.
    h.strain_rate_three_wave[k] = (c_i * (w.eps_i[k] - w.eps_r[k]) - c_t * w.eps_t[k]) / l_s;
    h.stress_front[k] = front_k * (w.eps_i[k] + w.eps_r[k]);
    h.stress_back[k] = back_k * w.eps_t[k];                         // Eq. 1.2
    h.stress_avg[k] = 0.5 * (h.stress_front[k] + h.stress_back[k]);  // Eq. 4.16
    sigma_i[k] = s.incident.youngs_modulus * w.eps_i[k];
    sigma_r[k] = s.incident.youngs_modulus * w.eps_r[k];
    sigma_t[k] = s.transmission.youngs_modulus * w.eps_t[k];
  }
  // Eq. 1.1: strain = -2 (c/L) int e_r dt, i.e. the integral of the Eq. 1.3 rate.
  h.strain = cumulative_trapezoid(h.strain_rate, dt);
  h.strain_three_wave = cumulative_trapezoid(h.strain_rate_three_wave, dt);

  fill_alpha(h, o);

  // Eqs. 2.11-2.13: incident and reflected waves in the incident bar, transmitted in the other.
  const AnalysisBar& bi = s.incident;
  const AnalysisBar& bt = s.transmission;
  h.w_incident = wave_energy(sigma_i, dt, bi.area(), bi.density, c_i);
  h.w_reflected = wave_energy(sigma_r, dt, bi.area(), bi.density, c_i);
  h.w_transmitted = wave_energy(sigma_t, dt, bt.area(), bt.density, c_t);
  h.w_loss.resize(n);
  h.dissipation_percent.resize(n);
  for (std::size_t k = 0; k < n; ++k) {
    h.w_loss[k] = h.w_incident[k] - h.w_reflected[k] - h.w_transmitted[k];
    h.dissipation_percent[k] = h.w_incident[k] > 0 ? 100.0 * h.w_loss[k] / h.w_incident[k] : nan;
  }
  return h;
}

SpecimenHistory analyze_faces(const std::vector<double>& t, const std::vector<double>& strain,
                              const std::vector<double>& strain_rate,
                              const std::vector<double>& stress_front,
                              const std::vector<double>& stress_back, const AnalysisOptions& o) {
  const std::size_t n = t.size();
  if (strain.size() != n || strain_rate.size() != n || stress_front.size() != n ||
      stress_back.size() != n)
    throw std::invalid_argument("analyze_faces: t, strain, strain_rate and stresses must have the same length");
  SpecimenHistory h;
  h.t = t;
  h.strain = strain;
  h.strain_rate = strain_rate;
  h.stress_front = stress_front;
  h.stress_back = stress_back;
  h.stress_avg.resize(n);
  for (std::size_t k = 0; k < n; ++k) h.stress_avg[k] = 0.5 * (stress_front[k] + stress_back[k]);  // Eq. 4.16
  fill_alpha(h, o);
  return h;
}

long first_equilibrium_index(const std::vector<double>& alpha, double threshold, long hold) {
  const long need = std::max(hold, 1L);
  long run = 0;
  for (long k = 0; k < static_cast<long>(alpha.size()); ++k) {
    // NaN compares false, so a NaN sample ends the run like a sample above the threshold.
    run = alpha[k] < threshold ? run + 1 : 0;
    if (run == need) return k - need + 1;
  }
  return -1;
}

EquilibriumIndices equilibrium_indices(const SpecimenHistory& h, long begin, long end) {
  const std::size_t n = h.stress_front.size();
  if (h.stress_back.size() != n || h.alpha.size() != n)
    throw std::invalid_argument("equilibrium_indices: history lengths differ");
  check_range(begin, end, n, "equilibrium_indices");

  // FBC and SEQI exactly as DynaMat-Platform computes them
  // (src/dynamat/mechanical/shpb/core/StressStrainCalculator.calculate_equilibrium_metrics,
  // in core/stress_strain.py; io/validity_assessment.py only holds the pass thresholds):
  // magnitudes (their "all metrics use absolute values"), samples where both stresses exceed
  // 1 % of the peak front stress, FBC = 1 - mean(|F_f - F_b| / max(F_f, F_b)) pointwise,
  // SEQI = exp(-RMSE(front - back) / (max - min of front)). Forces are stresses times A_s, so
  // the stress ratios are the force ratios; their 1e-10 guards are replaced by the mask.
  double peak = 0;
  for (long k = begin; k < end; ++k) peak = std::max(peak, std::abs(h.stress_front[k]));
  const double thr = 0.01 * peak;
  double fbc_sum = 0, sq_sum = 0, lo = std::numeric_limits<double>::infinity(), hi = -lo;
  long n_valid = 0;
  EquilibriumIndices r;
  r.max_strain_difference = nan;
  double alpha_sum = 0;
  long n_alpha = 0;
  for (long k = begin; k < end; ++k) {
    const double f = std::abs(h.stress_front[k]), b = std::abs(h.stress_back[k]);
    if (f > thr && b > thr) {
      fbc_sum += std::abs(f - b) / std::max(f, b);
      sq_sum += (f - b) * (f - b);
      lo = std::min(lo, f);
      hi = std::max(hi, f);
      ++n_valid;
    }
    if (std::isfinite(h.alpha[k])) alpha_sum += h.alpha[k], ++n_alpha;
  }
  if (n_valid > 0) {
    r.force_balance = 1.0 - fbc_sum / static_cast<double>(n_valid);
    const double rmse = std::sqrt(sq_sum / static_cast<double>(n_valid));
    // A flat front stress (zero range) leaves NRMSE undefined unless the two faces agree.
    const double range = hi - lo;
    r.stress_equilibrium = range > 0 ? std::exp(-rmse / range) : (rmse == 0 ? 1.0 : 0.0);
  } else {
    r.force_balance = nan;
    r.stress_equilibrium = nan;
  }
  r.mean_alpha = n_alpha > 0 ? alpha_sum / static_cast<double>(n_alpha) : nan;
  return r;
}

EquilibriumIndices equilibrium_indices(const FaceWaves& w, const SpecimenHistory& h, long begin,
                                       long end) {
  const std::size_t n = h.stress_front.size();
  if (w.eps_i.size() != n || w.eps_r.size() != n || w.eps_t.size() != n)
    throw std::invalid_argument("equilibrium_indices: waves and history lengths differ");
  EquilibriumIndices r = equilibrium_indices(h, begin, end);
  // Eq. 1.4 residual in bar strain (SHPB_Processing.py "strain_difference").
  r.max_strain_difference = 0;
  for (long k = begin; k < end; ++k)
    r.max_strain_difference =
        std::max(r.max_strain_difference, std::abs(w.eps_i[k] + w.eps_r[k] - w.eps_t[k]));
  return r;
}

double fitted_slope(const std::vector<double>& x, const std::vector<double>& y, long begin,
                    long end) {
  if (x.size() != y.size()) throw std::invalid_argument("fitted_slope: x and y lengths differ");
  check_range(begin, end, x.size(), "fitted_slope");
  if (end - begin < 2) throw std::invalid_argument("fitted_slope: need at least 2 samples");
  // Centred sums: the two-pass form avoids the cancellation of sum(x^2) - n xbar^2.
  double xm = 0, ym = 0;
  for (long k = begin; k < end; ++k) xm += x[k], ym += y[k];
  xm /= static_cast<double>(end - begin);
  ym /= static_cast<double>(end - begin);
  double sxy = 0, sxx = 0;
  for (long k = begin; k < end; ++k) {
    sxy += (x[k] - xm) * (y[k] - ym);
    sxx += (x[k] - xm) * (x[k] - xm);
  }
  if (!(sxx > 0)) throw std::invalid_argument("fitted_slope: x is constant over the range");
  return sxy / sxx;
}

}  // namespace kolsky::shpb
