#!/usr/bin/env bash
# Runs every Google Benchmark binary and keeps its JSON in benchmarks/results/, named by date
# and commit, then prints a one-line summary per benchmark.
set -euo pipefail
bin_dir=${1:?benchmark binary folder}
out_dir=${2:?results folder}
mkdir -p "$out_dir"
stamp=$(date -u +%Y%m%d)
commit=$(git rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
shopt -s nullglob
for b in "$bin_dir"/bench_*; do
  name=$(basename "$b")
  out="$out_dir/${stamp}_${commit}_${name}.json"
  "$b" --benchmark_out="$out.tmp" --benchmark_out_format=json --benchmark_repetitions=3 \
       --benchmark_report_aggregates_only=true
  # Google Benchmark writes a counter's cv over zeros (0 / 0) as a bare NaN, which is not JSON:
  # null instead, so that every tracked file parses (BenchSummary.TrackedResultsParse).
  sed -E -i 's/: -?(NaN|Infinity)([,}]|$)/: null\2/' "$out.tmp"
  mv "$out.tmp" "$out"
  echo "bench: wrote $out"
done
# The Chapter 5 set's list-scheduling model (issue 33): not a timing, the measured members' run
# times scheduled on 1-64 ranks, tracked beside the speeds (reports/benchmarks/README.md, (d)).
members=reproductions/chapter5/members_full_measured.json
schedule="$bin_dir/../reproductions/study_ch5_schedule"
if [[ -x "$schedule" && -f "$members" ]]; then
  out="$out_dir/${stamp}_${commit}_bench_ch5_model.json"
  "$schedule" "$members" 1 2 4 8 16 64 --json "$out" > /dev/null
  echo "bench: wrote $out"
fi
