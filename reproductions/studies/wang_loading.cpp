// study_wang_loading: the Wang et al. (2018) specimen of Chapter 5 under a loading history and
// grain-size curve of choice, read at the stresses the text names (issue 31, H2 and H3;
// reproductions/chapter5/README.md, "The preparation study").
// One case per call (resumable: a case whose summary exists is not rerun): the scene
// reproductions/chapter5/scene_wang.json at --upscale N with the set's sigma_lim0 rule
// (wang.cpp: 1.53 GPa at N = 1, else 1.53 GPa x N x 2.37 / 2.295), the loading file and end rule
// given, and the breakage counts, B_r and downscaled grain-size curve read at the first sample
// whose back stress reaches 20, 43, 60 and 72 MPa, not at an end time.
//   study_wang_loading --out DIR --label NAME [--upscale N] [--sigma PA] [--loading FILE]
//                      [--end-at PA] [--end-time S] [--psd FILE] [--seed K] [--cache DIR]
//                      [--reference DIR/NAME] [--set dotted.key=JSON ...]
// Writes DIR/NAME.json (summary), DIR/NAME_history.csv (t, strain, back stress, grains, broken
// parents, B_r) and DIR/NAME_psd<S>.csv (downscaled curve at S MPa).
#include <cmath>
#include <cstdio>
#include <optional>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "chapter5/ch5.hpp"
#include "dem/breakage_model.hpp"
#include "io/csv.hpp"
#include "studies/study_cli.hpp"

namespace {

using namespace kolsky;

struct Options {
  std::string out, label, loading = "../../data/digitized/chapter5/wang2018_strain_rate_held.csv", psd, cache,
                          reference;
  double upscale = 1, sigma = -1, end_at = 72e6, end_time = 420e-6;
  long seed = -1;
  std::vector<std::string> sets;  // --set dotted.key=JSON
};

// Printed values (targets.md 5e: Sec. 5.3.1) and the stresses Fig. 5.7 compares curves at.
constexpr double kSigmaN1 = 1.53e9, kSigmaN15 = 2.37e9, kFinesDMin = 7.5e-6;
constexpr double kStresses[] = {20e6, 43e6, 60e6, 72e6};

[[noreturn]] void usage(int code) {
  repro::exit_with_usage(code,
                         "usage: study_wang_loading --out DIR --label NAME [--upscale N] [--sigma PA]\n"
                         "         [--loading FILE] [--end-at PA] [--end-time S] [--psd FILE] [--seed K]\n"
                         "         [--cache DIR] [--reference DIR/NAME] [--set dotted.key=JSON ...]\n"
                         "Runs the Chapter 5 Wang scene with the loading file (default: the peak rate held,\n"
                         "wang2018_strain_rate_held.csv) until the back stress reaches --end-at (default\n"
                         "72e6 Pa; 0: --end-time only) and reads counts, B_r and the downscaled grain-size\n"
                         "curve at 20 / 43 / 60 / 72 MPa. Files relative to reproductions/chapter5/.\n"
                         "--reference: RMS of the curves at 43 and 72 MPa against that case's (points).\n");
}

Options parse(int argc, char** argv) {
  Options o;
  repro::read_flags(argc, argv, usage, [&](const std::string& a, repro::FlagReader& r) {
    if (a == "--out") o.out = r.value();
    else if (a == "--label") o.label = r.value();
    else if (a == "--upscale") o.upscale = r.number();
    else if (a == "--sigma") o.sigma = r.number();
    else if (a == "--loading") o.loading = r.value();
    else if (a == "--end-at") o.end_at = r.number();
    else if (a == "--end-time") o.end_time = r.number();
    else if (a == "--psd") o.psd = r.value();
    else if (a == "--seed") o.seed = r.integer();
    else if (a == "--cache") o.cache = r.value();
    else if (a == "--reference") o.reference = r.value();
    else if (a == "--set") o.sets.push_back(r.value());
    else return false;
    return true;
  });
  if (o.out.empty() || o.label.empty() || !(o.upscale >= 1)) usage(1);
  o.cache = repro::packing_cache_dir(o.cache, o.out);
  return o;
}

void write_curve(const std::string& path, const psd::GrainSizeCurve& g) {
  io::write_csv(path, {{"diameter_m", "percent_passing"}, {g.diameter, g.percent_passing}, {}, {}});
}

psd::GrainSizeCurve read_curve(const std::string& path) {
  const io::CsvTable t = io::read_csv(path);
  return {t.column("diameter_m"), t.column("percent_passing")};
}

}  // namespace

int main(int argc, char** argv) {
  repro::line_buffered_stdout();
  const Options o = parse(argc, argv);
  const std::string dir = std::string(KOLSKY_SOURCE_DIR) + "/reproductions/chapter5";
  const std::optional<std::string> case_stem = repro::start_case(o.out, o.label);
  if (!case_stem) return 0;
  const std::string& stem = *case_stem;
  ch5::CaseSpec spec;
  spec.label = o.label;
  spec.scene = "scene_wang.json";
  spec.upscale = o.upscale;
  // The set's rule (wang.cpp): the text's values at N = 1 and 1.5, Eq. 5.17 with the text's
  // own departure from it (2.37 / 2.295) elsewhere.
  const double m1 = ch5::scene_m1(dir, spec.scene);
  spec.sigma_lim0 = o.sigma > 0 ? o.sigma
                    : o.upscale == 1 ? kSigmaN1
                                     : dem::upscaled_sigma_lim0(kSigmaN1, o.upscale, m1) * kSigmaN15 /
                                           dem::upscaled_sigma_lim0(kSigmaN1, 1.5, m1);
  spec.fines_d_min = kFinesDMin;
  spec.end_time = o.end_time;
  spec.loading_file = o.loading;
  spec.end_at_back_stress = o.end_at;
  spec.seed = o.seed;
  spec.sets = o.sets;
  if (!o.psd.empty()) spec.sets.push_back("specimen.grain_size_curve=" + nlohmann::json(o.psd).dump());
  std::printf("%s: N = %g, sigma_lim0 = %.4g GPa, loading %s, end at %.3g MPa or %.3g us\n", o.label.c_str(),
              o.upscale, spec.sigma_lim0 / 1e9, o.loading.c_str(), o.end_at / 1e6, o.end_time * 1e6);
  const ch5::CaseResult c = ch5::run_case(spec, dir, o.cache);
  if (!c.ok) return repro::case_failed(o.label, c.failure);
  nlohmann::json j;
  j["label"] = o.label;
  j["upscale"] = c.upscale;
  j["sigma_lim0"] = spec.sigma_lim0;
  j["loading"] = o.loading;
  j["grain_size_curve"] = o.psd;
  j["seed"] = o.seed;
  j["sets"] = o.sets;
  j["end_at_back_stress"] = o.end_at;
  j["ended_by"] = c.ended_by;
  j["wall_s"] = c.wall_s;
  j["pack_s"] = c.pack_s;
  j["steps"] = c.steps;
  j["grains_initial"] = c.grains_initial;
  j["grains_final"] = c.grains_final;
  double peak = 0;
  for (double s : c.stress_back) peak = std::max(peak, s);
  j["peak_back_stress"] = peak;
  j["strain_end"] = c.strain.empty() ? NAN : c.strain.back();
  psd::GrainSizeCurve ref43, ref72;
  if (!o.reference.empty()) ref43 = read_curve(o.reference + "_psd43.csv"), ref72 = read_curve(o.reference + "_psd72.csv");
  std::printf("%s: %zu -> %zu grains, peak %.1f MPa, %.0f s (packing %.0f s)%s%s\n", o.label.c_str(),
              c.grains_initial, c.grains_final, peak / 1e6, c.wall_s, c.pack_s, c.ended_by.empty() ? "" : "; ",
              c.ended_by.c_str());
  std::printf("  %-8s %-8s %-8s %-9s %-8s %-9s %-7s %s\n", "MPa", "t (us)", "strain", "grains", "growth",
              "broken", "B_r", "PSD RMS vs ref (points)");
  for (double level : kStresses) {
    const long k = ch5::first_at_least(c.stress_back, level);
    const std::string key = std::to_string(static_cast<int>(std::lround(level / 1e6)));
    if (k < 0 || c.grain_count.empty()) {
      j["at"][key] = nullptr;
      std::printf("  %-8s not reached\n", key.c_str());
      continue;
    }
    const psd::GrainSizeCurve g = ch5::curve_at_stress(c, level);
    write_curve(stem + "_psd" + key + ".csv", g);
    const double growth = c.grain_count[k] / c.grains_initial;
    const double broken = c.broken_primary[k] + c.broken_secondary[k];
    double rms = NAN;
    const psd::GrainSizeCurve& ref = key == "43" ? ref43 : ref72;
    if ((key == "43" || key == "72") && ref.size() > 1) rms = ch5::passing_difference(ref, g, 0, 1);
    j["at"][key] = {{"t", c.t[k]}, {"strain", c.strain[k]}, {"grains", c.grain_count[k]}, {"growth", growth},
                    {"broken_parents", broken}, {"relative_breakage", c.relative_breakage[k]},
                    {"psd_rms_vs_reference", rms}};
    std::printf("  %-8s %-8.1f %-8.4f %-9.0f %-8.3f %-9.0f %-7.4f %s\n", key.c_str(), c.t[k] * 1e6, c.strain[k],
                c.grain_count[k], growth, broken, c.relative_breakage[k],
                std::isnan(rms) ? "-" : std::to_string(rms).c_str());
  }
  io::CsvTable h{{"t_s", "strain", "stress_back_pa"}, {c.t, c.strain, c.stress_back}, {}, {}};
  if (!c.grain_count.empty()) {
    std::vector<double> broken(c.t.size());
    for (std::size_t k = 0; k < broken.size(); ++k) broken[k] = c.broken_primary[k] + c.broken_secondary[k];
    h.header.insert(h.header.end(), {"grains", "broken_parents", "relative_breakage"});
    h.columns.insert(h.columns.end(), {c.grain_count, broken, c.relative_breakage});
  }
  io::write_csv(stem + "_history.csv", h);
  repro::finish_case(stem, j);
  return 0;
}
