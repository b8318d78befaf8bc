#!/usr/bin/env bash
# kolsky sweep over MPI ranks (issue 33): the same small sweep alone (threads) and under
# `mpirun -n 2 --oversubscribe` must give the same table, every column but the run times
# (run_s) equal as text, i.e. every number bit for bit. Usage: test_sweep_mpi.sh KOLSKY MPIEXEC NP_FLAG
set -uo pipefail
kolsky=$1; mpiexec=$2; np=$3
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT; cd "$work"
fail() { echo "FAIL [sweep_mpi_2]: $*"; exit 1; }
cat > s.json <<JSON
{"bars": {"incident": {"length": 2.0, "gauges": [1.0]}, "transmission": {"length": 1.0, "gauges": [0.5]}},
 "pulse": {"kind": "trapezoid", "amplitude": 50e6, "rise_time": 20e-6, "duration": 100e-6, "fall_time": 20e-6},
 "specimen": {"model": "elastic", "constrained_modulus": 230e6, "n_elements": 10},
 "time": {"end": 0.6e-3}}
JSON
set_args=(--set specimen.constrained_modulus=log:1e8:1e9:4 --set 'specimen.n_elements=[10,20,40]' --quiet)
"$kolsky" sweep s.json "${set_args[@]}" -o serial.csv --threads 2 || fail "serial sweep exit $?"
"$mpiexec" "$np" 2 --oversubscribe "$kolsky" sweep s.json "${set_args[@]}" -o ranks.csv || fail "mpirun sweep exit $?"
# The table without its run_s column (found by name in the header).
strip() { awk -F, 'NR == 1 { for (i = 1; i <= NF; i++) if ($i == "run_s") skip = i }
                   { out = ""; for (i = 1; i <= NF; i++) if (i != skip) out = out (out == "" ? "" : ",") $i; print out }' "$1"; }
[ "$(wc -l < ranks.csv)" -eq 13 ] || fail "want 12 rows: $(cat ranks.csv)"
diff <(strip serial.csv) <(strip ranks.csv) || fail "the tables differ"
echo "PASS [sweep_mpi_2]"
