// From raw strain-gauge records to face-referred waves: what real lab data needs.
//  1. Pre-trigger offset: mean of the samples before the incident pulse, removed per channel.
//  2. Pulse start: first sample where |incident| exceeds max(threshold_fraction * peak,
//     noise_sigmas * sigma_noise), then walked back to where the rising edge leaves the noise
//     (documented in docs/analysis.md).
//  3. Window separation at the incident gauge: the reflected wave arrives at start + 2 d_I / c;
//     incident = record before the middle of the quiet gap between the incident's end and that
//     arrival, reflected = record after it (the pulse must be shorter than 2 d_I / c; else the
//     split is at the arrival itself, with a warning).
//  4. Shift to the faces by the gauge-to-face travel time (+d_I/c incident, -d_I/c reflected,
//     -d_T/c transmitted), optionally with the first Pochhammer-Chree mode dispersion
//     correction (dispersion.hpp) instead of a pure time shift.
// Input strains are as measured: compression negative. Output FaceWaves are compression
// positive (analysis.hpp).
#pragma once
#include <cstddef>
#include <stdexcept>
#include <string>
#include <vector>

#include "shpb/analysis.hpp"

namespace kolsky::shpb {

/// A gauge record: uniform time base (s), incident- and transmission-bar gauge strains.
struct GaugeRecord {
  std::vector<double> t, incident, transmitted;
};

struct GaugeOptions {
  double threshold_fraction = 0.05;  ///< of the incident peak, for start detection
  double noise_sigmas = 5.0;         ///< detection threshold floor in units of noise sigma
  double pretrigger_fraction = 0.05; ///< fallback pre-trigger window if the pulse starts early
  bool dispersion_correction = false;
  double duration = 0.0;             ///< analysis window length after arrival; 0 = automatic
};

/// What the processing found, for the summary and the output's metadata.
struct GaugeReport {
  double offset_incident = 0, offset_transmitted = 0;   ///< removed offsets (strain, as measured)
  double noise_incident = 0, noise_transmitted = 0;     ///< pre-trigger sigma (strain)
  double start_time = 0;        ///< detected incident start at its gauge (record clock, s)
  double detection_level = 0;   ///< the strain level used for detection
  double window = 0;            ///< analysis window length (s)
  std::vector<std::string> warnings;
};

/// A rule broken at one sample of the record: what() names the 0-based row; a reader that
/// knows where the row came from (kolsky analyze: the CSV's file line) reports that instead.
struct GaugeRowError : std::invalid_argument {
  GaugeRowError(std::size_t row, const std::string& rule)
      : std::invalid_argument("process_gauges: row " + std::to_string(row) + ": " + rule),
        row(row), rule(rule) {}
  std::size_t row;
  std::string rule;
};

/// Throws std::invalid_argument on unusable input (no pulse found, ...), GaugeRowError for a
/// non-finite value or a non-uniform time step at one row.
FaceWaves process_gauges(const GaugeRecord& rec, const AnalysisSetup& setup,
                         const GaugeOptions& opt, GaugeReport* report = nullptr);

}  // namespace kolsky::shpb
