#!/usr/bin/env bash
# make rebaseline SET=<set> REASON="..." [SCALE=smoke|full] [RUNS=n]
# Runs the set once as written and RUNS more times with every float of its scenes moved by one
# ulp (reproduce_<set> --perturb-ulp k), then lets kolsky_gate write
# reproductions/<set>/baseline_<scale>.json (each value's tolerance from the spread of those
# runs) and append the reason, what moved and the commit to reproductions/BASELINES.md.
set -euo pipefail
build=${1:?build folder}
set_name=${2:-}
scale=${3:-smoke}
runs=${4:-}
reason=${5:-}
usage='usage: make rebaseline SET=<set> REASON="why the numbers moved" [SCALE=smoke|full] [RUNS=n]'
if [ -z "$set_name" ] || [ -z "$reason" ]; then echo "$usage" >&2; exit 2; fi
driver="$build/reproductions/reproduce_$set_name"
if [ ! -x "$driver" ]; then echo "rebaseline: no driver $driver (sets: $(ls "$build"/reproductions | sed -n 's/^reproduce_//p' | tr '\n' ' '))" >&2; exit 2; fi
# Smoke: 8 perturbed reruns (seconds to a minute each). Full: none by default (a chapter takes
# up to 40 minutes); its baseline then reports every change beyond the ulp floor, which suits a
# report that never fails on a move.
# A set without a scene file (verification: its checks build their inputs in code) has nothing
# to perturb, so it gets none.
# A set's scenes are scene_<scale>.json or scene_<test>.json (chapter5: scene_wang.json, ...).
if [ -z "$runs" ]; then
  if [ "$scale" = smoke ] && compgen -G "$(dirname "$0")/../reproductions/$set_name/scene_*.json" > /dev/null; then
    runs=8
  else
    runs=0
  fi
fi
commit=$(git describe --always --dirty --abbrev=12 2>/dev/null || echo unknown)
work="$build/rebaseline/$set_name/$scale"
rm -rf "$work"
mkdir -p "$work"
dirs=()
for k in $(seq 0 "$runs"); do
  out="$work/run$k"
  extra=()
  [ "$k" -gt 0 ] && extra=(--perturb-ulp "$k")
  echo "rebaseline: $set_name $scale run $k of $runs${extra:+ (--perturb-ulp $k)}" >&2
  # A set that fails a target still measured everything: its exit status is not the point here.
  "$driver" --scale "$scale" --out "$out" "${extra[@]}" > "$out.log" 2>&1 || true
  if [ ! -f "$out/measurements.json" ]; then
    echo "rebaseline: run $k wrote no measurements; its log:" >&2; tail -20 "$out.log" >&2; exit 3
  fi
  dirs+=("$out")
done
"$build/reproductions/kolsky_gate" rebaseline --set "$set_name" --scale "$scale" --runs "${dirs[@]}" \
  --reason "$reason" --commit "$commit"
