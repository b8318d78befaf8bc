// Human-readable summaries of an analysed SHPB record (shared by `run` and `analyze`).
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "shpb/analysis.hpp"

namespace kolsky::app {

/// Key numbers of an analysed record: peak stresses, final strain, mean strain rate over the
/// loading window, first time alpha stays below 0.05, energies and dissipation, indices.
/// A history without wave energies (a direct analysis, shpb::analyze_faces; w empty) gets the
/// stress-only indices and the average and back stresses at the peak strain instead.
nlohmann::json summarize(const shpb::FaceWaves& w, const shpb::SpecimenHistory& h);
/// Plain-text rendering, one quantity per line.
std::string format_summary(const nlohmann::json& s);

}  // namespace kolsky::app
