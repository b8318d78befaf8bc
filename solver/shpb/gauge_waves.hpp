// Face waves from simulated gauge records by the 1-D shift, for bars whose face waves are not
// known exactly (meshed bars): what the classic analysis does with lab records (Eqs. 1.1-1.3
// assume 1-D waves travelling at c0 = sqrt(E/rho) without change of shape).
//   incident at the face at t:    -E g_I(t - d_I/c0), while t < t_a + 2 d_I/c0 (before the
//                                 reflected wave reaches the gauge), t_a = L_I/c0 the arrival
//   reflected at the face at t:   -E g_I(t + d_I/c0) for t >= t_a, 0 before
//   transmitted at the face at t: -E g_T(t + d_T/c0)
// g as measured (compression negative); waves compression positive (Pa). Linear interpolation
// in the uniformly sampled record; NaN where the shifted time lies beyond its end. No
// dispersion correction (dispersion.hpp has one): the difference to the exact 1-D face waves
// is what the bars' 3-D behaviour does to a classic analysis.
#pragma once
#include "shpb/experiment.hpp"
#include "shpb/run_result.hpp"

namespace kolsky::shpb {

/// Fills the probes wave_incident, wave_reflected, wave_transmitted (Pa) and w_incident,
/// w_reflected, w_transmitted (J, Eqs. 2.11-2.13, cumulative trapezoid; NaN once a wave is)
/// of r from its first incident and transmission gauge probes.
void waves_from_gauges(RunResult& r, const BarSpec& incident, const BarSpec& transmission);

}  // namespace kolsky::shpb
