#!/usr/bin/env bash
# Issue 31, H1 (preparation), Chapter 3 (reproductions/chapter3/README.md, "The preparation
# study, H1"): each packing procedure at the printed porosity 0.465, relaxed to rest under the
# run's own law (LS-DYNA linear contacts with rolling friction), the tube rigid; the census at
# rest (Z_0, load-bearing Z, rattlers, wall stresses) from study_at_rest --hold 0.
# Usage: scripts/study-preparation-ch3.sh BUILD OUTDIR [N ...]   (default N: 3; resumable)
set -euo pipefail
build=${1:?build dir}; out=${2:?output dir}; shift 2
ns=("$@"); [ ${#ns[@]} -gt 0 ] || ns=(3)
mkdir -p "$out"
for n in "${ns[@]}"; do
  for pr in "jammed:false" "jammed:true" "servo_walls:false" "servo_walls:true"; do
    packing=${pr%%:*}; lock=${pr##*:}
    name="ch3_n${n}_${packing}_lock${lock}"
    log="$out/$name.log"
    [ -s "$log" ] && grep -q "rattlers" "$log" && { echo "skip $name (done)"; continue; }
    echo "== $name"
    "$build/reproductions/study_at_rest" reproductions/chapter3/scene_full.json --upscale "$n" \
      --relax on --hold 0 --cache "$out/packing_cache" \
      --set 'specimen.tube="rigid"' --set specimen.tube_youngs_modulus=null \
      --set specimen.tube_poisson_ratio=null --set specimen.tube_density=null \
      --set specimen.tube_thickness=null --set specimen.tube_length=null \
      --set "specimen.packing=\"$packing\"" \
      --set "specimen.packing_lock_rotation=$lock" > "$log.tmp" && mv "$log.tmp" "$log"
    grep -h "relaxation to rest" "$log" || true
    tail -1 "$log"
  done
done
