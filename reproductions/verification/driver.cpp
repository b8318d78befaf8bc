// Reproduction set "verification": runs every analytic check (verification/checks/) and writes
// reports/verification/report.md (check, expected, got, error, tolerance, pass) and
// results.json in the common results format (value = got, lo/hi = the tolerance interval).
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>

#include <nlohmann/json.hpp>

#include "checks/check.hpp"
#include "common/driver_args.hpp"
#include "core/atomic_file.hpp"
#include "harness/baseline.hpp"
#include "harness/gate.hpp"
#include "core/build_info.hpp"

using namespace kolsky;

namespace {

std::string num(double x) {
  char b[32];
  std::snprintf(b, sizeof b, "%.6g", x);
  return b;
}

}  // namespace

int main(int argc, char** argv) {
  const auto args = repro::parse_driver_args(argc, argv, "verification");
  const auto start = std::chrono::steady_clock::now();
  std::vector<verify::CheckResult> checks;
  for (auto group : {verify::bar_checks, verify::specimen_checks, verify::analysis_checks,
                     verify::fe_coupling_checks, verify::dem_coupling_checks})
    for (auto& c : group()) checks.push_back(std::move(c));
  const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();

  nlohmann::json results{{"set", "verification"}, {"scale", args.scale},
                         {"git_commit", build_info::git_commit()}, {"wall_time_s", wall},
                         {"targets", nlohmann::json::array()}};
  std::string md = "# Verification checks\n\nCommit `" + std::string(build_info::git_commit()) +
                   "`, wall time " + num(wall) + " s. Each check compares the code with a closed "
                   "form; the tolerance column says why it is what it is. Errors are relative "
                   "unless the check says absolute.\n\n"
                   "| check | closed form | expected | got | error | tolerance | why | pass |\n"
                   "|---|---|---|---|---|---|---|---|\n";
  int failed = 0;
  for (const auto& c : checks) {
    const double span = c.relative ? c.tolerance * std::fabs(c.expected) : c.tolerance;
    results["targets"].push_back({{"id", c.id}, {"value", c.got}, {"lo", c.expected - span},
                                  {"hi", c.expected + span}, {"reference", c.expected},
                                  {"unit", c.unit}, {"source", c.closed_form},
                                  {"status", "expected_pass"}, {"pass", c.pass()},
                                  {"error", c.error}, {"tolerance", c.tolerance},
                                  {"relative", c.relative}, {"note", c.note}});
    failed += c.pass() ? 0 : 1;
    md += "| `" + c.id + "` " + c.description + " | " + c.closed_form + " | " + num(c.expected) +
          " " + c.unit + " | " + num(c.got) + " | " + num(c.error) + (c.relative ? "" : " (abs)") +
          " | " + num(c.tolerance) + " | " + c.why_tolerance + " | " +
          (c.pass() ? "<span style=\"color:green\">pass</span>"
                    : "<span style=\"color:red\">FAIL</span>") + " |\n";
  }
  // The regression gate sees every check's value (docs/reproductions.md, "Regression gate").
  harness::Measurements m;
  for (const auto& c : checks) m.scalar(c.id, c.got);
  harness::write_measurements(args.out_dir, "verification", args.scale, m);
  md += harness::baseline_section_markdown(
      harness::compare_with_committed(args.repo_root, "verification", args.scale, m), args.scale);
  md += "\n## Notes\n\n";
  for (const auto& c : checks)
    if (!c.note.empty()) md += "- `" + c.id + "`: " + c.note + "\n";
  std::filesystem::create_directories(args.out_dir);
  write_file_atomic(args.out_dir + "/results.json", results.dump(2) + "\n");
  write_file_atomic(args.out_dir + "/report.md", md);
  std::printf("reproduce_verification: %zu checks, %d failed; report in %s/report.md\n",
              checks.size(), failed, args.out_dir.c_str());
  return failed == 0 ? 0 : 1;
}
