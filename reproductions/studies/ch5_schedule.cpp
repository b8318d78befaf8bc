// study_ch5_schedule: the list-scheduling model of the Chapter 5 set as an ensemble (issue 33;
// reproductions/chapter5/set.hpp) from a members log: the members.json a reproduce_chapter5 run
// writes beside its report, or the measured table of the last full runs
// (reproductions/chapter5/members_full_measured.json). Phase by phase (each waits for the one
// before), each phase's members longest first to the first free rank
// (ensemble::simulate_list_schedule): makespan, critical path (the phases' longest members
// summed) and idle fraction, and which member is each phase's longest.
//   study_ch5_schedule MEMBERS.json [RANKS ...] [--json OUT]   (default ranks: 1 2 4 8 16 64)
// --json OUT also writes the model in Google Benchmark's JSON shape (one BM_Ch5SetModel/K entry
// per rank count, counters makespan_s, critical_path_s, idle_fraction), which
// scripts/run-benchmarks.sh keeps in benchmarks/results/ for `make bench-summary`.
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include "chapter5/set.hpp"
#include "studies/study_cli.hpp"

using namespace kolsky;

int main(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]) == "--help")
    repro::exit_with_usage(argc < 2 ? 1 : 0, "usage: study_ch5_schedule MEMBERS.json [RANKS ...] [--json OUT]\n");
  std::vector<ch5::MemberRecord> log;
  try {
    std::ifstream f(argv[1]);
    if (!f) throw std::runtime_error(std::string(argv[1]) + ": cannot be read");
    log = ch5::members_from_json(nlohmann::json::parse(f));
  } catch (const std::exception& e) {
    std::fprintf(stderr, "study_ch5_schedule: %s\n", e.what());
    return 2;
  }
  std::vector<int> ranks;
  std::string json_out;
  for (int i = 2; i < argc; ++i) {
    if (std::string(argv[i]) == "--json") {
      if (i + 1 >= argc) repro::exit_with_usage(1, "study_ch5_schedule: --json needs a file name\n");
      json_out = argv[++i];
    } else {
      ranks.push_back(std::atoi(argv[i]));
    }
  }
  if (ranks.empty()) ranks = {1, 2, 4, 8, 16, 64};
  double total = 0;
  std::vector<std::string> phases;
  for (const auto& m : log) {
    total += m.wall_s;
    if (phases.empty() || phases.back() != m.phase) phases.push_back(m.phase);
  }
  std::printf("%s: %zu members, %.0f s of member time\n\n", argv[1], log.size(), total);
  for (const std::string& phase : phases) {
    const ch5::MemberRecord* longest = nullptr;
    double sum = 0;
    for (const auto& m : log)
      if (m.phase == phase) {
        sum += m.wall_s;
        if (longest == nullptr || m.wall_s > longest->wall_s) longest = &m;
      }
    std::printf("phase %s: %.0f s in all, longest %s (%.0f s)\n", phase.c_str(), sum, longest->label.c_str(),
                longest->wall_s);
  }
  std::printf("\n| ranks | makespan | critical path | idle |\n|---|---|---|---|\n");
  nlohmann::json entries = nlohmann::json::array();
  for (int k : ranks) {
    if (k < 1) continue;
    const ch5::SetSchedule s = ch5::model_schedule(log, k);
    std::printf("| %d | %.0f s (%.1f min) | %.0f s | %.0f %% |\n", k, s.makespan, s.makespan / 60, s.critical_path,
                100 * s.idle_fraction);
    const std::string name = "BM_Ch5SetModel/" + std::to_string(k);
    entries.push_back({{"name", name}, {"run_name", name}, {"run_type", "iteration"}, {"iterations", 1},
                       {"real_time", s.makespan}, {"cpu_time", s.makespan}, {"time_unit", "s"},
                       {"ranks", k}, {"makespan_s", s.makespan}, {"critical_path_s", s.critical_path},
                       {"idle_fraction", s.idle_fraction}, {"label", "model of " + std::to_string(log.size()) + " members"}});
  }
  if (!json_out.empty()) {
    char date[32];
    const std::time_t now = std::chrono::system_clock::to_time_t(std::chrono::system_clock::now());
    std::strftime(date, sizeof date, "%Y-%m-%dT%H:%M:%S+00:00", std::gmtime(&now));
    repro::write_json_atomic(json_out, {{"context", {{"date", date}, {"kind", "model"}, {"members_file", argv[1]},
                                                     {"members", log.size()}, {"member_seconds", total}}},
                                        {"benchmarks", entries}});
    std::printf("\nwrote %s\n", json_out.c_str());
  }
  return 0;
}
