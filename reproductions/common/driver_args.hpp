// Command line shared by every reproduction driver:
//   reproduce_<set> [--scale smoke|full] [--out DIR] [--perturb-ulp SEED]
// --perturb-ulp moves every float of the set's scenes by one ulp (common/perturb.hpp); the
// regression gate's `make rebaseline` uses it to measure each value's round-off sensitivity.
// Scenes and targets are read from reproductions/<set>/ under the source tree the build came
// from (KOLSKY_SOURCE_DIR), so the drivers run from any working directory.
#pragma once
#include <cstdio>
#include <cstdlib>
#include <string>

namespace kolsky::repro {

struct DriverArgs {
  std::string scale = "full";
  std::string out_dir;
  std::string repo_root = KOLSKY_SOURCE_DIR;
  std::string set_dir() const { return repo_root + "/reproductions/" + set; }
  std::string set;
  unsigned perturb_seed = 0;  // 0: scenes as written
};

inline DriverArgs parse_driver_args(int argc, char** argv, const std::string& set) {
  // Progress lines reach a log file as they are printed (a full set runs for up to an hour;
  // block-buffered, its log showed nothing for tens of minutes).
  std::setvbuf(stdout, nullptr, _IOLBF, 0);
  DriverArgs a;
  a.set = set;
  a.out_dir = "reports/" + set;
  for (int i = 1; i < argc; ++i) {
    const std::string k = argv[i];
    if ((k == "--scale" || k == "--out") && i + 1 < argc) {
      (k == "--scale" ? a.scale : a.out_dir) = argv[++i];
    } else if (k == "--perturb-ulp" && i + 1 < argc) {
      const std::string v = argv[++i];
      char* end = nullptr;
      const unsigned long seed = std::strtoul(v.c_str(), &end, 10);
      if (v.empty() || *end != '\0' || seed == 0 || seed > 1000000) {
        std::fprintf(stderr, "reproduce_%s: --perturb-ulp needs a seed in 1..1000000\n", set.c_str());
        std::exit(1);
      }
      a.perturb_seed = static_cast<unsigned>(seed);
    } else {
      std::fprintf(stderr, "usage: reproduce_%s [--scale smoke|full] [--out DIR] [--perturb-ulp SEED]\n",
                   set.c_str());
      std::exit(k == "--help" ? 0 : 1);
    }
  }
  if (a.scale != "smoke" && a.scale != "full") {
    std::fprintf(stderr, "reproduce_%s: --scale must be smoke or full\n", set.c_str());
    std::exit(1);
  }
  return a;
}

}  // namespace kolsky::repro
