#!/usr/bin/env bash
# End-to-end checks of the kolsky program: exit codes (0 ok, 1 usage, 2 bad input, 3 numerical
# failure), one-line errors naming file, JSON path and rule, outputs written atomically, and an
# incomplete run kept and marked. Usage: test_cli.sh KOLSKY_BINARY REPO_ROOT CASE
set -uo pipefail
kolsky=$1; repo=$2; case_name=$3
work=$(mktemp -d); trap 'rm -rf "$work"' EXIT; cd "$work"
fail() { echo "FAIL [$case_name]: $*"; exit 1; }
expect_exit() { local want=$1; shift; "$@" >out.txt 2>err.txt; local got=$?
  [ "$got" -eq "$want" ] || fail "exit $got (want $want) for: $* -- $(cat err.txt)"; }
no_temp_files() { ls -a | grep -q '\.tmp\.' && fail "temporary file left: $(ls -a | grep '\.tmp\.')"; return 0; }
# A small valid scene with an inline trapezoid pulse.
scene() { cat > "$1" <<JSON
{"bars": {"incident": {"length": 2.0, "gauges": [1.0]}, "transmission": {"length": 1.0, "gauges": [0.5]}},
 "pulse": {"kind": "trapezoid", "amplitude": 50e6, "rise_time": 20e-6, "duration": 100e-6, "fall_time": 20e-6},
 "specimen": {"model": "elastic", "constrained_modulus": 230e6, "n_elements": 10},
 "time": {"end": 0.6e-3 $2}}
JSON
}

case "$case_name" in
help)
  expect_exit 0 "$kolsky" --help; grep -q "kolsky run SCENE.json" out.txt || fail "usage text"
  expect_exit 1 "$kolsky"; expect_exit 1 "$kolsky" frobnicate
  expect_exit 0 "$kolsky" defaults
  for k in bars.incident.length pulse.kind specimen.constrained_modulus time.dt processing.threshold_fraction; do
    grep -q "$k" out.txt || fail "defaults lacks $k"; done ;;
run_ok)
  scene s.json ""
  expect_exit 0 "$kolsky" run s.json -o out.h5 --quiet --gauges-csv g.csv
  [ -s out.h5 ] && [ -s g.csv ] || fail "outputs missing"; no_temp_files
  h5dump -a /meta/complete out.h5 | grep -q "(0): 1" || fail "complete flag not 1"
  h5dump -d /probes/stress_back/value -H out.h5 >/dev/null || fail "probe missing"
  expect_exit 0 "$kolsky" run s.json --threads 2 --quiet; [ -s s.h5 ] || fail "default output name s.h5" ;;
bad_input)
  scene s.json ', "lenght": 1'
  expect_exit 2 "$kolsky" run s.json -o o.h5
  grep -q "s.json: time.lenght: unknown key 'lenght'" err.txt || fail "unknown-key message: $(cat err.txt)"
  [ "$(wc -l < err.txt)" -eq 1 ] || fail "error is not one line"
  [ ! -e o.h5 ] || fail "output written for bad input"; no_temp_files
  scene s2.json ', "dt": 1e-5'
  expect_exit 2 "$kolsky" run s2.json -o o.h5
  grep -q "s2.json: time.dt: .*above the stability limit" err.txt || fail "dt message: $(cat err.txt)"
  [ ! -e o.h5 ] || fail "output written for an unstable dt"
  echo '{"bars": ' > broken.json
  expect_exit 2 "$kolsky" run broken.json; grep -q "broken.json.*line" err.txt || fail "syntax error position"
  expect_exit 2 "$kolsky" run missing.json
  expect_exit 1 "$kolsky" run s.json --threads zero ;;
blow_up)
  # 1.05 x the column's Courant limit with the check off: the explicit scheme must blow up, be
  # caught (exit 3) and keep what it computed, marked incomplete.
  scene probe.json ""
  limit=$("$kolsky" run probe.json -o p.h5 2>&1 >/dev/null | sed -n 's/.*stable limit \([0-9.e+-]*\) s.*/\1/p')
  [ -n "$limit" ] || fail "could not read the stable limit"
  dt=$(awk -v l="$limit" 'BEGIN { printf "%.6e", 1.05 * l }')
  scene u.json ", \"dt\": $dt, \"check_stability\": false"
  expect_exit 3 "$kolsky" run u.json -o u.h5 --quiet
  grep -q "numerical failure" err.txt || fail "no failure message"
  [ -s u.h5 ] || fail "incomplete output not kept"; no_temp_files
  h5dump -a /meta/complete u.h5 | grep -q "(0): 0" || fail "incomplete run not marked" ;;
analyze)
  ex=$repo/data/examples
  expect_exit 0 "$kolsky" analyze "$ex/gauges_song2009_example.csv" --bars "$ex/bars_song2009.json" -o a.csv
  head -3 a.csv | grep -q "^t_s,eps_incident" || fail "analysis CSV header"
  no_temp_files
  expect_exit 1 "$kolsky" analyze "$ex/gauges_song2009_example.csv"
  printf 't,a,b\n0,1,2\n1,2\n' > ragged.csv
  expect_exit 2 "$kolsky" analyze ragged.csv --bars "$ex/bars_song2009.json"
  grep -q "ragged.csv: line 3" err.txt || fail "ragged CSV message: $(cat err.txt)" ;;
eos)
  expect_exit 0 "$kolsky" eos --water 3 -o e.csv
  grep -q "^eps_v,p_pa,p_bc_pa,p_d_pa,p_e_pa" e.csv || fail "eos CSV header"
  grep -q "abs_tol" e.csv || fail "ODE tolerances not recorded"
  expect_exit 2 "$kolsky" eos --water 30; grep -q "\-\-water" err.txt || fail "water range message"
  no_temp_files ;;
*) fail "unknown case" ;;
esac
echo "PASS [$case_name]"
