#!/usr/bin/env bash
# Reconstructs the grain-size curve of the Song et al. (2009) sand (Quikrete #1961, poorly graded
# silica sand), the original PSD of Fig. 4.3 / Fig. 5.13 (not available; the dissertation prints
# no PSD numbers). Model: a Weibull (Rosin-Rammler) cumulative truncated to [d_min, d_max] and
# renormalised,
#   F(d) = 1 - exp(-(d/d_c)^m),   P(d) = 100 (F(d) - F(d_min)) / (F(d_max) - F(d_min)),
# tabulated at n log-spaced diameters (the solver interpolates linearly in log d between rows).
# Parameters (docs/psd.md, song2009_psd_reconstructed.meta.json):
#   d_max = 0.6 mm   (Ch. 3: 0.9 mm after the 1.5x shift)
#   d_min = 75 um    (assumed: a washed sand with nothing finer than the No. 200 sieve)
#   d_c, m           calibrated together so that D50 = 0.300 mm (Ch. 3: monodisperse r = 0.15 mm
#                    is "the approximate D50") and the tabulated curve, upscaled by N = 2, gives
#                    34,411 spheres in a 19.1 mm x 9.3 mm cylinder at porosity 0.44 (Sec. 4.3).
# Usage: make_song_psd.sh > song2009_psd_reconstructed.csv
set -euo pipefail
awk -v d_min=75e-6 -v d_max=600e-6 -v d_c=335.29e-6 -v m=3.219 -v n=41 'BEGIN {
  f_lo = 1 - exp(-(d_min / d_c) ^ m);
  f_hi = 1 - exp(-(d_max / d_c) ^ m);
  print "# diameter_m,percent_passing  (reconstructed: see make_song_psd.sh and the .meta.json)";
  print "diameter_m,percent_passing";
  for (i = 0; i < n; i++) {
    if (i == 0) d = d_min;
    else if (i == n - 1) d = d_max;
    else d = d_min * exp(i / (n - 1) * log(d_max / d_min));
    p = 100 * ((1 - exp(-(d / d_c) ^ m)) - f_lo) / (f_hi - f_lo);
    if (i == 0) p = 0;
    if (i == n - 1) p = 100;
    printf "%.6e,%.4f\n", d, p;
  }
}'
