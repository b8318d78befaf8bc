// First longitudinal mode of the Pochhammer-Chree frequency equation for a solid cylinder and
// the frequency-domain dispersion shift of a sampled pulse.
//   Frequency equation (Graff, "Wave Motion in Elastic Solids", Sec. 8.2; Bancroft 1941):
//     (2p/a)(q^2 + k^2) J1(pa) J1(qa) - (q^2 - k^2)^2 J0(pa) J1(qa) - 4 k^2 p q J1(pa) J0(qa) = 0,
//     p^2 = w^2/c_L^2 - k^2, q^2 = w^2/c_S^2 - k^2.
//   Shift: each Fourier component of frequency f is delayed by distance / c(f)
//   (Follansbee & Frantz 1983; Gong, Malvern & Jenkins 1990). GSL radix-2 real FFT.
// SI units; speeds are ratios to c0 = sqrt(E/rho) inside the solver.
#include "shpb/dispersion.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_fft_halfcomplex.h>
#include <gsl/gsl_fft_real.h>
#include <gsl/gsl_roots.h>
#include <gsl/gsl_sf_bessel.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>
#include <vector>

namespace kolsky::shpb {
namespace {

constexpr double pi = std::numbers::pi;

/// The Bessel factors of one radial wavenumber s (s^2 = (pa)^2 or (qa)^2, either sign),
/// chosen so that the frequency equation stays real and free of the spurious root at s = 0:
///   s J1(s), J1(s)/s, J0(s) for s^2 > 0, and with s = i s' (J0(is') = I0(s'),
///   J1(is') = i I1(s')): -s' I1(s'), I1(s')/s', I0(s') for s^2 < 0.
/// For s^2 < 0 all three are scaled by exp(-s') (GSL *_scaled) so large k a cannot overflow;
/// every term of the equation carries exactly one factor of each wavenumber, so the common
/// positive scale changes neither the sign nor the root.
struct BesselFactors {
  double s_j1 = 0, j1_over_s = 0.5, j0 = 1;
};

/// GSL's *_e forms: an underflow is reported in the status instead of reaching the global
/// error handler (which aborts by default); the value it returns (0) is the right limit.
double bessel(int (*fn)(double, gsl_sf_result*), double s) {
  gsl_sf_result r{0.0, 0.0};
  fn(s, &r);
  return r.val;
}

BesselFactors bessel_factors(double s2) {
  BesselFactors b;
  if (s2 > 0) {
    const double s = std::sqrt(s2);
    const double j1 = bessel(&gsl_sf_bessel_J1_e, s);
    b = {s * j1, j1 / s, bessel(&gsl_sf_bessel_J0_e, s)};
  } else if (s2 < 0) {
    const double s = std::sqrt(-s2);
    const double i1 = bessel(&gsl_sf_bessel_I1_scaled_e, s);
    b = {-s * i1, i1 / s, bessel(&gsl_sf_bessel_I0_scaled_e, s)};
  }
  return b;
}

/// Material constants of the frequency equation, nondimensionalised by c0 and the radius.
struct PcBar {
  double inv_cl2 = 0;  ///< (c0/c_L)^2 = (1+nu)(1-2nu)/(1-nu)
  double inv_cs2 = 0;  ///< (c0/c_S)^2 = 2(1+nu)
  explicit PcBar(double nu) {
    if (!(nu >= 0.0 && nu < 0.5))
      throw std::invalid_argument("pochhammer_chree: poisson_ratio must lie in [0, 0.5), got " +
                                  std::to_string(nu));
    inv_cl2 = (1 + nu) * (1 - 2 * nu) / (1 - nu);
    inv_cs2 = 2 * (1 + nu);
  }
};

/// Where the equation is evaluated: at fixed k a (a curve against a/Lambda), or at fixed
/// omega a / c0 (inverting omega(k) for one Fourier component), then k a = omega a/(c0 xi).
struct FrequencyArgs {
  const PcBar* bar;
  double value;          ///< k a, or omega a / c0
  bool fixed_frequency;  ///< which of the two `value` is
};

/// Frequency equation divided by (qa) (removes the trivial root q = 0), as a function of the
/// phase-velocity ratio xi = c/c0.
double frequency_residual(double xi, void* params) {
  const auto* f = static_cast<const FrequencyArgs*>(params);
  const double ka = f->fixed_frequency ? f->value / xi : f->value;
  const double k2 = ka * ka;
  const double p2 = k2 * (xi * xi * f->bar->inv_cl2 - 1);
  const double q2 = k2 * (xi * xi * f->bar->inv_cs2 - 1);
  const BesselFactors p = bessel_factors(p2);
  const BesselFactors q = bessel_factors(q2);
  return 2 * p.s_j1 * (q2 + k2) * q.j1_over_s - (q2 - k2) * (q2 - k2) * p.j0 * q.j1_over_s -
         4 * k2 * p.s_j1 * q.j0;
}

/// Follows the first mode continuously from a/Lambda = 0 (xi = 1) upwards, in a/Lambda or in
/// frequency. The mode falls from c0, dips slightly below the Rayleigh speed (about 0.4 % for
/// nu = 0.3 near a/Lambda = 2.5) and returns to it from below, so each root is sought on both
/// sides of the previous one. Steps (a/Lambda by at most 0.002 below 1 and 0.2 % above, where
/// the curve is flat) are small enough that the second mode is never reached (checked against
/// the SurePulse fit and the Rayleigh limit in verification/test_dispersion.cpp).
class FirstModeTracker {
 public:
  explicit FirstModeTracker(double nu)
      : bar_(nu), solver_(gsl_root_fsolver_alloc(gsl_root_fsolver_brent)) {
    if (!solver_) throw std::runtime_error("pochhammer_chree: cannot allocate GSL root solver");
  }
  ~FirstModeTracker() { gsl_root_fsolver_free(solver_); }
  FirstModeTracker(const FirstModeTracker&) = delete;
  FirstModeTracker& operator=(const FirstModeTracker&) = delete;

  double xi() const { return xi_; }

  /// Advances to a/Lambda = target (>= the current one).
  void advance_to(double target) {
    while (x_ < target) {
      const double x = std::min(target, x_ + max_step());
      xi_ = solve({&bar_, 2 * pi * x, false}, x - x_);
      x_ = x;
      phi_ = x_ * xi_;
    }
  }
  /// Advances to the frequency number f a / c0 = (a/Lambda)(c/c0) = target.
  void advance_to_frequency(double target) {
    while (phi_ < target) {  // phi_ kept as state: phi_/xi_*xi_ need not round to phi_
      const double phi = std::min(target, phi_ + max_step() * xi_);
      xi_ = solve({&bar_, 2 * pi * phi, true}, phi - phi_);
      phi_ = phi;
      x_ = phi_ / xi_;
    }
  }

 private:
  double max_step() const { return x_ < 1.0 ? 0.002 : 0.002 * x_; }

  /// Root after a parameter step `dp`. Probes outwards on both sides (offsets 1e-9 * 2^j) of
  /// the linear extrapolation of the last two roots and takes the nearest sign change: the
  /// root moves by at most a few 1e-3 per step, while the second mode stays several per cent
  /// away.
  double solve(FrequencyArgs args, double dp) {
    gsl_function fn{&frequency_residual, &args};
    const bool same_kind = last_dp_ > 0 && last_fixed_frequency_ == args.fixed_frequency;
    const double center = xi_ + (same_kind ? (xi_ - last_xi_) / last_dp_ * dp : 0.0);
    last_xi_ = xi_, last_dp_ = dp, last_fixed_frequency_ = args.fixed_frequency;
    double lo = center, hi = center;
    double f_lo = frequency_residual(center, &args), f_hi = f_lo;
    if (f_lo == 0) return center;
    for (double d = 1e-9; d < 0.25; d *= 2) {
      const double lo_next = center - d, hi_next = center + d;
      const double f_lo_next = frequency_residual(lo_next, &args);
      const double f_hi_next = frequency_residual(hi_next, &args);
      if (f_lo_next == 0) return lo_next;
      if (f_hi_next == 0) return hi_next;
      if ((f_lo_next < 0) != (f_lo < 0)) return refine(fn, lo_next, lo);
      if ((f_hi_next < 0) != (f_hi < 0)) return refine(fn, hi, hi_next);
      lo = lo_next, hi = hi_next, f_lo = f_lo_next, f_hi = f_hi_next;
    }
    throw std::runtime_error("pochhammer_chree: first mode lost at a/Lambda = " +
                             std::to_string(x_));
  }

  double refine(gsl_function& fn, double lo, double hi) {
    gsl_root_fsolver_set(solver_, &fn, lo, hi);  // lo, hi straddle the root (checked above)
    for (int it = 0; it < 200; ++it) {
      gsl_root_fsolver_iterate(solver_);
      lo = gsl_root_fsolver_x_lower(solver_);
      hi = gsl_root_fsolver_x_upper(solver_);
      if (gsl_root_test_interval(lo, hi, 0.0, 1e-14) == GSL_SUCCESS) break;
    }
    return gsl_root_fsolver_root(solver_);
  }

  PcBar bar_;
  gsl_root_fsolver* solver_;
  double x_ = 0, xi_ = 1, phi_ = 0;  ///< a/Lambda, c/c0, f a / c0
  double last_xi_ = 1, last_dp_ = 0;  ///< the root before and the step since, to extrapolate
  bool last_fixed_frequency_ = false;
};

void check_positive(double v, const char* name) {
  if (!(v > 0) || !std::isfinite(v))
    throw std::invalid_argument(std::string("dispersion: ") + name + " must be > 0 and finite");
}

}  // namespace

double pochhammer_chree_phase_ratio(double a_over_lambda, double poisson_ratio) {
  return pochhammer_chree_phase_ratios({a_over_lambda}, poisson_ratio).front();
}

std::vector<double> pochhammer_chree_phase_ratios(const std::vector<double>& a_over_lambda,
                                                  double poisson_ratio) {
  FirstModeTracker tracker(poisson_ratio);
  std::vector<double> out;
  out.reserve(a_over_lambda.size());
  double prev = 0;
  for (double x : a_over_lambda) {
    if (!(x >= prev) || !std::isfinite(x))
      throw std::invalid_argument("pochhammer_chree: a/Lambda must be finite, >= 0, ascending");
    tracker.advance_to(x);
    out.push_back(tracker.xi());
    prev = x;
  }
  return out;
}

std::vector<double> propagate_dispersive(const std::vector<double>& signal, double dt,
                                         double distance, double wave_speed, double radius,
                                         double poisson_ratio) {
  check_positive(dt, "dt");
  check_positive(wave_speed, "wave_speed");
  check_positive(radius, "radius");
  const std::size_t n = signal.size();
  if (n == 0) return {};
  std::size_t m = 2;
  while (m < 2 * n) m *= 2;  // >= 2n keeps a delayed pulse from wrapping onto its own start
  std::vector<double> data(m, 0.0);
  std::copy(signal.begin(), signal.end(), data.begin());
  gsl_fft_real_radix2_transform(data.data(), 1, m);

  // Each component's phase velocity is the first-mode root at that exact frequency (omega(k)
  // inverted per bin, tracked upwards from f = 0): no table, so the phase has no
  // interpolation kinks that would smear the signal in time.
  FirstModeTracker tracker(poisson_ratio);
  // GSL radix-2 halfcomplex layout: Re z_i = data[i] (0 <= i <= m/2), Im z_i = data[m-i].
  for (std::size_t i = 1; i <= m / 2; ++i) {
    const double f = static_cast<double>(i) / (static_cast<double>(m) * dt);
    tracker.advance_to_frequency(f * radius / wave_speed);
    const double theta = 2 * pi * f * distance / (wave_speed * tracker.xi());
    const double c = std::cos(theta), s = std::sin(theta);
    if (i == m / 2) {
      data[i] *= c;  // the Nyquist term is real: keep the real part of its rotation
      continue;
    }
    const double re = data[i], im = data[m - i];
    data[i] = re * c + im * s;  // (re + i im) * exp(-i theta)
    data[m - i] = im * c - re * s;
  }
  gsl_fft_halfcomplex_radix2_inverse(data.data(), 1, m);
  data.resize(n);
  return data;
}

std::vector<double> propagate_nondispersive(const std::vector<double>& signal, double dt,
                                            double distance, double wave_speed) {
  check_positive(dt, "dt");
  check_positive(wave_speed, "wave_speed");
  const long n = static_cast<long>(signal.size());
  const double shift = distance / (wave_speed * dt);  // samples of delay
  std::vector<double> out(signal.size(), 0.0);
  for (long i = 0; i < n; ++i) {
    const double s = static_cast<double>(i) - shift;
    if (s < 0 || s > static_cast<double>(n - 1)) continue;  // outside the record: zero-filled
    const long k = std::min(static_cast<long>(s), n - 2 < 0 ? 0 : n - 2);
    const double w = s - static_cast<double>(k);
    out[i] = n == 1 ? signal[0] : (1 - w) * signal[k] + w * signal[k + 1];
  }
  return out;
}

}  // namespace kolsky::shpb
