// kolsky's side of the peer agreement check (benchmarks/lammps/agreement.sh): runs the
// bench_dem compaction scene (compaction_scene.hpp, the scene BM_DemCompaction times) and
// prints, at the requested steps, what the LAMMPS and LIGGGHTS decks print at the same steps:
// lid, bottom and tube forces (N, magnitudes) and the mean grain-grain coordination.
//
//   dem_agreement [--pack FILE] [--cut Z] [--dt S] [--steps 100,893] [--threads N]
//
// --cut Z keeps the grains with z + r <= Z and puts the lid at Z (the small scene of
// verification/test_dem_peer_reference.cpp); --dt replaces the scene's step (the peers use
// 3.78e-8 s, the shared README's value; the scene's own is printed). Output: a header line,
// then one tab-separated row per step: step, lid_N, bottom_N, tube_N, coordination, and a
// last line `# loop L s for S steps with N grains`: the wall time from the first requested
// step to the last (--steps 100,893: the 793 steps LAMMPS' "Loop time" covers in run.sh).
// Not named bench_*: scripts/run-benchmarks.sh runs every build/benchmarks/bench_* as a
// Google Benchmark.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <sstream>
#include <string>
#include <vector>

#include "compaction_scene.hpp"

namespace {

int usage(const char* why) {
  std::fprintf(stderr, "dem_agreement: %s\nusage: dem_agreement [--pack FILE] [--cut Z] "
               "[--dt S] [--steps 100,893] [--threads N]\n", why);
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace kolsky;
  std::string pack = bench::shared_pack_path();
  double cut = 0, dt = 0;
  std::vector<int> steps{100, 893};
  int threads = 1;
  for (int a = 1; a < argc; ++a) {
    const std::string k = argv[a];
    if (a + 1 >= argc) return usage(("missing value after " + k).c_str());
    const std::string v = argv[++a];
    if (k == "--pack") pack = v;
    else if (k == "--cut") cut = std::atof(v.c_str());
    else if (k == "--dt") dt = std::atof(v.c_str());
    else if (k == "--threads") threads = std::atoi(v.c_str());
    else if (k == "--steps") {
      steps.clear();
      std::istringstream in(v);
      for (std::string s; std::getline(in, s, ',');) steps.push_back(std::atoi(s.c_str()));
    } else return usage(("unknown option " + k).c_str());
  }
  std::sort(steps.begin(), steps.end());
  if (steps.empty() || steps.front() < 0 || threads < 1 || cut < 0 || dt < 0)
    return usage("bad --steps, --threads, --cut or --dt");
  bench::Specimen s;
  const bool ok = cut > 0 ? bench::read_pack(pack, s, cut) : bench::read_pack(pack, s);
  if (!ok) {
    std::fprintf(stderr, "dem_agreement: cannot read %s (the shared packing "
                 "pack_35k.data.gz; --pack FILE)\n", pack.c_str());
    return 2;
  }
  if (cut > 0) s.top = cut;
  omp_set_num_threads(threads);
  // The thread count asked for at every step: the peer figures compare fixed counts (the
  // thread governor, docs/dem.md "Threads beside a busy core", has its own benchmark case).
  dem::DemOptions opt;
  opt.adapt_threads = false;
  bench::Scene sc = bench::make_scene(s, opt);
  std::printf("# %zu grains, lid at %.6g m, scene dt %.6e s, used dt %.6e s, %d thread(s)\n",
              s.particles.size(), s.top, sc.dt, dt > 0 ? dt : sc.dt, threads);
  if (dt > 0) sc.dt = dt;
  std::printf("step\tlid_N\tbottom_N\ttube_N\tcoordination\n");
  int done = 0;
  double loop_s = 0;
  for (int target : steps) {
    const auto t0 = std::chrono::steady_clock::now();
    for (; done < target; ++done) sc.sys->step(sc.dt);
    if (target != steps.front())  // the rows' output stays outside the timed steps
      loop_s += std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    if (target == 0) sc.sys->compute_forces();
    const bench::PeerQuantities q = bench::peer_quantities(*sc.sys);
    std::printf("%d\t%.6g\t%.6g\t%.6g\t%.6g\n", target, q.lid_force, q.bottom_force,
                q.tube_force, q.coordination);
    std::fflush(stdout);
  }
  std::printf("# loop %.6g s for %d steps with %zu grains\n", loop_s, steps.back() - steps.front(),
              s.particles.size());
  return 0;
}
