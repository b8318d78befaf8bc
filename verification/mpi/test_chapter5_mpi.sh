#!/usr/bin/env bash
# The chapter5 smoke set over MPI ranks (issue 33): run under `mpirun -n 2 --oversubscribe`, its
# values must be bit for bit those of the smoke run on threads (CTest reproduce_chapter5_smoke,
# whose folder this reads): measurements.json compared byte for byte (every scalar, trend and
# curve the gate checks, written with round-trip digits; same build, so the same commit), and
# every plot's data but speed_vs_error's (which plots run times). Also checks that both ranks
# ran members. Usage: test_chapter5_mpi.sh DRIVER MPIEXEC NP_FLAG SERIAL_DIR OUT_DIR
set -uo pipefail
driver=$1; mpiexec=$2; np=$3; serial=$4; out=$5
fail() { echo "FAIL [reproduce_chapter5_mpi_2]: $*"; exit 1; }
[ -f "$serial/measurements.json" ] || fail "no serial smoke results in $serial (run reproduce_chapter5_smoke first)"
rm -rf "$out"; mkdir -p "$(dirname "$out")"
"$mpiexec" "$np" 2 --oversubscribe "$driver" --scale smoke --out "$out" > "$out.log" 2>&1 ||
  { tail -20 "$out.log"; fail "mpirun exit $? (log $out.log)"; }
cmp "$serial/measurements.json" "$out/measurements.json" || fail "measurements differ from $serial"
for f in "$serial"/plots_src/*.dat; do
  case "$(basename "$f")" in speed_vs_error.dat) continue ;; esac
  cmp "$f" "$out/plots_src/$(basename "$f")" || fail "plot data $(basename "$f") differs"
done
grep -q '"rank": 1' "$out/members.json" || fail "rank 1 ran no member ($out/members.json)"
grep -q '"rank": 0' "$out/members.json" || fail "rank 0 ran no member ($out/members.json)"
echo "PASS [reproduce_chapter5_mpi_2]: $(grep -c '"label"' "$out/members.json") members on 2 ranks, values as on threads"
