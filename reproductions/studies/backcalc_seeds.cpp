// study_backcalc_seeds: the Chapter 5 sigma_lim0 back-calculation (Sec. 5.3.4; chapter5/backcalc)
// repeated over packing seeds at one N, for the seed scatter issue 31 item 3 asks for beside
// Eq. 5.17 (reproductions/chapter5/README.md, "sigma_lim0 over packing seeds").
// The reference curve is a recorded N = 1 history (study_wang_loading's NAME_history.csv), cut
// at the first sample whose back stress reaches --until: with the set's loading (the peak rate
// held, the run ending at 72 MPa) that is the set's own reference run, sample for sample. Each
// candidate is the set's: scene_wang.json at --upscale N, loaded the same way, with the seed's
// packing. The search is the set's (back_calculate: Brent on ln sigma, bracket x/ 1.25, 3 %,
// at most 10 runs).
//   study_backcalc_seeds --reference HISTORY.csv --upscale N --seeds 1,2,3 --out DIR
//                        [--until PA] [--cache DIR] [--max-evaluations K]
// One DIR/N<N>_seed<K>.json per seed (written when its search ends: a rerun skips it), and a
// summary line per N: the mean and sample standard deviation of sigma_lim0 over the seeds.
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "chapter5/backcalc.hpp"
#include "common/stats.hpp"
#include "dem/breakage_model.hpp"
#include "io/csv.hpp"
#include "scene/json_reader.hpp"
#include "studies/study_cli.hpp"

namespace {

using namespace kolsky;

// The set's inputs (cases_full.json, reported.json; targets.md 5e): sigma_lim0 at N = 1, the
// fines' smallest size, the held loading and the stress the runs end at.
constexpr double kSigmaN1 = 1.53e9, kFinesDMin = 7.5e-6, kEndAt = 72e6, kEndTime = 420e-6, kBracket = 1.25;
const char* const kLoading = "../../data/digitized/chapter5/wang2018_strain_rate_held.csv";

struct Options {
  std::string reference, out, cache;
  double upscale = 0, until = kEndAt;
  int max_evaluations = 10;
  std::vector<long> seeds;
};

[[noreturn]] void usage(int code) {
  repro::exit_with_usage(code,
                         "usage: study_backcalc_seeds --reference HISTORY.csv --upscale N --seeds 1,2,3 --out DIR\n"
                         "         [--until PA] [--cache DIR] [--max-evaluations K]\n"
                         "Back-calculates sigma_lim0 of the Chapter 5 Wang specimen at N against the reference\n"
                         "curve (t_s, strain, stress_back_pa; cut at the first sample reaching --until, default\n"
                         "72e6 Pa) once per packing seed, as the set does for seed 1. Resumable: a seed whose\n"
                         "DIR/N<N>_seed<K>.json exists is not rerun.\n");
}

std::vector<long> parse_seeds(const std::string& text) {
  std::vector<long> out;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    char* end = nullptr;
    const long k = std::strtol(item.c_str(), &end, 10);
    if (item.empty() || *end != '\0' || k < 1) {
      std::fprintf(stderr, "--seeds: '%s' is not a list of positive whole numbers\n", text.c_str());
      usage(1);
    }
    out.push_back(k);
  }
  return out;
}

Options parse(int argc, char** argv) {
  Options o;
  repro::read_flags(argc, argv, usage, [&](const std::string& a, repro::FlagReader& r) {
    if (a == "--reference") o.reference = r.value();
    else if (a == "--upscale") o.upscale = r.number();
    else if (a == "--seeds") o.seeds = parse_seeds(r.value());
    else if (a == "--out") o.out = r.value();
    else if (a == "--until") o.until = r.number();
    else if (a == "--cache") o.cache = r.value();
    else if (a == "--max-evaluations") o.max_evaluations = static_cast<int>(r.integer());
    else return false;
    return true;
  });
  if (o.reference.empty() || o.out.empty() || o.seeds.empty() || !(o.upscale > 1) || o.max_evaluations < 3) usage(1);
  o.cache = repro::packing_cache_dir(o.cache, o.out);
  return o;
}

// The reference run as the set holds it: samples up to and including the first at `until`.
ch5::CaseResult read_reference(const std::string& path, double until) {
  const io::CsvTable h = io::read_csv(path);
  ch5::CaseResult r;
  r.ok = true;
  const auto t = h.column("t_s"), strain = h.column("strain"), stress = h.column("stress_back_pa");
  for (std::size_t k = 0; k < t.size(); ++k) {
    r.t.push_back(t[k]), r.strain.push_back(strain[k]), r.stress_back.push_back(stress[k]);
    if (stress[k] >= until) break;
  }
  return r;
}

}  // namespace

int main(int argc, char** argv) {
  repro::line_buffered_stdout();
  const Options o = parse(argc, argv);
  const std::string dir = std::string(KOLSKY_SOURCE_DIR) + "/reproductions/chapter5";
  std::filesystem::create_directories(o.out);
  ch5::CaseResult reference;
  try {
    reference = read_reference(o.reference, o.until);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "study_backcalc_seeds: %s\n", e.what());
    return 2;
  }
  std::printf("reference %s: %zu samples to back stress %.1f MPa\n", o.reference.c_str(), reference.t.size(),
              reference.stress_back.back() / 1e6);
  const double eq517 = dem::upscaled_sigma_lim0(kSigmaN1, o.upscale, ch5::scene_m1(dir, "scene_wang.json"));
  std::vector<double> sigmas;
  for (long seed : o.seeds) {
    char name[64];
    std::snprintf(name, sizeof name, "/N%g_seed%ld.json", o.upscale, seed);
    const std::string file = o.out + name;
    if (std::filesystem::exists(file)) {
      const nlohmann::json j = scene::read_json_file(file);
      sigmas.push_back(j.at("sigma_lim0").get<double>());
      std::printf("N = %g, seed %ld: done before, %.4g GPa\n", o.upscale, seed, sigmas.back() / 1e9);
      continue;
    }
    ch5::BackCalcSettings bc;
    bc.guess = eq517;
    bc.factor = kBracket;
    bc.max_evaluations = o.max_evaluations;
    bc.stress_lo = 1e6;
    const auto run = [&](double sigma) {
      ch5::CaseSpec s;
      s.label = "N = " + std::to_string(o.upscale) + ", seed " + std::to_string(seed);
      s.scene = "scene_wang.json";
      s.upscale = o.upscale;
      s.sigma_lim0 = sigma;
      s.fines_d_min = kFinesDMin;
      s.loading_file = kLoading;
      s.end_at_back_stress = kEndAt;
      s.end_time = kEndTime;
      s.seed = seed;
      return ch5::run_case(s, dir, o.cache);
    };
    const ch5::BackCalcResult r = ch5::back_calculate(run, reference, bc);
    nlohmann::json j;
    j["upscale"] = o.upscale;
    j["seed"] = seed;
    j["sigma_lim0"] = r.sigma;
    j["eq517"] = eq517;
    j["rms_pa"] = r.score;
    j["bracket"] = {r.bracket_lo, r.bracket_hi};
    j["converged"] = r.converged;
    j["runs"] = r.evaluated.size();
    for (const auto& [s, score] : r.evaluated) j["evaluated"].push_back({s, score});
    j["note"] = r.note;
    repro::write_json_atomic(file, j);
    sigmas.push_back(r.sigma);
    std::printf("N = %g, seed %ld: %.4g GPa (/ Eq. 5.17 %.3f), RMS %.2f MPa, %zu runs%s\n", o.upscale, seed,
                r.sigma / 1e9, r.sigma / eq517, r.score / 1e6, r.evaluated.size(), r.converged ? "" : ", not converged");
  }
  const repro::SampleStat s = repro::sample_stat(sigmas);
  std::printf("N = %g over %zu seeds: sigma_lim0 %.4g +- %.2g GPa (mean +- sample sd), / Eq. 5.17 %.3f +- %.3f\n",
              o.upscale, sigmas.size(), s.mean / 1e9, s.sd / 1e9, s.mean / eq517, s.sd / eq517);
  return 0;
}
