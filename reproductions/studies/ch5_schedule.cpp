// study_ch5_schedule: the list-scheduling model of the Chapter 5 set as an ensemble (issue 33;
// reproductions/chapter5/set.hpp) from a members log: the members.json a reproduce_chapter5 run
// writes beside its report, or the measured table of the last full runs
// (reproductions/chapter5/members_full_measured.json). Phase by phase (each waits for the one
// before), each phase's members longest first to the first free rank
// (ensemble::simulate_list_schedule): makespan, critical path (the phases' longest members
// summed) and idle fraction, and which member is each phase's longest.
//   study_ch5_schedule MEMBERS.json [RANKS ...]   (default ranks: 1 2 4 8 16 64)
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <string>
#include <vector>

#include "chapter5/set.hpp"
#include "studies/study_cli.hpp"

using namespace kolsky;

int main(int argc, char** argv) {
  if (argc < 2 || std::string(argv[1]) == "--help")
    repro::exit_with_usage(argc < 2 ? 1 : 0, "usage: study_ch5_schedule MEMBERS.json [RANKS ...]\n");
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
  for (int i = 2; i < argc; ++i) ranks.push_back(std::atoi(argv[i]));
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
  for (int k : ranks) {
    if (k < 1) continue;
    const ch5::SetSchedule s = ch5::model_schedule(log, k);
    std::printf("| %d | %.0f s (%.1f min) | %.0f s | %.0f %% |\n", k, s.makespan, s.makespan / 60, s.critical_path,
                100 * s.idle_fraction);
  }
  return 0;
}
