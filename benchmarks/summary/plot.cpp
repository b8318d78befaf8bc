// See plot.hpp. Colours, quoting, file names and the gnuplot run are solver/plot's.
#include "summary/plot.hpp"

#include "core/atomic_file.hpp"
#include "plot/gnuplot.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <iterator>
#include <stdexcept>

namespace kolsky::benchsum {
namespace {

namespace fs = std::filesystem;

using plot::gnuplot_quote;
using plot::kPlotColours;

std::string num(double v) {
  char buf[40];
  return std::string(buf, std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 12).ptr);
}

std::string with_clause(const std::string& style) {
  if (style == "linespoints") return "linespoints lw 2 pt 7 ps 1.0";
  if (style == "points") return "points pt 9 ps 1.6";
  if (style == "dashed") return "lines lw 2 dt 2";
  if (style == "open") return "points pt 6 ps 1.8 lw 2";
  throw std::invalid_argument("series style '" + style + "' (valid: linespoints, points, open, dashed)");
}

bool drawable(const Series& s) {
  if (s.x.size() != s.y.size()) throw std::invalid_argument("series '" + s.label + "': x and y differ in length");
  return !s.x.empty();
}

}  // namespace

std::string gnuplot_script(const Figure& f) {
  const std::string stem = plot::png_stem(f.file);
  std::string gp = "# " + f.title + "\n# Regenerate: run `gnuplot " + stem + ".gp` in this folder; it writes ../" +
                   f.file + ".\n";
  gp += "if (!exists(\"outfile\")) outfile = " + gnuplot_quote("../" + f.file) + "\n";
  gp += "set terminal pngcairo size 1000,620 noenhanced font 'sans,11'\nset output outfile\n";
  gp += "set title " + gnuplot_quote(f.title) + "\nset xlabel " + gnuplot_quote(f.xlabel) + "\nset ylabel " + gnuplot_quote(f.ylabel) + "\n";
  gp += "set grid\nset key " + f.key + " opaque box Left reverse\n";
  if (f.logx) gp += "set logscale x\n";
  if (f.logy) gp += "set logscale y\n";
  if (!f.xtics.empty()) {
    gp += "set xrange [-0.5:" + num(static_cast<double>(f.xtics.size()) - 0.5) + "]\nset xtics rotate by 35 right (";
    for (std::size_t i = 0; i < f.xtics.size(); ++i)
      gp += (i ? ", " : "") + gnuplot_quote(f.xtics[i]) + " " + std::to_string(i);
    gp += ")\n";
  }
  bool any_y2 = false;
  double max1 = 0, max2 = 0;
  for (const Series& s : f.series) {
    any_y2 = any_y2 || (s.y2 && drawable(s));
    for (double v : s.y) (s.y2 ? max2 : max1) = std::max(s.y2 ? max2 : max1, v);
  }
  if (any_y2) gp += "set ytics nomirror\nset y2tics\nset y2label " + gnuplot_quote(f.y2label) + "\n";
  // Linear axes from zero, so that a difference looks as large as it is, and up to 1.5 x the
  // largest value, so that the key in the top corner covers no point.
  if (!f.logy) {
    if (max1 > 0) gp += "set yrange [0:" + num(1.5 * max1) + "]\n";
    if (max2 > 0) gp += "set y2range [0:" + num(1.5 * max2) + "]\n";
  }
  gp += f.extra;
  std::string plot;
  std::size_t block = 0;
  for (std::size_t k = 0; k < f.series.size(); ++k) {
    const Series& s = f.series[k];
    if (!drawable(s)) continue;
    plot += (plot.empty() ? "plot " : ", \\\n     ") + gnuplot_quote(stem + ".dat") + " index " + std::to_string(block++) +
            " using 1:2" + (s.y2 ? " axes x1y2" : "") + " with " + with_clause(s.style) + " lc rgb '" +
            kPlotColours[k % std::size(kPlotColours)] + "' title " + gnuplot_quote(s.label);
  }
  return gp + (plot.empty() ? "# nothing to plot" : plot) + "\n";
}

RenderResult render(const Figure& f, const std::string& out_dir, const std::string& gnuplot) {
  const std::string stem = plot::png_stem(f.file);
  const fs::path src = fs::path(out_dir) / "plots_src";
  fs::create_directories(src);
  std::string dat;
  bool any = false;
  for (const Series& s : f.series) {
    if (!drawable(s)) continue;
    any = true;
    dat += "# " + s.label + "\n";
    for (std::size_t i = 0; i < s.x.size(); ++i) dat += num(s.x[i]) + " " + num(s.y[i]) + "\n";
    dat += "\n\n";  // two blank lines end a gnuplot data block (index)
  }
  write_file_atomic((src / (stem + ".dat")).string(), dat);
  write_file_atomic((src / (stem + ".gp")).string(), gnuplot_script(f));
  if (!any) return {false, "not generated: no data"};
  const std::string why = plot::render_script(gnuplot, out_dir, stem, f.file);
  return {why.empty(), why.empty() ? "" : "not generated: " + why};
}

}  // namespace kolsky::benchsum
