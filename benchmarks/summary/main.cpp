// summarize_benchmarks: the benchmark tracking of benchmarks/results/ (reports/benchmarks/README.md).
//   summarize_benchmarks summary --results DIR --out DIR [--gnuplot PATH]     (make bench-summary)
//   summarize_benchmarks check --results DIR --margin ID=F... [--seed-as PREFIX] RUN.json...
//                                                                             (make bench-check)
//   summarize_benchmarks spread RUN.json...          (the spread of the ratios over several runs)
// Exit codes: 0 ok (check: no ratio dropped beyond its margin, or nothing to compare with);
// 1 check: a ratio dropped beyond its margin; 2 usage or input error.
// Not named bench_*: scripts/run-benchmarks.sh runs every build/benchmarks/bench_* binary.
#include <cstdlib>
#include <filesystem>
#include <iostream>
#include <map>
#include <set>
#include <string>
#include <vector>

#include "plot/gnuplot.hpp"
#include "summary/plot.hpp"
#include "summary/report.hpp"
#include "summary/results.hpp"

namespace {

using namespace kolsky::benchsum;
namespace fs = std::filesystem;

int usage(const std::string& why) {
  std::cerr << "summarize_benchmarks: " << why << "\n"
            << "usage: summarize_benchmarks summary --results DIR --out DIR [--gnuplot PATH]\n"
               "       summarize_benchmarks check --results DIR --margin ID=FRACTION... [--seed-as PREFIX] RUN.json...\n"
               "       summarize_benchmarks spread RUN.json...\n"
               "tracked ratio ids:";
  for (const Tracked& t : tracked()) std::cerr << " " << t.id;
  std::cerr << "\n";
  return 2;
}

// When no tracked file of a bench has a usable ratio of this run's reference version, the run
// itself becomes the first tracked value: copied to <results>/<prefix>_<bench>.json (the name `make
// bench` would give it), never over an existing file.
void seed(const std::vector<CheckRow>& rows, const std::vector<std::string>& run_paths,
          const std::vector<ResultFile>& runs, const std::string& results, const std::string& prefix) {
  std::set<std::string> benches;
  for (const CheckRow& r : rows)  // only where this run has a usable value to give
    if (!r.base && r.skipped.empty()) benches.insert(r.figure.bench);
  for (std::size_t k = 0; k < runs.size(); ++k) {
    if (!benches.count(runs[k].bench)) continue;
    const fs::path dest = fs::path(results) / (prefix + "_" + runs[k].bench + ".json");
    if (fs::exists(dest)) {
      std::cout << "bench-check: " << dest.string() << " exists; not overwritten (run `make bench` for a tracked file)\n";
      continue;
    }
    fs::copy_file(run_paths[k], dest);
    std::cout << "bench-check: no tracked " << runs[k].bench << " result had a reference: this run is now the tracked "
              << "value, " << dest.string() << " (short run; `make bench` gives a fuller one; review and commit it)\n";
  }
}

int check(const std::vector<std::string>& args) {
  std::string results, prefix;
  std::map<std::string, double> margins;
  std::vector<std::string> paths;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    if ((a == "--results" || a == "--margin" || a == "--seed-as") && i + 1 >= args.size())
      return usage(a + " needs a value");
    if (a == "--results") results = args[++i];
    else if (a == "--seed-as") prefix = args[++i];
    else if (a == "--margin") {
      const std::string m = args[++i];
      const std::size_t eq = m.find('=');
      char* end = nullptr;
      const double v = eq == std::string::npos ? -1 : std::strtod(m.c_str() + eq + 1, &end);
      if (eq == std::string::npos || end == m.c_str() + eq + 1 || *end != '\0' || !(v >= 0 && v < 1))
        return usage("--margin " + m + ": expected ID=FRACTION with 0 <= FRACTION < 1");
      margins[m.substr(0, eq)] = v;
    } else if (a.rfind("--", 0) == 0) return usage("unknown option " + a);
    else paths.push_back(a);
  }
  if (results.empty() || paths.empty()) return usage("check needs --results and at least one RUN.json");
  std::vector<std::string> skipped;
  const std::vector<ResultFile> tracked_files = read_results_dir(results, skipped);
  std::vector<ResultFile> runs;
  for (const std::string& p : paths) runs.push_back(read_result_file(p));
  const std::vector<CheckRow> rows = compare(tracked_files, runs, margins);
  if (rows.empty()) {
    std::cerr << "bench-check: the runs have no tracked ratio (kernel and BM_Reference)\n";
    return 2;
  }
  std::cout << "bench-check: this run (";
  for (std::size_t k = 0; k < paths.size(); ++k) std::cout << (k ? ", " : "") << paths[k];
  std::cout << ") against the newest tracked file of " << results << " with the same reference version\n\n"
            << format_check(rows) << "\n";
  bool any_base = false, regression = false;
  for (const CheckRow& r : rows) {
    any_base = any_base || r.base.has_value();
    regression = regression || r.regression;
  }
  bool missing = false;
  for (const CheckRow& r : rows) missing = missing || !r.base;
  if (missing) {
    if (!prefix.empty()) seed(rows, paths, runs, results, prefix);
    else std::cout << "bench-check: some figures have no tracked value with a reference; run `make bench`\n";
  }
  if (regression) {
    std::cout << "bench-check: FAILED: a ratio fell more than its margin below the tracked value\n";
    return 1;
  }
  std::cout << (any_base ? "bench-check: ok\n" : "bench-check: nothing to compare with yet\n");
  return 0;
}

int run(const std::vector<std::string>& args) {
  if (args.empty()) return usage("no command");
  const std::string cmd = args[0];
  const std::vector<std::string> rest(args.begin() + 1, args.end());
  if (cmd == "summary") {
    std::string results, out, gnuplot = kolsky::plot::default_gnuplot();
    for (std::size_t i = 0; i < rest.size(); ++i) {
      if (i + 1 >= rest.size()) return usage(rest[i] + " needs a value");
      if (rest[i] == "--results") results = rest[++i];
      else if (rest[i] == "--out") out = rest[++i];
      else if (rest[i] == "--gnuplot") gnuplot = rest[++i];
      else return usage("unknown option " + rest[i]);
    }
    if (results.empty() || out.empty()) return usage("summary needs --results and --out");
    std::vector<std::string> skipped;
    const std::vector<ResultFile> files = read_results_dir(results, skipped);
    write_summary(files, skipped, out, gnuplot, std::cout);
    return 0;
  }
  if (cmd == "check") return check(rest);
  if (cmd == "spread") {
    if (rest.empty()) return usage("spread needs RUN.json files");
    std::vector<ResultFile> runs;
    for (const std::string& p : rest) runs.push_back(read_result_file(p));
    std::cout << format_spread(runs);
    return 0;
  }
  return usage("unknown command " + cmd);
}

}  // namespace

int main(int argc, char** argv) {
  try {
    return run(std::vector<std::string>(argv + 1, argv + argc));
  } catch (const std::exception& e) {
    std::cerr << "summarize_benchmarks: " << e.what() << "\n";
    return 2;
  }
}
