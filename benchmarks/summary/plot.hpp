// Figures of the benchmark summary through gnuplot, with solver/plot/gnuplot.hpp: a .dat + .gp
// pair per figure kept in <out>/plots_src/ (a reader can edit and re-run them), rendered by
// plot::render_script. plot::Plot has no labelled x ticks and no second y axis, which the
// over-commits figures need, hence this small variant of the script writer.
#pragma once
#include <string>
#include <vector>

namespace kolsky::benchsum {

struct Series {
  std::string label;
  std::vector<double> x, y;
  std::string style = "linespoints";  ///< "linespoints", "points" (filled), "open" (circles), "dashed"
  bool y2 = false;                    ///< on the right-hand axis
};

struct Figure {
  std::string file;  ///< plain name ending in .png
  std::string title, xlabel, ylabel, y2label;
  std::vector<std::string> xtics;  ///< when set: x = 0, 1, ... labelled by these, rotated
  std::vector<Series> series;      ///< empty series are left out
  bool logx = false, logy = false;
  std::string key = "top left";  ///< gnuplot key position, inside the plot
  std::string extra;             ///< further gnuplot lines (ranges, tics), before the plot command
};

struct RenderResult {
  bool ok = false;
  std::string message;  ///< why not, when !ok
};

/// The .gp script of `f` reading <stem>.dat (exposed for the unit test).
std::string gnuplot_script(const Figure& f);

/// Writes out_dir/plots_src/<stem>.{dat,gp} and renders out_dir/<file> with `gnuplot`.
RenderResult render(const Figure& f, const std::string& out_dir, const std::string& gnuplot);

}  // namespace kolsky::benchsum
