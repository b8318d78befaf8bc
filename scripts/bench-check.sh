#!/usr/bin/env bash
# make bench-check: a short benchmark run whose speed ratios (kolsky rate / BM_Reference rate
# of the same process) are compared with the newest tracked ones in benchmarks/results/; exits
# 1 with a table when one fell more than its margin below. Not part of `make test`: tests never
# depend on wall time. See reports/benchmarks/README.md (make bench-summary).
#
#   scripts/bench-check.sh BUILD RESULTS             the check (16 s idle, ~1 min loaded)
#   scripts/bench-check.sh BUILD RESULTS --spread N  N short runs, each ratio's spread (no check):
#                                                    how the margins below were measured
#
# What runs: bench_dem BM_Reference/{1,2} and BM_DemCompaction/{1,2} (never BM_DemUpscale,
# whose packings take ~35 min on first use), bench_fe BM_Reference/1 and
# BM_FeSpecimenStep/10/20; REPS repetitions each, randomly interleaved
# (--benchmark_enable_random_interleaving), so that reference and kernel repetitions alternate
# and see the same phases of the machine; the ratio is of the means over the repetitions.
set -euo pipefail
build=${1:?build folder}
results=${2:?results folder}
spread=0
if [[ ${3:-} == --spread ]]; then spread=${4:?--spread needs a run count}; fi
bin=$build/benchmarks
reps=${BENCH_CHECK_REPS:-3}

# Allowed drop of each ratio below the tracked value, as a fraction; measured, not guessed.
# `--spread` on the 2-core development VM, 2026-12-01, REPS = 3, 1-thread ratios per CPU
# second (see summary/results.hpp, Tracked::cpu_time):
#   5 runs 20:38-20:43, load 4-6 (another engineer's build and tests on both cores), and
#   3 runs 20:58-20:59, idle (a rebuilt bench_dem: the solver had changed meanwhile);
#   DEM 1 thread:  0.08364 0.08435 0.08605 0.08558 0.08935 | 0.08550 0.08790 0.08748
#                  median 0.0858, cv 2.2 %, range 6.7 %; the kernel's own wall-time rate
#                  ranged 5.7-9.4 M/s (52 % in the loaded set), so the ratio does cancel it
#   FE 10 x 20:    0.04078 0.04284 0.04105 0.04282 0.04238 | 0.04231 0.04099 0.04148
#                  median 0.0419, cv 2.0 %, range 4.9 % (wall-time ratios, loaded set: 39 %)
#   DEM 2 threads: idle only (loaded, the second core was never free: BM_Reference 2 / 1
#                  threads 0.58-0.67, not compared): 0.08486 0.08669 0.06622, the last with
#                  factor 1.84 (its kernel 12.8 M/s against 18.0), which kMinTwoCoreFactor
#                  = 1.9 now excludes.
# Reasoning: a check compares one run with one tracked run, both noisy, so the difference has
# sqrt(2) x the spread of one; 3 sigma of it is 3 x 1.41 x 2.2 % = 9.4 % (DEM) and 8.6 % (FE),
# above the worst drop seen between any two of the eight runs (6.4 %, 4.8 %): a false alarm
# about 1 in 700 checks if the noise is normal, while a slowdown beyond ~10 % fails. The 2-thread
# ratio spreads 10 times more (docs/dem.md: +-20 % between idle runs of one binary), and
# three runs cannot measure it: its margin only catches a collapse of the parallel speed-up
# (a serial region, lost threads), not a small regression; the 1-thread figure is the fine one.
# Re-measured (issue 34) on the 2-core Intel Xeon with AVX-512, 2026-12-06, after the gathered
# Hertz-Mindlin law, idle, `--spread 5` twice (10 runs):
#   DEM 1 thread:  median 0.0991, cv 1.75 %, 3 sigma of a difference 7.4 %, worst drop between
#                  two runs 5.7 %: the 10 % margin stays
#   DEM 2 threads: median 0.0956, cv 4.0 %, 3 sigma 16.8 %, worst drop 12.0 %: 25 % stays
#   FE 10 x 20:    median 0.0427, cv 2.8 %, 3 sigma 12.0 %, worst drop 9.0 %: the margin
#                  rises from 10 % to 12 % (by the rule above; 10 % would fail about 1 check
#                  in 160 on this machine with nothing changed)
margin_dem_1t=0.10
margin_dem_2t=0.25
margin_fe=0.12

stamp=$(date -u +%Y%m%d)
commit=$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
dirty=no
if ! git diff --quiet HEAD -- solver benchmarks 2>/dev/null; then dirty=yes; fi
for b in bench_dem bench_fe summarize_benchmarks; do
  [[ -x $bin/$b ]] || { echo "bench-check: $bin/$b missing (run make)" >&2; exit 2; }
done
if [[ ! -f $(dirname "$0")/../../shared/bench/pack_35k.data.gz ]]; then
  echo "bench-check: ../shared/bench/pack_35k.data.gz absent: BM_DemCompaction runs on the Song" \
       "packing (packed once, minutes; not comparable with pack_35k results)" >&2
fi

# One short run: both binaries, JSON named as `make bench` names its files (plus a tag).
one_run() {  # $1: folder, $2: tag inserted in the file names ("" or "r<k>")
  local dir=$1 tag=${2:+_$2}
  local common=(--benchmark_repetitions="$reps" --benchmark_enable_random_interleaving=true
                --benchmark_out_format=json
                --benchmark_context=kind=bench-check,git_commit="$commit",git_dirty="$dirty")
  local b filter
  for b in bench_dem bench_fe; do
    if [[ $b == bench_dem ]]; then filter='^BM_(Reference|DemCompaction)/[12]/'
    else filter='^BM_(Reference/1/|FeSpecimenStep/10/20$)'; fi
    # The console table and context go to a log; the JSON is what counts.
    if ! "$bin/$b" "${common[@]}" --benchmark_filter="$filter" \
         --benchmark_out="$dir/${stamp}_${commit}${tag}_$b.json" >"$dir/$b$tag.log" 2>&1; then
      cat "$dir/$b$tag.log" >&2
      echo "bench-check: $b failed (log above)" >&2
      exit 2
    fi
  done
}

if (( spread > 0 )); then
  dir=$build/bench-check/spread-$(date -u +%Y%m%dT%H%M%S)
  mkdir -p "$dir"
  for ((k = 1; k <= spread; k++)); do
    echo "bench-check: spread run $k of $spread ($(date -u +%H:%M:%S) UTC, load $(cut -d' ' -f1-3 /proc/loadavg))"
    one_run "$dir" "r$k"
  done
  "$bin/summarize_benchmarks" spread "$dir"/*_bench_dem.json "$dir"/*_bench_fe.json
  echo "bench-check: runs kept in $dir"
  exit 0
fi

dir=$build/bench-check/$(date -u +%Y%m%dT%H%M%S)
mkdir -p "$dir"
echo "bench-check: $reps interleaved repetitions of BM_Reference, BM_DemCompaction/1, /2 and" \
     "BM_FeSpecimenStep/10/20 (load $(cut -d' ' -f1-3 /proc/loadavg); commit $commit, changes: $dirty)"
one_run "$dir" ""
"$bin/summarize_benchmarks" check --results "$results" --seed-as "${stamp}_${commit}" \
  --margin dem_1t="$margin_dem_1t" --margin dem_2t="$margin_dem_2t" --margin fe="$margin_fe" \
  "$dir/${stamp}_${commit}_bench_dem.json" "$dir/${stamp}_${commit}_bench_fe.json"
