#!/usr/bin/env bash
# Issue 31, H1 (preparation) at rest, Chapters 3 and 5 (the chapter READMEs, "The preparation
# study, H1"): each packing procedure (jammed growth or servo walls, rotation free or locked
# while packing) at the printed porosity, relaxed to rest under the run's own law; the census at
# rest (Z_0, load-bearing Z, rattlers, wall stresses) from study_at_rest --hold 0.
#   Chapter 3: scene_full.json at N = 3 with the tube rigid (the level within 3 % of the full
#   model); Chapter 5: scene_wang.json at N = 2 (breakage on, as the runs).
# Usage: scripts/study-preparation-census.sh BUILD OUTDIR 3|5 [N]   (resumable)
set -euo pipefail
build=${1:?build dir}; out=${2:?output dir}; chapter=${3:?chapter 3 or 5}
case $chapter in
  3) scene=reproductions/chapter3/scene_full.json; n=${4:-3}
     extra=(--set 'specimen.tube="rigid"' --set specimen.tube_youngs_modulus=null
            --set specimen.tube_poisson_ratio=null --set specimen.tube_density=null
            --set specimen.tube_thickness=null --set specimen.tube_length=null) ;;
  5) scene=reproductions/chapter5/scene_wang.json; n=${4:-2}; extra=() ;;
  *) echo "chapter must be 3 or 5" >&2; exit 1 ;;
esac
mkdir -p "$out"
for pr in "jammed:false" "jammed:true" "servo_walls:false" "servo_walls:true"; do
  packing=${pr%%:*}; lock=${pr##*:}
  name="ch${chapter}_n${n}_${packing}_lock${lock}"
  log="$out/$name.log"
  [ -s "$log" ] && grep -q "rattlers" "$log" && { echo "skip $name (done)"; continue; }
  echo "== $name"
  "$build/reproductions/study_at_rest" "$scene" --upscale "$n" --relax on --hold 0 \
    --cache "$out/packing_cache" "${extra[@]}" --set "specimen.packing=\"$packing\"" \
    --set "specimen.packing_lock_rotation=$lock" > "$log.tmp" && mv "$log.tmp" "$log"
  grep -h "relaxation to rest" "$log" || true
  tail -1 "$log"
done
