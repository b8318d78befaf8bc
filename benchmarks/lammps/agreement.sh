#!/usr/bin/env bash
# Same physics before same speed: the lid, bottom and tube forces and the mean coordination of
# the bench_dem compaction scene at fixed steps, from kolsky (build/benchmarks/dem_agreement,
# the scene of BM_DemCompaction), LAMMPS (in.compaction_hertz_history, in.compaction_granular)
# and LIGGGHTS (in.compaction_liggghts); a table of them and of each peer's difference from
# kolsky, and a verdict per peer: it agrees when, at every recorded step after step 0, its
# lid and tube forces are within TOL (relative) of kolsky's and its coordination within ZTOL
# (step 0 is shown, not judged: LIGGGHTS sums the lid force from the first step only).
# run.sh reports a speed ratio only against a peer that agrees. Not timed: the decks run with
# diag 1 (wall-force outputs), which costs time; kolsky runs on one thread.
#
#   benchmarks/lammps/agreement.sh [OUT.tsv]     (default: a temporary file, printed only)
#
# Environment (all optional):
#   PACK      packing (../shared/bench/pack_35k.data.gz beside the repository)
#   CUT       keep only the grains with z + r <= CUT (m) and put the lid there (the in-test
#             check's scene, verification/test_dem_peer_reference.cpp); default: all grains
#   WARMUP / TIMED / THERMO   steps (100 / 793 / 100): rows at every THERMO steps and at the end
#   CODES     peers to run ("hertz_history granular liggghts")
#   TOL, ZTOL tolerances (0.05, 0.05); why 5 %: README.md, "Agreement"
#   REFERENCE write the LAMMPS `granular` rows to this path as the in-test reference
#             (benchmarks/lammps/reference/cut2mm_lammps_granular.tsv)
#   LMP, LIGGGHTS, KOLSKY_BUILD, KOLSKY   binaries (common.sh)
# Exit status: 0 every peer agrees, 3 one does not, 2 something missing, 1 a run failed.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"  # sets here, root, tmp (removed on exit)

PACK=${PACK:-"$root/../shared/bench/pack_35k.data.gz"}
WARMUP=${WARMUP:-100}
TIMED=${TIMED:-793}
THERMO=${THERMO:-100}
CODES=${CODES:-"hertz_history granular liggghts"}
TOL=${TOL:-0.05}
ZTOL=${ZTOL:-0.05}
CUT=${CUT:-}
out=${1:-"$tmp/agreement.tsv"}

find_peers
find_kolsky
prepare_data "$PACK" "$CUT"
total=$((WARMUP + TIMED))
steps=$( (echo 0; seq "$THERMO" "$THERMO" "$total"; echo "$WARMUP"; echo "$total") | sort -n | uniq |
         paste -sd, -)
ztop_args=()
kolsky_args=(--pack "$PACK" --dt 3.78e-8 --steps "$steps")
if [[ -n "$CUT" ]]; then
  ztop_args=(-var ztop "$CUT")
  kolsky_args+=(--cut "$CUT")
fi
echo "agreement: $natoms grains${CUT:+ (cut at z + r <= $CUT m)}, steps $steps; tolerance" \
     "lid and tube $TOL relative, coordination $ZTOL"

rows="$tmp/rows.tsv"
"$KOLSKY" "${kolsky_args[@]}" | awk '!/^#/ && $1 ~ /^[0-9]+$/ {
  printf "kolsky\t%s\t%s\t%s\t%s\t%s\n", $1, $2, $3, $4, $5 }' >"$rows"
for code in $CODES; do
  run_peer "$code" 1 "$tmp/$code.log" -var diag 1 -var thermo "$THERMO" \
    -var warmup "$WARMUP" -var timed "$TIMED" "${ztop_args[@]}"
  peer_forces "$code" "$tmp/$code.log" >>"$rows"
done
cp "$rows" "$out"

# Table: per step, each code's values; then each peer's largest differences over the steps.
awk -F'\t' -v tol="$TOL" -v ztol="$ZTOL" -v codes="kolsky $CODES" \
    -v verdicts="$tmp/verdicts" '
  { v[$1, $2] = $0; lid[$1, $2] = $3; bot[$1, $2] = $4; tube[$1, $2] = $5; z[$1, $2] = $6
    if (!($2 in seen)) { seen[$2] = 1; order[++ns] = $2 } }
  function rel(a, b) { return b != 0 ? (a - b) / b : 0 }
  function absv(x) { return x < 0 ? -x : x }
  END {
    nc = split(codes, c, " ")
    printf "%-14s %5s %10s %10s %10s %7s %8s %8s %7s\n", "code", "step", "lid_N", "bottom_N",
           "tube_N", "Z", "d_lid", "d_tube", "d_Z"
    for (k = 1; k <= ns; k++) { s = order[k]
      for (i = 1; i <= nc; i++) { n = c[i]; if (!((n, s) in lid)) continue
        printf "%-14s %5d %10.1f %10.1f %10.1f %7.3f", n, s, lid[n, s], bot[n, s], tube[n, s], z[n, s]
        if (n != "kolsky" && ("kolsky", s) in lid)
          printf " %+7.1f%% %+7.1f%% %+7.3f", 100 * rel(lid[n, s], lid["kolsky", s]),
                 100 * rel(tube[n, s], tube["kolsky", s]), z[n, s] - z["kolsky", s]
        printf "\n" } }
    printf "\n%-14s %11s %11s %9s  %s\n", "peer", "max|d_lid|", "max|d_tube|", "max|d_Z|", "verdict"
    bad = 0
    for (i = 2; i <= nc; i++) { n = c[i]; ml = mt = mz = 0; cnt = 0
      for (k = 1; k <= ns; k++) { s = order[k]
        if (s + 0 == 0 || !((n, s) in lid) || !(("kolsky", s) in lid)) continue
        cnt++
        if (absv(rel(lid[n, s], lid["kolsky", s])) > ml) ml = absv(rel(lid[n, s], lid["kolsky", s]))
        if (absv(rel(tube[n, s], tube["kolsky", s])) > mt) mt = absv(rel(tube[n, s], tube["kolsky", s]))
        if (absv(z[n, s] - z["kolsky", s]) > mz) mz = absv(z[n, s] - z["kolsky", s]) }
      ok = cnt > 0 && ml <= tol && mt <= tol && mz <= ztol
      if (!ok) bad = 1
      printf "%-14s %10.2f%% %10.2f%% %9.3f  %s\n", n, 100 * ml, 100 * mt, mz, ok ? "agrees" : "DISAGREES"
      printf "%s\t%s\t%.5f\t%.5f\t%.4f\n", n, ok ? "agrees" : "disagrees", ml, mt, mz >verdicts }
    exit bad }' "$rows" && status=0 || status=$?
[[ $status -le 1 ]] || die "table failed"
cp "$tmp/verdicts" "$out.verdicts"

if [[ -n "${REFERENCE:-}" ]]; then
  grep -q '^granular' "$rows" || die "REFERENCE needs the granular deck in CODES"
  {
    echo "# The LAMMPS reference of verification/test_dem_peer_reference.cpp (tolerance and its"
    echo "# reason: the .json beside this file). Rows of benchmarks/lammps/in.compaction_granular"
    echo "# (diag 1) on the cut of pack_35k with z + r <= ${CUT:-(none)} m, the lid there."
    echo "# produced by: CUT=${CUT:-} WARMUP=$WARMUP TIMED=$TIMED THERMO=$THERMO REFERENCE=... benchmarks/lammps/agreement.sh"
    echo "# LAMMPS $lmp_version; packing sha256 $pack_sha; grains $natoms; dt 3.78e-8 s"
    printf 'step\tlid_N\tbottom_N\ttube_N\tcoordination\n'
    awk -F'\t' '$1 == "granular" { print $2 "\t" $3 "\t" $4 "\t" $5 "\t" $6 }' "$rows"
  } >"$REFERENCE"
  echo "wrote $REFERENCE"
fi
[[ $status -eq 0 ]] || { echo "agreement: a peer disagrees beyond the tolerance" >&2; exit 3; }
