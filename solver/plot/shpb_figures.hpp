// The figures of one SHPB record, for `kolsky analyze --plot` and `kolsky run --plot`: raw gauge
// records (with the detected pulse windows and removed offsets when they were processed), the
// face-referred waves, strain rate (Eq. 1.3), front/back/average stress against strain
// (Eqs. 1.1, 1.2, 4.16), alpha(t) with the 0.05 equilibrium line (Eq. 2.15) and the wave
// energies (Eqs. 2.11-2.13). A simulated run adds one figure per further probe its assembly
// declares (face velocities, energy ledger, DEM coordination and kinetic energy, ...).
// Axes in us, microstrain, MPa, 1/s, J; every title ends with the input file.
#pragma once
#include <string>
#include <vector>

#include "plot/gnuplot.hpp"
#include "shpb/analysis.hpp"
#include "shpb/gauge_processing.hpp"
#include "shpb/run_result.hpp"

namespace kolsky::plot {

/// Figures of a measured record processed by shpb::process_gauges (`kolsky analyze`).
/// `source` (the gauge file) ends every title.
std::vector<Plot> analyze_figures(const shpb::GaugeRecord& rec, const shpb::GaugeReport& report,
                                  const shpb::AnalysisSetup& setup, const shpb::FaceWaves& waves,
                                  const shpb::SpecimenHistory& h, const std::string& source);

/// Figures of a simulated run (`kolsky run`): its gauge probes as recorded, the analysis of
/// its face waves, and one figure per probe not drawn there. `source`: the scene file.
std::vector<Plot> run_figures(const shpb::RunResult& r, const shpb::FaceWaves& waves,
                              const shpb::SpecimenHistory& h, const std::string& source);

}  // namespace kolsky::plot
