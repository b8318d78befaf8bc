// `kolsky sweep --plot DIR`: one figure per summary figure of the table (sweep_table.hpp),
// against the first key given more than one value (against the seed when only seeds vary). The
// members that share the other varied keys' values are one group: each member as a point (the seed scatter), and per value
// of the first key the group's mean with +- one standard deviation bars (the sample sd over
// the seeds; drawn when some value has more than one member). Failed members are left out. A
// first key whose values are not numbers is drawn at 1, 2, ... with the values in the axis label.
#pragma once
#include <string>
#include <vector>

#include "plot/gnuplot.hpp"
#include "sweep/sweep_table.hpp"

namespace kolsky::sweep {

/// The figures, files "sweep_<figure>.png"; `source` (the scene file) ends every title.
std::vector<plot::Plot> sweep_figures(const SweepTable& t, const std::string& source);

}  // namespace kolsky::sweep
