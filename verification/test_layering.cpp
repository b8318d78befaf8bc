// House rules that keep the tree readable, checked on the sources themselves:
//  - modules depend downward only (docs/architecture.md): core <- time <- psd <- physics (bar,
//    fe, dem, eos) <- coupling <- shpb <- io <- scene | plot | ensemble <- sweep <- app; physics
//    never includes io, scene, plot or app;
//  - every number a reproduction target quotes from the dissertation is also recorded, with
//    its provenance, under data/digitized/ (same id, same value).
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <regex>
#include <set>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace {

// psd (grain-size curves) holds no physics: DEM packing builds on it, so it sits below.
// coupling is where two physics modules may meet (FE surfaces <-> DEM walls, for the coupled
// FEM-DEM assembly of shpb/assembly.hpp), so it sits above them and below shpb.
// plot (gnuplot figures, for the program and the reports) draws shpb records and needs no
// scene: a sibling of scene, so neither includes the other and no physics includes plotting.
// ensemble (many runs on threads or MPI ranks) holds no physics and needs only core: a sibling
// of scene and plot, for the program (kolsky sweep) and the reproduction sets.
// sweep (kolsky sweep's members, table and figures) builds on scene, plot and ensemble.
const std::map<std::string, int> kLayer = {{"core", 0}, {"time", 1},     {"psd", 2},  {"bar", 3},
                                           {"fe", 3},   {"dem", 3},      {"eos", 3},  {"coupling", 4},
                                           {"shpb", 5}, {"io", 6},       {"scene", 7}, {"plot", 7},
                                           {"ensemble", 7}, {"sweep", 8}, {"app", 9}};

TEST(Layering, ModulesIncludeOnlyLowerLayers) {
  const fs::path solver = fs::path(KOLSKY_SOURCE_DIR) / "solver";
  const std::regex include_re("#include \"([a-z_]+)/");
  int files = 0;
  for (const auto& entry : fs::recursive_directory_iterator(solver)) {
    if (!entry.is_regular_file()) continue;
    const auto ext = entry.path().extension();
    if (ext != ".hpp" && ext != ".cpp") continue;
    const std::string module = entry.path().parent_path().filename().string();
    ASSERT_TRUE(kLayer.count(module)) << "unknown module folder " << module;
    ++files;
    std::ifstream f(entry.path());
    std::string line;
    while (std::getline(f, line)) {
      std::smatch m;
      if (!std::regex_search(line, m, include_re)) continue;
      const std::string dep = m[1];
      ASSERT_TRUE(kLayer.count(dep)) << entry.path() << " includes unknown module " << dep;
      // Physics modules are siblings: none includes another (they meet in shpb).
      const bool ok = dep == module || kLayer.at(dep) < kLayer.at(module);
      EXPECT_TRUE(ok) << entry.path().string() << " (" << module << ") includes " << dep
                      << ": modules may include only lower layers";
    }
  }
  EXPECT_GT(files, 10);
}

TEST(Provenance, TargetReferencesMatchDigitizedValues) {
  const fs::path root(KOLSKY_SOURCE_DIR);
  std::map<std::string, double> digitized;
  for (const auto& entry : fs::recursive_directory_iterator(root / "data" / "digitized")) {
    if (entry.path().filename() != "reported.json") continue;
    std::ifstream f(entry.path());
    const auto doc = nlohmann::json::parse(f);  // kept alive: ranging over a temporary's member dangles
    for (const auto& v : doc.at("values"))
      digitized[v.at("id").get<std::string>()] = v.at("value").get<double>();
  }
  int matched = 0;
  std::vector<fs::path> files;  // targets.json, and targets_smoke.json where a set has one
  for (const auto& entry : fs::directory_iterator(root / "reproductions"))
    for (const char* name : {"targets.json", "targets_smoke.json"})
      if (fs::exists(entry.path() / name)) files.push_back(entry.path() / name);
  for (const fs::path& t : files) {
    std::ifstream f(t);
    const auto doc = nlohmann::json::parse(f);
    for (const auto& target : doc.at("targets")) {
      const std::string id = target.at("id");
      const auto& ref = target.at("reference");
      if (!digitized.count(id) || !ref.contains("value")) continue;
      const double want = digitized.at(id);
      const double scale = target.value("unit", "") == "MPa" ? 1e6 : 1.0;  // data files are SI
      EXPECT_NEAR(ref.at("value").get<double>() * scale, want, 1e-9 * std::abs(want))
          << id << ": targets.json and data/digitized disagree";
      ++matched;
    }
  }
  EXPECT_GE(digitized.size(), 4u) << "no data/digitized/*/reported.json found";
  EXPECT_GE(matched, 4) << "targets quoting the dissertation should be recorded in data/digitized";
}

}  // namespace
