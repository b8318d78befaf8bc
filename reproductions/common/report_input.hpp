// The report a driver fills, set up from its command line: the set, the scale, its targets
// file (targets_smoke.json at the smoke scale for a set that has smoke bands, targets.json
// otherwise), the output folder (created now: the drivers write caches there before the
// report) and the source tree that curve references are relative to.
#pragma once
#include <filesystem>
#include <string>

#include "common/driver_args.hpp"
#include "harness/report.hpp"

namespace kolsky::repro {

enum class SmokeTargets { own_file, same_as_full };

inline harness::ReportInput report_input(const DriverArgs& a, SmokeTargets smoke_targets) {
  harness::ReportInput rep;
  rep.set = a.set;
  rep.scale = a.scale;
  const bool own = smoke_targets == SmokeTargets::own_file && a.scale == "smoke";
  rep.targets_path = a.set_dir() + (own ? "/targets_smoke.json" : "/targets.json");
  rep.out_dir = a.out_dir;
  rep.repo_root = a.repo_root;
  std::filesystem::create_directories(rep.out_dir);
  return rep;
}

}  // namespace kolsky::repro
