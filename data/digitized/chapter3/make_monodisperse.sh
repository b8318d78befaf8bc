#!/usr/bin/env bash
# Monodisperse grain-size curve of Sec. 3.4: spheres of radius 0.15 mm ("approximate D50 of the
# original PSD"). The solver's curve needs a rising table, so the single size is written as a
# +-0.01 % bin around d = 0.3 mm (mean-volume diameter 0.3 mm to 1e-8 relative).
# Usage: make_monodisperse.sh > monodisperse_r015.csv
set -euo pipefail
printf '# diameter_m,percent_passing  (monodisperse r = 0.15 mm: see make_monodisperse.sh)\n'
printf 'diameter_m,percent_passing\n2.9997e-04,0.0000\n3.0003e-04,100.0000\n'
