// Figures through gnuplot, for the reproduction reports, the benchmark summary and
// `kolsky analyze|run --plot`: one .dat + .gp pair per plot in <out_dir>/plots_src/ (kept so a
// reader can edit and re-run them), rendered to <out_dir>/<file>.png with pngcairo 900x600.
// gnuplot is an optional runtime dependency: it is looked up when a figure is drawn
// (default_gnuplot), so a build without it works and a later install is picked up.
// Above the physics (docs/architecture.md): no physics module includes plotting.
#pragma once
#include <string>
#include <vector>

namespace kolsky::plot {

/// A measured or computed line. style: "lines" | "points" | "linespoints" | "dashed" | "steps".
struct PlotSeries {
  std::string label;
  std::vector<double> x, y;
  std::string style = "lines";
};

/// A shaded band lo(x)..hi(x) (tolerance envelope, experimental scatter, a time window).
struct PlotBand {
  std::string label;
  std::vector<double> x, lo, hi;
};

/// Reference points, with symmetric y error bars when yerr is non-empty (same length as x),
/// and each point annotated with its text when point_labels is non-empty (same length).
struct PlotPoints {
  std::string label;
  std::vector<double> x, y, yerr;
  std::vector<std::string> point_labels;
};

struct Plot {
  std::string file;  // "stress_strain.png": a plain file name in out_dir, ending in .png
  std::string title, xlabel, ylabel;
  std::vector<PlotSeries> series;
  std::vector<PlotBand> bands;
  std::vector<PlotPoints> reference_points;
  bool logx = false, logy = false;
};

/// Outcome of one plot: ok, or why not (shown in the report instead of the image).
struct PlotResult {
  bool ok = false;
  std::string message;
};

/// Colour-blind-safe cycle (Okabe-Ito) of every figure, in drawing order.
inline constexpr const char* kPlotColours[] = {"#0072B2", "#D55E00", "#009E73", "#CC79A7",
                                               "#E69F00", "#56B4E9", "#000000", "#F0E442"};
/// A gnuplot single-quoted string: '' for a quote, line breaks as spaces.
std::string gnuplot_quote(const std::string& s);

/// The gnuplot to run: $KOLSKY_GNUPLOT when set (empty: plotting off; a test points it at a
/// missing path), else the first executable `gnuplot` on $PATH, else "".
std::string default_gnuplot();

/// "" when `gnuplot` names an executable file, else why not ("gnuplot not available at X").
std::string gnuplot_missing(const std::string& gnuplot);

/// The stem of a plot file name: "a.png" -> "a". Throws std::invalid_argument unless the name
/// is plain ([A-Za-z0-9_.-], no leading dot) and ends in .png (no writing outside out_dir).
std::string png_stem(const std::string& file);

/// Writes out_dir/plots_src/<stem>.{dat,gp} and, when gnuplot is a usable executable, renders
/// out_dir/<file> (written to a temporary name and renamed, so a failed run leaves no half PNG).
/// Throws std::invalid_argument for a bad file name or mismatched vector lengths (caller bugs);
/// gnuplot failures are returned, with the tail of its output, not thrown.
PlotResult render_plot(const Plot& p, const std::string& out_dir, const std::string& gnuplot);

/// Renders out_dir/plots_src/<stem>.gp (which sets `outfile` unless given) to out_dir/<png>:
/// gnuplot by fork/exec in plots_src/ (no shell parses labels or paths), the PNG written under a
/// temporary name and renamed. Returns "" on success, else why not (gnuplot missing, its exit
/// status and the tail of its log, no image). Shared by render_plot and the benchmark summary.
std::string render_script(const std::string& gnuplot, const std::string& out_dir,
                          const std::string& stem, const std::string& png);

}  // namespace kolsky::plot
