// The peer check inside `make test`, without LAMMPS: kolsky's lid force on a cut of the
// benchmark packing (../shared/bench/pack_35k.data.gz, the grains with z + r <= 2 mm, the lid
// at 2 mm moving down at 9.3 m/s; the scene of bench_dem's BM_DemCompaction otherwise,
// benchmarks/compaction_scene.hpp) against the rows the LAMMPS deck
// benchmarks/lammps/in.compaction_granular printed for the same cut
// (benchmarks/lammps/reference/cut2mm_lammps_granular.tsv, written by
// `CUT=0.002 CODES=granular REFERENCE=... benchmarks/lammps/agreement.sh`). The tolerance, the
// first step checked and the reason for both are in cut2mm_tolerance.json beside it. The full
// scene's agreement with LAMMPS and LIGGGHTS (within 1.5 %) is agreement.sh's job.
#include <gtest/gtest.h>
#include <omp.h>

#include <cmath>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "compaction_scene.hpp"
#include "test_support.hpp"

namespace {

struct Row {
  int step = 0;
  double lid = 0;
};

std::vector<Row> read_reference(const std::string& path) {
  std::ifstream in(path);
  std::vector<Row> rows;
  std::string line;
  while (std::getline(in, line)) {
    if (line.empty() || line[0] == '#' || line.rfind("step", 0) == 0) continue;
    std::istringstream ls(line);
    Row r;
    if (ls >> r.step >> r.lid) rows.push_back(r);
  }
  return rows;
}

}  // namespace

TEST(DemPeerReference, LidForceOnCutOfPack35kMatchesLammpsGranular) {
  using namespace kolsky;
  const std::string dir = std::string(KOLSKY_SOURCE_DIR) + "/benchmarks/lammps/reference/";
  std::ifstream tin(dir + "cut2mm_tolerance.json");
  ASSERT_TRUE(tin) << "missing " << dir << "cut2mm_tolerance.json";
  const nlohmann::json tol = nlohmann::json::parse(tin);
  const std::vector<Row> ref = read_reference(dir + tol.at("reference").get<std::string>());
  ASSERT_GE(ref.size(), 5u) << "reference rows";
  const double cut = tol.at("cut_top_m").get<double>();
  const double rel = tol.at("relative_tolerance").get<double>();
  const int from = tol.at("from_step").get<int>();
  const std::string why = tol.at("reason").get<std::string>();

  bench::Specimen s;
  if (!bench::read_pack(bench::shared_pack_path(), s, cut))
    GTEST_SKIP() << bench::shared_pack_path() << " absent (the shared benchmark packing)";
  ASSERT_EQ(s.particles.size(), tol.at("grains").get<std::size_t>()) << "not the reference's cut";
  s.top = cut;
  // One thread: the results do not depend on the count (docs/dem.md, "Parallel determinism"),
  // and two spinning threads beside ctest's other tests on a 2-core machine take 7x longer.
  const int previous = omp_get_max_threads();
  omp_set_num_threads(1);
  bench::Scene sc = bench::make_scene(s);
  sc.dt = tol.at("timestep_s").get<double>();  // the decks' step, not the cut's own r_min

  int done = 0, checked = 0;
  double worst = 0;
  for (const Row& r : ref) {
    for (; done < r.step; ++done) sc.sys->step(sc.dt);
    if (r.step < from) continue;
    const double lid = bench::peer_quantities(*sc.sys).lid_force;
    const double d = (lid - r.lid) / r.lid;
    worst = std::max(worst, std::abs(d));
    ++checked;
    EXPECT_NEAR(lid, r.lid, rel * r.lid) << "step " << r.step << ": kolsky " << lid
                                         << " N, LAMMPS granular " << r.lid << " N (" << why << ")";
  }
  omp_set_num_threads(previous);
  EXPECT_GE(checked, 3) << "too few reference steps at or after " << from;
  kolsky::testing::record("worst_relative_lid_difference", worst);
}
