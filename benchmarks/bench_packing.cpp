// Packing time of the Chapter 4 specimens (issue 18: "the jammed N = 2 packing in under a
// minute on two threads"). Each case packs reproductions/chapter4/scene_full.json's specimen
// (reconstructed Song curve, 19.1 x 9.3 mm, n = 0.44, seed 1, jammed, pre-stressed to 65 kPa
// against the Table 4.1 wall springs) with the upscaling factor replaced, through the scene
// reader, so the PackingParams are exactly those `make reproduce-chapter4` uses; no cache.
//   BM_ChapterFourPacking/10N/threads/scaled (N = 6 to 1.5; 1 or 2 OpenMP threads; scaled = 1:
//   the packing as it is, with density scaling while jamming; 0: the jamming before it, no
//   scaling and 200 steps per stage, for the before/after figures): one iteration.
//   Counters: grains, wall seconds of each phase (growth_s, settle_s, prestress_s; from the
//   packing's progress reports), stages and DEM steps, and the acceptance figures the
//   Chapter 4 set and test_dem_packing check: porosity, coordination (with and without
//   rattlers), rattler fraction, largest overlap / mean radius, wall mean stress after the
//   pre-stress (Pa) and whether the settling and the servo converged.
#include <benchmark/benchmark.h>
#include <omp.h>

#include <chrono>
#include <fstream>
#include <string>
#include <variant>

#include <nlohmann/json.hpp>

#include "dem/dem_specimen_params.hpp"
#include "dem/packing.hpp"
#include "scene/scene.hpp"

namespace {

using namespace kolsky;
using Clock = std::chrono::steady_clock;

dem::PackingParams chapter4_packing(double upscale) {
  const std::string dir = std::string(KOLSKY_SOURCE_DIR) + "/reproductions/chapter4";
  std::ifstream f(dir + "/scene_full.json");
  nlohmann::json j = nlohmann::json::parse(f);
  j["specimen"]["upscale"] = upscale;
  const scene::Scene sc = scene::parse_scene(j, dir + "/scene_full.json", dir);
  return std::get<dem::DemSpecimenParams>(sc.spec.specimen).packing;
}

// range(2): 1 the scene's jammed growth (density scaled), 0 the growth before issue 18 (no
// density scaling, 200 steps a stage), 2 servo-wall compaction, 3 servo walls with rotation
// locked (issue 31; docs/dem.md, Packing); the procedure's first phase is timed as growth_s.
void BM_ChapterFourPacking(benchmark::State& st) {
  const double upscale = st.range(0) / 10.0;
  const int previous = omp_get_max_threads();
  omp_set_num_threads(static_cast<int>(st.range(1)));
  dem::PackingParams p = chapter4_packing(upscale);
  if (st.range(2) == 0) {  // the jamming before issue 18: no density scaling, 200 steps a stage
    p.jam_mass_scaling = false;
    p.jam_steps_per_stage = 200;
  }
  if (st.range(2) >= 2) {
    p.servo_walls = true;
    p.packing_lock_rotation = st.range(2) == 3;
  }
  double phase_s[3] = {0, 0, 0};  // growth, settle, prestress
  Clock::time_point last;
  p.on_progress = [&](const dem::PackingProgress& q) {
    const Clock::time_point now = Clock::now();
    const std::string phase = q.phase;
    const int k = phase == "growth" || phase == "compaction" ? 0 : phase == "settle" ? 1 : 2;
    phase_s[k] += std::chrono::duration<double>(now - last).count();
    last = now;
  };
  dem::PackingResult r;
  for (auto _ : st) {
    last = Clock::now();
    r = dem::generate_packing(p);
  }
  st.counters["grains"] = static_cast<double>(r.count);
  st.counters["growth_s"] = phase_s[0];
  st.counters["settle_s"] = phase_s[1];
  st.counters["prestress_s"] = phase_s[2];
  st.counters["stages"] = r.stages;
  st.counters["steps"] = r.steps;
  st.counters["porosity"] = r.porosity;
  st.counters["coordination"] = r.coordination;
  st.counters["coordination_no_rattlers"] = r.coordination_no_rattlers;
  st.counters["rattler_fraction"] = r.rattler_fraction;
  st.counters["max_overlap"] = r.max_overlap;
  st.counters["mean_stress_Pa"] = r.mean_stress;
  st.counters["settled"] = r.settled;
  st.counters["prestress_converged"] = r.prestress_converged;
  st.counters["fabric_anisotropy"] = dem::fabric_anisotropy(r.particles, p.diameter, p.length);
  const char* procedure[] = {", unscaled (before issue 18)", "", ", servo walls",
                             ", servo walls, rotation locked"};
  st.SetLabel("chapter 4 packing, N = " + std::to_string(upscale).substr(0, 3) +
              procedure[st.range(2)]);
  omp_set_num_threads(previous);
}

}  // namespace

// Smallest first: the unscaled N = 2 packing takes over a minute on two threads.
// N = 6 (smoke), 4, 3 (twin and seed study), 2.5, 2 (the set), 1.5: the Chapter 4 packings of
// the reference curve (reproductions/chapter4/README.md, "Upscaling").
BENCHMARK(BM_ChapterFourPacking)
    ->Args({60, 1, 0})->Args({60, 1, 1})->Args({40, 2, 0})->Args({40, 2, 1})
    ->Args({30, 1, 0})->Args({30, 1, 1})->Args({30, 2, 0})->Args({30, 2, 1})
    ->Args({25, 2, 0})->Args({25, 2, 1})->Args({20, 2, 0})->Args({20, 2, 1})->Args({20, 1, 1})
    ->Args({15, 2, 0})->Args({15, 2, 1})
    ->Args({40, 2, 2})->Args({40, 2, 3})->Args({20, 2, 2})->Args({20, 2, 3})
    ->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();
BENCHMARK_MAIN();
