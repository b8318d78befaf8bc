#!/usr/bin/env bash
# The sanitized build of kolsky's input layer (fuzz/CMakeLists.txt) and its two uses:
#   scripts/sanitize.sh fuzz  [BUILD_DIR]  each libFuzzer target for FUZZ_SECONDS (default 60)
#   scripts/sanitize.sh check [BUILD_DIR]  the ASan + UBSan unit tests (kolsky_tests_sanitize)
# BUILD_DIR defaults to build-sanitize. FUZZ_TARGETS (default "scene bars csv gauges") picks
# targets. Each target first replays its committed corpus (fuzz/corpus/<target>/: the project's
# own files and every reproducer found so far), then mutates, keeping what it finds in
# BUILD_DIR/corpus/<target>/ between runs. A crash, a sanitizer report, a leak, a hang (10 s)
# or an exception other than InputError stops the target: the input is written to
# BUILD_DIR/artifacts/<target>/ and the line to reproduce it is printed (docs/fuzzing.md).
set -euo pipefail
cd "$(dirname "$0")/.."
mode=${1:-}
build=${2:-build-sanitize}
case "$mode" in fuzz|check) ;; *) echo "usage: scripts/sanitize.sh fuzz|check [BUILD_DIR]" >&2; exit 2 ;; esac

cxx=$(command -v clang++-14 || command -v clang++ || true)
cc=$(command -v clang-14 || command -v clang || true)
if [ -z "$cxx" ] || [ -z "$cc" ]; then
  echo "sanitize: clang++ not found (scripts/install-deps.sh installs clang-14)" >&2; exit 1
fi
launcher=()
if command -v ccache >/dev/null 2>&1; then launcher=(-DCMAKE_CXX_COMPILER_LAUNCHER=ccache -DCMAKE_C_COMPILER_LAUNCHER=ccache); fi
jobs=${JOBS:-$(nproc 2>/dev/null || echo 2)}
cmake -S fuzz -B "$build" -DCMAKE_CXX_COMPILER="$cxx" -DCMAKE_C_COMPILER="$cc" "${launcher[@]}" >/dev/null

if [ "$mode" = check ]; then
  cmake --build "$build" -j "$jobs" --target kolsky_tests_sanitize
  cd "$build" && exec ctest --output-on-failure -j "$jobs"
fi

seconds=${FUZZ_SECONDS:-60}
targets=${FUZZ_TARGETS:-scene bars csv gauges}
for t in $targets; do
  [ -d "fuzz/corpus/$t" ] || { echo "sanitize: no target '$t' (fuzz/corpus/$t missing)" >&2; exit 2; }
done
# shellcheck disable=SC2086
cmake --build "$build" -j "$jobs" --target $(printf 'fuzz_%s ' $targets)

# Longest input per target: a little above the largest seed (a gauge record of a few hundred
# rows, a pulse table); longer inputs only slow the search down.
max_len() { case "$1" in scene) echo 4096 ;; bars) echo 2048 ;; *) echo 16384 ;; esac; }
status=0
for t in $targets; do
  work="$build/corpus/$t"; artifacts="$build/artifacts/$t"; log="$build/fuzz_$t.log"
  rm -rf "$artifacts"; mkdir -p "$work" "$artifacts"
  set +e
  "$build/fuzz_$t" -max_total_time="$seconds" -max_len="$(max_len "$t")" -timeout=10 \
    -rss_limit_mb=2048 -print_final_stats=1 -artifact_prefix="$artifacts/" \
    "$work" "fuzz/corpus/$t" >"$log" 2>&1
  rc=$?
  set -e
  runs=$(sed -n 's/^stat::number_of_executed_units: *//p' "$log")
  rate=$(sed -n 's/^stat::average_exec_per_sec: *//p' "$log")
  if [ "$rc" -eq 0 ]; then
    echo "fuzz_$t: ${runs:-?} inputs in ${seconds} s (${rate:-?}/s), no failure"
  else
    status=1
    echo "fuzz_$t: FAILED (exit $rc) after ${runs:-?} inputs; the report:"
    grep -E "ERROR|SUMMARY|runtime error|uncaught|what\(\)|Test unit written" "$log" | head -20
    for a in "$artifacts"/*; do
      [ -e "$a" ] && echo "  reproduce: $build/fuzz_$t $a   (then add it to fuzz/corpus/$t/)"
    done
    echo "  full log: $log"
  fi
done
exit $status
