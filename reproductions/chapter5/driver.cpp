// Reproduction set "chapter5": the dissertation's Chapter 5 (headed "CHAPTER 6"), DEM with
// particle breakage (PFC3D in the text): the Wang et al. (2018) and Huang et al. (2013) tests by
// strain-rate-controlled walls and the Song et al. (2009) test in the full sphere-chain SHPB,
// with Ciantia's Hertzian-contact breakage (docs/breakage.md); the automated back-calculation
// of sigma_lim0(N) against Eq. 5.17, with its twin experiment; speed against error of N.
// What runs at which scale: cases_<scale>.json; targets: targets.json / targets_smoke.json.
// The cases run as an ensemble (set.hpp, docs/scale-out.md): on KOLSKY_CH5_THREADS threads
// (default 2; KOLSKY_CH5_SERIAL=1: one), or under `mpirun -n K` on K ranks, with the same
// values either way. Environment: KOLSKY_CH5_STUDIES="wang,huang,song" (default all) runs a
// subset; the targets of a study not run read "not measured"; KOLSKY_CH5_CASES=file.json
// replaces cases_<scale>.json (the report names the file); KOLSKY_CH5_RESUME=1 keeps each
// finished member's results in <out>/ensemble_cache/ and takes them from there on a rerun of
// the same build (a killed run resumes).
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <filesystem>
#include <string>

#include "chapter5/studies.hpp"
#include "common/driver_args.hpp"
#include "common/report_input.hpp"
#include "core/atomic_file.hpp"
#include "core/errors.hpp"
#include "ensemble/ensemble.hpp"
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

bool env_is(const char* name, const std::string& value) {
  const char* v = std::getenv(name);
  return v != nullptr && value == v;
}

int env_int(const char* name, int fallback) {
  const char* v = std::getenv(name);
  return v != nullptr && std::atoi(v) > 0 ? std::atoi(v) : fallback;
}

}  // namespace

int main(int argc, char** argv) {
  ensemble::MpiSession mpi(&argc, &argv);  // under mpirun the members spread over the ranks
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
  s.m = &rep.m;
  s.plots = &rep.plots;
  // The ensemble: members on threads, or on the ranks under mpirun; the scheduler's expected
  // costs from the last run's members.json in this folder where it has them.
  ch5::SetEnsemble e;
  e.options.threads = env_is("KOLSKY_CH5_SERIAL", "1") ? 1 : env_int("KOLSKY_CH5_THREADS", 2);
  if (env_is("KOLSKY_CH5_RESUME", "1")) e.options.cache_dir = rep.out_dir + "/ensemble_cache";
  const std::string members_path = rep.out_dir + "/members.json";
  e.costs = ch5::read_costs(members_path);
  const ensemble::RankLayout ranks = ensemble::rank_layout();
  const std::string where = ranks.size > 1 ? fmt("%d MPI ranks", ranks.size) : fmt("%d thread(s)", e.options.threads);
  try {
    if (!ch5::run_studies(s, e, wanted)) return 0;  // a rank other than 0: rank 0 reports
  } catch (const std::exception& ex) {
    std::fprintf(stderr, "reproduce_chapter5: %s\n", ex.what());
    return 1;
  }
  write_file_atomic(members_path, ch5::members_json(e.log).dump(1) + "\n");
  rep.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  rep.preamble_markdown = fmt("Scale **%s** (%s), %.0f s on %s. Inputs the text shows only as figures are "
                              "reconstructions (data/digitized/chapter5/, each with its .meta.json); the initial grain counts "
                              "are what the grain-size curves were fitted to, so they are reported here, not scored.\n\n",
                              args.scale.c_str(), cases_name.c_str(), rep.wall_time_s,
                              (where + ", OpenMP " + (std::getenv("OMP_NUM_THREADS") ? std::getenv("OMP_NUM_THREADS") : "default") +
                               " thread(s) each").c_str()) +
                          s.markdown + ch5::members_markdown(e.log, where);
  const int failed = harness::write_report(rep);
  std::printf("chapter5: %d expected target(s) failed; report in %s\n", failed, rep.out_dir.c_str());
  return failed == 0 ? 0 : 1;
}
