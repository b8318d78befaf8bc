// One case pipeline for every reproduction set (issue 32): a case is a set's scene file plus
// a list of changes (dotted key = JSON value), a label and where its packings are cached;
// running it applies the changes, builds the scene through the solver's public API
// (scene::parse_scene, shpb::SimulatedShpb), runs it, analyses it, and hands back what the
// sets measure through named fields: the run's probes, the bar-gauge analysis (Eqs. 1.1-1.4 on
// the face waves), the face records from the incident arrival, the DEM specimen's final state,
// and the wall times. No hook is bent to another use and nothing reaches into the assembly.
//
// A case also has a content key (content_key): FNV-1a over the final scene's JSON text and the
// binary's version, the identity by which the ensemble layer (issue 33) caches members.
// The packing cache's folder is left out of it (it says where packings are kept, not what is
// run); files a scene names by path (a loading table) enter by their path, not their bytes.
#pragma once
#include <cmath>
#include <cstddef>
#include <exception>
#include <functional>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "dem/packing_cache.hpp"
#include "psd/grain_size_curve.hpp"
#include "scene/scene_change.hpp"
#include "shpb/analysis.hpp"
#include "shpb/run_result.hpp"

namespace kolsky::harness {

// The changes and the content key live in the scene module (scene/scene_change.hpp), shared
// with `kolsky sweep`; the sets name them through the harness as they always have.
using scene::apply_change;
using scene::binary_version;
using scene::changes_from_patch;
using scene::parse_change;
using scene::SceneChange;

struct Case {
  std::string label;
  std::string scene_path;      ///< the set's scene file: named in messages; relative paths in the
                               ///< scene resolve against its folder
  nlohmann::json scene;        ///< that file's JSON as read (moved by one ulp for `make rebaseline`)
  std::vector<SceneChange> changes;  ///< applied in order, after packing_cache
  std::string packing_cache;   ///< specimen.packing_cache (made absolute); "" keeps the scene's
  /// Seconds between grain-size curves of a specimen whose grains break (0: none).
  double grain_size_curve_every = 0;
  /// Progress lines on stdout, headed by the label: one per 1/progress_lines of the run (0:
  /// none), for runs of minutes to an hour.
  int progress_lines = 0;

  /// This case with one more change (the studies' variants of a set's case).
  Case with(const std::string& key, const nlohmann::json& value, const std::string& new_label) const;
};

/// The scene the case runs: its JSON with packing_cache and every change applied. Throws
/// InputError(scene_path, key, ...) naming the change whose path cannot be followed (a part
/// that is empty, or a value on the way that is not an object).
nlohmann::json final_scene(const Case& c);

/// The folder a case's relative paths resolve against (its scene file's).
std::string scene_dir(const Case& c);

/// Parses final_scene(c) as the solver does, without building anything (no packing, no
/// step): InputError for a bad change or a scene the reader refuses.
void validate(const Case& c);

/// scene::content_key of the final scene: the same case, however its changes are written, has
/// the same key.
std::string content_key(const Case& c);

/// The packing of a DEM case, through its cache, with a progress line headed by the case's
/// label every 10 stages and every 20 pre-stress servo intervals while it packs (a full-scale
/// packing takes minutes). InputError for a case whose specimen is not DEM.
dem::CachedPacking pack(const Case& c);

/// The key its packing is cached under (dem::packing_cache_key): cases with the same key share
/// one packing, which an ensemble can make once before they run. "" for a case whose specimen
/// is not DEM; InputError for a scene the reader refuses.
std::string packing_key(const Case& c);

/// The specimen's face records (interface probes) from the incident arrival on, t = 0 there.
struct FaceRecord {
  std::vector<double> t;       ///< s after the arrival
  std::vector<double> front;   ///< stress_front: incident-side wall force / area, Pa
  std::vector<double> back;    ///< stress_back: transmission-side wall force / area, Pa
  std::vector<double> strain;  ///< specimen_strain from the face displacements
};

/// The DEM specimen after the run (grains 0: the specimen is not DEM).
struct DemFinalState {
  std::size_t grains = 0;
  long held_steps = 0;         ///< steps the grains were held as packed (hold_until_loaded)
  double porosity = NAN;       ///< 1 - grain volume / tube volume between the end walls
  double grain_volume = NAN;   ///< m^3, the grains' summed volume
  double face_area = NAN;      ///< m^2, the specimen's cross-section
};

/// A grain-size curve of the specimen at time t (Case::grain_size_curve_every).
struct CurveAt {
  double t = 0;
  psd::GrainSizeCurve curve;
};

/// The stresses at the bar gauges (1-D bars with gauges), on the run's clock (from the start
/// of loading at the incident bar's far end): -strain x the bar's E, Pa (compression positive).
struct GaugeRecord {
  std::vector<double> t, incident, transmission;
};

struct CaseOutputs {
  std::string label;
  std::string content_key;
  bool ok = false;             ///< the run completed (its analysis may still have failed)
  std::string failure;         ///< why not
  /// The InputError the solver refused the scene with (failure holds its text), for a driver
  /// that exits 2 on it; empty for every other failure.
  std::exception_ptr refusal;
  shpb::RunResult run;         ///< every probe, t, dt, steps, arrival_time
  shpb::SpecimenHistory history;  ///< bar-gauge analysis, t = 0 at the incident arrival
  shpb::FaceWaves waves;       ///< the face-referred bar waves that analysis read (none for walls)
  std::string analysis_failure;   ///< why history is empty for a completed run
  FaceRecord faces;            ///< filled for a completed run
  DemFinalState dem;
  std::vector<CurveAt> curves; ///< on the run's clock
  GaugeRecord gauges;          ///< filled when the run has gauge probes
  double wall_s = 0;           ///< the whole case: scene, packing (or its cache), run, analysis
  double build_s = 0;          ///< its part up to the built simulation: scene, packing (or its cache)
  double run_s = 0;            ///< the time loop alone
};

/// Runs one case. Never throws: a refused scene, a failed build or an incomplete run comes
/// back with ok = false and its failure (refusal set for an InputError).
CaseOutputs run_case(const Case& c);

/// The values of `probe` at the samples of the face record (t >= arrival).
std::vector<double> from_arrival(const shpb::RunResult& run, const std::string& probe);

/// The values of `probe` at the samples of the analysis (history.t, t = 0 at the incident
/// arrival), linear between the run's samples and held at its ends.
std::vector<double> on_history(const CaseOutputs& out, const std::string& probe);

}  // namespace kolsky::harness
