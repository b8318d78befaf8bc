// Geometric dispersion of longitudinal waves in a cylindrical elastic bar: the first mode of
// the Pochhammer-Chree frequency equation (Pochhammer 1876, Chree 1889; Graff, "Wave Motion in
// Elastic Solids", Sec. 8.2), and the frequency-domain correction of a pulse for propagation
// over a distance (Follansbee & Frantz 1983; Gong, Malvern & Jenkins 1990).
#pragma once
#include <vector>

namespace kolsky::shpb {

/// Phase velocity ratio c/c0 of the first longitudinal mode for a bar of radius a and Poisson
/// ratio nu, as a function of a/Lambda (Lambda = wavelength). c0 = sqrt(E/rho).
double pochhammer_chree_phase_ratio(double a_over_lambda, double poisson_ratio);

/// The same ratio at many points in one continuous tracking pass (a_over_lambda ascending,
/// >= 0); cheaper than calling the scalar form per point, which tracks from 0 each time.
std::vector<double> pochhammer_chree_phase_ratios(const std::vector<double>& a_over_lambda,
                                                  double poisson_ratio);

/// Moves a uniformly sampled signal by `distance` along the bar (positive: in the direction of
/// travel, i.e. the wave arrives later), with each Fourier component delayed by
/// distance / c(f) from the first Pochhammer-Chree mode. Zero-padded FFT (GSL).
std::vector<double> propagate_dispersive(const std::vector<double>& signal, double dt,
                                         double distance, double wave_speed, double radius,
                                         double poisson_ratio);

/// The same move without dispersion: a pure delay distance / c0 (linear interpolation).
std::vector<double> propagate_nondispersive(const std::vector<double>& signal, double dt,
                                            double distance, double wave_speed);

}  // namespace kolsky::shpb
