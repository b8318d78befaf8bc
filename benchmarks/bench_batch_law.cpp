// The batch Hertz-Mindlin law alone (solver/dem/hertz_mindlin_batch.hpp), for the second half
// of its roofline point (docs/dem.md, "The batch law's operation count"): the same batch of
// grain contacts evaluated again and again, so that its arrays stay in this core's L1/L2 and
// nothing but the law is timed (no pair sweep, no gathers of the partners' state).
//   BM_BatchLaw/variant/count: variant 0 portable, 1 AVX2, 2 AVX-512 (skipped where the CPU
//   lacks it); count: contacts per call (128 fills the batch's 39 KB of arrays, 64 touches half
//   of each array: the L1 check). Counters: contacts_per_s, and flop_per_s = contacts_per_s x
//   213, the hand count of docs/dem.md (~200 additions and multiplications, 6 square roots, 7
//   divisions, each root or division counted as one operation).
// The contacts: two alike quartz grains (E 78 GPa, nu 0.3, mu 0.5, e 0.5), radii 0.1-0.3 mm,
// overlaps 1e-4 to 1e-2 of the smaller radius, relative velocities and spins of ~0.1-1 m/s and
// rad/s, and tangential histories on both sides of the Coulomb cap, so that both selects'
// sides are live (every lane pays for both anyway: docs/dem.md).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>
#include <vector>

#include "dem/contact_hertz_mindlin.hpp"
#include "dem/hertz_mindlin_batch.hpp"

using namespace kolsky;

namespace {

constexpr double kOperationsPerContact = 213;  // docs/dem.md: ~200 add/mul + 6 sqrt + 7 div

// A batch of kCapacity contacts from a fixed low-discrepancy pattern (no random state).
dem::HertzMindlinBatch synthetic_batch() {
  const std::vector<dem::Material> sand{dem::Material{78e9, 0.3, 2650}};
  const dem::HertzMindlin law(sand, dem::HertzMindlinParams{0.5, 0.5});
  const dem::HertzMindlinConstants k = dem::hertz_mindlin_table(law).front();
  dem::HertzMindlinBatch b{};
  for (int c = 0; c < dem::HertzMindlinBatch::kCapacity; ++c) {
    const double u = std::fmod(0.6180339887 * (c + 1), 1.0), w = std::fmod(0.7548776662 * (c + 1), 1.0);
    const double ri = 1e-4 * (1 + 2 * u), rj = 1e-4 * (1 + 2 * w);
    const double overlap = std::min(ri, rj) * std::pow(10.0, -4 + 2 * u);
    const double dist = ri + rj - overlap;
    const double theta = 2 * std::numbers::pi * w, phi = std::numbers::pi * u;  // the contact normal's direction
    b.dx[c] = dist * std::sin(phi) * std::cos(theta);
    b.dy[c] = dist * std::sin(phi) * std::sin(theta);
    b.dz[c] = dist * std::cos(phi);
    b.ri[c] = ri, b.rj[c] = rj;
    const double mi = 2650 * 4.0 / 3.0 * std::numbers::pi * ri * ri * ri, mj = 2650 * 4.0 / 3.0 * std::numbers::pi * rj * rj * rj;
    b.r_eff[c] = dem::pair_effective(ri, rj), b.m_eff[c] = dem::pair_effective(mi, mj);
    b.dvx[c] = 0.5 - u, b.dvy[c] = 0.3 * (w - 0.5), b.dvz[c] = -0.2 - 0.5 * u;
    b.wix[c] = 10 * (u - 0.5), b.wiy[c] = 5 * w, b.wiz[c] = -3 * u;
    b.wjx[c] = -4 * w, b.wjy[c] = 6 * (u - 0.5), b.wjz[c] = 2 * w;
    // Tangential history: up to twice the overlap times mu's reach (some lanes slide).
    b.hx[c] = overlap * (u - 0.5), b.hy[c] = overlap * (w - 0.5), b.hz[c] = 0;
    b.k_force[c] = k.force, b.k_stiffness[c] = k.stiffness, b.k_damping[c] = k.damping;
    b.k_shear[c] = k.shear, b.k_friction[c] = k.friction, b.k_tdamp[c] = k.tangential_damping_scale;
  }
  return b;
}

// The divider's own throughput, the bound docs/dem.md expects for the law: one square root and
// one division per lane over the same 128-lane arrays, one body compiled per instruction set as
// hertz_mindlin_batch.cpp does (the law's 6 roots and 7 divisions per contact then allow at
// most rate / 6.5 contacts per second).
[[gnu::always_inline]] inline void roots_and_divisions(const double* x, const double* a, double* y, double* z) {
  for (int i = 0; i < 128; ++i) {
    y[i] = std::sqrt(x[i]);
    z[i] = a[i] / x[i];
  }
}
void roots_and_divisions_portable(const double* x, const double* a, double* y, double* z) {
  roots_and_divisions(x, a, y, z);
}
[[gnu::target("avx2")]] void roots_and_divisions_avx2(const double* x, const double* a, double* y, double* z) {
  roots_and_divisions(x, a, y, z);
}
[[gnu::target("avx512f")]] void roots_and_divisions_avx512(const double* x, const double* a, double* y, double* z) {
  roots_and_divisions(x, a, y, z);
}

// False, with the benchmark skipped and the reason given, where the CPU or build lacks `variant`.
bool variant_available(benchmark::State& st, dem::BatchKernel variant) {
  if (dem::batch_kernel_available(variant)) return true;
  st.SkipWithError((std::string(dem::batch_kernel_name(variant)) + ": not on this CPU or build").c_str());
  return false;
}

void BM_BatchLaw(benchmark::State& st) {
  const auto variant = static_cast<dem::BatchKernel>(st.range(0));
  const int count = static_cast<int>(st.range(1));
  if (!variant_available(st, variant)) return;
  const dem::HertzMindlinBatch start = synthetic_batch();
  dem::HertzMindlinBatch b = start;
  const double dt = 1e-9;
  long calls = 0;
  for (auto _ : st) {
    // The history is written over its input: restore it now and then so that the lanes keep
    // their mix of sliding and sticking (a copy of 3 arrays every 64 calls, ~1 % of the time).
    if ((calls++ & 63) == 0) {
      std::copy(std::begin(start.hx), std::end(start.hx), std::begin(b.hx));
      std::copy(std::begin(start.hy), std::end(start.hy), std::begin(b.hy));
      std::copy(std::begin(start.hz), std::end(start.hz), std::begin(b.hz));
    }
    dem::evaluate_with(variant, b, count, dt);
    benchmark::DoNotOptimize(b.fx[count - 1]);
    benchmark::ClobberMemory();
  }
  const double contacts = static_cast<double>(calls) * count;
  st.counters["contacts_per_s"] = benchmark::Counter(contacts, benchmark::Counter::kIsRate);
  st.counters["flop_per_s"] = benchmark::Counter(contacts * kOperationsPerContact, benchmark::Counter::kIsRate);
  st.SetLabel(std::string(dem::batch_kernel_name(variant)) + ", " + std::to_string(count) + " contacts per call");
}

void BM_RootsAndDivisions(benchmark::State& st) {
  const auto variant = static_cast<dem::BatchKernel>(st.range(0));
  if (!variant_available(st, variant)) return;
  alignas(64) double x[128], a[128], y[128], z[128];
  for (int i = 0; i < 128; ++i) x[i] = 1.0 + 0.01 * i, a[i] = 2.0 - 0.003 * i;
  long calls = 0;
  for (auto _ : st) {
    if (variant == dem::BatchKernel::avx512) roots_and_divisions_avx512(x, a, y, z);
    else if (variant == dem::BatchKernel::avx2) roots_and_divisions_avx2(x, a, y, z);
    else roots_and_divisions_portable(x, a, y, z);
    benchmark::DoNotOptimize(y[127] + z[127]);
    benchmark::ClobberMemory();
    ++calls;
  }
  // Each lane: one root and one division.
  st.counters["roots_and_divisions_per_s"] = benchmark::Counter(2.0 * 128 * calls, benchmark::Counter::kIsRate);
  st.SetLabel(dem::batch_kernel_name(variant));
}

}  // namespace

BENCHMARK(BM_RootsAndDivisions)->Arg(0)->Arg(1)->Arg(2)->Unit(benchmark::kNanosecond)->UseRealTime()->MinTime(0.5);
BENCHMARK(BM_BatchLaw)
    ->ArgsProduct({{0, 1, 2}, {64, 128}})
    ->Unit(benchmark::kMicrosecond)
    ->UseRealTime()
    ->MinTime(0.5);

BENCHMARK_MAIN();
