// Reproduction set "chapter5": the dissertation's Chapter 5 (headed "CHAPTER 6"), DEM with
// particle breakage (PFC3D in the text): the Wang et al. (2018) and Huang et al. (2013) tests by
// strain-rate-controlled walls and the Song et al. (2009) test in the full sphere-chain SHPB,
// with Ciantia's Hertzian-contact breakage (docs/breakage.md); the automated back-calculation
// of sigma_lim0(N) against Eq. 5.17, with its twin experiment; speed against error of N.
// What runs at which scale: cases_<scale>.json; targets: targets.json / targets_smoke.json.
// Environment: KOLSKY_CH5_STUDIES="wang,huang,song" (default all) runs a subset; the
// targets of a study not run read "not measured"; KOLSKY_CH5_CASES=file.json replaces
// cases_<scale>.json (the report names the file); KOLSKY_CH5_SERIAL=1 runs the studies one
// after the other instead of side by side.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <initializer_list>
#include <string>
#include <thread>
#include <utility>

#include "chapter5/studies.hpp"
#include "common/driver_args.hpp"
#include "common/report_input.hpp"
#include "core/errors.hpp"
#include "harness/report.hpp"

using namespace kolsky;
using ch5::fmt;

namespace {

bool wanted(const std::string& study) {
  const char* env = std::getenv("KOLSKY_CH5_STUDIES");
  if (!env) return true;
  const std::string list = std::string(",") + env + ",";
  return list.find("," + study + ",") != std::string::npos;
}

}  // namespace

int main(int argc, char** argv) {
  std::setvbuf(stdout, nullptr, _IOLBF, 0);  // progress lines reach a log file as they happen
  const auto args = repro::parse_driver_args(argc, argv, "chapter5");
  const auto start = std::chrono::steady_clock::now();
  const bool smoke = args.scale == "smoke";
  harness::ReportInput rep = repro::report_input(args, repro::SmokeTargets::own_file);
  ch5::Study s;
  s.smoke = smoke;
  s.dir = args.set_dir();
  s.cache = std::filesystem::absolute(rep.out_dir + "/packing_cache").string();
  // KOLSKY_CH5_CASES=file.json: another list of cases (e.g. fewer N) at this scale's targets.
  const char* cases_env = std::getenv("KOLSKY_CH5_CASES");
  const std::string cases_path = cases_env ? cases_env : args.set_dir() + "/cases_" + args.scale + ".json";
  s.cases = ch5::read_json(cases_path);
  const std::string cases_name = cases_env ? cases_path : "cases_" + args.scale + ".json";
  s.reported = ch5::read_json(args.repo_root + "/data/digitized/chapter5/reported.json");
  s.perturb_seed = args.perturb_seed;
  // The trends' thresholds (docs/reproductions.md): this scale's targets file, and targets.json
  // for the targets the smoke file leaves out but the smoke runs still measure (and gate).
  harness::TargetSet targets, full_targets;
  try {
    targets = harness::load_targets(rep.targets_path, args.repo_root);
    full_targets = smoke ? harness::load_targets(args.set_dir() + "/targets.json", args.repo_root) : targets;
  } catch (const InputError& e) {
    std::fprintf(stderr, "reproduce_chapter5: %s\n", e.what());
    return 2;
  }
  s.targets = &targets;
  s.full_targets = &full_targets;
  // Two parts side by side: Wang (the N pair, the variants and the back-calculations: about
  // half the cost) on this thread, Huang then Song on a second. Each part measures into its own
  // copy; they are merged in the fixed order Wang, Huang, Song, so the report does not depend
  // on which finished first. Each DEM step picks one or two OpenMP threads by its own timing
  // (dem/thread_governor: one while the other core is busy), and results do not depend on the
  // thread count (docs/dem.md), so every value is the serial run's.
  struct Part {
    ch5::Study s;
    harness::Measurements m;
    std::vector<harness::Plot> plots;
    std::exception_ptr error;
  };
  Part wang{s, {}, {}, nullptr}, others{s, {}, {}, nullptr};
  for (Part* p : {&wang, &others}) p->s.m = &p->m, p->s.plots = &p->plots;
  using StudyFn = void (*)(ch5::Study&);
  const auto run_part = [](Part& p, std::initializer_list<std::pair<const char*, StudyFn>> studies) {
    try {
      for (const auto& [name, study] : studies)
        if (wanted(name)) study(p.s);
    } catch (...) {
      p.error = std::current_exception();
    }
  };
  const auto run_wang = [&] { run_part(wang, {{"wang", ch5::wang_study}}); };
  const auto run_others = [&] { run_part(others, {{"huang", ch5::huang_study}, {"song", ch5::song_study}}); };
  const char* serial = std::getenv("KOLSKY_CH5_SERIAL");
  if (serial && std::string(serial) == "1") {
    run_wang();
    run_others();
  } else {
    std::thread second(run_others);
    run_wang();
    second.join();
  }
  for (Part* p : {&wang, &others}) {
    try {
      if (p->error) std::rethrow_exception(p->error);
    } catch (const std::exception& e) {
      std::fprintf(stderr, "reproduce_chapter5: %s\n", e.what());
      return 1;
    }
    rep.m.merge(p->m);
    rep.plots.insert(rep.plots.end(), p->plots.begin(), p->plots.end());
    s.markdown += p->s.markdown;
  }
  rep.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rep.preamble_markdown = fmt("Scale **%s** (%s), %.0f s on %s. Inputs the text shows only as figures are "
                              "reconstructions (data/digitized/chapter5/, each with its .meta.json); the initial grain counts "
                              "are what the grain-size curves were fitted to, so they are reported here, not scored.\n\n",
                              args.scale.c_str(), cases_name.c_str(), rep.wall_time_s,
                              std::getenv("OMP_NUM_THREADS") ? (std::string(std::getenv("OMP_NUM_THREADS")) + " thread(s)").c_str()
                                                             : "the default threads") +
                          s.markdown;
  const int failed = harness::write_report(rep);
  std::printf("chapter5: %d expected target(s) failed; report in %s\n", failed, rep.out_dir.c_str());
  return failed == 0 ? 0 : 1;
}
