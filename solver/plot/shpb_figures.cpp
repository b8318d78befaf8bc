// SHPB record figures (see shpb_figures.hpp). Only data are chosen here; gnuplot.cpp draws them.
#include "plot/shpb_figures.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <set>

#include "shpb/probe_record.hpp"

namespace kolsky::plot {
namespace {

constexpr double kUs = 1e6;     // s -> us
constexpr double kMicro = 1e6;  // strain -> microstrain
constexpr double kMpa = 1e-6;   // Pa -> MPa

std::vector<double> scaled(const std::vector<double>& v, double k) {
  std::vector<double> out(v.size());
  std::transform(v.begin(), v.end(), out.begin(), [k](double x) { return k * x; });
  return out;
}

Plot figure(const std::string& file, const std::string& what, const std::string& source,
            const std::string& xlabel, const std::string& ylabel) {
  Plot p;
  p.file = file;
  p.title = what + " - " + std::filesystem::path(source).filename().string();  // a path would not fit
  p.xlabel = xlabel;
  p.ylabel = ylabel;
  return p;
}

/// A horizontal line across [x0, x1] (removed offsets, the alpha = 0.05 criterion).
PlotSeries level(const std::string& label, double x0, double x1, double y) {
  return {label, {x0, x1}, {y, y}, "dashed"};
}

/// Waves, strain rate, stress-strain, alpha and energies; none for a record too short to analyse.
std::vector<Plot> analysis_figures(const shpb::FaceWaves& w, const shpb::SpecimenHistory& h,
                                   const std::string& source) {
  if (h.t.size() < 2 || w.t.size() < 2) return {};
  const auto t = scaled(h.t, kUs);
  const char* t_label = "t (us), 0: incident arrival at the specimen face";
  std::vector<Plot> out;

  Plot waves = figure("waves.png", "Face-referred bar waves", source, t_label,
                      "bar strain (microstrain, compression +)");
  const auto tw = scaled(w.t, kUs);
  waves.series = {{"incident", tw, scaled(w.eps_i, kMicro)},
                  {"reflected", tw, scaled(w.eps_r, kMicro)},
                  {"transmitted", tw, scaled(w.eps_t, kMicro)}};
  out.push_back(std::move(waves));

  Plot rate = figure("strain_rate.png", "Specimen strain rate, Eq. 1.3", source, t_label,
                     "strain rate (1/s)");
  rate.series = {{"strain rate", t, h.strain_rate}};
  out.push_back(std::move(rate));

  Plot ss = figure("stress_strain.png", "Specimen stress vs strain (Eqs. 1.1, 1.2, 4.16)", source,
                   "strain (-, compression +)", "stress (MPa, compression +)");
  ss.series = {{"front (incident-bar face)", h.strain, scaled(h.stress_front, kMpa)},
               {"back (transmission-bar face), Eq. 1.2", h.strain, scaled(h.stress_back, kMpa)},
               {"average, Eq. 4.16", h.strain, scaled(h.stress_avg, kMpa), "dashed"}};
  out.push_back(std::move(ss));

  // Log scale: alpha falls by decades through equilibrium, and 0.05 sits among them.
  Plot alpha = figure("alpha.png", "Stress non-uniformity alpha(t), Eq. 2.15", source, t_label,
                      "alpha (-)");
  alpha.series = {{"alpha", t, h.alpha}, level("0.05 (equilibrium)", t.front(), t.back(), 0.05)};
  alpha.logy = true;
  out.push_back(std::move(alpha));

  Plot energy = figure("energies.png", "Wave energies, Eqs. 2.11-2.13", source, t_label,
                       "energy (J)");
  energy.series = {{"W incident", t, h.w_incident},
                   {"W reflected", t, h.w_reflected},
                   {"W transmitted", t, h.w_transmitted},
                   {"W loss = W_i - W_r - W_t", t, h.w_loss, "dashed"}};
  out.push_back(std::move(energy));
  return out;
}

}  // namespace

std::vector<Plot> analyze_figures(const shpb::GaugeRecord& rec, const shpb::GaugeReport& report,
                                  const shpb::AnalysisSetup& setup, const shpb::FaceWaves& waves,
                                  const shpb::SpecimenHistory& h, const std::string& source) {
  Plot g = figure("gauges.png", "Gauge records as measured, pulse windows, removed offsets",
                  source, "t (us), record clock", "gauge strain (microstrain, compression -)");
  const auto t = scaled(rec.t, kUs);
  const auto inc = scaled(rec.incident, kMicro), tra = scaled(rec.transmitted, kMicro);
  double lo = 0, hi = 0;
  for (const auto* v : {&inc, &tra})
    for (double x : *v)
      if (std::isfinite(x)) lo = std::min(lo, x), hi = std::max(hi, x);
  // The windows process_gauges cut (gauge_processing.hpp, step 4): the incident wave from its
  // detected start, the reflected one 2 d_I / c_I later at the same gauge, the transmitted one
  // d_I / c_I + d_T / c_T later at its gauge; each as long as the analysis window.
  const double c_i = setup.incident.wave_speed(), c_t = setup.transmission.wave_speed();
  const double d_i = setup.incident.gauge_distance, d_t = setup.transmission.gauge_distance;
  const std::pair<const char*, double> starts[] = {
      {"incident window", report.start_time},
      {"reflected window", report.start_time + 2.0 * d_i / c_i},
      {"transmitted window", report.start_time + d_i / c_i + d_t / c_t}};
  for (const auto& [label, t0] : starts)
    g.bands.push_back({label, {t0 * kUs, (t0 + report.window) * kUs}, {lo, lo}, {hi, hi}});
  g.series = {{"incident bar", t, inc},
              {"transmission bar", t, tra}};
  if (!t.empty()) {
    g.series.push_back(level("removed offset, incident", t.front(), t.back(),
                             report.offset_incident * kMicro));
    g.series.push_back(level("removed offset, transmission", t.front(), t.back(),
                             report.offset_transmitted * kMicro));
  }
  std::vector<Plot> out{std::move(g)};
  for (Plot& p : analysis_figures(waves, h, source)) out.push_back(std::move(p));
  return out;
}

std::vector<Plot> run_figures(const shpb::RunResult& r, const shpb::FaceWaves& waves,
                              const shpb::SpecimenHistory& h, const std::string& source) {
  const auto t = scaled(r.t, kUs);
  Plot g = figure("gauges.png", "Simulated gauge records", source, "t (us), from the start of loading",
                  "gauge strain (microstrain, compression -)");
  std::set<std::string> drawn;  // probes the figures above already show
  for (const char* bar : {"incident", "transmission"})
    for (std::size_t k = 0; r.has_probe(shpb::gauge_probe_name(bar, k)); ++k) {
      const shpb::Probe& p = r.probe(shpb::gauge_probe_name(bar, k));
      g.series.push_back({p.name, t, scaled(p.value, kMicro)});
      drawn.insert(p.name);
    }
  std::vector<Plot> out;
  if (!g.series.empty()) out.push_back(std::move(g));
  for (Plot& p : analysis_figures(waves, h, source)) out.push_back(std::move(p));
  // The face waves and their energies are the waves and energies figures.
  for (const char* name : {"wave_incident", "wave_reflected", "wave_transmitted", "stress_front",
                           "stress_back", "w_incident", "w_reflected", "w_transmitted"})
    drawn.insert(name);
  for (const shpb::Probe& p : r.probes) {
    // A probe with no finite sample (a meshed-bar wave after its gauge) is no figure: gnuplot
    // refuses an all-undefined plot.
    const bool any = std::any_of(p.value.begin(), p.value.end(), [](double v) { return std::isfinite(v); });
    if (drawn.count(p.name) || !any) continue;
    const bool pa = p.unit == "Pa";  // stresses in MPa, as in the other figures
    Plot f = figure("probe_" + p.name + ".png", p.name + ": " + p.description, source,
                    "t (us), from the start of loading",
                    p.name + " (" + (pa ? "MPa" : p.unit == "1" ? "-" : p.unit) + ")");
    f.series = {{p.name, t, pa ? scaled(p.value, kMpa) : p.value}};
    out.push_back(std::move(f));
  }
  return out;
}

}  // namespace kolsky::plot
