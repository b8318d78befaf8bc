// What a simulated SHPB test hands back: the probes (named time series on one clock) and how the
// run went. Every probe is found by its name; which names a run has depends on its assembly
// (shpb/assembly.hpp) and is fixed before the first step (SimulatedShpb::declared_probes()).
#pragma once
#include <string>
#include <vector>

#include "shpb/analysis.hpp"

namespace kolsky::shpb {

/// One sampled series on RunResult::t.
struct Probe {
  std::string name, unit, description;
  std::vector<double> value;
};

struct RunResult {
  std::vector<double> t;       ///< s, from the start of loading at the incident bar's far end
  std::vector<Probe> probes;   ///< in the order the assembly declared them (the HDF5 order)
  bool complete = true;
  std::string failure;         ///< why the run stopped early (empty when complete)
  /// Set when a complete run ended before time.end by its scene's rule
  /// (loading.end_at_back_stress): what was reached, and when.
  std::string ended_by;
  double dt = 0, stable_dt = 0, arrival_time = 0;  ///< dt, stable_dt: as planned (s)
  long steps = 0;
  /// The step at the end (s) and how often the run refined it (time_loop::refine: a break
  /// lowered the limit); dt_final = dt when it never did.
  double dt_final = 0;
  long dt_refinements = 0;

  /// Throws std::out_of_range naming the probe and the probes this run has (a DEM probe asked
  /// of a column run, a gauge probe of a bar without gauges).
  const Probe& probe(const std::string& name) const;
  bool has_probe(const std::string& name) const;
  /// Face waves (compression-positive bar strains) with t = 0 at the incident arrival, up to
  /// the first sample where a wave is undefined (gauge-derived waves of meshed bars).
  FaceWaves face_waves(double incident_modulus, double transmission_modulus) const;
};

}  // namespace kolsky::shpb
