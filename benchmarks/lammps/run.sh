#!/usr/bin/env bash
# Side-by-side timings of kolsky's bench_dem scene and its peers (README.md in this folder):
# kolsky (build/benchmarks/dem_agreement: the scene of BM_DemCompaction, compaction_scene.hpp),
# LAMMPS in.compaction_hertz_history and in.compaction_granular, LIGGGHTS in.compaction_liggghts.
#
#   benchmarks/lammps/run.sh [OUT.json]
#
# 1. Agreement first (agreement.sh, untimed): the codes' lid and tube forces and coordination
#    at fixed steps. A speed ratio kolsky / peer is reported only for a peer that agrees.
# 2. Then REPS rounds; in each round every code runs once on 1 and on 2 ranks (LAMMPS and
#    LIGGGHTS: MPI ranks, OMP_NUM_THREADS=1; kolsky: OpenMP threads), alternated so that a
#    slow phase of the machine hits all codes alike. Each run times the same TIMED steps after
#    WARMUP untimed ones: LAMMPS' and LIGGGHTS' "Loop time" of the timed `run`, kolsky's wall
#    time over the same steps. particle-steps/s = grains x TIMED / loop time.
# 3. Medians per code and rank count, the ratio of the medians and the median of the per-round
#    ratios; a table, and OUT.json (default benchmarks/results/<yyyymmdd>_<commit>_lammps.json,
#    the format bench-summary reads: context, runs, summary; plus agreement and ratios).
#
# Environment (all optional):
#   PACK      packing (../shared/bench/pack_35k.data.gz next to the repository)
#   REPS      rounds (3)              WARMUP / TIMED  steps (100 / 793)
#   RANKS     rank / thread counts ("1 2")
#   CODES     codes to time ("kolsky hertz_history granular liggghts")
#   TOL, ZTOL agreement tolerances (agreement.sh: 0.05, 0.05)
#   MPIRUN    MPI launcher (mpirun); LMP, LIGGGHTS, KOLSKY_BUILD, KOLSKY: binaries (common.sh)
# Exit status: 0 done, 2 a binary or the packing missing, 1 a run failed.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"  # sets here, root, tmp (removed on exit)

REPS=${REPS:-3}
WARMUP=${WARMUP:-100}
TIMED=${TIMED:-793}
RANKS=${RANKS:-"1 2"}
CODES=${CODES:-"kolsky hertz_history granular liggghts"}
PACK=${PACK:-"$root/../shared/bench/pack_35k.data.gz"}
commit=$(git -C "$root" rev-parse --short=12 HEAD 2>/dev/null || echo unknown)
out=${1:-"$root/benchmarks/results/$(date +%Y%m%d)_${commit}_lammps.json"}

find_peers
find_kolsky
prepare_data "$PACK"
peers=$(tr ' ' '\n' <<<"$CODES" | grep -v '^kolsky$' | paste -sd' ' - || true)
command -v "${MPIRUN:-mpirun}" >/dev/null 2>&1 || RANKS=1

# --- 1. agreement ---------------------------------------------------------------------------------
echo "== agreement (untimed; agreement.sh)"
CODES="$peers" PACK="$PACK" WARMUP="$WARMUP" TIMED="$TIMED" \
  "$here/agreement.sh" "$tmp/agreement.tsv" && agree_status=0 || agree_status=$?
[[ $agree_status -eq 0 || $agree_status -eq 3 ]] || code=1 die "agreement.sh failed"
agrees() { awk -F'\t' -v c="$1" '$1 == c && $2 == "agrees" { f = 1 } END { exit !f }' \
             "$tmp/agreement.tsv.verdicts"; }

# --- 2. alternated timed rounds ---------------------------------------------------------------------
load_start=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "")
ncpu=$(nproc 2>/dev/null || echo 0)
cpu_model=$(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | sed 's/.*: //' || true)
if [[ -n "$load_start" ]] && awk -v l="${load_start%% *}" 'BEGIN { exit !(l > 0.5) }'; then
  echo "note: load average $load_start at start: other work shares the CPUs, timings will be low" >&2
fi
echo "== timing: $natoms grains, $WARMUP warm-up + $TIMED timed steps, $REPS rounds of: $CODES on ranks/threads $RANKS"
results="$tmp/results.tsv"
: >"$results"
dates=()
printf '%-14s %5s %4s %10s %14s %9s %7s %8s\n' code ranks run loop_s particle_steps/s pair_s builds neigh/at
for rep in $(seq 1 "$REPS"); do
  dates+=("$(date -Iseconds)")
  for ranks in $RANKS; do
    for c in $CODES; do
      log="$tmp/$c.$ranks.$rep.log"
      if [[ "$c" == kolsky ]]; then
        OMP_NUM_THREADS=$ranks "$KOLSKY" --pack "$PACK" --dt 3.78e-8 --threads "$ranks" \
          --steps "$WARMUP,$((WARMUP + TIMED))" >"$log" || code=1 die "kolsky failed ($log)"
        read -r loop steps atoms < <(awk '/^# loop/ { print $3, $6, $9 }' "$log")
        pair=null builds=null neigh=null
      else
        run_peer "$c" "$ranks" "$log" -var warmup "$WARMUP" -var timed "$TIMED"
        read -r loop steps atoms < <(loop_time "$log")
        # Pair time: LAMMPS "Pair | min | avg | ...", LIGGGHTS "Pair  time (%) = T (P)".
        pair=$(awk -F'|' '/^Pair +\|/ { gsub(/ /, "", $3); p = $3 }
                          /^Pair +time/ { split($0, a, "= "); split(a[2], b, " "); p = b[1] }
                          END { print (p == "" ? "null" : p) }' "$log")
        builds=$(awk '/Neighbor list builds/ { b = $NF } END { print (b == "" ? "null" : b) }' "$log")
        neigh=$(awk '/Ave neighs\/atom/ { n = $NF } END { print (n == "" ? "null" : n) }' "$log")
      fi
      [[ "$steps" == "$TIMED" ]] || code=1 die "unexpected log (timed part has $steps steps): $log"
      pss=$(awk -v n="$atoms" -v s="$steps" -v t="$loop" 'BEGIN { printf "%.6e", n * s / t }')
      printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$c" "$ranks" "$rep" "$loop" "$pss" "${pair:-null}" \
        "${builds:-null}" "${neigh:-null}" >>"$results"
      printf '%-14s %5s %4s %10.4f %14.4g %9s %7s %8s\n' "$c" "$ranks" "$rep" "$loop" "$pss" \
        "${pair:-}" "${builds:-}" "${neigh:-}"
    done
  done
done
load_end=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "")

# --- 3. medians and ratios --------------------------------------------------------------------------
median() { sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2];
                                               else printf "%.6g\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
rate() { awk -F'\t' -v c="$1" -v r="$2" -v k="${3:-}" '$1 == c && $2 == r && (k == "" || $3 == k) { print $5 }' "$results"; }
echo
printf '%-14s %5s %16s %16s %8s\n' code ranks median_psteps/s per_rank spread
summary=()
for c in $CODES; do
  for ranks in $RANKS; do
    med=$(rate "$c" "$ranks" | median)
    medloop=$(awk -F'\t' -v c="$c" -v r="$ranks" '$1 == c && $2 == r { print $4 }' "$results" | median)
    lo=$(rate "$c" "$ranks" | sort -g | head -n 1); hi=$(rate "$c" "$ranks" | sort -g | tail -n 1)
    per=$(awk -v m="$med" -v r="$ranks" 'BEGIN { printf "%.6e", m / r }')
    printf '%-14s %5s %16.4g %16.4g %s-%s\n' "$c" "$ranks" "$med" "$per" \
      "$(awk -v x="$lo" 'BEGIN { printf "%.3g", x / 1e6 }')" "$(awk -v x="$hi" 'BEGIN { printf "%.3gM", x / 1e6 }')"
    summary+=("{\"style\": \"$c\", \"ranks\": $ranks, \"median_loop_time_s\": $medloop, \"median_particle_steps_per_s\": $med, \"median_particle_steps_per_s_per_rank\": $per, \"min_particle_steps_per_s\": $lo, \"max_particle_steps_per_s\": $hi}")
  done
done
echo
ratios=()
if [[ " $CODES " == *" kolsky "* ]]; then
  printf '%-14s %5s %16s %22s\n' "kolsky / peer" ranks ratio_of_medians "median_per_round (range)"
  for p in $peers; do
    for ranks in $RANKS; do
      if ! agrees "$p"; then
        printf '%-14s %5s %s\n' "$p" "$ranks" "not reported: its forces disagree with kolsky's (agreement above)"
        ratios+=("{\"peer\": \"$p\", \"ranks\": $ranks, \"agrees\": false}")
        continue
      fi
      rm_=$(awk -v a="$(rate kolsky "$ranks" | median)" -v b="$(rate "$p" "$ranks" | median)" 'BEGIN { printf "%.4f", a / b }')
      per_round=$(for rep in $(seq 1 "$REPS"); do
        awk -v a="$(rate kolsky "$ranks" "$rep")" -v b="$(rate "$p" "$ranks" "$rep")" 'BEGIN { printf "%.4f\n", a / b }'; done)
      rr=$(median <<<"$per_round")
      rlo=$(sort -g <<<"$per_round" | head -n 1); rhi=$(sort -g <<<"$per_round" | tail -n 1)
      printf '%-14s %5s %16s %22s\n' "$p" "$ranks" "x$rm_" "x$rr ($rlo-$rhi)"
      ratios+=("{\"peer\": \"$p\", \"ranks\": $ranks, \"agrees\": true, \"ratio_of_medians\": $rm_, \"median_per_round_ratio\": $rr, \"min_per_round_ratio\": $rlo, \"max_per_round_ratio\": $rhi}")
    done
  done
fi
echo "load average: start $load_start, end $load_end (on $ncpu CPUs)"

# --- 4. JSON ------------------------------------------------------------------------------------------
json_array() { local i sep; for i in "${!ARR[@]}"; do sep=,; [[ $i -eq $((${#ARR[@]} - 1)) ]] && sep=
                 echo "    ${ARR[$i]}$sep"; done; }
loadjson() { [[ -n "$1" ]] && echo "[${1// /, }]" || echo "null"; }
runs=()
while IFS=$'\t' read -r c ranks rep loop pss pair builds neigh; do
  runs+=("{\"style\": \"$c\", \"ranks\": $ranks, \"run\": $rep, \"loop_time_s\": $loop, \"particle_steps_per_s\": $pss, \"pair_time_s\": $pair, \"neighbor_builds\": $builds, \"ave_neighs_per_atom\": $neigh}")
done <"$results"
agreement=()
while IFS=$'\t' read -r c step lid bot tube z; do
  agreement+=("{\"code\": \"$c\", \"step\": $step, \"lid_N\": $lid, \"bottom_N\": $bot, \"tube_N\": $tube, \"coordination\": $z}")
done <"$tmp/agreement.tsv"
verdicts=()
while IFS=$'\t' read -r c v ml mt mz; do
  verdicts+=("{\"peer\": \"$c\", \"verdict\": \"$v\", \"max_rel_lid\": $ml, \"max_rel_tube\": $mt, \"max_abs_coordination\": $mz}")
done <"$tmp/agreement.tsv.verdicts"
mkdir -p "$(dirname "$out")"
{
  echo "{"
  echo "  \"context\": {"
  echo "    \"date\": \"${dates[0]}\","
  echo "    \"dates\": [$(printf '"%s",' "${dates[@]}" | sed 's/,$//')],"
  echo "    \"host_name\": \"$(hostname)\","
  echo "    \"num_cpus\": $ncpu,"
  echo "    \"cpu_model\": \"$cpu_model\","
  echo "    \"load_avg_start\": $(loadjson "$load_start"),"
  echo "    \"load_avg_end\": $(loadjson "$load_end"),"
  echo "    \"commit\": \"$commit\","
  echo "    \"lammps_version\": \"$lmp_version\","
  echo "    \"lammps_binary\": \"$LMP\","
  echo "    \"liggghts_version\": \"$liggghts_version\","
  echo "    \"liggghts_binary\": \"$LIGGGHTS\","
  echo "    \"kolsky_binary\": \"$KOLSKY\","
  echo "    \"omp_num_threads\": 1,"
  echo "    \"ranks_note\": \"ranks = MPI ranks for LAMMPS and LIGGGHTS (OMP_NUM_THREADS=1), OpenMP threads for kolsky\","
  echo "    \"packing\": \"$PACK\","
  echo "    \"packing_sha256\": \"$pack_sha\","
  echo "    \"grains\": $natoms,"
  echo "    \"warmup_steps\": $WARMUP,"
  echo "    \"timed_steps\": $TIMED,"
  echo "    \"timestep_s\": 3.78e-8,"
  echo "    \"reps\": $REPS,"
  echo "    \"order\": \"alternated: each round runs every code once per rank count\","
  echo "    \"inputs\": \"benchmarks/lammps/in.compaction_{hertz_history,granular,liggghts}, benchmarks/dem_agreement.cpp\","
  echo "    \"peer_figures_quoted_in_issue\": {\"hertz_history\": 4.2e6, \"granular\": 3.2e6, \"note\": \"particle-steps/s, single core, same machine class\"}"
  echo "  },"
  echo "  \"runs\": ["; ARR=("${runs[@]}"); json_array; echo "  ],"
  echo "  \"summary\": ["; ARR=("${summary[@]}"); json_array; echo "  ],"
  echo "  \"ratios\": ["; ARR=("${ratios[@]+"${ratios[@]}"}"); [[ ${#ARR[@]} -gt 0 ]] && json_array; echo "  ],"
  echo "  \"agreement\": {"
  echo "    \"tolerance\": {\"lid_and_tube_relative\": ${TOL:-0.05}, \"coordination_absolute\": ${ZTOL:-0.05}, \"reason\": \"benchmarks/lammps/README.md, Agreement\"},"
  echo "    \"verdicts\": ["; ARR=("${verdicts[@]}"); json_array | sed 's/^/  /'; echo "    ],"
  echo "    \"rows\": ["; ARR=("${agreement[@]}"); json_array | sed 's/^/  /'; echo "    ]"
  echo "  }"
  echo "}"
} >"$out"
echo "wrote $out"
