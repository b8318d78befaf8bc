#!/usr/bin/env bash
# Issue 31, item 2, H1 (preparation), Chapter 4: each preparation procedure at the printed
# porosity, relaxed to rest under the run's law, then the printed case (k = 0.99999975 per ns)
# loaded at the scene's rate; per N and procedure: the relaxation's Z and stress
# (study_at_rest, no hold) and the run's report (reproduce_chapter4 with KOLSKY_CH4_SET; the
# 1-3 MPa slope, the strain at 0.1 and 1 MPa in plots_src/stress_strain.dat).
# Usage: scripts/study-preparation.sh BUILD OUTDIR [N ...]   (default N: 4 3; resumable)
set -euo pipefail
build=${1:?build dir}; out=${2:?output dir}; shift 2
ns=("$@"); [ ${#ns[@]} -gt 0 ] || ns=(4 3)
mkdir -p "$out"
procedures=("jammed:false" "jammed:true" "servo_walls:false" "servo_walls:true")
for n in "${ns[@]}"; do
  for pr in "${procedures[@]}"; do
    packing=${pr%%:*}; lock=${pr##*:}
    name="n${n}_${packing}_lock${lock}"
    dir="$out/$name"
    [ -s "$dir/report.md" ] && { echo "skip $name (done)"; continue; }
    echo "== $name"
    mkdir -p "$dir"
    "$build/reproductions/study_at_rest" reproductions/chapter4/scene_full.json --upscale "$n" \
      --relax on --hold 0 --cache "$dir/packing_cache" \
      --set "specimen.packing=\"$packing\"" --set "specimen.packing_lock_rotation=$lock" \
      > "$dir/at_rest.log"
    KOLSKY_CH4_SET="specimen.upscale=$n;specimen.packing=\"$packing\";specimen.packing_lock_rotation=$lock;specimen.relax_to_rest=true" \
    KOLSKY_CH4_KS=0.99999975 KOLSKY_CH4_STUDIES= KOLSKY_CH4_NS= KOLSKY_CH4_SEEDS= \
      "$build/reproductions/reproduce_chapter4" --scale full --out "$dir" > "$dir/run.log" 2>&1 || true
    grep -h "relaxation to rest" "$dir/at_rest.log" || true
  done
done
