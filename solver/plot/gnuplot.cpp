// gnuplot rendering (see gnuplot.hpp). gnuplot is run with fork/exec rather than std::system so
// that no shell parses labels or paths, and with its working directory set to plots_src/ so the
// kept script uses the same relative paths when a reader re-runs it.
#include "plot/gnuplot.hpp"

#include "core/atomic_file.hpp"

#include <fcntl.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace kolsky::plot {
namespace {

namespace fs = std::filesystem;

void put(std::string& out, double v) {
  if (!std::isfinite(v)) {
    out += "NaN";  // gnuplot leaves a gap at undefined points
    return;
  }
  char buf[40];
  out.append(buf, std::to_chars(buf, buf + sizeof buf, v, std::chars_format::general, 12).ptr);
}

/// One whitespace-separated data row.
void put_row(std::string& out, std::initializer_list<double> values) {
  bool first = true;
  for (double v : values) {
    if (!first) out += ' ';
    put(out, v);
    first = false;
  }
  out += '\n';
}

std::string style_clause(const std::string& style) {
  if (style == "lines") return "lines lw 2";
  if (style == "points") return "points pt 7 ps 0.8";
  if (style == "linespoints") return "linespoints lw 2 pt 7 ps 0.6";
  if (style == "dashed") return "lines lw 2 dt 2";
  if (style == "steps") return "steps lw 2";
  throw std::invalid_argument("plot series style '" + style +
                              "' is unknown (valid: lines, points, linespoints, dashed, steps)");
}

void require_same_size(const std::string& plot, const std::string& label,
                       std::initializer_list<const std::vector<double>*> vs) {
  for (const auto* v : vs)
    if (v->size() != (*vs.begin())->size())
      throw std::invalid_argument("plot " + plot + ", '" + label + "': vectors differ in length");
}

/// Runs `gnuplot -e "outfile='...'" script` in dir; returns "" on success or why it failed.
std::string run_gnuplot(const std::string& gnuplot, const std::string& dir,
                        const std::string& script, const std::string& outfile,
                        const std::string& log) {
  const std::string setting = "outfile=" + gnuplot_quote(outfile);
  std::vector<std::string> args = {gnuplot, "-e", setting, script};
  std::vector<char*> argv;
  for (auto& a : args) argv.push_back(a.data());
  argv.push_back(nullptr);
  const pid_t pid = fork();
  if (pid < 0) return "fork failed";
  if (pid == 0) {  // child: async-signal-safe calls only (the parent may run OpenMP threads)
    if (chdir(dir.c_str()) != 0) _exit(126);
    const int out = open(log.c_str(), O_WRONLY | O_CREAT | O_TRUNC, 0644);
    const int in = open("/dev/null", O_RDONLY);
    if (out >= 0) {
      dup2(out, STDOUT_FILENO);
      dup2(out, STDERR_FILENO);
    }
    if (in >= 0) dup2(in, STDIN_FILENO);
    execv(gnuplot.c_str(), argv.data());
    _exit(127);
  }
  int status = 0;
  while (waitpid(pid, &status, 0) < 0)
    if (errno != EINTR) return "waitpid failed";
  if (WIFEXITED(status) && WEXITSTATUS(status) == 0) return "";
  std::ifstream f(fs::path(dir) / log);
  std::stringstream ss;
  ss << f.rdbuf();
  // One line, so it fits in the report; the full log stays in plots_src/.
  std::string tail;
  for (char c : ss.str()) {
    const bool space = c == ' ' || c == '\n' || c == '\r' || c == '\t';
    if (!space) tail += c;
    else if (!tail.empty() && tail.back() != ' ') tail += ' ';
  }
  if (!tail.empty() && tail.back() == ' ') tail.pop_back();
  if (tail.size() > 300) tail = "..." + tail.substr(tail.size() - 300);
  return (WIFEXITED(status) ? "gnuplot exited with status " + std::to_string(WEXITSTATUS(status))
                            : std::string("gnuplot was killed")) +
         (tail.empty() ? "" : ": " + tail);
}

}  // namespace

std::string default_gnuplot() {
  if (const char* chosen = std::getenv("KOLSKY_GNUPLOT")) return chosen;
  const char* path = std::getenv("PATH");
  std::string dirs = path ? path : "";
  for (size_t begin = 0; begin <= dirs.size();) {
    const size_t end = std::min(dirs.find(':', begin), dirs.size());
    const std::string dir = end > begin ? dirs.substr(begin, end - begin) : ".";
    const std::string candidate = dir + "/gnuplot";
    if (access(candidate.c_str(), X_OK) == 0 && fs::is_regular_file(candidate)) return candidate;
    begin = end + 1;
  }
  return "";
}

std::string gnuplot_missing(const std::string& gnuplot) {
  if (gnuplot.empty()) return "gnuplot not available (none on PATH, KOLSKY_GNUPLOT unset or empty)";
  std::error_code ec;
  if (access(gnuplot.c_str(), X_OK) != 0 || !fs::is_regular_file(gnuplot, ec))
    return "gnuplot not available at " + gnuplot;
  return "";
}

std::string png_stem(const std::string& f) {
  const bool plain = !f.empty() && f.front() != '.' &&
                     f.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ"
                                         "0123456789_.-") == std::string::npos;
  if (!plain || f.size() <= 4 || f.compare(f.size() - 4, 4, ".png") != 0)
    throw std::invalid_argument("plot file '" + f +
                                "' must be a plain name ([A-Za-z0-9_.-]) ending in .png");
  return f.substr(0, f.size() - 4);
}

std::string gnuplot_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) {
    if (c == '\'') out += "''";
    else if (c == '\n' || c == '\r') out += ' ';
    else out += c;
  }
  return out + "'";
}

PlotResult render_plot(const Plot& p, const std::string& out_dir, const std::string& gnuplot) {
  const std::string stem = png_stem(p.file);
  const fs::path src = fs::path(out_dir) / "plots_src";
  fs::create_directories(src);

  std::string dat, plot_cmd, annotations;
  size_t block = 0, colour = 0;
  // One data block per element; empty ones are left out because gnuplot refuses an empty plot.
  const auto add_block = [&](const std::string& header, const std::string& rows,
                             const std::string& using_with, const std::string& label) {
    if (rows.empty()) return;
    dat += "# " + header + "\n" + rows + "\n\n";
    plot_cmd += (plot_cmd.empty() ? "plot " : ", \\\n     ") + gnuplot_quote(stem + ".dat") + " index " +
                std::to_string(block++) + " using " + using_with + " lc rgb '" +
                kPlotColours[colour++ % std::size(kPlotColours)] + "' title " + gnuplot_quote(label);
  };
  for (const PlotBand& b : p.bands) {
    require_same_size(p.file, b.label, {&b.x, &b.lo, &b.hi});
    std::string rows;
    for (size_t i = 0; i < b.x.size(); ++i) put_row(rows, {b.x[i], b.lo[i], b.hi[i]});
    add_block("band x lo hi: " + b.label, rows, "1:2:3 with filledcurves", b.label);
  }
  for (const PlotSeries& s : p.series) {
    require_same_size(p.file, s.label, {&s.x, &s.y});
    const std::string with = style_clause(s.style);
    std::string rows;
    for (size_t i = 0; i < s.x.size(); ++i) put_row(rows, {s.x[i], s.y[i]});
    add_block("series x y: " + s.label, rows, "1:2 with " + with, s.label);
  }
  for (const PlotPoints& r : p.reference_points) {
    require_same_size(p.file, r.label, {&r.x, &r.y});
    const bool bars = !r.yerr.empty();
    if (bars) require_same_size(p.file, r.label, {&r.x, &r.yerr});
    std::string rows;
    for (size_t i = 0; i < r.x.size(); ++i) {
      if (bars) put_row(rows, {r.x[i], r.y[i], r.yerr[i]});
      else put_row(rows, {r.x[i], r.y[i]});
    }
    add_block(std::string("reference x y") + (bars ? " yerr: " : ": ") + r.label, rows,
              bars ? "1:2:3 with yerrorbars pt 7 ps 1.2" : "1:2 with points pt 7 ps 1.2", r.label);
    if (r.point_labels.empty()) continue;
    if (r.point_labels.size() != r.x.size())
      throw std::invalid_argument("plot " + p.file + ": '" + r.label + "' has " + std::to_string(r.x.size()) +
                                  " points and " + std::to_string(r.point_labels.size()) + " point labels");
    for (size_t i = 0; i < r.x.size(); ++i) {
      if (!std::isfinite(r.x[i]) || !std::isfinite(r.y[i])) continue;  // not drawn either
      std::string at;
      put(at, r.x[i]);
      at += ',';
      put(at, r.y[i]);
      annotations += "set label " + gnuplot_quote(r.point_labels[i]) + " at " + at + " offset 0.8,0.6\n";
    }
  }

  std::string gp = "# " + p.title + "\n# Regenerate: run `gnuplot " + stem +
                   ".gp` in this folder; it writes ../" + p.file + ".\n";
  gp += "if (!exists(\"outfile\")) outfile = " + gnuplot_quote("../" + p.file) + "\n";
  gp += "set terminal pngcairo size 900,600 noenhanced font 'sans,11'\nset output outfile\n";
  gp += "set title " + gnuplot_quote(p.title) + "\nset xlabel " + gnuplot_quote(p.xlabel) + "\nset ylabel " +
        gnuplot_quote(p.ylabel) + "\n";
  gp += "set grid\nset key top left opaque box Left reverse\nset style fill transparent solid 0.25 noborder\n";
  // A log axis labels decades as 1e-05 ... 10, not gnuplot's default 0.000010 ... 10.000000.
  if (p.logx) gp += "set logscale x\nset format x '%g'\n";
  if (p.logy) gp += "set logscale y\nset format y '%g'\n";
  gp += annotations;
  gp += (plot_cmd.empty() ? "# nothing to plot" : plot_cmd) + "\n";
  write_file_atomic((src / (stem + ".dat")).string(), dat);
  write_file_atomic((src / (stem + ".gp")).string(), gp);

  if (plot_cmd.empty()) return {false, "plot not generated: no data"};
  const std::string why = render_script(gnuplot, out_dir, stem, p.file);
  return {why.empty(), why.empty() ? "" : "plot not generated: " + why};
}

std::string render_script(const std::string& gnuplot, const std::string& out_dir,
                          const std::string& stem, const std::string& png) {
  if (std::string missing = gnuplot_missing(gnuplot); !missing.empty()) return missing;
  const fs::path src = fs::path(out_dir) / "plots_src";
  const std::string tmp_name = temporary_name(png);  // sibling of the final PNG in out_dir
  const fs::path tmp = fs::path(out_dir) / tmp_name;
  const std::string log = stem + ".log";
  std::string why = run_gnuplot(gnuplot, src.string(), stem + ".gp", "../" + tmp_name, log);
  std::error_code ec;
  if (why.empty() && (!fs::exists(tmp, ec) || fs::file_size(tmp, ec) == 0))
    why = "gnuplot wrote no image";
  if (!why.empty()) {
    fs::remove(tmp, ec);
    return why + " (script and log in plots_src/)";
  }
  fs::remove(src / log, ec);
  commit_file(tmp.string(), (fs::path(out_dir) / png).string());
  return "";
}

}  // namespace kolsky::plot
