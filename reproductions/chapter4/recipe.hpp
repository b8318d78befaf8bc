// The Chapter 4 set as a recipe of numbered steps (issue 32; the shape of the Laghos and MFEM
// example drivers): driver.cpp's main calls them in order, each a few dozen lines in one of
// the steps_*.cpp files, and Recipe carries what one step hands to the later ones. The order
// is the report's: every measurement, table and plot is made in the order the set always
// made it, so results.json, report.md and the plots read as before the split.
#pragma once
#include <cmath>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "chapter4/calibration.hpp"
#include "chapter4/ch4.hpp"
#include "common/driver_args.hpp"
#include "common/format.hpp"
#include "dem/packing_cache.hpp"
#include "harness/case_pipeline.hpp"
#include "harness/report.hpp"

namespace kolsky::ch4 {

inline std::string mpa(double pa) { return repro::fmt("%.1f MPa", pa / 1e6); }

struct Recipe {
  // 1. Inputs.
  repro::DriverArgs args;
  bool smoke = false;
  harness::ReportInput rep;        ///< measurements, plots and preamble of the report
  nlohmann::json targets, studies; ///< targets(_smoke).json, studies.json
  double tie_stiffest = 0, tie_softest = 0, tie_arrival = 0, tie_alpha = 0;  ///< tie_rtol
  double limit = 10e6;             ///< Pa, the comparison's back stress (Sec. 4.4.1)
  double threshold = 0.05;         ///< alpha of equilibrium (Eq. 4.15)
  double k_cal = 1;                ///< the printed rotational factor per 1 ns (Sec. 4.3)
  CalSettings cal_set;
  harness::Case set_case;          ///< the set's scene, packing cache, diagnostic overrides
  std::string override_note;       ///< the report's note of those overrides ("" when none)
  double upscale = 2;              ///< N of the set's scene
  // 2. Packing.
  dem::CachedPacking packing;
  double pack_s = 0;
  // 3. Twin experiment.
  Calibration twin;
  std::string twin_md;
  // 4. Cases: the printed k first, then the rotational family.
  std::vector<CaseResult> cases;
  std::vector<Measures> ms;
  long i0 = -1, i1 = -1;           ///< index of k = 0 and k = 1 among the cases (-1: not run)
  std::string family_md;
  // 7. Back-calculation of k.
  Calibration cal;
  std::string cal_md;
  // 8. Jammed diagnostic specimen.
  std::vector<CaseResult> jam;
  std::vector<Measures> jam_m;
  double jam_porosity = NAN;
  std::string jam_md;
  // 10, 11. Upscaling and packing-seed studies.
  std::string upscaling_md, scatter_md;

  harness::Measurements& m() { return rep.m; }
  const CaseResult& printed() const { return cases.front(); }
  const Measures& printed_m() const { return ms.front(); }
  /// sigma_t samples of the printed case up to its first 10 MPa sample (all without one).
  long printed_end() const {
    return printed_m().i_end > 0 ? printed_m().i_end : static_cast<long>(printed().history.t.size());
  }
};

/// KOLSKY_CH4_STUDIES ("twin,calibration,jammed" by default; "" for none) names the studies
/// beyond the printed cases (README, "The rotational factor back-calculated").
bool study_on(const std::string& name);

/// One case of a back-calculation (twin or real): run, measured, printed, as a CalPoint.
CalPoint run_point(const Recipe& r, const harness::Case& c, double k, const std::string& label);

/// Mean alpha over the time window every case covers (the latest 1 MPa start to the earliest
/// 10 MPa end), written into each Measures::alpha_mean, so a case reaching 10 MPa sooner is not
/// judged on less of the (decreasing) alpha history. When the windows do not overlap (k = 0
/// reaches 10 MPa before a softer case reaches 1 MPa), each case keeps its own 1-10 MPa window
/// (equal stress levels instead of times) and the function returns false.
bool common_window_alpha(const std::vector<CaseResult>& cases, std::vector<Measures>& ms, double& t_a,
                         double& t_b);

Recipe read_inputs(const repro::DriverArgs& args);  // 1
void pack_specimen(Recipe& r);                      // 2
void twin_experiment(Recipe& r);                    // 3
void run_family(Recipe& r);                         // 4
void measure_printed(Recipe& r);                    // 5: Sec. 4.4.1
void rotation_orderings(Recipe& r);                 // 6: Sec. 4.4.2
void back_calculate_k(Recipe& r);                   // 7
void jammed_specimen(Recipe& r);                    // 8
void case_plots(Recipe& r);                         // 9
void upscaling(Recipe& r);                          // 10
void seed_scatter(Recipe& r);                       // 11
void calibration_plots(Recipe& r);                  // 12
int write_report(Recipe& r, double wall_s);         // 13: the set's exit status

}  // namespace kolsky::ch4
