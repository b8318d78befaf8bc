// Hardin (1985) relative breakage B_r = B_t / B_p, as Sec. 5.3.1 uses it (threshold 75 um):
//   B_p = integral over d > d_t of (1 - P_0(d)/100) d(log10 d)   breakage potential of the
//         initial curve (area above it, right of the threshold, up to 100 % passing);
//   B_t = integral over d > d_t of (P(d) - P_0(d))/100 d(log10 d) total breakage = B_p - B_pl,
//         the area between initial and current curves (Hardin's signed definition: a curve that
//         coarsens gives a negative contribution).
// B_r = 0 for no change, 1 when everything above d_t has been crushed below it. Both curves are
// linear in log d between their rows (grain_size_curve.hpp), so the integrals are exact: on each
// interval between merged breakpoints both curves are linear, and the midpoint rule is exact.
#pragma once
#include "psd/grain_size_curve.hpp"

namespace kolsky::psd {

/// The two areas (in decades of log10 d) and their ratio.
struct HardinBreakage {
  double potential = 0.0;  ///< B_p
  double total = 0.0;      ///< B_t
  double relative = 0.0;   ///< B_r = B_t / B_p
};

/// B_r of `current` against `initial` over sizes > threshold (m, > 0; 75e-6 in Sec. 5.3.1,
/// Hardin's No. 200 sieve 0.074 mm). Throws std::invalid_argument if the initial curve has no
/// breakage potential (all its mass at or below the threshold) or on invalid curves.
HardinBreakage hardin_breakage(const GrainSizeCurve& initial, const GrainSizeCurve& current,
                               double threshold);

}  // namespace kolsky::psd
