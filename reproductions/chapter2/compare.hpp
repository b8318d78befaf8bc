// Chapter 2 comparisons on top of the calibrated dry EOS:
//   bar model: the polycarbonate 480/s case with the 1-D characteristic bars and with meshed
//     (axisymmetric FE) bars, both analysed classically from their face waves (meshed: from the
//     surface gauges by the 1-D shift); max / RMS stress difference at equal strain over the
//     slope window and the slope difference (docs/fe.md "Meshed bars");
//   rate independence (Sec. 2.3.4): the stress up to which the 900/s curve stays within a
//     tolerance of the 480/s curve at equal strain (target ch2.rate_independence_limit);
//   mesh refinement: specimen meshes halving the element size against the slope (speed vs
//     error table and plot).
// Each records its measurements, appends its plots and a markdown table to the summary.
#pragma once
#include <utility>
#include <vector>

#include "chapter2/studies.hpp"

namespace kolsky::ch2 {

struct BarComparisonSettings {
  int mesh_radial = 4;            ///< meshed bars: radial elements
  double element_length = 2e-3;   ///< meshed bars: axial element length, m
};

/// Runs `spec` (its eos set) with characteristic and with meshed bars.
void bar_model_comparison(const StudyContext& ctx, CaseSpec spec, const BarComparisonSettings& s);

/// 480/s vs 900/s histories (calibrated EOS, polycarbonate): target ch2.rate_independence_limit.
void rate_independence(const StudyContext& ctx, const shpb::SpecimenHistory& h480,
                       const shpb::SpecimenHistory& h900);

/// Specimen meshes (n_radial, n_axial), coarse to fine, for `spec` (its eos set).
void mesh_refinement_study(const StudyContext& ctx, CaseSpec spec, const std::vector<std::pair<int, int>>& meshes);

/// Stress (Pa) of history h at strain e along its loading branch (up to the peak strain, t <=
/// t_end), linear in strain; NaN outside the branch.
double stress_at_strain(const shpb::SpecimenHistory& h, double e, double t_end);

}  // namespace kolsky::ch2
