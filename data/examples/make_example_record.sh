#!/usr/bin/env bash
# Makes gauges_song2009_example.csv: the simulated gauge record of song2009_elastic.json with
# what real lab data has added: a constant offset per channel (+40 and -25 microstrain) and
# Gaussian noise of 3 microstrain (Park-Miller generator and Box-Muller, seed 20091,
# reproducible with any awk). Usage: make_example_record.sh path/to/kolsky
set -euo pipefail
kolsky=${1:?path to the kolsky binary}
here=$(cd "$(dirname "$0")" && pwd)
tmp=$(mktemp -d)
"$kolsky" run "$here/song2009_elastic.json" -o "$tmp/run.h5" --gauges-csv "$tmp/clean.csv" --quiet >/dev/null
awk -F, 'BEGIN { seed = 20091; pi = 3.141592653589793 }
  function u() { seed = (16807 * seed) % 2147483647; return seed / 2147483647 }
  function gauss() { return sqrt(-2 * log(u())) * cos(2 * pi * u()) }
  /^#/ { next }
  /^time_s/ { print "# Example SHPB gauge record (simulated, see make_example_record.sh): strain as measured,";
              print "# compression negative; offsets +40 / -25 microstrain and 3 microstrain noise added.";
              print; next }
  { printf "%.12e,%.6e,%.6e\n", $1, $2 + 40e-6 + 3e-6 * gauss(), $3 - 25e-6 + 3e-6 * gauss() }' \
  "$tmp/clean.csv" > "$here/gauges_song2009_example.csv"
rm -rf "$tmp"
echo "wrote $here/gauges_song2009_example.csv"
