// `kolsky analyze GAUGES.csv --bars BARS.json [-o OUT.csv] [--plot DIR] [--quiet]
//  [--allow-incomplete]`
// GAUGES.csv: three columns in this order, time (s), incident-bar gauge strain, transmission-
// bar gauge strain, as measured (compression negative); '#' comments and a header row allowed.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <utility>
#include <vector>

#include "app/commands.hpp"
#include "app/plot_output.hpp"
#include "app/run_checks.hpp"
#include "core/errors.hpp"
#include "io/csv.hpp"
#include "plot/shpb_figures.hpp"
#include "scene/scene.hpp"
#include "shpb/gauge_processing.hpp"
#include "shpb/summary.hpp"

namespace kolsky::app {

namespace {

/// The analysis of finite strains can still overflow (strains of 1e296 square to inf in the
/// wave energies): a result that is not finite is a numerical failure (exit 3) naming the
/// quantity, not a CSV of inf and nan. alpha and dissipation_percent are NaN by design where
/// their denominator vanishes (below the alpha floor, before any incident energy).
void check_finite(const shpb::FaceWaves& w, const shpb::SpecimenHistory& h) {
  const std::pair<const char*, const std::vector<double>*> results[] = {
      {"eps_incident", &w.eps_i},        {"eps_reflected", &w.eps_r},
      {"eps_transmitted", &w.eps_t},     {"strain", &h.strain},
      {"strain_rate_per_s", &h.strain_rate}, {"stress_front_pa", &h.stress_front},
      {"stress_back_pa", &h.stress_back}, {"stress_avg_pa", &h.stress_avg},
      {"w_incident_j", &h.w_incident},   {"w_reflected_j", &h.w_reflected},
      {"w_transmitted_j", &h.w_transmitted}, {"w_loss_j", &h.w_loss}};
  for (const auto& [name, v] : results)
    for (std::size_t k = 0; k < v->size(); ++k)
      if (!std::isfinite((*v)[k])) {
        char msg[200];
        std::snprintf(msg, sizeof msg, "analyze: %s is not finite (%g at t = %.6g s, sample %zu): "
                      "the gauge strains are too large for the analysis; nothing written",
                      name, (*v)[k], k < h.t.size() ? h.t[k] : NAN, k);
        throw NumericalError(msg, k < h.t.size() ? h.t[k] : NAN);
      }
}

}  // namespace

int cmd_analyze(const std::vector<std::string>& args) {
  const Options o = parse_options(args, {"-o", "--bars", "--plot", "--quiet", "--allow-incomplete"});
  if (o.positional.size() != 1) throw UsageError("needs exactly one GAUGES.csv");
  if (o.bars.empty()) throw UsageError("needs --bars BARS.json");
  const std::string gnuplot = o.plot_dir.empty() ? "" : prepare_plots(o.plot_dir);
  const std::string& file = o.positional[0];
  const std::string out = o.output.empty()
      ? std::filesystem::path(file).stem().string() + "_analysis.csv" : o.output;
  check_outputs({{"-o", out}}, {file, o.bars});
  const scene::BarsFile bars = scene::load_bars_file(o.bars);
  const io::CsvTable csv = io::read_csv(file);
  if (!o.allow_incomplete && !csv.comments.empty() && csv.comments.front().starts_with(kIncompleteRecordMark))
    throw InputError(file, "line 1", "the record is marked '" + csv.comments.front() +
                                         "'; analysing it needs --allow-incomplete");
  if (csv.columns.size() < 3)
    throw InputError(file, "", "needs 3 columns (time, incident strain, transmitted strain), found " +
                                   std::to_string(csv.columns.size()));
  shpb::GaugeRecord rec{csv.columns[0], csv.columns[1], csv.columns[2]};
  shpb::GaugeReport report;
  shpb::FaceWaves waves;
  try {
    waves = shpb::process_gauges(rec, bars.setup, bars.gauge, &report);
  } catch (const shpb::GaugeRowError& e) {  // the file line, as every other CSV error gives
    throw InputError(file, "line " + std::to_string(csv.lines.at(e.row)), e.rule);
  } catch (const std::invalid_argument& e) {
    throw InputError(file, "", e.what());
  }
  const auto h = shpb::analyze(waves, bars.setup, bars.analysis);
  check_finite(waves, h);

  io::CsvTable t;
  t.header = {"t_s", "eps_incident", "eps_reflected", "eps_transmitted", "strain",
              "strain_rate_per_s", "stress_front_pa", "stress_back_pa", "stress_avg_pa",
              "alpha", "w_incident_j", "w_reflected_j", "w_transmitted_j", "w_loss_j",
              "dissipation_percent"};
  t.columns = {h.t, waves.eps_i, waves.eps_r, waves.eps_t, h.strain, h.strain_rate,
               h.stress_front, h.stress_back, h.stress_avg, h.alpha, h.w_incident,
               h.w_reflected, h.w_transmitted, h.w_loss, h.dissipation_percent};
  io::write_csv(out, t,
                "kolsky analyze " + file + " --bars " + o.bars +
                    "\nt = 0 at the incident arrival at the specimen face; bar strains "
                    "compression positive; specimen stress/strain compression positive");

  auto s = shpb::summarize(waves, h);
  s["offset_incident"] = report.offset_incident;
  s["offset_transmitted"] = report.offset_transmitted;
  s["noise_incident"] = report.noise_incident;
  s["start_time_at_gauge_s"] = report.start_time;
  s["window_s"] = report.window;
  std::printf("kolsky analyze: %s -> %s\n", file.c_str(), out.c_str());
  if (!o.quiet) std::fputs(shpb::format_summary(s).c_str(), stdout);
  for (const auto& w : report.warnings) std::fprintf(stderr, "kolsky analyze: warning: %s\n", w.c_str());
  if (!o.plot_dir.empty())
    write_plots(plot::analyze_figures(rec, report, bars.setup, waves, h, file), o.plot_dir, gnuplot,
                "analyze");
  return 0;
}

}  // namespace kolsky::app
