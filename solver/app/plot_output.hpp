// `--plot DIR` of `kolsky analyze` and `kolsky run`: figures of the record as PNGs in DIR
// (solver/plot/), their gnuplot scripts and data in DIR/plots_src/. gnuplot is an optional
// runtime dependency ($KOLSKY_GNUPLOT, else PATH): without it, or without a usable DIR, the
// command stops with exit 2 before doing any work, naming the option.
#pragma once
#include <string>
#include <vector>

#include "plot/gnuplot.hpp"

namespace kolsky::app {

/// Before any work: the gnuplot to use, with DIR created. Throws InputError("--plot", ...)
/// when gnuplot is missing or DIR cannot be made or written.
std::string prepare_plots(const std::string& dir);

/// Renders `figures` into dir and prints one line listing them. Throws InputError("--plot", ...)
/// naming the first figure gnuplot did not draw.
void write_plots(const std::vector<plot::Plot>& figures, const std::string& dir,
                 const std::string& gnuplot, const std::string& command);

}  // namespace kolsky::app
