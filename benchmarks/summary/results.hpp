// Reading benchmarks/results/: Google Benchmark JSON (<date>_<commit>_bench_*.json, written by
// `make bench` and `make bench-check`) and the LAMMPS runs of benchmarks/lammps/run.sh
// (*_lammps.json, another format); the values the summary and bench-check take from them, the
// tracked ratios (kolsky rate / BM_Reference rate of the same process) and the power-law fit
// of the upscaling series. No I/O beyond reading the files: the rest is testable on literals.
#pragma once
#include <nlohmann/json.hpp>

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace kolsky::benchsum {

/// One benchmark record of a Google Benchmark file.
struct Entry {
  std::string key;        ///< run name without /real_time, /iterations:N: "BM_DemCompaction/1"
  std::string aggregate;  ///< "" for a single run, else "mean", "median", "stddev", "cv"
  std::map<std::string, double> counters;  ///< user counters (particle_steps_per_s, ...)
  std::string label;
  bool real_time = false;            ///< UseRealTime: rate counters are per wall second
  double real = 0, cpu = 0;          ///< real_time and cpu_time per iteration (same unit)
};

struct ResultFile {
  std::string name;    ///< file name, no folder
  std::string bench;   ///< "bench_dem", "bench_fe", "bench_bars", ..., or "lammps"
  std::string commit;  ///< the hex token of the name (12 digits), "" for LAMMPS files
  std::string date;    ///< context.date as written
  long long time = 0;  ///< context.date in UTC seconds since 1970 (ordering)
  std::string kind;    ///< context.kind: "bench-check" for the short runs of make bench-check
  std::vector<Entry> entries;
  std::optional<double> lammps_rate;  ///< LAMMPS gran/hertz/history, 1 rank: median particle-steps/s
  int lammps_runs = 0;
};

/// "BM_X/1/iterations:3/real_time/threads:1" -> "BM_X/1/threads:1": drops the tokens that
/// say how the run was timed, not what ran (real_time, process_time, manual_time, iterations:N,
/// min_time:S, repeats:N).
std::string normalize_key(const std::string& run_name);

/// "2026-11-22T13:04:39+00:00" (or ...Z, or no zone: UTC) -> seconds since 1970, UTC.
/// Throws std::invalid_argument on another format.
long long parse_iso_time(const std::string& s);

/// Bench and commit from a results file name: "20261122_b193267a4c12_bench_dem.json" ->
/// {"bench_dem", "b193267a4c12"}; "20261122_1716_lammps.json" -> {"lammps", ""}.
std::pair<std::string, std::string> parse_file_name(const std::string& name);

/// Parses one file's JSON; throws std::runtime_error naming what is missing.
ResultFile parse_result(const nlohmann::json& j, const std::string& file_name);
ResultFile read_result_file(const std::string& path);

/// Every *.json of `dir`, ordered by context date (then name); files that cannot be read or
/// parsed go to `skipped` as "name: reason" instead.
std::vector<ResultFile> read_results_dir(const std::string& dir, std::vector<std::string>& skipped);

/// A counter of benchmark `key`: its mean aggregate when present, else the mean over the
/// single runs (a run without repetitions has one), else nothing.
std::optional<double> value(const ResultFile& f, const std::string& key, const std::string& counter);

/// The same, per second of the benchmark thread's CPU time: a wall-time rate scaled by
/// real_time / cpu_time (a CPU-time rate as it is). Time the process spent waiting for a core
/// (another process running) is then left out of kernel and reference alike; only meaningful
/// for single-threaded benchmarks (Google Benchmark times the main thread's CPU).
std::optional<double> cpu_rate(const ResultFile& f, const std::string& key, const std::string& counter);

/// A tracked speed figure: kernel rate / reference rate, measured in one process.
struct Tracked {
  std::string id;         ///< "dem_1t", "dem_2t", "fe"
  std::string bench;      ///< the binary both come from
  std::string kernel;     ///< entry key of the kernel
  std::string counter;    ///< its rate counter
  std::string reference;  ///< entry key of the reference (BM_Reference/<threads>)
  std::string title;
  bool two_cores = false;  ///< meaningful only when the run had both cores (two_core_factor)
  /// Rates per CPU second (cpu_rate) rather than per wall second. The 1-thread figures: on
  /// the shared VM wall-time ratios of 5 loaded runs spread 13 % (DEM) and 39 % (FE, whose
  /// counter is per CPU second while the reference's was per wall second), CPU-time ones 7 %
  /// and 5 %. Not for 2 threads, whose spinning in barriers is CPU time too.
  bool cpu_time = false;
};
const std::vector<Tracked>& tracked();
inline const char* const kReferenceCounter = "ref_pair_updates_per_s";

struct Ratio {
  double kernel = 0, reference = 0, ratio = 0;  ///< rates per wall or CPU second (Tracked::cpu_time)
  int version = 0;  ///< reference_version of the reference workload
};
/// The ratio of `t` in `f`; nothing when f is another bench or lacks the kernel or reference.
std::optional<Ratio> ratio(const ResultFile& f, const Tracked& t);

/// BM_Reference/2 rate over BM_Reference/1 rate of one file: about 2 when the run had both
/// cores, less when another process held one. The 2-thread DEM kernel then collapses far more
/// than the reference (its threads spin in the barriers of every step: 0.93 M particle-steps/s
/// against 8.7 M on one thread, while the reference fell to 0.64 x its 1-thread rate), so
/// its ratio says nothing about the code and is neither checked nor used as a tracked value.
std::optional<double> two_core_factor(const ResultFile& f);
/// Measured 2026-12-01: idle runs 1.95-2.02, runs with the other core busy 0.58-0.67, and one
/// at 1.84 (load 1) whose 2-thread kernel lost 29 % while the reference lost 7 %; 1.9 keeps
/// the idle runs and drops that one.
inline constexpr double kMinTwoCoreFactor = 1.9;
/// Whether `t`'s ratio in `f` counts: the ratio exists, and for a 2-thread figure both cores were free.
bool usable(const ResultFile& f, const Tracked& t);

/// y = a x^p by least squares on (log x, log y); needs two or more distinct positive x and
/// positive y (others are ignored).
struct PowerFit {
  double exponent = 0, prefactor = 0;
  int points = 0;
};
std::optional<PowerFit> fit_power_law(const std::vector<double>& x, const std::vector<double>& y);

/// BM_DemUpscale/<10 N> of one file: N, grains, particle-steps/s, wall s per simulated us.
struct UpscalePoint {
  double n = 0, grains = 0, rate = 0, s_per_sim_us = 0;
};
std::vector<UpscalePoint> upscale_series(const ResultFile& f);

/// "2026-11-22T13:04:39+00:00" -> "2026-11-22 13:04" (UTC).
std::string short_date(long long utc_seconds);

}  // namespace kolsky::benchsum
