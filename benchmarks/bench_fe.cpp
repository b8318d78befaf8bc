// Cost of the explicit axisymmetric FE (Google Benchmark), one thread:
//   BM_FeSpecimenStep: element updates per second ("elem_updates_per_s") on the Chapter 2
//     specimen (pseudo-tensor sand + compaction EOS in a meshed 3.2 mm steel tube, 2 x 25),
//     SHPB-like drive (front face pushed at 4.5 m/s, i.e. ~480/s), meshes 10 x 20 (the full
//     Chapter 2 scene) and 20 x 40;
//   BM_MeshedBarsStep: the same per step with meshed bars (4.1 m + 2.44 m, 4 radial elements,
//     2 mm axially: ~13 000 bar elements), the step of fe::MeshedShpb;
//   BM_Chapter2Run: one full-scale Chapter 2 case (reproductions/chapter2/scene_full.json:
//     steel tube, 480/s, 1.3 ms) end to end through shpb::SimulatedShpb with characteristic
//     bars (Arg 0) and with meshed bars (Arg 1, run to 1.6 ms: the reflected wave must reach the
//     incident gauge); "wall_s_per_sim_us" is wall seconds per simulated microsecond.
//   BM_Reference/threads (1, 2): the frozen reference workload (reference_workload.hpp); the
//     tracked figure is BM_FeSpecimenStep/10/20's elem_updates_per_s / ref_pair_updates_per_s
//     (1 thread) of the same process, both per CPU second (reports/benchmarks/README.md,
//     `make bench-check`).
// Measured on the shared 2-core development machine under load (docs/fe.md "OpenMP and speed").
#include <benchmark/benchmark.h>

#include <cmath>
#include <string>

#include "fe/fe_specimen.hpp"
#include "fe/meshed_shpb.hpp"
#include "reference_workload.hpp"
#include "scene/scene.hpp"
#include "shpb/simulation.hpp"

using namespace kolsky;

namespace {

fe::PseudoTensorModeI sand() {
  fe::PseudoTensorModeI m;
  m.eos.loading.x = {0.0, 0.05, 0.10, 0.20};
  m.eos.loading.y = {0.0, 7.25e6, 18e6, 60e6};
  m.eos.loading.extrapolate = true;
  m.eos.unloading_bulk_modulus = 2e9;
  return m;
}

fe::FeSpecimenParams chapter2_specimen(int n_r, int n_z) {
  fe::FeSpecimenParams p;
  p.n_r = n_r;
  p.n_z = n_z;
  p.material = sand();
  fe::MeshedTube tube;
  tube.material = fe::LinearElastic{200e9, 0.33, 8100};
  tube.thickness = 3.2e-3;
  tube.n_r = 2;
  tube.n_z = 25;
  p.tube = tube;
  return p;
}

constexpr long kSteps = 400;  // steps per iteration (loading to ~1 % strain at 0.7 x stable dt)

void BM_FeSpecimenStep(benchmark::State& st) {
  const auto p = chapter2_specimen(static_cast<int>(st.range(0)), static_cast<int>(st.range(1)));
  long elements = 0;
  for (auto _ : st) {
    st.PauseTiming();
    fe::FeSpecimen s(p);
    const double dt = 0.7 * s.stable_dt();
    elements = static_cast<long>(s.body().mesh().quads.size());
    FaceState f;
    st.ResumeTiming();
    for (long k = 0; k < kSteps; ++k) {
      f.rate_front = 4.5;  // 480/s x 9.3 mm
      f.intrusion_front += f.rate_front * dt;
      benchmark::DoNotOptimize(s.forces(f));
      s.advance(dt);
    }
  }
  st.counters["elements"] = static_cast<double>(elements);
  st.counters["elem_updates_per_s"] =
      benchmark::Counter(static_cast<double>(elements * kSteps), benchmark::Counter::kIsIterationInvariantRate);
}

void BM_MeshedBarsStep(benchmark::State& st) {
  fe::MeshedShpbParams p;
  p.specimen = chapter2_specimen(10, 20);
  p.incident = {fe::LinearElastic{200e9, 0.33, 8100}, 4.1, 9.55e-3, {2.05}};
  p.transmission = {fe::LinearElastic{200e9, 0.33, 8100}, 2.44, 9.55e-3, {0.5}};
  p.bar_n_r = 4;
  p.bar_element_length = 2e-3;
  p.applied_stress = [](double t) { return 2e11 * t; };  // a ramp: 20 MPa at 100 us
  long elements = 0;
  constexpr long kMeshedSteps = 100;
  for (auto _ : st) {
    st.PauseTiming();
    fe::MeshedShpb m(p);
    const double dt = 0.7 * m.stable_dt();
    elements = static_cast<long>(m.body().mesh().quads.size());
    st.ResumeTiming();
    for (long k = 0; k < kMeshedSteps; ++k) m.step(static_cast<double>(k) * dt, dt);
    benchmark::DoNotOptimize(m.gauge_strain(0, 0));
  }
  st.counters["elements"] = static_cast<double>(elements);
  st.counters["elem_updates_per_s"] = benchmark::Counter(static_cast<double>(elements * kMeshedSteps),
                                                         benchmark::Counter::kIsIterationInvariantRate);
}

void BM_Chapter2Run(benchmark::State& st) {
  const std::string dir = std::string(KOLSKY_SOURCE_DIR) + "/reproductions/chapter2";
  auto sc = scene::load_scene(dir + "/scene_full.json");
  if (st.range(0) == 1) {
    sc.spec.bar_kind = shpb::BarKind::meshed;
    sc.spec.time.end_time = 1.6e-3;
  }
  long steps = 0;
  double dt = 0;
  for (auto _ : st) {
    shpb::SimulatedShpb sim(sc.spec);
    const auto r = sim.run();
    if (!r.complete) st.SkipWithError(r.failure.c_str());
    steps = r.steps;
    dt = r.dt;
  }
  st.counters["steps"] = static_cast<double>(steps);
  st.counters["dt_ns"] = dt * 1e9;
  st.counters["wall_s_per_sim_us"] = benchmark::Counter(
      sc.spec.time.end_time * 1e6, benchmark::Counter::kIsIterationInvariantRate | benchmark::Counter::kInvert);
}

// Registered first (static initialisation runs in order of definition).
[[maybe_unused]] const auto* const kReference = kolsky::bench::register_reference_benchmark();

}  // namespace

BENCHMARK(BM_FeSpecimenStep)->Args({10, 20})->Args({20, 40})->Unit(benchmark::kMillisecond);
BENCHMARK(BM_MeshedBarsStep)->Unit(benchmark::kMillisecond);
// Real time: the counter is wall seconds per simulated microsecond (on a loaded machine the
// JSON's cpu_time is the steadier figure).
BENCHMARK(BM_Chapter2Run)->Arg(0)->Arg(1)->Iterations(1)->UseRealTime()->Unit(benchmark::kSecond);
BENCHMARK_MAIN();
