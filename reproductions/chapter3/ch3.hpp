// Chapter 3 reproduction helpers: one coupled FE-DEM (or reduced-model) SHPB case built from
// the set's scene JSON plus a JSON merge patch (the studies file names every variant as data),
// and what Sec. 3.4 measures on it: the stress-strain slope over 2-6 % strain, the curve up to
// the 13 MPa cut-off (Secs. 3.3, 3.4.1: LS-DYNA's DES cannot break grains, so the text stops
// there) and the agreement of the two face stresses (Fig. 3.4).
#pragma once
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "harness/case_pipeline.hpp"
#include "harness/targets.hpp"

namespace kolsky::ch3 {

/// One case (harness/case_pipeline.hpp): the set's scene with a study's changes. The face
/// records (faces) are the specimen's own; the energy balance is read off them too.
struct CaseResult : harness::CaseOutputs {
  std::vector<double> energy_error_if, delivered_if;  ///< held - delivered, delivered (J), on faces.t
  double off_axis = NAN;          ///< largest face lateral / axial contact resultant (coupled only)
  // What the specimen's momentum balance needs (measure(): face_inertia_ratio).
  double mass_per_area = NAN;     ///< kg/m^2, grain mass over the face area (rho_s (1 - n) L)
  double z_incident = NAN, z_transmission = NAN;  ///< Pa s/m, the bars' impedances sqrt(E rho)
  std::vector<double> incident_if;  ///< Pa, the incident pulse at the face on faces.t
};

/// Runs one case; never throws for a run that fails (ok = false, failure = why), rethrows
/// kolsky::InputError for a scene the reader refuses (the driver exits 2 with it).
CaseResult run_case(const harness::Case& c);

/// Sec. 3.4 measurements on one case, on the face records (back-face stress from the summed
/// contact forces, strain from the face displacements; the bar-gauge slope beside it),
/// truncated at the first sample where the back-face stress reaches `cutoff` (13 MPa).
struct Measures {
  long i_end = -1;                ///< one past the last sample used
  bool reached_cutoff = false;
  double strain_at_cutoff = NAN, time_at_cutoff = NAN;  ///< time after the incident arrival, s
  double slope = NAN;             ///< Pa: least-squares back-face stress vs strain, [eps_lo, eps_hi]
  double slope_gauges = NAN;      ///< Pa: the same from the bar-gauge analysis (NaN: not covered)
  long slope_points = 0;
  double strain_rate = NAN;       ///< 1/s, mean Eq. 1.3 over the slope window
  double energy_error = NAN;      ///< max |held - delivered| to the cut-off / delivered there
  double face_gap_max = NAN;      ///< Pa, max |front - back| face stress after the ringing time
  double face_alpha_max = NAN;    ///< max |front - back| / mean of the two, same window
  double ringing_end = NAN;       ///< s after the arrival where the window of face_gap starts
  double stress_at_ringing_end = NAN;  ///< Pa, back face there
  /// Before the ringing time, the measured front - back gap over the gap the specimen's
  /// momentum needs (face_inertia_gap), summed over the samples where that is at least half its
  /// largest: 1 when the early gap is the inertia of the specimen accelerated by the pulse's rise.
  double face_inertia_ratio = NAN;
  double face_inertia_gap_max = NAN;  ///< Pa, largest predicted gap before the ringing time
};
Measures measure(const CaseResult& c, double eps_lo, double eps_hi, double cutoff,
                 double ringing_time);

/// The front - back face stress the specimen's momentum needs with frictionless walls and a
/// linear velocity profile (the uniform strain SHPB assumes): v_front = (2 s_I - s_f) / Z_I,
/// v_back = s_b / Z_T, P / A = (m / A) (v_front + v_back) / 2, so
///   s_f - s_b = (m / 2A) (2 ds_I/dt / Z_I - ds_f/dt / Z_I + ds_b/dt / Z_T),
/// the rates by central differences over +-half_width (smoothing the grains' force noise).
std::vector<double> face_inertia_gap(const CaseResult& c, double half_width);

/// The back-face stress-strain curve up to the cut-off, for plots and comparisons.
harness::Curve curve_to_cutoff(const CaseResult& c, const Measures& m);

/// RMS difference of two back-face stress-strain curves at equal strain over [lo, hi], hi
/// lowered to the smaller of the two curves' strains at the cut-off (Pa; NaN: no overlap).
double curve_rms_difference(const CaseResult& a, const Measures& ma, const CaseResult& b,
                            const Measures& mb, double lo, double hi);

nlohmann::json read_json(const std::string& path);

}  // namespace kolsky::ch3
