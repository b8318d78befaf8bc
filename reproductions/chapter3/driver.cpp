// Reproduction set "chapter3": the dissertation's Ch. 3 coupled FEM-DEM SHPB (LS-DYNA in the
// text) on kolsky's FE-DEM coupling (docs/coupling.md): meshed FE bars and an FE steel tube
// around DEM spheres with the LS-DYNA DES linear contacts (Eqs. 3.1-3.4, Table 3.2), the Song
// et al. (2009) test at ~470/s. Cases (Sec. 3.4): the original grain-size curve, the same x 1.5,
// monodisperse r = 0.15 mm, and interface friction 0.3; then the model levels (speed against
// error), the NORMK back-calculation with its twin experiment and the printed E = 70 MPa.
// Scenes: scene_<scale>.json (the original curve, full model); every variant is a JSON merge
// patch in studies_<scale>.json; targets: targets.json (full) / targets_smoke.json.
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>

#include "chapter3/studies.hpp"
#include "common/driver_args.hpp"
#include "common/report_input.hpp"
#include "common/format.hpp"
#include "common/perturb.hpp"
#include "core/errors.hpp"
#include "harness/report.hpp"

using namespace kolsky;
using repro::fmt;

namespace {

std::string mpa(double pa) { return std::isfinite(pa) ? fmt("%.1f", pa / 1e6) : "-"; }

harness::PlotSeries stress_strain(const std::string& label, const ch3::CaseResult& c, const ch3::Measures& m) {
  const auto cv = ch3::curve_to_cutoff(c, m);
  harness::PlotSeries s{label, cv.x, {}, "lines"};
  for (double y : cv.y) s.y.push_back(y / 1e6);
  return s;
}

struct Ran {
  ch3::CaseResult c;
  ch3::Measures m;
  double upscale = 1, text_upscale = 1;  // the scene's N and the text's (1; 1.5 for the shifted curve)
};

// 1. Inputs: the scale's scene (with the packing cache next to the report), the studies file
// with the windows of Sec. 3.4 (slope over 2-6 % strain, the 13 MPa cut-off of Sec. 3.3), and the
// speed-ups the model-level targets ask for, read before any run.
ch3::Context read_inputs(const repro::DriverArgs& args, harness::ReportInput& rep) {
  ch3::Context x;
  x.scene_path = args.set_dir() + "/scene_" + args.scale + ".json";
  x.m = &rep.m;
  x.plots = &rep.plots;
  x.scene = repro::read_scene_json(x.scene_path, args.perturb_seed);
  x.packing_cache = std::filesystem::absolute(rep.out_dir + "/packing_cache").string();
  x.studies = ch3::read_json(args.set_dir() + "/studies_" + args.scale + ".json");
  const auto& w = x.studies.at("windows");
  x.eps_lo = w.at("slope_strain")[0], x.eps_hi = w.at("slope_strain")[1];
  x.cutoff = w.at("cutoff_stress"), x.ringing_time = w.at("ringing_time");
  x.min_speedup = ch3::level_speedups(x, harness::load_targets(rep.targets_path, args.repo_root));
  return x;
}

// 2. The cases of Sec. 3.4: the original grain-size curve, the same x 1.5, monodisperse
// r = 0.15 mm and interface friction 0.3, each a merge patch of the studies file; grain counts
// scaled to the text's N (a count goes as N^-3 for one curve shape).
std::map<std::string, Ran> run_cases(ch3::Context& x) {
  std::map<std::string, Ran> ran;
  std::string table = "| case | grains | x (N_scene / N_text)^3 | porosity | slope 2-6 % (MPa) | strain at 13 MPa | "
                      "mean strain rate (1/s) | max face alpha after ringing | off-axis fraction | wall time (s): case / time loop |\n"
                      "|---|---|---|---|---|---|---|---|---|---|\n";
  for (const auto& cs : x.studies.at("cases")) {
    const std::string id = cs.at("id");
    Ran r;
    const harness::Case spec = ch3::make_case(x, id, cs.at("patch"));
    r.upscale = harness::final_scene(spec).at("specimen").at("upscale");
    r.text_upscale = cs.at("text_upscale");
    std::printf("case %s: running\n", id.c_str());
    r.c = ch3::run_case(spec);
    r.m = ch3::measure(x, r.c);
    const double to_text = std::pow(r.upscale / r.text_upscale, 3);  // count ~ N^-3 for one curve shape
    std::printf("case %s: %zu grains, slope %s MPa (gauges %s), 13 MPa at strain %.4f, %.0f us after arrival, energy error %.2g; %s, %.1f s\n",
                id.c_str(), r.c.dem.grains, mpa(r.m.slope).c_str(), mpa(r.m.slope_gauges).c_str(), r.m.strain_at_cutoff,
                r.m.time_at_cutoff * 1e6, r.m.energy_error, r.c.ok ? "ok" : r.c.failure.c_str(), r.c.wall_s);
    table += "| " + id + " | " + std::to_string(r.c.dem.grains) + " | " + fmt("%.4g", to_text) + " | " + fmt("%.4f", r.c.dem.porosity) +
             " | " + mpa(r.m.slope) + " | " + fmt("%.4f", r.m.strain_at_cutoff) + " | " + fmt("%.0f", r.m.strain_rate) + " | " +
             fmt("%.3f", r.m.face_alpha_max) + " | " + fmt("%.2g", r.c.off_axis) + " | " + fmt("%.1f", r.c.wall_s) + " / " + fmt("%.1f", r.c.run_s) + " |" +
             (r.c.ok ? "" : " failed: " + r.c.failure) + "\n";
    if (cs.value("count_target", false)) {
      x.m->scalar("ch3.count_" + id, static_cast<double>(r.c.dem.grains) * to_text);
      x.m->note("ch3.count_" + id, std::to_string(r.c.dem.grains) + " grains at N = " + fmt("%g", r.upscale) + ", x " +
                                       fmt("%.4g", to_text) + " to the text's N = " + fmt("%g", r.text_upscale));
    }
    ran[id] = std::move(r);
  }
  x.markdown += "### Cases (Sec. 3.4)\n\n" + table;
  return ran;
}

// 3. What Sec. 3.4 compares: the slopes of the three curves and the friction case, the
// energy balance, the face stresses of the 1.5x specimen (Fig. 3.4), the cut-off reached.
void measure_cases(ch3::Context& x, const std::map<std::string, Ran>& ran) {
  const Ran& o = ran.at("original");
  const Ran& s = ran.at("shifted");
  const Ran& u = ran.at("monodisperse");
  const Ran& f = ran.at("friction");
  x.m->scalar("ch3.slope_original", o.m.slope / 1e6);
  x.m->note("ch3.slope_original", std::to_string(o.m.slope_points) + " samples in 2-6 % strain below 13 MPa (reached at " +
                                      fmt("%.4f", o.m.strain_at_cutoff) + "); bar-gauge analysis: " + mpa(o.m.slope_gauges) + " MPa");
  x.m->note("ch3.slope_monodisperse", "13 MPa reached at strain " + fmt("%.4f", u.m.strain_at_cutoff));
  x.m->scalar("ch3.energy_error", std::max({o.m.energy_error, s.m.energy_error, u.m.energy_error, f.m.energy_error}));
  x.m->note("ch3.energy_error", "largest over the four cases of max |held - delivered| up to 13 MPa over the work delivered");
  x.m->scalar("ch3.slope_monodisperse", u.m.slope / 1e6);
  // Companion of ch3.count_shifted: the shifted count over the original's count moved to the
  // shifted curve's N, (N_o / N_s)^3 (a pure shift of one curve shape, targets.md 3e.4).
  const double own_shift = static_cast<double>(o.c.dem.grains) * std::pow(o.upscale / s.text_upscale, 3);
  x.m->scalar("ch3.count_shifted_pure_shift", static_cast<double>(s.c.dem.grains) * std::pow(s.upscale / s.text_upscale, 3) / own_shift);
  x.m->note("ch3.count_shifted_pure_shift", "the pure shift of this run's original packing predicts " + fmt("%.0f", own_shift) +
                                                " grains at N = " + fmt("%g", s.text_upscale) + "; Table 3.1 prints 53,602");
  x.m->scalar("ch3.shifted_to_original_slope", s.m.slope / o.m.slope);
  x.m->note("ch3.shifted_to_original_slope", "shifted " + mpa(s.m.slope) + " MPa, original " + mpa(o.m.slope) + " MPa");
  x.m->trend("ch3.monodisperse_softer", u.m.slope < o.m.slope,
             "monodisperse " + mpa(u.m.slope) + " MPa vs original " + mpa(o.m.slope) + " MPa");
  x.m->trend("ch3.friction_stiffer", f.m.slope > o.m.slope,
             "interface friction 0.3: " + mpa(f.m.slope) + " MPa vs frictionless " + mpa(o.m.slope) + " MPa");
  x.m->scalar("ch3.face_alpha_shifted", s.m.face_alpha_max);
  x.m->note("ch3.face_alpha_shifted",
            std::isfinite(s.m.ringing_end)
                ? "max |front - back| / mean face stress from the ringing time, " + fmt("%.0f us", s.m.ringing_end * 1e6) +
                      " after arrival (back face " + mpa(s.m.stress_at_ringing_end) + " MPa), to 13 MPa; largest gap " +
                      mpa(s.m.face_gap_max) + " MPa"
                : "no window: the back face reaches 13 MPa " + fmt("%.0f us", s.m.time_at_cutoff * 1e6) + " after arrival, before the " +
                      fmt("%.0f us", x.ringing_time * 1e6) + " ringing time");
  x.m->scalar("ch3.face_inertia_ratio", s.m.face_inertia_ratio);
  x.m->note("ch3.face_inertia_ratio", "1.5 x specimen before the ringing time: measured front - back gap over the gap its momentum "
                                          "needs (largest " + fmt("%.2f", s.m.face_inertia_gap_max / 1e6) + " MPa), where that is at least half its largest");
  // Companion of the slope known deviations (README, "The preparation study, H1"): the
  // network the original specimen starts with (full scale only: studies_full.json
  // "companions").
  if (x.studies.contains("companions")) {
    if (o.c.run.has_probe("coordination_number") && !o.c.run.probe("coordination_number").value.empty()) {
      x.m->scalar("ch3.initial_coordination", o.c.run.probe("coordination_number").value.front());
      x.m->note("ch3.initial_coordination", "grain contacts per grain of the original specimen at t = 0, as packed");
    }
  }
  x.m->scalar("ch3.porosity", o.c.dem.porosity);
  x.m->scalar("ch3.strain_rate", o.m.strain_rate);
  x.m->scalar("ch3.off_axis_fraction", f.c.off_axis);
  x.m->note("ch3.off_axis_fraction", "friction case (frictionless faces carry no lateral force: " + fmt("%.2g", o.c.off_axis) + ")");
  x.m->trend("ch3.reaches_cutoff", o.m.reached_cutoff && s.m.reached_cutoff && u.m.reached_cutoff && f.m.reached_cutoff,
             "every case's back-face stress reaches 13 MPa (strain there: original " + fmt("%.4f", o.m.strain_at_cutoff) + ")");
}

// 4. Plots: the three curves (Fig. 3.3), the friction pair (Fig. 3.5), the shifted specimen's
// face stresses (Fig. 3.4).
std::vector<harness::Plot> case_plots(const ch3::Context& x, const std::map<std::string, Ran>& ran) {
  const Ran& o = ran.at("original");
  const Ran& s = ran.at("shifted");
  const Ran& f = ran.at("friction");
  harness::Plot ss{"stress_strain.png", "Back-face stress vs strain (face records) to 13 MPa: grain-size curves (Fig. 3.3)",
                   "strain (-)", "stress (MPa)", {}, {}, {}};
  for (const char* id : {"original", "shifted", "monodisperse"}) ss.series.push_back(stress_strain(id, ran.at(id).c, ran.at(id).m));
  harness::Plot fp{"friction.png", "Back-face stress vs strain to 13 MPa: interface friction 0 and 0.3 (Fig. 3.5)", "strain (-)",
                   "stress (MPa)", {}, {}, {}};
  fp.series.push_back(stress_strain("frictionless", o.c, o.m));
  fp.series.push_back(stress_strain("friction 0.3", f.c, f.m));
  harness::Plot fs{"face_stresses.png", "Face stresses of the 1.5x specimen (summed contact forces / area, Fig. 3.4)",
                   "t after arrival (us)", "stress (MPa)", {}, {}, {}};
  harness::PlotSeries sf{"incident-bar face", {}, {}, "lines"}, sb{"transmission-bar face", {}, {}, "lines"};
  for (std::size_t k = 0; k < s.c.faces.t.size(); ++k) {
    if (s.c.faces.back[k] > 1.2 * x.cutoff) break;
    sf.x.push_back(s.c.faces.t[k] * 1e6), sf.y.push_back(s.c.faces.front[k] / 1e6);
    sb.x.push_back(s.c.faces.t[k] * 1e6), sb.y.push_back(s.c.faces.back[k] / 1e6);
  }
  fs.series = {sf, sb};
  return {ss, fp, fs};
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // progress lines reach a log file as they happen
  const auto args = repro::parse_driver_args(argc, argv, "chapter3");
  const auto start = std::chrono::steady_clock::now();
  harness::ReportInput rep = repro::report_input(args, repro::SmokeTargets::own_file);
  ch3::Context x;
  try {
    x = read_inputs(args, rep);                             // 1
    const std::map<std::string, Ran> ran = run_cases(x);   // 2
    measure_cases(x, ran);                                  // 3
    rep.plots = case_plots(x, ran);                         // 4
    // 5. Model levels, speed against error, on the original curve (issue 16).
    const Ran& o = ran.at("original");
    ch3::model_levels(x, o.c, o.m);
    // 6. The NORMK back-calculation with its twin experiment, and E = 70 MPa as printed.
    ch3::normk_studies(x, o.m.slope);
  } catch (const InputError& e) {
    std::fprintf(stderr, "reproduce_chapter3: %s\n", e.what());
    return 2;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "reproduce_chapter3: %s\n", e.what());
    return 1;
  }
  // 7. The report, scored against targets(_smoke).json.
  rep.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const char* threads = std::getenv("OMP_NUM_THREADS");
  rep.preamble_markdown = "Scale **" + args.scale + "**, " + fmt("%.0f s", rep.wall_time_s) + " on " +
                          (threads ? std::string(threads) + " thread(s)" : std::string("the default threads")) +
                          ". Grain modulus read as E = 70 GPa (Table 3.2 prints 70 MPa: README, 'The grain modulus'); "
                          "inputs the text shows only as figures are reconstructions (data/digitized/chapter3/).\n\n" +
                          x.markdown;
  const int failed = harness::write_report(rep);
  std::printf("chapter3: %d expected target(s) failed; report in %s\n", failed, rep.out_dir.c_str());
  return failed == 0 ? 0 : 1;
}
