#!/usr/bin/env bash
# Issue 31, H2 and H3 (reproductions/chapter5/README.md, "H2 and H3"): the Wang specimen with the
# peak rate held until the back stress reaches 72 MPa, read at the stresses the text names
# (20 / 43 / 60 / 72 MPa), with the reconstructed grain-size curve (top size L/6.4) and with the
# same count at top size L/10; at N = 1 and 1.5 (the text's pair; N = 1.5 compared with N = 1) and
# at N = 2 over three packing seeds (the scatter). One OpenMP thread per case; resumable: a case
# whose summary exists is skipped, packings are cached in OUTDIR/packing_cache.
# prep: the two packing procedures that keep something at rest (the README's H1 census), relaxed
# and loaded the same way at N = 2 (their packings cached with the census's, OUTDIR/../study-preparation).
# Usage: scripts/study-wang-loading.sh BUILD OUTDIR [seeds|pair|prep]   (default: all three)
set -euo pipefail
build=$1 out=$2 part=${3:-all}
study="$build/reproductions/study_wang_loading"
l10=../../data/digitized/chapter5/wang2018_psd_dmax_l10.csv
export OMP_NUM_THREADS=1
run() { "$study" --out "$out" --cache "$out/packing_cache" "$@"; }
if [[ $part == all || $part == seeds ]]; then
  for seed in 1 2 3; do
    run --label "n2_seed${seed}" --upscale 2 --seed "$seed"
    run --label "n2_l10_seed${seed}" --upscale 2 --seed "$seed" --psd "$l10"
  done
fi
if [[ $part == all || $part == prep ]]; then
  prep_cache="$(dirname "$out")/study-preparation/packing_cache"
  run --label n2_jammed_locked_relaxed --upscale 2 --cache "$prep_cache" \
      --set specimen.packing_lock_rotation=true --set specimen.relax_to_rest=true
  run --label n2_servo_free_relaxed --upscale 2 --cache "$prep_cache" \
      --set 'specimen.packing="servo_walls"' --set specimen.relax_to_rest=true
fi
if [[ $part == all || $part == pair ]]; then
  run --label n1 --upscale 1
  run --label n1_5 --upscale 1.5 --reference "$out/n1"
  run --label n1_l10 --upscale 1 --psd "$l10"
  run --label n1_5_l10 --upscale 1.5 --psd "$l10" --reference "$out/n1_l10"
fi
