// Chapter 4 reproduction helpers: one DEM SHPB case (the set's scene JSON with a variant
// rolling factor), and the measurements of Sec. 4.4 on it, truncated where the back-face stress
// first reaches the comparison limit (10 MPa, Sec. 4.4.1).
#pragma once
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dem/particles.hpp"
#include "harness/case_pipeline.hpp"

namespace kolsky::ch4 {

/// One case of the set (harness/case_pipeline.hpp) at a rolling factor k. ok: the run
/// completed and its bar-gauge analysis ran (a case without sigma_t(strain) measures nothing).
struct CaseResult : harness::CaseOutputs {
  double rolling_factor = 1;
};

/// Runs `base` (the set's case, changed as a study needs) with specimen.rolling_factor = k.
CaseResult run_case(const harness::Case& base, double k, const std::string& label);

/// What Sec. 4.4 compares, on one case, up to the first sample with back stress >= limit.
struct Measures {
  long i_lo = -1, i_end = -1;      ///< bar-gauge samples: first >= lo_stress, first >= limit
  bool reached_limit = false;
  double max_back = 0;             ///< Pa, largest bar-gauge back stress in the run
  double modulus_initial = NAN;    ///< Pa, fit of stress_back vs strain, back in [lo, mid]
  double modulus_late = NAN;       ///< Pa, fit over back stress in [0.7 limit, limit]
  double modulus_back = NAN;       ///< Pa, fit over [lo, limit] (whole comparison window)
  double modulus_avg = NAN;        ///< Pa, same window, stress_avg (Eq. 4.16)
  double modulus_back_if = NAN, modulus_avg_if = NAN;  ///< interface-probe versions
  double alpha_min = NAN, alpha_first = NAN, alpha_last = NAN, alpha_mean = NAN;
  double back_arrival = NAN;       ///< s after the incident arrival: back interface stress
                                   ///< first exceeds its initial value by 0.2 MPa
  double time_at_limit = NAN;      ///< s after the incident arrival
};
Measures measure(const CaseResult& c, double lo_stress, double mid_stress, double limit);

/// Solid fraction of a packing in its core (at least one largest-grain diameter from every
/// wall) and as a whole, by the lattice count of dem/wall_layer.hpp at a spacing of a third of
/// the smallest radius (relative error ~3e-4, test_dem_wall_layer.cpp). The walls hold a looser
/// layer, so at a fixed porosity the core is denser the coarser the grains (README, "What the
/// toe is"). `j` gives the cylinder (specimen.diameter, specimen.length).
struct WallLayer {
  double whole = NAN, core = NAN;  ///< solid fractions
  double core_share = NAN;         ///< share of the specimen volume in the core
};
WallLayer wall_layer(const nlohmann::json& j, const dem::Particles& p);

nlohmann::json read_json(const std::string& path);
/// "0,0.999,1" -> {0, 0.999, 1}; "" -> {} (environment overrides of the driver's lists).
std::vector<double> parse_list(const std::string& text);
/// Applies "dotted.key=JSON;dotted.key=JSON" (KOLSKY_CH4_SET; null or "": nothing) to the
/// case as changes and returns the report's note naming them ("" when none). Throws
/// InputError for an item without '=' or a value that is not JSON.
std::string apply_scene_overrides(harness::Case& c, const char* overrides);
std::vector<double> scaled(const std::vector<double>& v, double f, long n = -1);
/// Reference value of a target in targets.json (its "value", in the file's unit).
double reference_value(const nlohmann::json& targets, const std::string& id);

}  // namespace kolsky::ch4
