// Cost of the two bar models per simulated microsecond (Google Benchmark):
//   characteristic (delay-line) bar: O(1) per step, no stability limit of its own;
//   sphere-chain bar (Sec. 4.3): O(N) per step, dt <= sqrt(m/k) ~ 3.8 us for 19.1 mm balls.
// Both are stepped at the same dt (0.1 us, the order a soft specimen column imposes) and the
// chain also at half its own limit. Counter "sim_us_per_s": simulated microseconds per second.
// Also the coupled Song set-up (4.1 m + 2.44 m bars, 20-element elastic specimen).
#include <benchmark/benchmark.h>

#include <cmath>

#include "bar/characteristic_bar.hpp"
#include "bar/sphere_chain.hpp"
#include "shpb/simulation.hpp"

using namespace kolsky;

namespace {

const bar::Pulse kPulse = bar::TrapezoidPulse{100e6, 100e-6, 500e-6, 100e-6, 0.0};
constexpr double kSimulated = 1e-3;  // s of simulated time per iteration

template <class Bar>
void step_for(Bar& b, double dt) {
  const long n = static_cast<long>(kSimulated / dt);
  for (long s = 0; s < n; ++s) b.step(s * dt, dt, 0.0);
}

void BM_CharacteristicBar(benchmark::State& st) {
  const double dt = st.range(0) * 1e-9;
  for (auto _ : st) {
    bar::CharacteristicBar b(bar::BarMaterial{}, bar::BarGeometry{4.1, 0.0191}, kPulse, 1e-4);
    step_for(b, dt);
    benchmark::DoNotOptimize(b.intrusion());
  }
  st.counters["sim_us_per_s"] = benchmark::Counter(kSimulated * 1e6, benchmark::Counter::kIsIterationInvariantRate);
}

void BM_SphereChainBar(benchmark::State& st) {
  const auto props = bar::sphere_chain_properties(bar::BarMaterial{}, 0.0191);
  const double dt = st.range(0) > 0 ? st.range(0) * 1e-9
                                    : 0.5 * std::sqrt(props.ball_mass / props.contact_stiffness);
  for (auto _ : st) {
    bar::SphereChainBar b(bar::BarMaterial{}, bar::BarGeometry{4.1, 0.0191}, 215, kPulse, 1e-4);
    step_for(b, dt);
    benchmark::DoNotOptimize(b.intrusion());
  }
  st.counters["sim_us_per_s"] = benchmark::Counter(kSimulated * 1e6, benchmark::Counter::kIsIterationInvariantRate);
  st.counters["dt_ns"] = dt * 1e9;
}

void BM_CoupledSong(benchmark::State& st) {
  shpb::ExperimentSpec s;
  s.bar_kind = st.range(0) == 0 ? shpb::BarKind::characteristic : shpb::BarKind::sphere_chain;
  s.incident.geometry = {4.1, 0.0191};
  s.transmission.geometry = {2.44, 0.0191};
  s.incident.gauges = {2.05};
  s.transmission.gauges = {0.5};
  s.pulse = kPulse;
  bar::ColumnParams column;
  column.n_elements = 20;
  column.density = 1457.5;
  s.specimen = column;
  s.time.end_time = 1.5e-3;
  s.output.interval = 1e-6;
  for (auto _ : st) {
    shpb::SimulatedShpb sim(s);
    benchmark::DoNotOptimize(sim.run().t.size());
  }
  st.counters["sim_us_per_s"] = benchmark::Counter(1.5e3, benchmark::Counter::kIsIterationInvariantRate);
}

}  // namespace

BENCHMARK(BM_CharacteristicBar)->Arg(100)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SphereChainBar)->Arg(100)->Arg(0)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_CoupledSong)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
