// Particle-count scaling and cost of the Chapter 5 breakage runs against the upscaling factor
// N, tracked over commits (issue 15; reproductions/chapter5/README.md, "Speed against error"):
//   BM_Ch5WangUpscaling/N10: the chapter5 set's Wang scene (reproductions/chapter5/
//     scene_wang.json: strain-rate walls, breakage, c_lim 8) at N = N10 / 10 with
//     sigma_lim0 = 1.53 GPa x N (Eq. 5.17), run for the first 60 us (past the onset of
//     breakage) on one thread. Counters: grains at the start and at the end, the growth ratio,
//     wall seconds per simulated microsecond and particle-steps per second (grains counted at
//     every output sample, times the steps between samples).
//   BM_Ch5WangSafetyFactor/N10/S100: the same run at time.safety_factor S100 / 100 (the
//     scene's is 1.0, the one of BM_Ch5WangUpscaling): whether a step at the chapter's factor
//     costs more per grain than at 0.3 (issue 34, docs/dem.md "Chapter 5's step").
// The packing is made once per N through the specimen's packing cache in the build folder
// (KOLSKY_BENCH_CACHE) and is not timed.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <cmath>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "dem/breakage_model.hpp"
#include "scene/scene.hpp"
#include "shpb/simulation.hpp"

namespace {

using namespace kolsky;

nlohmann::json wang_scene(double n, double safety_factor = 0) {
  const std::string dir = std::string(KOLSKY_SOURCE_DIR) + "/reproductions/chapter5";
  std::ifstream f(dir + "/scene_wang.json");
  auto j = nlohmann::json::parse(f);
  j["specimen"]["upscale"] = n;
  j["specimen"]["packing_cache"] = std::string(KOLSKY_BENCH_CACHE) + "/ch5";
  j["specimen"]["breakage"]["sigma_lim0"] = dem::upscaled_sigma_lim0(1.53e9, n, j["specimen"]["breakage"]["m1"].get<double>());
  j["specimen"]["breakage"]["fines_d_min"] = 7.5e-6 * n;
  j["time"]["end"] = 60e-6;
  if (safety_factor > 0) j["time"]["safety_factor"] = safety_factor;
  return j;
}

void run_wang(benchmark::State& st, double n, double safety_factor) {
  omp_set_num_threads(1);
  const std::string dir = std::string(KOLSKY_SOURCE_DIR) + "/reproductions/chapter5";
  const auto sc = scene::parse_scene(wang_scene(n, safety_factor), dir + "/scene_wang.json", dir);
  double grains0 = 0, grains1 = 0, particle_steps = 0, simulated = 0, steps = 0;
  for (auto _ : st) {
    st.PauseTiming();
    shpb::SimulatedShpb sim(sc.spec);  // packs once (cached), then only reads the cache
    st.ResumeTiming();
    const auto r = sim.run();
    benchmark::DoNotOptimize(r.steps);
    const auto& g = r.probe("grain_count").value;
    grains0 = g.front();
    grains1 = g.back();
    const double steps_per_sample = static_cast<double>(r.steps) / std::max<std::size_t>(1, g.size() - 1);
    particle_steps = 0;
    for (std::size_t k = 1; k < g.size(); ++k) particle_steps += g[k] * steps_per_sample;
    simulated = r.t.back();
    steps = static_cast<double>(r.steps);
  }
  st.counters["grains_start"] = grains0;
  st.counters["grains_end"] = grains1;
  st.counters["growth"] = grains1 / grains0;
  st.counters["particle_steps_per_s"] = benchmark::Counter(particle_steps, benchmark::Counter::kIsIterationInvariantRate);
  st.counters["s_per_simulated_us"] =
      benchmark::Counter(simulated * 1e6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
  st.counters["steps"] = steps;
  st.SetLabel("Wang 5 x 15 mm, n = 0.41, N = " + std::to_string(n).substr(0, 4) + ", 60 us" +
              (safety_factor > 0 ? ", safety factor " + std::to_string(safety_factor).substr(0, 4) : ""));
}

void BM_Ch5WangUpscaling(benchmark::State& st) { run_wang(st, st.range(0) / 10.0, 0); }
void BM_Ch5WangSafetyFactor(benchmark::State& st) { run_wang(st, st.range(0) / 10.0, st.range(1) / 100.0); }

}  // namespace

BENCHMARK(BM_Ch5WangUpscaling)->Arg(20)->Arg(25)->Arg(30)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK(BM_Ch5WangSafetyFactor)->Args({20, 30})->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK_MAIN();
