// Grain-size curves (percent passing by mass vs diameter) and the numbers taken from them:
// D_x, C_u, C_c, up/downscaling by a factor N (Ch. 3-5: sizes times N, Prabhu and Qiu 2019;
// Sec. 5.3.1 shifts back by N for comparison), the mean grain volume and the expected particle
// count of a specimen, n = V (1 - porosity) / mean grain volume.
// Within-curve model (docs/psd.md): percent passing is linear in log d between rows, i.e. the
// mass of a bin is spread uniformly in log d; a first row with P > 0 is a lump of that much mass
// at the smallest size (so a one-row curve {d, 100} is monodisperse). Grains are spheres of one
// density. Units: diameters in m, volumes in m^3, passing in percent (0..100).
#pragma once
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

namespace kolsky::psd {

/// A rule of a grain-size curve broken at `row` (0-based index into the table; `kWholeCurve`
/// for rules about the curve as a whole). The scene layer maps row to the CSV line.
class InvalidCurve : public std::invalid_argument {
 public:
  static constexpr std::size_t kWholeCurve = std::numeric_limits<std::size_t>::max();
  InvalidCurve(std::size_t row, const std::string& rule);
  std::size_t row() const { return row_; }

 private:
  std::size_t row_;
};

/// Percent passing by mass at each diameter. Rules (validate()): at least one row; diameters
/// finite, > 0, strictly increasing; passing finite, in [0, 100], non-decreasing; last = 100.
struct GrainSizeCurve {
  std::vector<double> diameter;         ///< m
  std::vector<double> percent_passing;  ///< % of solid mass with size <= diameter

  /// Throws InvalidCurve naming the first broken rule and its row.
  void validate() const;
  std::size_t size() const { return diameter.size(); }
  double d_min() const { return diameter.front(); }
  double d_max() const { return diameter.back(); }
};

/// Percent passing at d (m): 0 below the first size, 100 from the last, linear in log d between.
/// Precondition: curve.validate() passed (not re-checked: this is called per grain and size).
double passing_at(const GrainSizeCurve& curve, double d);

/// D_x: the smallest diameter with passing_at >= x, for 0 < x <= 100 (m).
double percentile_diameter(const GrainSizeCurve& curve, double x_percent);
inline double d10(const GrainSizeCurve& c) { return percentile_diameter(c, 10.0); }
inline double d30(const GrainSizeCurve& c) { return percentile_diameter(c, 30.0); }
inline double d50(const GrainSizeCurve& c) { return percentile_diameter(c, 50.0); }
inline double d60(const GrainSizeCurve& c) { return percentile_diameter(c, 60.0); }
/// Coefficient of uniformity C_u = D60/D10 (ASTM D2487; sands with C_u < 6 are poorly graded).
double uniformity_coefficient(const GrainSizeCurve& curve);
/// Coefficient of curvature C_c = D30^2/(D10 D60) (ASTM D2487).
double curvature_coefficient(const GrainSizeCurve& curve);

/// Upscaled curve: every diameter times factor (> 0), passing unchanged (Ch. 3-5).
GrainSizeCurve upscale(const GrainSizeCurve& curve, double factor);
/// Downscaled curve: every diameter divided by factor (> 0); Sec. 5.3.1's shift back.
GrainSizeCurve downscale(const GrainSizeCurve& curve, double factor);

/// Mean volume of one grain when grains are counted (m^3): V_s / N for a sample of solid volume
/// V_s drawn from the curve. Per unit solid volume a bin [a, b] holding mass fraction f has
/// f (a^-3 - b^-3)/(3 ln(b/a)) * 6/pi grains (mass uniform in log d, spheres); a lump at d has
/// f * 6/(pi d^3).
double mean_grain_volume(const GrainSizeCurve& curve);
/// Mean-volume-equivalent diameter d_v = (sum n_i d_i^3 / sum n_i)^(1/3) = (6 V_mean/pi)^(1/3).
double mean_volume_diameter(const GrainSizeCurve& curve);

/// Volume of a cylinder (m^3) of the given diameter and length (m).
double cylinder_volume(double diameter, double length);
/// Expected particle count of a packing of total volume V (m^3) at porosity n (0 <= n < 1):
/// V (1 - n) / mean_grain_volume(curve). Not rounded.
double expected_particle_count(const GrainSizeCurve& curve, double total_volume, double porosity);

}  // namespace kolsky::psd
