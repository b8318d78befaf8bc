// kolsky_gate: the regression gate's command line (docs/reproductions.md, "Regression gate").
//   kolsky_gate check --results DIR [--scale smoke] [--repo ROOT] [--all]
//     compares DIR/<set>/measurements.json with reproductions/<set>/baseline_<scale>.json for
//     every set that has a driver, checks that reproductions/BASELINES.md logs each baseline's
//     digest, prints the table of what moved; exit 0 clean, 1 a value moved or a log line is
//     missing, 2 bad input.
//   kolsky_gate rebaseline --set S --scale smoke|full --runs D0 [D1 ...] --reason TEXT
//                          [--commit C] [--repo ROOT]
//     D0 is the unperturbed run, D1... the --perturb-ulp reruns (scripts/rebaseline.sh makes
//     them); writes the baseline and appends the log entry.
#include "core/atomic_file.hpp"
#include "core/build_info.hpp"
#include "core/errors.hpp"
#include "harness/baseline.hpp"
#include "harness/gate.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace kolsky;
using namespace kolsky::harness;
namespace fs = std::filesystem;

namespace {

constexpr const char* kUsage =
    "usage: kolsky_gate check --results DIR [--scale smoke|full] [--repo ROOT] [--all]\n"
    "       kolsky_gate rebaseline --set SET --scale smoke|full --runs D0 [D1 ...] --reason TEXT\n"
    "                              [--commit C] [--repo ROOT]\n";

struct Args {
  std::string command, results, scale = "smoke", repo = KOLSKY_SOURCE_DIR, set, reason, commit;
  std::vector<std::string> runs;
  bool all = false;
};

[[noreturn]] void usage(const std::string& why) {
  std::fprintf(stderr, "kolsky_gate: %s\n%s", why.c_str(), kUsage);
  std::exit(1);
}

Args parse(int argc, char** argv) {
  Args a;
  if (argc < 2) usage("missing command");
  a.command = argv[1];
  if (a.command == "--help" || a.command == "-h") {
    std::fputs(kUsage, stdout);
    std::exit(0);
  }
  if (a.command != "check" && a.command != "rebaseline") usage("unknown command '" + a.command + "'");
  for (int i = 2; i < argc; ++i) {
    const std::string k = argv[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= argc) usage(k + " needs a value");
      return argv[++i];
    };
    if (k == "--results") a.results = value();
    else if (k == "--scale") a.scale = value();
    else if (k == "--repo") a.repo = value();
    else if (k == "--set") a.set = value();
    else if (k == "--reason") a.reason = value();
    else if (k == "--commit") a.commit = value();
    else if (k == "--all") a.all = true;
    else if (k == "--runs") {
      while (i + 1 < argc && std::string(argv[i + 1]).rfind("--", 0) != 0) a.runs.push_back(argv[++i]);
    } else usage("unknown option '" + k + "'");
  }
  if (a.scale != "smoke" && a.scale != "full") usage("--scale must be smoke or full");
  if (a.command == "check" && a.results.empty()) usage("check needs --results DIR");
  if (a.command == "rebaseline" && (a.set.empty() || a.runs.empty() || a.reason.empty()))
    usage("rebaseline needs --set, --runs and a non-empty --reason");
  return a;
}

std::string read_text(const std::string& path) {
  std::ifstream f(path);
  std::stringstream s;
  s << f.rdbuf();
  return s.str();
}

std::string log_path(const Args& a) { return a.repo + "/reproductions/BASELINES.md"; }

/// Sets with a driver (reproductions/<set>/driver.cpp), sorted.
std::vector<std::string> sets_with_driver(const std::string& repo) {
  std::vector<std::string> sets;
  for (const auto& e : fs::directory_iterator(repo + "/reproductions"))
    if (fs::exists(e.path() / "driver.cpp")) sets.push_back(e.path().filename().string());
  std::sort(sets.begin(), sets.end());
  return sets;
}

int check(const Args& a) {
  const std::string log = read_text(log_path(a));
  std::vector<GateRow> failing, shown;
  std::string summary;
  for (const std::string& set : sets_with_driver(a.repo)) {
    const std::string bpath = baseline_path(a.repo, set, a.scale);
    GateRow problem;
    problem.set = set;
    problem.id = "(set)";
    problem.verdict = Verdict::missing;
    if (!fs::exists(bpath)) {
      problem.why = "no " + fs::path(bpath).filename().string() +
                    ": make rebaseline SET=" + set + " SCALE=" + a.scale + " REASON=\"...\"";
      failing.push_back(problem);
      summary += "  " + set + ": no baseline\n";
      continue;
    }
    const Baseline b = load_baseline(bpath);
    if (b.set != set || b.scale != a.scale)
      throw InputError(bpath, "set", "is '" + b.set + "' at scale '" + b.scale + "', expected '" +
                                         set + "' at '" + a.scale + "'");
    if (!log_has_entry(log, b)) {
      problem.why = "baseline digest " + baseline_digest(b) + " has no entry in " + log_path(a) +
                    " (changed without make rebaseline?)";
      failing.push_back(problem);
    }
    const std::string mpath = a.results + "/" + set + "/measurements.json";
    if (!fs::exists(mpath)) {
      problem.why = mpath + " is missing (did reproduce_" + set + " --scale " + a.scale + " run?)";
      failing.push_back(problem);
      summary += "  " + set + ": no measurements\n";
      continue;
    }
    const auto rows = compare_to_baseline(b, read_measurements(mpath).m);
    std::map<Verdict, int> count;
    for (const auto& r : rows) {
      count[r.verdict]++;
      if (r.fails()) failing.push_back(r);
      if (a.all || r.fails() || r.verdict == Verdict::within) shown.push_back(r);
    }
    summary += "  " + set + ": " + std::to_string(rows.size()) + " values, " +
               std::to_string(count[Verdict::same]) + " bitwise equal, " +
               std::to_string(count[Verdict::within]) + " within tolerance, " +
               std::to_string(count[Verdict::ungated]) + " ungated, " +
               std::to_string(count[Verdict::moved] + count[Verdict::missing] + count[Verdict::added]) +
               " failing (baseline " + b.git_commit + ")\n";
  }
  std::printf("kolsky_gate: %s results in %s against reproductions/<set>/baseline_%s.json\n%s",
              a.scale.c_str(), a.results.c_str(), a.scale.c_str(), summary.c_str());
  if (!shown.empty()) std::printf("\n%s", gate_table_text(shown).c_str());
  if (failing.empty()) {
    std::printf("\nkolsky_gate: PASS\n");
    return 0;
  }
  std::printf("\nkolsky_gate: FAIL, %zu problem(s):\n%s", failing.size(), gate_table_text(failing).c_str());
  std::printf("If the change is intended: make rebaseline SET=<set> REASON=\"why the numbers moved\"\n");
  return 1;
}

std::string utc_now() {
  const std::time_t t = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
  char b[32];
  std::strftime(b, sizeof b, "%Y-%m-%d %H:%M UTC", std::gmtime(&t));
  return b;
}

int rebaseline(const Args& a) {
  const MeasurementsFile base = read_measurements(a.runs[0] + "/measurements.json");
  if (base.set != a.set || base.scale != a.scale)
    throw InputError(a.runs[0] + "/measurements.json", "set",
                     "is '" + base.set + "' at '" + base.scale + "', expected '" + a.set + "' at '" + a.scale + "'");
  std::vector<MeasurementsFile> perturbed;
  for (size_t i = 1; i < a.runs.size(); ++i) perturbed.push_back(read_measurements(a.runs[i] + "/measurements.json"));
  const std::string build = std::string(kolsky::build_info::build_type()) + ", GCC " + __VERSION__;
  Baseline b = make_baseline(base, perturbed, RebaselineRule{}, build, utc_now());
  if (!a.commit.empty()) b.git_commit = a.commit;

  const std::string bpath = baseline_path(a.repo, a.set, a.scale);
  std::string moved = "First baseline of this set and scale.\n";
  if (fs::exists(bpath)) {
    const auto rows = compare_to_baseline(load_baseline(bpath), base.m);
    std::vector<GateRow> changed;
    for (const auto& r : rows)
      if (r.verdict != Verdict::same) changed.push_back(r);
    moved = changed.empty()
                ? "Every value bitwise equal to the previous baseline (tolerances re-measured).\n"
                : std::to_string(changed.size()) + " of " + std::to_string(rows.size()) +
                      " values differ from the previous baseline (tolerance and verdict are the "
                      "previous baseline's):\n\n" + gate_table_markdown(changed);
  }
  write_file_atomic(bpath, baseline_json(b).dump(1) + "\n");

  std::string log = read_text(log_path(a));
  if (log.empty())
    log = "# Baseline log\n\nOne entry per `make rebaseline` (newest last), written by `kolsky_gate "
          "rebaseline`. The regression gate refuses a baseline whose digest has no entry here. "
          "Format and tolerance rule: docs/reproductions.md, \"Regression gate\".\n";
  log += "\n## " + b.created + " · " + a.set + " · " + a.scale + " · commit " + b.git_commit +
         " · digest " + baseline_digest(b) + "\n\nReason: " + a.reason + "\n\nMethod: " + b.method +
         ". Build: " + build + ".\n\n" + moved;
  write_file_atomic(log_path(a), log);
  std::printf("kolsky_gate: wrote %s (%zu values, digest %s) and a log entry in %s\n", bpath.c_str(),
              b.values.size(), baseline_digest(b).c_str(), log_path(a).c_str());
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const Args a = parse(argc, argv);
  try {
    return a.command == "check" ? check(a) : rebaseline(a);
  } catch (const InputError& e) {
    std::fprintf(stderr, "kolsky_gate: %s\n", e.what());
    return kExitInputError;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "kolsky_gate: %s\n", e.what());
    return kExitInputError;
  }
}
