#!/usr/bin/env bash
# Grain-size curve of the Song et al. (2009) sand as Chapter 3 needs it (Fig. 3.2, not
# available): the Chapter 4/5 reconstruction (../chapter4/make_song_psd.sh: truncated Weibull,
# d_c = 335.29 um, m = 3.219, d_max = 0.6 mm) with its fines cut at d_min = 161 um instead of
# 75 um, so that at N = 1 and porosity 0.465 it gives Table 3.1's 138,275 spheres in the
# 19.1 mm x 9.3 mm cylinder (the Chapter 4 curve gives 263,041 there: targets.md 3e.4, 4e.11).
# d_min was found by bisection on the solver's count (mass uniform in log d within a row,
# psd/grain_size_curve.cpp) and rounded to 1 um. Same 41 log-spaced rows.
# Usage: make_song_psd_ch3.sh > song2009_psd_ch3_reconstructed.csv
set -euo pipefail
awk -v d_min=161e-6 -v d_max=600e-6 -v d_c=335.29e-6 -v m=3.219 -v n=41 'BEGIN {
  f_lo = 1 - exp(-(d_min / d_c) ^ m);
  f_hi = 1 - exp(-(d_max / d_c) ^ m);
  print "# diameter_m,percent_passing  (reconstructed: see make_song_psd_ch3.sh and the .meta.json)";
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
