#!/usr/bin/env bash
# Issue 31, item 0: does the Chapter 4 specimen stay at rest? For N = 4, 3, 2 (the Chapter 4
# scene at full scale, its packing cache shared with the reproduction), the specimen held
# between fixed walls with no load for 200 us, started (a) as the runs started it before
# (packing positions, no tangential history) and (b) after the relaxation to rest under the
# run's own law (specimen.relax_to_rest), each with the printed rotational factor
# (0.99999975 per ns: rotation nearly free) and with rotation locked (0).
# Usage: scripts/study-at-rest.sh BUILD OUTDIR [N ...]   (resumable: a finished case is skipped)
set -euo pipefail
build=${1:?build dir}; out=${2:?output dir}; shift 2
ns=("$@"); [ ${#ns[@]} -gt 0 ] || ns=(4 3 2)
mkdir -p "$out"
for n in "${ns[@]}"; do
  for rolling in 0.99999975 0; do
    for relax in off on; do
      name="n${n}_k${rolling}_${relax}"
      [ -s "$out/$name.csv" ] && { echo "skip $name (done)"; continue; }
      echo "== $name"
      "$build/reproductions/study_at_rest" reproductions/chapter4/scene_full.json --upscale "$n" \
        --rolling "$rolling" --relax "$relax" --cache "$out/packings" --every 20e-6 \
        --csv "$out/$name.csv" | tee "$out/$name.log"
    done
  done
done
