#!/usr/bin/env bash
# Issue 31 item 3 (reproductions/chapter5/README.md, "sigma_lim0 over packing seeds"): the
# Chapter 5 back-calculation of sigma_lim0 at N = 2.5 and 2 over packing seeds 1-3, against the
# N = 1 reference the set uses (the Wang specimen, peak rate held, ended at 72 MPa). The reference
# is study_wang_loading's n1 case (shared with make study-wang-loading, ~35 min if not there yet).
# One OpenMP thread per run; resumable (finished seeds and packings are kept in OUTDIR).
# Usage: scripts/study-backcalc-seeds.sh BUILD OUTDIR [N ...]   (default N: 2.5 2)
set -euo pipefail
build=$1 out=$2
shift 2
ns=("$@")
[[ ${#ns[@]} -gt 0 ]] || ns=(2.5 2)
export OMP_NUM_THREADS=1
wang="$(dirname "$out")/study-wang"
"$build/reproductions/study_wang_loading" --out "$wang" --cache "$wang/packing_cache" --label n1 --upscale 1
for n in "${ns[@]}"; do
  "$build/reproductions/study_backcalc_seeds" --reference "$wang/n1_history.csv" --upscale "$n" --seeds 1,2,3 \
      --out "$out" --cache "$out/packing_cache"
done
