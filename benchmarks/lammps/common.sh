# Shared by run.sh and agreement.sh (sourced, not run): the peer binaries, the packing copies
# the decks read, and the parsing of their thermo output. Sets $here (this folder), $root (the
# repository) and $tmp (a scratch folder, removed when the script exits); the scripts set
# `set -euo pipefail` before sourcing it.

here=$(cd "$(dirname "${BASH_SOURCE[0]}")" && pwd)
root=$(cd "$here/../.." && pwd)
tmp=$(mktemp -d)
trap 'rm -rf "$tmp"' EXIT

die() { echo "${0##*/}: $*" >&2; exit "${code:-2}"; }

# LAMMPS and LIGGGHTS are optional benchmark peers: not part of the build, `make test` or CI.
# When one is missing, install it through the project's install script (idempotent; Debian
# bookworm packages lammps, liggghts, openmpi-bin; needs root or sudo).
find_peers() {
  local need=0
  if [[ -z "${LMP:-}" ]]; then
    for c in lmp lmp_serial lmp_mpi lmp_stable; do
      if command -v "$c" >/dev/null 2>&1; then LMP=$c; break; fi
    done
  fi
  LIGGGHTS=${LIGGGHTS:-liggghts}
  [[ -n "${LMP:-}" ]] && command -v "$LMP" >/dev/null 2>&1 || need=1
  command -v "$LIGGGHTS" >/dev/null 2>&1 || need=1
  if [[ $need -eq 1 ]]; then
    echo "note: LAMMPS or LIGGGHTS missing: scripts/install-deps.sh --bench-peers" >&2
    bash "$root/scripts/install-deps.sh" --bench-peers >&2 ||
      die "could not install the peers; on Debian 12: apt-get install -y lammps liggghts openmpi-bin"
    LMP=${LMP:-lmp}
  fi
  LMP=$(command -v "$LMP") || die "LAMMPS not found (set LMP=...)"
  LIGGGHTS=$(command -v "$LIGGGHTS") || die "LIGGGHTS not found (set LIGGGHTS=...)"
  local help
  help=$("$LMP" -h 2>/dev/null || true)
  for s in gran/hertz/history granular wall/gran wall/gran/region nve/sphere; do
    grep -qw -- "$s" <<<"$help" || die "$LMP lacks the style '$s' (needs the GRANULAR package)"
  done
  lmp_version=$(grep -m1 -o 'Simulator - .*' <<<"$help" | sed 's/^Simulator - //' || true)
  # From $tmp: LIGGGHTS writes log.liggghts into its working folder even for -h.
  liggghts_version=$(cd "$tmp" && "$LIGGGHTS" -h 2>/dev/null | grep -m1 -o 'Version [^,]*' || true)
}

# kolsky's side: build/benchmarks/dem_agreement (KOLSKY_BUILD, default <repo>/build).
find_kolsky() {
  KOLSKY=${KOLSKY:-"${KOLSKY_BUILD:-$root/build}/benchmarks/dem_agreement"}
  [[ -x "$KOLSKY" ]] || die "no $KOLSKY: build it first
  (cmake --build build --target dem_agreement; or set KOLSKY_BUILD / KOLSKY)"
}

# prepare_data PACK [CUT]: $tmp/pack.data (as given: 1 atom type) and $tmp/pack2.data (the
# header says 2 atom types, type 2 being LIGGGHTS' wall material). With CUT (m), only the
# grains with z + d/2 <= CUT, the count line adjusted (the small scene of the in-test check).
prepare_data() {
  local pack=$1 cut=${2:-}
  [[ -r "$pack" ]] || die "packing not found: $pack
  (the shared benchmark packing pack_35k.data.gz; set PACK=... to point at it)"
  case "$pack" in
    *.gz) gzip -dc "$pack" >"$tmp/pack.data" ;;
    *) cp "$pack" "$tmp/pack.data" ;;
  esac
  grep -qE '^[[:space:]]*[0-9]+[[:space:]]+atoms' "$tmp/pack.data" && grep -qE '^Atoms' "$tmp/pack.data" ||
    die "$pack has no LAMMPS header (count, types, box, Atoms)"
  if [[ -n "$cut" ]]; then
    awk -v cut="$cut" '
      /^Atoms/ { atoms = 1; next }
      atoms && NF == 7 && $1 ~ /^[0-9]+$/ { if ($7 + $3 / 2 <= cut) rows[++n] = $0; next }
      !atoms { head[++h] = $0 }
      END { for (i = 1; i <= h; i++) {
              if (head[i] ~ /^[[:space:]]*[0-9]+[[:space:]]+atoms/) print n " atoms"; else print head[i] }
            print "Atoms # sphere\n"
            for (i = 1; i <= n; i++) print rows[i] }' "$tmp/pack.data" >"$tmp/cut.data"
    mv "$tmp/cut.data" "$tmp/pack.data"
  fi
  sed 's/^\([[:space:]]*\)1 atom types/\12 atom types/' "$tmp/pack.data" >"$tmp/pack2.data"
  natoms=$(grep -m1 -E '^[[:space:]]*[0-9]+[[:space:]]+atoms' "$tmp/pack.data" | awk '{print $1}')
  pack_sha=$(sha256sum "$pack" | awk '{print $1}')
}

# peer_forces CODE LOG: the deck's diag rows as `step lid bottom tube coordination` (N,
# magnitudes), the first row of each step (a run's setup repeats the step before it, and its
# contact/atom and mesh-stress values are not those of a completed step).
peer_forces() {
  local code=$1 log=$2
  awk -v code="$code" '
    /^ *Step/ { on = 1; next }
    /^Loop time/ { on = 0; next }
    on && $1 ~ /^[0-9]+$/ && !seen[$1]++ {
      if (code == "liggghts") { lid = $4; bot = $5; tube = $6; z = $7 }
      else { lid = $7; bot = $8; tube = $9; z = $11 }
      printf "%s\t%s\t%.6g\t%.6g\t%.6g\t%.6g\n", code, $1, (lid < 0 ? -lid : lid),
             (bot < 0 ? -bot : bot), (tube < 0 ? -tube : tube), z }' "$log"
}

# loop_time LOG: "loop_s steps atoms" of the last run in a LAMMPS or LIGGGHTS log.
loop_time() {
  grep '^Loop time of' "$1" | tail -n 1 | awk '{ sub(/,$/, "", $12); print $4, $9, $12 }'
}

# run_peer CODE RANKS LOG ARGS...: one run of a deck (CODE hertz_history, granular or
# liggghts) on RANKS MPI ranks, from $tmp.
run_peer() {
  local code=$1 ranks=$2 log=$3; shift 3
  local launch bin input data screen=(-screen none)
  if [[ "$code" == liggghts ]]; then
    bin=$LIGGGHTS; input="$here/in.compaction_liggghts"; data="$tmp/pack2.data"
    screen=(-screen "$log.screen")  # -screen none crashes its STL reader
    set -- -var stl "$here/lid.stl" "$@"
  else
    bin=$LMP; input="$here/in.compaction_$code"; data="$tmp/pack.data"
    set -- -nocite "$@"
  fi
  launch=("$bin")
  [[ "$ranks" -gt 1 ]] && launch=("${MPIRUN:-mpirun}" -np "$ranks" "$bin")
  if ! (cd "$tmp" && OMP_NUM_THREADS=1 "${launch[@]}" -echo none "${screen[@]}" -log "$log" \
          -in "$input" -var data "$data" "$@" >"$log.out" 2>&1); then
    cat "$log.out" >&2
    tail -n 20 "$log" >&2 2>/dev/null || true
    code=1 die "$code failed on $ranks rank(s) (log $log)"
  fi
}

# Open MPI refuses to run as root without these.
if [[ $(id -u) -eq 0 ]]; then export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1; fi
