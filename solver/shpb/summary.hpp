// The key numbers of an analysed SHPB record: what `kolsky run` and `kolsky analyze` print,
// and the figures `kolsky sweep` tabulates for each member.
#pragma once
#include <nlohmann/json.hpp>
#include <string>

#include "shpb/analysis.hpp"

namespace kolsky::shpb {

/// Key numbers of an analysed record: peak stresses, final strain, mean strain rate over the
/// loading window, first time alpha stays below 0.05, energies and dissipation, indices.
/// A history without wave energies (a direct analysis, analyze_faces; w empty) gets the
/// stress-only indices and the average and back stresses at the peak strain instead.
nlohmann::json summarize(const FaceWaves& w, const SpecimenHistory& h);
/// Plain-text rendering, one quantity per line.
std::string format_summary(const nlohmann::json& s);

}  // namespace kolsky::shpb
