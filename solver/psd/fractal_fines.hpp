// Fractal redistribution of the mass lost at breakage (Sec. 5.2.3, Eq. 5.16; Ciantia et al. 2015):
//   M(L<d)/M_T = (d^(3-a) - d_min^(3-a)) / (d_max^(3-a) - d_min^(3-a)),   d_min <= d <= d_max,
// with a = 2.6 (McDowell et al. 1996; Altuhafi and Coop 2011), d_max the diameter of the
// smallest apollonian daughter (0.224 of the parent's, Table 5.3), d_min the smallest size in
// the PSD (7.5 um for Wang et al. 2018). The lost 47 % is not made into particles: it is added
// to the PSD only, which is what passing_with_fines() does. Units: m, m^3.
#pragma once
#include <cstddef>
#include <span>
#include <vector>

#include "psd/grain_size_curve.hpp"

namespace kolsky::psd {

/// Eq. 5.16: fraction (0..1) of the redistributed mass finer than d; 0 below d_min, 1 above
/// d_max. Requires 0 < d_min < d_max and a finite alpha; alpha = 3 is the limit ln(d/d_min) /
/// ln(d_max/d_min) (Eq. 5.16 is 0/0 there).
double fractal_passing_fraction(double d, double d_min, double d_max, double alpha);

/// Solid volume removed from the particles by one or more breakage events and spread over
/// [d_min, d_max] by Eq. 5.16.
struct FractalFines {
  double volume = 0.0;  ///< m^3 (mass / density)
  double d_min = 0.0;   ///< m
  double d_max = 0.0;   ///< m
  double alpha = 2.6;   ///< fractal dimension (Sec. 5.2.3)
};

/// Eq. 5.16 tabulated at n_points >= 2 sizes log-spaced from d_min to d_max, as a curve (between
/// rows the curve is linear in log d, so this approximates Eq. 5.16 to O(spacing^2)).
GrainSizeCurve fractal_curve(double d_min, double d_max, double alpha, std::size_t n_points);

/// Percent passing by mass at each size for particles (diameters, m) plus redistributed fines:
/// 100 * (sum of grain volumes with d <= size + sum of fines volume * Eq. 5.16 at size) / total.
/// Either part may be empty, not both.
std::vector<double> passing_with_fines(std::span<const double> diameters,
                                       std::span<const FractalFines> fines,
                                       std::span<const double> sizes);

}  // namespace kolsky::psd
