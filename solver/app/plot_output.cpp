#include "app/plot_output.hpp"

#include <unistd.h>

#include <cstdio>
#include <filesystem>

#include "core/errors.hpp"

namespace kolsky::app {

std::string prepare_plots(const std::string& dir) {
  std::string gnuplot = plot::default_gnuplot();
  if (const std::string missing = plot::gnuplot_missing(gnuplot); !missing.empty())
    throw InputError("--plot", "", missing + ": install gnuplot (scripts/install-deps.sh), set "
                                             "KOLSKY_GNUPLOT to its path, or leave out --plot");
  std::error_code ec;
  std::filesystem::create_directories(dir, ec);
  if (ec || !std::filesystem::is_directory(dir) || access(dir.c_str(), W_OK) != 0)
    throw InputError("--plot", "", "cannot create or write the folder '" + dir + "'" +
                                       (ec ? ": " + ec.message() : std::string()));
  return gnuplot;
}

void write_plots(const std::vector<plot::Plot>& figures, const std::string& dir,
                 const std::string& gnuplot, const std::string& command) {
  std::string written;
  for (const plot::Plot& p : figures) {
    const plot::PlotResult r = plot::render_plot(p, dir, gnuplot);
    if (!r.ok) throw InputError("--plot", p.file, r.message);
    written += (written.empty() ? "" : ", ") + p.file;
  }
  std::printf("kolsky %s: plots -> %s/ (%s)\n", command.c_str(), dir.c_str(), written.c_str());
}

}  // namespace kolsky::app
