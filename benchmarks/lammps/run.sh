#!/usr/bin/env bash
# LAMMPS peer timings for kolsky's bench_dem scene (see README.md in this folder).
#
#   benchmarks/lammps/run.sh [OUT.json]
#
# Runs in.compaction_hertz_history and in.compaction_granular on the benchmark packing, REPS
# times each on one core (OMP_NUM_THREADS=1, no -sf suffix) and, when mpirun exists, on
# MPI_RANKS ranks; reads the "Loop time" of the timed run (TIMED steps after WARMUP untimed
# ones), prints a table and writes OUT.json (default benchmarks/results/<yyyymmdd>_lammps.json).
#
# Environment (all optional):
#   LMP        LAMMPS binary (default: the first of lmp, lmp_serial, lmp_mpi, lmp_stable in PATH)
#   PACK       packing (default ../shared/bench/pack_35k.data.gz next to the repository)
#   REPS       runs per configuration (3)         WARMUP / TIMED  steps (100 / 793)
#   MPI_RANKS  ranks of the parallel runs (2; 0 or 1 = single core only)
#   STYLES     inputs to run ("hertz_history granular")
#   MPIRUN     MPI launcher (mpirun)
# Exit status: 0 done, 2 LAMMPS, its GRANULAR package or the packing missing, 1 a run failed.
set -euo pipefail

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)

REPS=${REPS:-3}
WARMUP=${WARMUP:-100}
TIMED=${TIMED:-793}
MPI_RANKS=${MPI_RANKS:-2}
STYLES=${STYLES:-"hertz_history granular"}
MPIRUN=${MPIRUN:-mpirun}
PACK=${PACK:-"$root/../shared/bench/pack_35k.data.gz"}
out=${1:-"$root/benchmarks/results/$(date +%Y%m%d)_lammps.json"}

die() { echo "run.sh: $*" >&2; exit "${code:-2}"; }

# --- LAMMPS --------------------------------------------------------------------------------------
if [[ -z "${LMP:-}" ]]; then
  for c in lmp lmp_serial lmp_mpi lmp_stable; do
    if command -v "$c" >/dev/null 2>&1; then LMP=$c; break; fi
  done
fi
[[ -n "${LMP:-}" ]] && command -v "$LMP" >/dev/null 2>&1 ||
  die "LAMMPS not found (tried lmp, lmp_serial, lmp_mpi, lmp_stable; set LMP=...).
  It is optional and not part of the project's install script; on Debian/Ubuntu:
  apt-get install -y lammps"
LMP=$(command -v "$LMP")
help=$("$LMP" -h 2>/dev/null || true)
for s in gran/hertz/history granular wall/gran nve/sphere; do
  grep -qw -- "$s" <<<"$help" || die "$LMP lacks the style '$s' (needs the GRANULAR package)"
done
version=$(grep -m1 -o 'Simulator - .*' <<<"$help" | sed 's/^Simulator - //' || true)

# --- packing -------------------------------------------------------------------------------------
[[ -r "$PACK" ]] || die "packing not found: $PACK
  (the shared benchmark packing pack_35k.data.gz; set PACK=... to point at it)"
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT
data="$tmp/pack.data"
case "$PACK" in
  *.gz) gzip -dc "$PACK" >"$data" ;;
  *) cp "$PACK" "$data" ;;
esac
# read_data needs a LAMMPS header (count, types, box) and an Atoms section; the shared file has
# them. A bare list of `id type diameter density x y z` rows gets one here (box = rows' extent
# plus 0.5 mm).
if ! head -n 40 "$data" | grep -qE '^[[:space:]]*[0-9]+[[:space:]]+atoms' ||
   ! grep -qE '^Atoms' "$data"; then
  awk 'NF == 7 && $1 ~ /^[0-9]+$/ {
         n++; r = $3 / 2
         if (n == 1) { xl = $5 - r; xh = $5 + r; yl = $6 - r; yh = $6 + r; zl = $7 - r; zh = $7 + r }
         if ($5 - r < xl) xl = $5 - r; if ($5 + r > xh) xh = $5 + r
         if ($6 - r < yl) yl = $6 - r; if ($6 + r > yh) yh = $6 + r
         if ($7 - r < zl) zl = $7 - r; if ($7 + r > zh) zh = $7 + r
         rows[n] = $0 }
       END { m = 5e-4
         print "header added by benchmarks/lammps/run.sh\n"
         printf "%d atoms\n1 atom types\n\n", n
         printf "%.10e %.10e xlo xhi\n%.10e %.10e ylo yhi\n%.10e %.10e zlo zhi\n\nAtoms # sphere\n\n",
                xl - m, xh + m, yl - m, yh + m, zl - m, zh + m
         for (i = 1; i <= n; i++) print rows[i] }' "$data" >"$data.new"
  mv "$data.new" "$data"
  echo "note: $PACK had no LAMMPS header; added one" >&2
fi
natoms=$(grep -m1 -E '^[[:space:]]*[0-9]+[[:space:]]+atoms' "$data" | awk '{print $1}')
pack_sha=$(sha256sum "$PACK" | awk '{print $1}')

# --- configurations ------------------------------------------------------------------------------
ranks_list=(1)
if [[ "$MPI_RANKS" -gt 1 ]]; then
  if command -v "$MPIRUN" >/dev/null 2>&1; then
    ranks_list+=("$MPI_RANKS")
    if [[ $(id -u) -eq 0 ]]; then  # Open MPI refuses root without these
      export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
    fi
  else
    echo "note: $MPIRUN not found: single-core runs only" >&2
  fi
fi

load_start=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "")
ncpu=$(nproc 2>/dev/null || echo 0)
cpu_model=$(grep -m1 'model name' /proc/cpuinfo 2>/dev/null | sed 's/.*: //' || true)
if [[ -n "$load_start" ]] && awk -v l="${load_start%% *}" 'BEGIN { exit !(l > 0.5) }'; then
  echo "note: load average $load_start at start: other work shares the CPUs, timings will be low" >&2
fi
echo "LAMMPS ${version:-?} ($LMP), $natoms grains, $WARMUP warm-up + $TIMED timed steps, $REPS runs each"

export OMP_NUM_THREADS=1
results="$tmp/results.tsv"
: >"$results"
printf '%-14s %5s %4s %12s %14s %12s %7s %8s\n' style ranks run loop_s particle_steps/s pair_s builds neigh/at
for style in $STYLES; do
  input="$here/in.compaction_$style"
  [[ -r "$input" ]] || die "no input $input"
  for ranks in "${ranks_list[@]}"; do
    for rep in $(seq 1 "$REPS"); do
      log="$tmp/$style.$ranks.$rep.log"
      launch=("$LMP")
      [[ "$ranks" -gt 1 ]] && launch=("$MPIRUN" -np "$ranks" "$LMP")
      if ! (cd "$tmp" && "${launch[@]}" -nocite -echo none -screen none -log "$log" \
              -in "$input" -var data "$data" -var warmup "$WARMUP" -var timed "$TIMED" \
              >"$tmp/stdout" 2>&1); then
        cat "$tmp/stdout" >&2
        tail -n 20 "$log" >&2 2>/dev/null || true
        code=1 die "LAMMPS failed: $style, $ranks rank(s), run $rep"
      fi
      # "Loop time of T on P procs for S steps with N atoms" of the last (timed) run
      read -r loop steps atoms < <(grep '^Loop time of' "$log" | tail -n 1 | awk '{print $4, $9, $12}')
      [[ "$steps" == "$TIMED" ]] || code=1 die "unexpected log (timed run has $steps steps): $log"
      pair=$(grep -E '^Pair +\|' "$log" | tail -n 1 | awk -F'|' '{gsub(/ /, "", $3); print $3}')
      builds=$(grep 'Neighbor list builds' "$log" | tail -n 1 | awk '{print $NF}')
      neigh=$(grep 'Ave neighs/atom' "$log" | tail -n 1 | awk '{print $NF}')
      pss=$(awk -v n="$atoms" -v s="$steps" -v t="$loop" 'BEGIN { printf "%.6e", n * s / t }')
      printf '%s\t%s\t%s\t%s\t%s\t%s\t%s\t%s\n' "$style" "$ranks" "$rep" "$loop" "$pss" "$pair" \
        "$builds" "$neigh" >>"$results"
      printf '%-14s %5s %4s %12.4f %14.4g %12.4f %7s %8.3f\n' "$style" "$ranks" "$rep" "$loop" \
        "$pss" "$pair" "$builds" "$neigh"
    done
  done
done

# --- medians -------------------------------------------------------------------------------------
median() { sort -g | awk '{ v[NR] = $1 } END { if (NR % 2) print v[(NR + 1) / 2];
                                               else printf "%.6e\n", (v[NR / 2] + v[NR / 2 + 1]) / 2 }'; }
echo
printf '%-14s %5s %16s %16s\n' style ranks median_psteps/s per_rank
summary=()
for style in $STYLES; do
  for ranks in "${ranks_list[@]}"; do
    med=$(awk -F'\t' -v s="$style" -v r="$ranks" '$1 == s && $2 == r { print $5 }' "$results" | median)
    medloop=$(awk -F'\t' -v s="$style" -v r="$ranks" '$1 == s && $2 == r { print $4 }' "$results" | median)
    per=$(awk -v m="$med" -v r="$ranks" 'BEGIN { printf "%.6e", m / r }')
    printf '%-14s %5s %16.4g %16.4g\n' "$style" "$ranks" "$med" "$per"
    summary+=("{\"style\": \"$style\", \"ranks\": $ranks, \"median_loop_time_s\": $medloop, \"median_particle_steps_per_s\": $med, \"median_particle_steps_per_s_per_rank\": $per}")
  done
done
load_end=$(cut -d' ' -f1-3 /proc/loadavg 2>/dev/null || echo "")
echo "load average: start $load_start, end $load_end (on $ncpu CPUs)"

# --- JSON ----------------------------------------------------------------------------------------
json_list() { local IFS=,; echo "$*"; }
runs=()
while IFS=$'\t' read -r style ranks rep loop pss pair builds neigh; do
  runs+=("{\"style\": \"$style\", \"ranks\": $ranks, \"run\": $rep, \"loop_time_s\": $loop, \"particle_steps_per_s\": $pss, \"pair_time_s\": $pair, \"neighbor_builds\": $builds, \"ave_neighs_per_atom\": $neigh}")
done <"$results"
mkdir -p "$(dirname "$out")"
loadjson() { [[ -n "$1" ]] && echo "[${1// /, }]" || echo "null"; }
{
  echo "{"
  echo "  \"context\": {"
  echo "    \"date\": \"$(date -Iseconds)\","
  echo "    \"host_name\": \"$(hostname)\","
  echo "    \"num_cpus\": $ncpu,"
  echo "    \"cpu_model\": \"$cpu_model\","
  echo "    \"load_avg_start\": $(loadjson "$load_start"),"
  echo "    \"load_avg_end\": $(loadjson "$load_end"),"
  echo "    \"lammps_version\": \"$version\","
  echo "    \"lammps_binary\": \"$LMP\","
  echo "    \"omp_num_threads\": 1,"
  echo "    \"packing\": \"$PACK\","
  echo "    \"packing_sha256\": \"$pack_sha\","
  echo "    \"grains\": $natoms,"
  echo "    \"warmup_steps\": $WARMUP,"
  echo "    \"timed_steps\": $TIMED,"
  echo "    \"timestep_s\": 3.78e-8,"
  echo "    \"reps\": $REPS,"
  echo "    \"inputs\": \"benchmarks/lammps/in.compaction_{$(json_list $STYLES)}\","
  echo "    \"peer_figures_quoted_in_issue\": {\"hertz_history\": 4.2e6, \"granular\": 3.2e6, \"note\": \"particle-steps/s, single core, same machine class\"}"
  echo "  },"
  echo "  \"runs\": ["
  for i in "${!runs[@]}"; do
    sep=,; [[ $i -eq $((${#runs[@]} - 1)) ]] && sep=
    echo "    ${runs[$i]}$sep"
  done
  echo "  ],"
  echo "  \"summary\": ["
  for i in "${!summary[@]}"; do
    sep=,; [[ $i -eq $((${#summary[@]} - 1)) ]] && sep=
    echo "    ${summary[$i]}$sep"
  done
  echo "  ]"
  echo "}"
} >"$out"
echo "wrote $out"
