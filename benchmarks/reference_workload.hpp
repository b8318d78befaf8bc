// FROZEN reference workload for benchmark ratios (reports/benchmarks/README.md, `make
// bench-check`). Do not edit: the tracked speed figures in benchmarks/results/ are
// kolsky rate / BM_Reference rate from the same process, and any change here (sizes, seed,
// constants, loop order, even a reordering the compiler could vectorize differently) moves the
// denominator and so invalidates every tracked ratio. If it must change, increment
// kReferenceVersion: the summary and bench-check compare ratios of one version only, and older
// files then count as having no reference.
//
// Why a reference at all: the development VM's speed drifts by 15-25 % between minutes, the
// same binary included, so an absolute rate cannot show a 5-10 % regression. A fixed workload
// timed in the same process, interleaved with the kernels, sees the same machine phase; the
// ratio cancels most of the drift (for one thread, of rates per CPU second: 7 % spread over 5
// loaded runs where the DEM kernel's wall-time rate spread 52 %; scripts/bench-check.sh). A
// ratio compares commits on one kind of machine: on another CPU (cache sizes, AVX-512, which
// the DEM kernel's clones use and this baseline-x86-64 loop does not) it takes another value.
//
// Why this workload: its memory and floating-point character resembles the DEM and FE sweeps
// (owner-ordered pair loop, gather of the partner's position and velocity, a per-pair history
// read and written, sqrt and division, scatter of the partner's force, then a node update):
// 34,500 nodes (as pack_35k) with 4 partners each (pack_35k lists 4.06 pairs per grain), drawn
// from a fixed SplitMix64 stream with the index locality of a Morton-ordered packing (80 %
// within 48 nodes, 12 % within 1365, 8 % anywhere). It is self-contained (its own SplitMix64,
// no solver code) so that no library change can move it, and branch-free so that its cost does
// not depend on the values. Each iteration resets the state, so every iteration does the same
// work on the same numbers. About 230 ms per iteration on the development machine.
#pragma once
#include <benchmark/benchmark.h>
#include <omp.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace kolsky::bench {

/// Written to every BM_Reference result as the counter "reference_version".
inline constexpr int kReferenceVersion = 1;

inline constexpr std::uint32_t kRefNodes = 34500;
inline constexpr std::uint32_t kRefPartners = 4;
inline constexpr int kRefSteps = 200;  // steps per iteration
inline constexpr double kRefDt = 0.02, kRefStiff = 0.05, kRefShear = 0.01;

struct ReferenceNetwork {
  std::vector<double> x0;               // initial positions, 3 per node (lattice of spacing 1)
  std::vector<std::uint32_t> partner;   // kRefPartners per node, owner-ordered
  std::vector<double> rest;             // rest length per pair (2 % under the initial distance)
};

/// The fixed network (built once per process; read-only afterwards, shared by threads).
inline ReferenceNetwork make_reference_network() {
  std::uint64_t state = 20261122;  // SplitMix64 (Steele, Lea and Flood 2014), inlined: frozen
  const auto next = [&state] {
    std::uint64_t z = (state += 0x9e3779b97f4a7c15ULL);
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
  };
  ReferenceNetwork net;
  net.x0.resize(3 * std::size_t{kRefNodes});
  for (std::uint32_t i = 0; i < kRefNodes; ++i) {  // 33 x 33 lattice layers
    net.x0[3 * i] = i % 33;
    net.x0[3 * i + 1] = (i / 33) % 33;
    net.x0[3 * i + 2] = i / 1089;
  }
  for (std::uint32_t i = 0; i < kRefNodes; ++i) {
    for (std::uint32_t q = 0; q < kRefPartners; ++q) {
      const std::uint64_t u = next();
      const std::uint64_t kind = u % 100, pick = u >> 32;
      const std::uint64_t off = kind < 80 ? 1 + pick % 48 : kind < 92 ? 49 + pick % 1317
                                                                      : 1 + pick % (kRefNodes - 1);
      const auto j = static_cast<std::uint32_t>((i + off) % kRefNodes);
      const double dx = net.x0[3 * j] - net.x0[3 * i], dy = net.x0[3 * j + 1] - net.x0[3 * i + 1],
                   dz = net.x0[3 * j + 2] - net.x0[3 * i + 2];
      net.partner.push_back(j);
      net.rest.push_back(0.98 * std::sqrt(dx * dx + dy * dy + dz * dz));
    }
  }
  return net;
}

inline const ReferenceNetwork& reference_network() {
  static const ReferenceNetwork net = make_reference_network();
  return net;
}

/// One thread's state: positions, velocities, forces (3 per node), shear history (3 per pair).
struct ReferenceState {
  std::vector<double> x, v, f, h;
  explicit ReferenceState(const ReferenceNetwork& net)
      : x(net.x0), v(net.x0.size(), 0.0), f(net.x0.size(), 0.0), h(3 * net.partner.size(), 0.0) {}
  void reset(const ReferenceNetwork& net) {
    x = net.x0;
    std::fill(v.begin(), v.end(), 0.0);
    std::fill(f.begin(), f.end(), 0.0);
    std::fill(h.begin(), h.end(), 0.0);
  }
};

/// One step: the pair sweep (Hertz-like normal force delta^1.5 along the pair, linear spring on
/// the integrated relative velocity), then symplectic Euler on unit masses. Bounded motion:
/// every force derives from springs near their rest state, so the values never blow up or
/// decay to subnormals (which would change the cost).
inline void reference_step(const ReferenceNetwork& net, ReferenceState& s) {
  const std::uint32_t* partner = net.partner.data();
  const double* rest = net.rest.data();
  double *x = s.x.data(), *v = s.v.data(), *f = s.f.data(), *h = s.h.data();
  for (std::size_t i = 0; i < kRefNodes; ++i) {
    const double xi = x[3 * i], yi = x[3 * i + 1], zi = x[3 * i + 2];
    const double ui = v[3 * i], vi = v[3 * i + 1], wi = v[3 * i + 2];
    double fx = 0, fy = 0, fz = 0;
    for (std::size_t k = kRefPartners * i; k < kRefPartners * (i + 1); ++k) {
      const std::size_t j = partner[k];
      const double dx = x[3 * j] - xi, dy = x[3 * j + 1] - yi, dz = x[3 * j + 2] - zi;
      const double r = std::sqrt(dx * dx + dy * dy + dz * dz + 1e-6);  // never 0
      const double delta = rest[k] - r;                                 // > 0: compressed
      const double fn = kRefStiff * delta * std::sqrt(std::fabs(delta)) / r;
      h[3 * k] += kRefDt * (v[3 * j] - ui);
      h[3 * k + 1] += kRefDt * (v[3 * j + 1] - vi);
      h[3 * k + 2] += kRefDt * (v[3 * j + 2] - wi);
      const double px = kRefShear * h[3 * k] - fn * dx, py = kRefShear * h[3 * k + 1] - fn * dy,
                   pz = kRefShear * h[3 * k + 2] - fn * dz;  // force on i; -p on j
      fx += px;
      fy += py;
      fz += pz;
      f[3 * j] -= px;
      f[3 * j + 1] -= py;
      f[3 * j + 2] -= pz;
    }
    f[3 * i] += fx;
    f[3 * i + 1] += fy;
    f[3 * i + 2] += fz;
  }
  for (std::size_t c = 0; c < 3 * std::size_t{kRefNodes}; ++c) {
    v[c] += kRefDt * f[c];
    x[c] += kRefDt * v[c];
    f[c] = 0;
  }
}

/// Sum of the squared displacements and velocities (not of x and v, which momentum
/// conservation keeps constant): a fixed value for a given number of steps, checked by
/// test_benchmark_summary so that an accidental edit of the workload fails a test.
inline double reference_checksum(const ReferenceNetwork& net, const ReferenceState& s) {
  double sum = 0;
  for (std::size_t c = 0; c < s.x.size(); ++c)
    sum += (s.x[c] - net.x0[c]) * (s.x[c] - net.x0[c]) + s.v[c] * s.v[c];
  return sum;
}

/// BM_Reference/threads: `threads` OpenMP threads, each stepping its own state on the shared
/// network, with a barrier after every step. Why OpenMP and the barrier rather than Google
/// Benchmark's ->Threads(): its threads time themselves and average their times, which hides
/// a thread delayed by another process; here the iteration's wall time waits for the slowest,
/// and the barrier per step makes a stolen core cost what it costs the DEM sweep (whose
/// threads meet several times per step), so the 2-thread DEM ratio cancels more of it.
inline void reference_benchmark(benchmark::State& st) {
  const ReferenceNetwork& net = reference_network();
  const int threads = static_cast<int>(st.range(0));
  std::vector<ReferenceState> states(static_cast<std::size_t>(threads), ReferenceState(net));
  for (auto _ : st) {
#pragma omp parallel num_threads(threads)
    {
      ReferenceState& s = states[static_cast<std::size_t>(omp_get_thread_num())];
      s.reset(net);
      for (int k = 0; k < kRefSteps; ++k) {
        reference_step(net, s);
#pragma omp barrier
      }
    }
    benchmark::DoNotOptimize(states.data());
    benchmark::ClobberMemory();
  }
  st.counters["threads"] = threads;
  st.counters["ref_pair_updates_per_s"] =
      benchmark::Counter(static_cast<double>(threads) * static_cast<double>(net.partner.size()) * kRefSteps,
                         benchmark::Counter::kIsIterationInvariantRate);
  st.counters["reference_version"] = kReferenceVersion;
}

/// Registers BM_Reference/{1,2}/iterations:3/real_time (the argument: threads). Call it at
/// static initialisation before the BENCHMARK lines, so that it runs first in `make bench` too
/// (before any packing). Fixed iterations (3 x ~230 ms) make every repetition the same work.
inline benchmark::internal::Benchmark* register_reference_benchmark() {
  return benchmark::RegisterBenchmark("BM_Reference", reference_benchmark)
      ->Arg(1)
      ->Arg(2)
      ->Iterations(3)
      ->UseRealTime()
      ->Unit(benchmark::kMillisecond);
}

}  // namespace kolsky::bench
