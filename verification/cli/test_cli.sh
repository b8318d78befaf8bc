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

# A small DEM scene (~250 grains of the reconstructed Song curve x5) between short bars.
dem_scene() { cat > "$1" <<JSON
{"bars": {"incident": {"length": 0.6, "gauges": [0.3]}, "transmission": {"length": 0.4, "gauges": [0.2]}},
 "pulse": {"kind": "trapezoid", "amplitude": 20e6, "rise_time": 40e-6, "duration": 200e-6, "fall_time": 40e-6},
 "specimen": {"model": "dem", "grain_size_curve": "$repo/data/digitized/chapter4/song2009_psd_reconstructed.csv",
              "upscale": 5, "seed": 7, "length": 0.006, "diameter": 0.008},
 "time": {"end": 200e-6}, "output": {"interval": 2e-6 $2}}
JSON
}

case "$case_name" in
help)
  expect_exit 0 "$kolsky" --help; grep -q "kolsky run SCENE.json" out.txt || fail "usage text"
  expect_exit 0 "$kolsky" run --help; grep -q "kolsky run SCENE.json" out.txt || fail "run --help"
  expect_exit 0 "$kolsky" analyze -h; grep -q "kolsky analyze" out.txt || fail "analyze -h"
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
  scene s3.json ""; sed -i 's/"end": 0.6e-3/"end": 0.2e-3/' s3.json  # the wave arrives at 0.4 ms
  expect_exit 2 "$kolsky" run s3.json -o o.h5
  grep -q "s3.json: time.end: must be more than .* reaches the specimen" err.txt || fail "end message: $(cat err.txt)"
  [ ! -e o.h5 ] || fail "output written for a run ending before the wave arrives"
  expect_exit 1 "$kolsky" run s.json --threads zero
  # Bad input the parser or the planner meets, named by file and key (issue 17).
  scene big.json ', "dt": 1e400'
  expect_exit 2 "$kolsky" run big.json; grep -q "big.json: time.dt: the number '1e400' is outside the range of a double" err.txt || fail "1e400 message: $(cat err.txt)"
  scene dup.json ', "end": 1e-3'
  expect_exit 2 "$kolsky" run dup.json; grep -q "dup.json: time.end: duplicate key 'end'" err.txt || fail "duplicate message: $(cat err.txt)"
  scene tiny.json ', "dt": 1e-300'
  expect_exit 2 "$kolsky" run tiny.json; grep -q "tiny.json: time.dt: .* steps, more than the 1e+10" err.txt || fail "step-count message: $(cat err.txt)"
  scene long.json ""; sed -i 's/"end": 0.6e-3/"end": 1e300/' long.json
  expect_exit 2 "$kolsky" run long.json; grep -q "long.json: time.end: .* steps, more than the 1e+10" err.txt || fail "step-count message: $(cat err.txt)"
  scene nul.json ', "e\u0000nd": 1'
  expect_exit 2 "$kolsky" run nul.json; grep -q "nul.json: time.e.u0000nd: unknown key .*did you mean 'end'" err.txt || fail "NUL key message: $(cat err.txt)"
  mkdir folder.json; expect_exit 2 "$kolsky" run folder.json; grep -q "folder.json: is a directory" err.txt || fail "folder message: $(cat err.txt)"
  # A DEM specimen too small for a grain, or too porous to pack: exit 2 before any packing.
  dem_scene d.json ""; sed -i 's/"diameter": 0.008/"diameter": 0.0005/' d.json
  expect_exit 2 "$kolsky" run d.json; grep -q "d.json: specimen.diameter: the specimen holds no grain" err.txt || fail "tiny tube message: $(cat err.txt)"
  dem_scene p.json ""; sed -i 's/"seed": 7/"seed": 7, "porosity": 0.8/' p.json
  expect_exit 2 "$kolsky" run p.json; grep -q "p.json: specimen.porosity: must be in (0, 0.75), got 0.8" err.txt || fail "porosity message: $(cat err.txt)"
  dem_scene e.json ""; sed -i 's/"end": 200e-6/"end": 100e-6/' e.json
  expect_exit 2 "$kolsky" run e.json; grep -q "e.json: time.end: must be more than" err.txt || fail "DEM end message: $(cat err.txt)"
  grep -q "packing" err.txt && fail "packed before the end time was checked: $(cat err.txt)"
  no_temp_files ;;
blow_up)
  # 1.05 x the column's Courant limit with the checks off (time.check_stability = false lifts
  # the dt limit and the energy check): the explicit scheme must blow up, overflow, be caught
  # as non-finite (exit 3) and keep what it computed, marked incomplete. The energy check
  # itself is shown firing at 1.05 x in test_shpb_energy_check.cpp.
  scene probe.json ""
  limit=$("$kolsky" run probe.json -o p.h5 2>&1 >/dev/null | sed -n 's/.*stable limit \([0-9.e+-]*\) s.*/\1/p')
  [ -n "$limit" ] || fail "could not read the stable limit"
  dt=$(awk -v l="$limit" 'BEGIN { printf "%.6e", 1.05 * l }')
  scene u.json ", \"dt\": $dt, \"check_stability\": false"
  sed -i 's/"end": 0.6e-3/"end": 3e-3/' u.json  # long enough to overflow (1e28 J at 0.6 ms)
  expect_exit 3 "$kolsky" run u.json -o u.h5 --quiet
  grep -q "numerical failure: .*non-finite" err.txt || fail "no failure message: $(cat err.txt)"
  [ -s u.h5 ] || fail "incomplete output not kept"; no_temp_files
  h5dump -a /meta/complete u.h5 | grep -q "(0): 0" || fail "incomplete run not marked"
  # A failure before the incident wave reaches the specimen (nothing to analyse yet) is still a
  # numerical failure: exit 3, the check that fired named, the probes so far kept, complete = 0.
  scene big.json ""; sed -i 's/"amplitude": 50e6/"amplitude": 1e308/' big.json
  expect_exit 3 "$kolsky" run big.json -o big.h5 --quiet --gauges-csv big.csv
  grep -q "numerical failure: .*non-finite" err.txt || fail "early failure message: $(cat err.txt)"
  grep -q "internal error" err.txt && fail "early failure reported as internal: $(cat err.txt)"
  [ -s big.h5 ] && [ -e big.csv ] || fail "early failure output not kept: $(ls)"; no_temp_files
  h5dump -a /meta/complete big.h5 | grep -q "(0): 0" || fail "early failure not marked incomplete"
  h5dump -H -d /probes/applied_stress/value big.h5 >/dev/null || fail "probes of an early failure missing"
  # The same load on sphere chains overflows in the incident chain at the first sample (t = 1 us,
  # the wave arrives at 0.4 ms).
  sed 's/"bars": {/"bars": {"kind": "sphere_chain", /' big.json > chain.json
  expect_exit 3 "$kolsky" run chain.json -o chain.h5 --quiet
  grep -q "numerical failure: .*non-finite" err.txt || fail "chain blow-up message: $(cat err.txt)"
  h5dump -a /meta/complete chain.h5 | grep -q "(0): 0" || fail "chain blow-up not marked incomplete" ;;
analyze)
  ex=$repo/data/examples
  expect_exit 0 "$kolsky" analyze "$ex/gauges_song2009_example.csv" --bars "$ex/bars_song2009.json" -o a.csv
  head -3 a.csv | grep -q "^t_s,eps_incident" || fail "analysis CSV header"
  no_temp_files
  expect_exit 1 "$kolsky" analyze "$ex/gauges_song2009_example.csv"
  printf 't,a,b\n0,1,2\n1,2\n' > ragged.csv
  expect_exit 2 "$kolsky" analyze ragged.csv --bars "$ex/bars_song2009.json"
  grep -q "ragged.csv: line 3" err.txt || fail "ragged CSV message: $(cat err.txt)"
  # Every CSV error gives the file line: a NaN sample (line 31 of the record), a decimal comma.
  awk 'NR == 31 { sub(/,[^,]*$/, ",nan") } { print }' "$ex/gauges_song2009_example.csv" > nan.csv
  expect_exit 2 "$kolsky" analyze nan.csv --bars "$ex/bars_song2009.json" -o n.csv
  grep -q "nan.csv: line 31: non-finite value" err.txt || fail "NaN row message: $(cat err.txt)"
  printf '0,0;0,0\n0,5;1,2\n' > comma.csv
  expect_exit 2 "$kolsky" analyze comma.csv --bars "$ex/bars_song2009.json"
  grep -q "comma.csv: line 1: .*decimal-comma" err.txt || fail "decimal-comma message: $(cat err.txt)"
  # A record kolsky run marked incomplete (stopped early) is refused unless told.
  { echo "# INCOMPLETE run (stopped on request): the record ends early"; cat "$ex/gauges_song2009_example.csv"; } > cut.csv
  expect_exit 2 "$kolsky" analyze cut.csv --bars "$ex/bars_song2009.json" -o c.csv
  grep -q "cut.csv: line 1: .*--allow-incomplete" err.txt || fail "incomplete record message: $(cat err.txt)"
  [ ! -e c.csv ] || fail "an output was written for a refused record"
  expect_exit 0 "$kolsky" analyze cut.csv --bars "$ex/bars_song2009.json" -o c.csv --allow-incomplete ;;
eos)
  expect_exit 0 "$kolsky" eos --water 3 -o e.csv
  grep -q "^eps_v,p_pa,p_bc_pa,p_d_pa,p_e_pa" e.csv || fail "eos CSV header"
  grep -q "abs_tol" e.csv || fail "ODE tolerances not recorded"
  expect_exit 2 "$kolsky" eos --water 30; grep -q "\-\-water" err.txt || fail "water range message"
  no_temp_files ;;
snapshots)
  dem_scene d.json ', "snapshot_interval": 50e-6'
  expect_exit 0 "$kolsky" run d.json -o run.h5 --quiet
  [ -s run.h5 ] && [ -s run.particles.h5 ] && [ -s run.xmf ] || fail "outputs missing: $(ls)"; no_temp_files
  h5dump -a /meta/complete run.particles.h5 | grep -q "(0): 1" || fail "snapshots not marked complete"
  h5dump -H -d /snapshots/0/position run.particles.h5 | grep -q "SIMPLE { ( [0-9]*, 3 )" || fail "position not n x 3"
  h5dump -a /snapshots/1/time run.particles.h5 | grep -q "(0): 4.99" || fail "second snapshot not at 50 us"
  for k in 0 1 2 3; do grep -q "run.particles.h5:/snapshots/$k/force" run.xmf || fail "xmf lacks snapshot $k"; done
  grep -q 'AttributeType="Vector"' run.xmf && grep -q 'TopologyType="Polyvertex"' run.xmf || fail "xmf content"
  for p in grain_kinetic_energy coordination_number coordination_with_walls grain_contacts wall_contacts stress_front stress_back specimen_strain analysis_alpha; do
    h5dump -H -d /probes/$p/value run.h5 >/dev/null || fail "DEM probe $p missing"; done
  scene e.json '}, "output": {"snapshot_interval": 1e-6'
  expect_exit 2 "$kolsky" run e.json -o e.h5
  grep -q "e.json: output.snapshot_interval: .*only when specimen.model = dem" err.txt || fail "variant message: $(cat err.txt)" ;;
restart)
  # Elastic column and DEM specimen: full run vs checkpoint + restart, probes bitwise (h5diff
  # without a tolerance compares exactly).
  scene s.json ""
  expect_exit 0 "$kolsky" run s.json -o full.h5 --quiet
  expect_exit 0 "$kolsky" run s.json -o part.h5 --quiet --checkpoint-every 0.25e-3 --checkpoint-file ck.h5
  [ -s ck.h5 ] || fail "no checkpoint written"; no_temp_files
  expect_exit 0 "$kolsky" run s.json -o again.h5 --quiet --restart ck.h5
  h5diff full.h5 again.h5 /probes /probes >diff.txt || fail "restarted elastic run differs: $(head -5 diff.txt)"
  dem_scene d.json ""
  expect_exit 0 "$kolsky" run d.json -o dfull.h5 --quiet
  expect_exit 0 "$kolsky" run d.json -o dpart.h5 --quiet --checkpoint-every 70e-6
  [ -s dpart.ckpt.h5 ] || fail "default checkpoint name dpart.ckpt.h5"
  expect_exit 0 "$kolsky" run d.json -o dagain.h5 --quiet --restart dpart.ckpt.h5
  h5diff dfull.h5 dagain.h5 /probes /probes >diff.txt || fail "restarted DEM run differs: $(head -5 diff.txt)"
  h5dump -a /meta/complete dagain.h5 | grep -q "(0): 1" || fail "restarted run not complete"
  # Another scene, a non-checkpoint file, an option without its partner.
  scene other.json ', "dt": 1e-8'
  expect_exit 2 "$kolsky" run other.json -o o.h5 --restart ck.h5
  grep -q "ck.h5: scene: .*time.dt differs" err.txt || fail "scene mismatch message: $(cat err.txt)"
  [ ! -e o.h5 ] || fail "output written for a mismatched restart"
  expect_exit 2 "$kolsky" run s.json -o o.h5 --restart full.h5
  grep -q "full.h5: .*not a kolsky checkpoint" err.txt || fail "non-checkpoint message: $(cat err.txt)"
  expect_exit 1 "$kolsky" run s.json --checkpoint-file x.h5
  expect_exit 1 "$kolsky" run s.json --checkpoint-every -1
  no_temp_files ;;
strain_rate)
  # Strain-rate-controlled walls (Sec. 5.2.1, methodology 1): the shipped example runs, is
  # analysed directly (no waves: no wave probes, no wave analysis), restarts bitwise, and its
  # bad inputs exit 2 naming the file and the path.
  ex=$repo/data/examples/wang2018_strain_rate_example.json
  expect_exit 0 "$kolsky" run "$ex" -o w.h5 --quiet
  grep -q "sigma_back_at_peak_eps_mpa" out.txt || fail "summary lacks the stress-strain end point: $(cat out.txt)"
  grep -q "w_incident" out.txt && fail "wave energies in a strain-rate summary"
  h5dump -a /meta/complete w.h5 | grep -q "(0): 1" || fail "complete flag not 1"
  for p in specimen_strain strain_rate stress_front stress_back stress_avg alpha face_displacement_front \
           grain_contacts analysis_strain analysis_stress_back analysis_stress_avg analysis_alpha; do
    h5dump -H -d /probes/$p/value w.h5 >/dev/null || fail "probe $p missing"; done
  h5dump -H -d /probes/wave_incident/value w.h5 >/dev/null 2>&1 && fail "a wave probe in a strain-rate run"
  expect_exit 0 "$kolsky" run "$ex" -o part.h5 --quiet --checkpoint-every 30e-6
  [ -s part.ckpt.h5 ] || fail "no checkpoint written"
  expect_exit 0 "$kolsky" run "$ex" -o again.h5 --quiet --restart part.ckpt.h5
  h5diff w.h5 again.h5 /probes /probes >diff.txt || fail "restarted strain-rate run differs: $(head -5 diff.txt)"
  expect_exit 2 "$kolsky" run "$ex" -o g.h5 --gauges-csv g.csv
  grep -q "wang2018_strain_rate_example.json: loading.kind: --gauges-csv" err.txt || fail "gauges message: $(cat err.txt)"
  walls() { cat > "$1" <<JSON
{"loading": {"kind": "strain_rate", "file": "$2"} $3,
 "specimen": {"model": "dem", "grain_size_curve": "$repo/data/digitized/chapter4/song2009_psd_reconstructed.csv",
              "upscale": 5, "seed": 7, "length": 0.006, "diameter": 0.008},
 "time": {"end": 20e-6}}
JSON
  }
  printf 'time_s,strain_rate\n0,0\n2e-5,1\n1e-5,1\n' > bad.csv
  walls b.json bad.csv ""
  expect_exit 2 "$kolsky" run b.json -o b.h5
  grep -q "bad.csv: line 4: time_s must be strictly increasing" err.txt || fail "CSV message: $(cat err.txt)"
  printf 'time_s,strain_rate\n0,0\n1e-5,1200\n' > rate.csv
  walls p.json rate.csv ', "pulse": {"kind": "trapezoid", "amplitude": 1e8, "duration": 1e-4}'
  expect_exit 2 "$kolsky" run p.json -o b.h5
  grep -q "p.json: pulse: 'pulse' is unused with loading.kind = strain_rate" err.txt || fail "unused message: $(cat err.txt)"
  [ "$(wc -l < err.txt)" -eq 1 ] || fail "error is not one line"
  [ ! -e b.h5 ] || fail "output written for bad input"; no_temp_files ;;
dem_checks)
  # What a DEM scene is told before its run: the packing's initial wall stress, and a warning
  # when it exceeds 5 % of the pulse (here 4 mm grains in an 8.2 mm tube: ~19 MPa of 20 MPa).
  dem_scene d.json ""
  expect_exit 0 "$kolsky" run d.json -o d.h5
  grep -q "d.json: DEM packing: initial wall stress [0-9.e-]* MPa (front)" err.txt || fail "no initial stress: $(cat err.txt)"
  grep -q "warning" err.txt && fail "warning for a 0.05 MPa packing: $(cat err.txt)"
  h5dump -a /meta/meta_json d.h5 | grep -q "initial_wall_stress_pa" || fail "initial stress not in /meta"
  printf 'diameter_m,percent_passing\n0.0038,0\n0.004,100\n' > coarse.csv
  sed -e 's|"grain_size_curve": "[^"]*"|"grain_size_curve": "coarse.csv"|' -e 's/"upscale": 5, "seed": 7, "length": 0.006, "diameter": 0.008/"porosity": 0.5, "length": 0.0093, "diameter": 0.0082/' d.json > c.json
  "$kolsky" run c.json -o c.h5 --quiet >out.txt 2>err.txt
  grep -q "warning: c.json: the packing starts with [0-9.]* MPa on an end wall, [0-9]* % of the pulse's 20 MPa" err.txt || fail "no warning: $(cat err.txt)"
  grep -q "DEM packing: initial wall stress" err.txt && fail "--quiet printed the report: $(cat err.txt)"
  no_temp_files ;;
outputs)
  # Every output path is checked before any work (exit 2 naming the option), no output may be
  # an input or another output, and analyze refuses non-finite results (exit 3).
  scene s.json ""
  for args in "-o nodir/o.h5" "-o ." "-o o.h5 --gauges-csv nodir/g.csv" "-o s.json" "-o o.h5 --gauges-csv o.h5"; do
    expect_exit 2 "$kolsky" run s.json $args --quiet
    [ "$(wc -l < err.txt)" -eq 1 ] || fail "error is not one line: $(cat err.txt)"
  done
  grep -q "gauges-csv: 'o.h5' is also the output of -o" err.txt || fail "same-output message: $(cat err.txt)"
  expect_exit 2 "$kolsky" run s.json -o s.json; grep -q "^kolsky: error: -o: 's.json' is an input" err.txt || fail "input message: $(cat err.txt)"
  grep -q '"bars"' s.json || fail "the scene was overwritten"
  expect_exit 2 "$kolsky" run s.json -o o.h5 --gauges-csv nodir/g.csv; grep -q "^kolsky: error: --gauges-csv: cannot write 'nodir/g.csv'" err.txt || fail "gauges path message: $(cat err.txt)"
  [ ! -e o.h5 ] || fail "run file written although the gauge path is bad"; no_temp_files
  ex=$repo/data/examples
  expect_exit 2 "$kolsky" analyze "$ex/gauges_song2009_example.csv" --bars "$ex/bars_song2009.json" -o nodir/a.csv
  grep -q "^kolsky: error: -o: cannot write 'nodir/a.csv'" err.txt || fail "analyze -o message: $(cat err.txt)"
  awk -F, '/^[0-9]/ { printf "%s,%.10g,%.10g\n", $1, $2 * 1e150, $3 * 1e150; next } { print }' "$ex/gauges_song2009_example.csv" > huge.csv
  expect_exit 3 "$kolsky" analyze huge.csv --bars "$ex/bars_song2009.json" -o h.csv
  grep -q "numerical failure: analyze: w_incident_j is not finite" err.txt || fail "non-finite analysis message: $(cat err.txt)"
  [ ! -e h.csv ] || fail "non-finite analysis written"
  # Gauges: at most 1000 per bar; a run whose probes would pass 1 GB says so before it starts
  # (stopped here at once by SIGTERM: exit 143, what it had kept and marked incomplete).
  gauges=$(awk 'BEGIN { for (i = 1; i <= 1001; ++i) printf "%s%.6f", (i > 1 ? "," : ""), i * 0.0019 }')
  sed "s/\"gauges\": \[1.0\]/\"gauges\": [$gauges]/" s.json > many.json
  expect_exit 2 "$kolsky" run many.json; grep -q "many.json: bars.incident.gauges: at most 1000 gauges per bar" err.txt || fail "gauge limit message: $(cat err.txt)"
  scene big.json ""; sed -i 's/"end": 0.6e-3/"end": 5/' big.json
  : >err.txt  # as below: no stale line for the wait to find
  "$kolsky" run big.json -o big.h5 >out.txt 2>err.txt & pid=$!
  for i in $(seq 100); do grep -q "warning: the probes will take about" err.txt && break; sleep 0.1; done
  kill -TERM $pid; wait $pid; rc=$?
  grep -q "warning: the probes will take about [0-9.]* GB" err.txt || fail "no size warning: $(cat err.txt)"
  [ "$rc" -eq 143 ] || fail "exit $rc after SIGTERM (want 143): $(cat err.txt)"
  h5dump -a /meta/complete big.h5 | grep -q "(0): 0" || fail "stopped run not marked incomplete"; no_temp_files
  # A sibling output that fails after the run (its folder removed meanwhile): the run file is
  # kept but not marked complete, names the failure, and the command exits 1.
  dem_scene d.json ""; sed -i 's/"end": 200e-6/"end": 3e-3/' d.json; mkdir sub
  # Emptied first: the background job's own redirection may come after the first grep below,
  # which would then read the previous run's "steps of" and remove the folder too early.
  : >err.txt
  "$kolsky" run d.json -o d.h5 --gauges-csv sub/g.csv >out.txt 2>err.txt & pid=$!
  # Until the run has started (its packing takes seconds on a quiet machine, minutes on a loaded
  # one), however long that is: removing the folder before the start tests the pre-check instead.
  while kill -0 $pid 2>/dev/null && ! grep -q "steps of" err.txt; do sleep 0.1; done
  rmdir sub; wait $pid; rc=$?
  [ "$rc" -eq 1 ] || fail "exit $rc with a failed sibling output (want 1): $(cat err.txt)"
  grep -q "error: --gauges-csv: .*d.h5 kept, marked incomplete" err.txt || fail "sibling message: $(cat err.txt)"
  h5dump -a /meta/complete d.h5 | grep -q "(0): 0" || fail "run file marked complete beside a failed output"
  h5dump -a /meta/meta_json d.h5 | grep -q "output_failure" || fail "output failure not in /meta"; no_temp_files ;;
signals)
  # SIGINT during a DEM run with snapshots and checkpoints: it stops at the next step, keeps
  # the run file and the particle file marked incomplete, leaves no temporary, exits 130.
  dem_scene d.json ', "snapshot_interval": 50e-6'; sed -i 's/"end": 200e-6/"end": 50e-3/' d.json
  "$kolsky" run d.json -o run.h5 --checkpoint-every 20e-6 --gauges-csv g.csv >out.txt 2>err.txt & pid=$!
  for i in $(seq 600); do grep -q "steps of" err.txt && break; sleep 0.1; done  # packed, running
  sleep 1; kill -INT $pid; wait $pid; rc=$?
  [ "$rc" -eq 130 ] || fail "exit $rc after SIGINT (want 130): $(cat err.txt)"
  grep -q "SIGINT: stopped on request" err.txt || fail "stop message: $(cat err.txt)"
  for f in run.h5 run.particles.h5; do
    h5dump -a /meta/complete $f | grep -q "(0): 0" || fail "$f not marked incomplete"; done
  [ -s run.ckpt.h5 ] && [ -s run.xmf ] || fail "outputs missing: $(ls)"
  head -1 g.csv | grep -q "^# INCOMPLETE run" || fail "gauge record not marked incomplete: $(head -2 g.csv)"
  no_temp_files ;;
sweep)
  # kolsky sweep: listed by --help; bad input refused with exit 2 before any member runs (no
  # table, no cache); a small sweep's table, resumed from its cache; a failed member recorded
  # with exit 3; --plot without gnuplot refused before any work.
  expect_exit 0 "$kolsky" --help; grep -q "kolsky sweep SCENE.json" out.txt || fail "sweep not in --help"
  expect_exit 0 "$kolsky" sweep --help; grep -q "log:lo:hi:count" out.txt || fail "sweep --help"
  scene s.json ""
  expect_exit 1 "$kolsky" sweep s.json
  expect_exit 2 "$kolsky" sweep s.json --set 'specimen.constrained_modulus=[1e8,2e8]' --set 'specimen.lenght=[0.01]' -o t.csv
  grep -q "s.json: specimen.lenght: unknown key 'lenght'; did you mean 'length'? (sweep member " err.txt || fail "bad key message: $(cat err.txt)"
  [ "$(wc -l < err.txt)" -eq 1 ] || fail "error is not one line: $(cat err.txt)"
  expect_exit 2 "$kolsky" sweep s.json --set specimen.constrained_modulus=1e8:2e8:0 -o t.csv
  grep -q "^kolsky: error: --set: specimen.constrained_modulus: a range's count" err.txt || fail "range message: $(cat err.txt)"
  expect_exit 2 "$kolsky" sweep s.json --set specimen.constrained_modulus -o t.csv
  grep -q "no '='" err.txt || fail "no = message: $(cat err.txt)"
  expect_exit 2 "$kolsky" sweep s.json --set 'specimen.constrained_modulus=[]' -o t.csv
  grep -q "no member" err.txt || fail "empty list message: $(cat err.txt)"
  expect_exit 2 "$kolsky" sweep s.json --seeds 2 -o t.csv  # an elastic column has no packing seed
  grep -q "s.json: specimen.seed: " err.txt || fail "seed message: $(cat err.txt)"
  KOLSKY_GNUPLOT=$work/no_gnuplot expect_exit 2 "$kolsky" sweep s.json --set specimen.n_elements=[10,20] -o t.csv --plot p
  grep -q "gnuplot not available" err.txt || fail "gnuplot message: $(cat err.txt)"
  [ ! -e t.csv ] && [ ! -e t.h5 ] && [ ! -e t.cache ] || fail "bad input left outputs: $(ls)"
  expect_exit 0 "$kolsky" sweep s.json --set specimen.constrained_modulus=1e8:3e8:3 --set 'specimen.n_elements=[10,20]' -o t.csv --threads 2
  [ "$(wc -l < t.csv)" -eq 7 ] || fail "want a header and 6 rows: $(cat t.csv)"
  head -1 t.csv | grep -q "^member,specimen.constrained_modulus,specimen.n_elements,.*peak_stress_back_mpa.*,run_s,status,failure_kind,error,key$" || fail "header: $(head -1 t.csv)"
  [ "$(grep -c ',ok,,,' t.csv)" -eq 6 ] || fail "members not ok: $(cat t.csv)"
  h5dump -d /table/peak_stress_back_mpa -H t.h5 >/dev/null || fail "HDF5 table column missing"
  grep -q "6/6 done" err.txt || fail "no progress lines: $(cat err.txt)"; no_temp_files
  expect_exit 0 "$kolsky" sweep s.json --set specimen.constrained_modulus=1e8:3e8:3 --set 'specimen.n_elements=[10,20]' -o t.csv
  [ "$(grep -c 'from the cache' err.txt)" -eq 6 ] || fail "rerun did not take every member from the cache: $(cat err.txt)"
  expect_exit 0 "$kolsky" sweep s.json --set specimen.n_elements=[10,20] -o q.csv --quiet
  [ ! -s err.txt ] || fail "--quiet printed: $(cat err.txt)"
  expect_exit 3 "$kolsky" sweep s.json --set 'specimen.constrained_modulus=[1e8,5e10]' --set time.dt=1.2e-6 \
    --set time.check_stability=false --set time.end=3e-3 -o f.csv
  grep -q ",failed,numerical,numerical failure: non-finite" f.csv || fail "failed member not recorded: $(cat f.csv)"
  grep -q ",ok,,," f.csv || fail "the other member did not run: $(cat f.csv)"
  no_temp_files ;;
*) fail "unknown case" ;;
esac
echo "PASS [$case_name]"
