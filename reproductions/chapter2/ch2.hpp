// Chapter 2 reproduction helpers: one FE SHPB case, the set's scene with the study's variant
// keys changed (the compaction EOS table too, as a CSV file the scene names), run and analysed
// through the sets' case pipeline (harness/case_pipeline.hpp), and the measurements the
// studies share (slope, plateau rate, equilibrium time, dissipation at a strain).
#pragma once
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "core/table.hpp"
#include "shpb/analysis.hpp"

namespace kolsky::ch2 {

/// Confining tube (Sec. 2.3.1 materials; the wall thickness is a choice, targets.md 2d).
struct TubeSpec {
  std::string name;
  double youngs_modulus = 200e9, poisson_ratio = 0.33, density = 8100, thickness = 3.2e-3;
};

/// One SHPB case: variant keys over the base scene.
struct CaseSpec {
  std::string label;
  TubeSpec tube;
  std::string pulse_file;    ///< "" keeps the scene's pulse
  double pulse_scale = 1.0;  ///< factor on the tabulated incident stress
  double length = 0.0;       ///< specimen length, m; 0 keeps the scene's
  double friction = 0.0;     ///< Coulomb mu at both faces and the tube wall
  Table1D eos;               ///< loading table eps_v -> P (Pa), from (0, 0)
  std::string bars;          ///< bar model ("characteristic", "meshed"); "" keeps the scene's
  int bar_mesh_radial = 0;   ///< meshed bars: radial elements; 0 keeps the scene's/default
  double bar_element_length = 0;  ///< meshed bars: axial element length, m; 0 keeps
  int n_radial = 0, n_axial = 0;  ///< specimen mesh; 0 keeps the scene's
  double end_time = 0;       ///< s; 0 keeps the scene's
};

struct CaseResult {
  bool ok = false;
  std::string failure;
  shpb::SpecimenHistory h;
  double dt = 0, wall_s = 0;
  long steps = 0;
};

/// Base scene (the raw JSON, for variants), the folder its relative paths resolve against, and
/// the folder the cases' EOS tables are written to (one CSV per distinct table, named by its
/// content, written once).
struct BaseScene {
  nlohmann::json json;
  std::string path, dir;
  std::string table_dir;
};

/// Runs the case; a refused scene or a solver failure is returned in CaseResult, not thrown.
CaseResult run_case(const BaseScene& base, const CaseSpec& c);

/// Least-squares slope of stress_back (Pa) against strain over samples with t <= t_end and
/// strain in [e0, e1] during loading (before the peak strain). NaN if fewer than 3 samples.
double loading_slope(const shpb::SpecimenHistory& h, double e0, double e1, double t_end);
/// Mean of v over t in [t0, t1] (NaN if empty).
double mean_over(const std::vector<double>& t, const std::vector<double>& v, double t0, double t1);
/// Settling time (s): the start of the last run of samples with alpha < threshold that lasts to
/// t_end (alpha stays below from then on, through the loading window), or NaN if alpha is not
/// below at t_end. A first dip that rings back above the threshold does not count.
double equilibrium_time(const shpb::SpecimenHistory& h, double threshold, double t_end);
/// Value of series v at the first sample where strain reaches `strain` (NaN if never).
double at_strain(const shpb::SpecimenHistory& h, const std::vector<double>& v, double strain);

/// Reference value of a target in targets.json (its "value", in the file's unit), or of a
/// printed number in data/digitized/chapter2/reported.json (SI), whichever document is given.
double reference_value(const nlohmann::json& targets, const std::string& id);
/// Table1D from a two-column CSV (header/comment lines skipped).
Table1D read_table_csv(const std::string& path);
/// Writes the table atomically with 17 digits, then reads it back and throws if a value differs.
void write_table_csv(const std::string& path, const Table1D& t, const std::string& header);
nlohmann::json read_json(const std::string& path);
std::vector<double> scaled(const std::vector<double>& v, double f);
/// Compaction-EOS unloading modulus for a loading table: at least 1 GPa and 1.2 x its steepest
/// segment (CompactionEos requires K_u >= every loading slope).
double unloading_modulus_for(const Table1D& t);

}  // namespace kolsky::ch2
