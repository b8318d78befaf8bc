// The report figures are the program's (solver/plot/gnuplot.hpp): one plotting code for the
// reports, the benchmark summary and `kolsky analyze|run --plot`. The drivers keep writing
// harness::Plot; these names are that code's, not copies.
#pragma once
#include "plot/gnuplot.hpp"

namespace kolsky::harness {

using plot::default_gnuplot;
using plot::Plot;
using plot::PlotBand;
using plot::PlotPoints;
using plot::PlotResult;
using plot::PlotSeries;
using plot::render_plot;

}  // namespace kolsky::harness
