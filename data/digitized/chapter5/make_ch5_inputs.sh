#!/usr/bin/env bash
# Reconstructs the Chapter 5 inputs the dissertation shows only as figures (targets.md 5d):
#   wang2018_psd_reconstructed.csv        Fig. 5.4, original curve (N = 1)
#   huang2013_psd_reconstructed.csv       Fig. 5.9, the approximated curve (tail cut at 0.1 mm)
#   huang2013_psd_tail.csv                Fig. 5.9, the original curve with its tail (for the
#                                         downscaled comparison, Sec. 5.3.2: tail added back)
#   wang2018_strain_rate_reconstructed.csv  Fig. 5.3 (peak 1200/s)
#   wang2018_psd_dmax_l10.csv             the Wang curve's shape and count, top size L/10 (H3)
#   wang2018_strain_rate_held.csv         the same rise, the peak held to 400 us (strain 0.47):
#                                         run with loading.end_at_back_stress (issue 31, H2)
#   huang2013_strain_rate_700_reconstructed.csv  the 700/s history (no figure)
# Each has a .meta.json beside it saying from what and how.
#
# Grain-size curves: a Weibull (Rosin-Rammler) cumulative truncated to [d_lo, d_hi] and
# renormalised, as for the Song curve (../chapter4/make_song_psd.sh):
#   P(d) = 100 (F(d) - F(d_lo)) / (F(d_hi) - F(d_lo)),  F(d) = 1 - exp(-(d/d_c)^m),
# tabulated at 41 log-spaced diameters. The scale d_c is solved by bisection so that the curve,
# upscaled by N and read with the solver's within-bin model (mass uniform in log d between rows,
# psd::mean_grain_volume), gives the printed particle count at the stated geometry and porosity:
#   count = V (1 - n) (6/pi) sum_bins f_b <d^-3>_b,  <d^-3> = a^-3 (1 - (a/b)^3) / (3 ln(b/a)).
# That count is then circular: it cannot be scored (reproductions/chapter5/README.md).
#   Wang: the Song curve's shape (m = 3.219, d_lo/d_c and d_hi/d_c of make_song_psd.sh: both are
#         'poorly graded silica sand') scaled to 43,642 grains at n = 0.41 in 5 x 15 mm, N = 1.
#   Huang: 'fine silica sand' with a tail to 0.01 mm (the smallest size of Sec. 5.3.2's
#         downscaling): the Song modulus m = 3.219, d_hi = 2 d_c (Song: 1.79 d_c); the
#         approximated curve is that curve cut at 0.1 mm and renormalised, scaled to 37,595
#         grains at N = 2.5, n = 0.40 (assumed: the text gives none), 10 x 37.2 mm.
# Strain-rate histories: smoothstep rise to the peak, plateau, smoothstep fall to zero
# (the usual shape of a shaped-pulse sand test); durations in the .meta.json.
# Usage: bash make_ch5_inputs.sh   (writes the seven CSVs into this folder)
set -euo pipefail
cd "$(dirname "$0")"

# curve NAME M LO_OVER_C HI_OVER_C CUT N COUNT POROSITY LENGTH DIAMETER
# CUT = 0: no cut; else the curve is restricted to d >= CUT (m) and renormalised.
curve() {
  awk -v m="$2" -v lo_c="$3" -v hi_c="$4" -v cut="$5" -v N="$6" -v target="$7" -v n="$8" \
      -v L="$9" -v D="${10}" -v name="$1" -v mode="${11}" 'function F(d) { return 1 - exp(-(d / dc) ^ m) }
  function table(  i, d) {
    lo = lo_c * dc; hi = hi_c * dc; a = (cut > 0 && cut > lo) ? cut : lo;
    for (i = 0; i < 41; i++) {
      d = (i == 0) ? a : (i == 40 ? hi : a * exp(i / 40 * log(hi / a)));
      x[i] = d; p[i] = 100 * (F(d) - F(a)) / (F(hi) - F(a));
    }
    p[0] = 0; p[40] = 100;
  }
  function count(  i, s, f, A, B, r) {
    table(); s = 0;
    for (i = 1; i < 41; i++) {
      f = (p[i] - p[i - 1]) / 100; A = N * x[i - 1]; B = N * x[i]; r = log(B / A);
      s += f * A ^ -3 * (1 - (A / B) ^ 3) / (3 * r);
    }
    return 3.14159265358979 / 4 * D * D * L * (1 - n) * 6 / 3.14159265358979 * s;
  }
  BEGIN {
    g = 1e-6; h = 1e-2;                      # bracket on d_c (m); count falls as d_c grows
    for (k = 0; k < 200; k++) { dc = sqrt(g * h); if (count() > target) g = dc; else h = dc; }
    dc = sprintf("%.4g", dc) + 0;            # rounded to 4 digits, then tabulated
    c = count();
    if (mode == "count") {
      for (i = 1; i < 41; i++) if (p[i] >= 50) { d50 = x[i - 1] * exp((50 - p[i - 1]) / (p[i] - p[i - 1]) * log(x[i] / x[i - 1])); break }
      printf "%s d_c=%.4g m count=%.1f d50=%.4g m d_hi=%.4g m\n", name, dc, c, d50, x[40]; exit }
    printf "# diameter_m,percent_passing  (reconstructed: see make_ch5_inputs.sh and the .meta.json)\n";
    print "diameter_m,percent_passing";
    for (i = 0; i < 41; i++) printf "%.6e,%.4f\n", x[i], p[i];
  }'
}

# The Song shape (make_song_psd.sh): d_c = 335.29 um, d_min = 75 um, d_max = 600 um, m = 3.219.
song_lo=$(awk 'BEGIN{printf "%.6f", 75/335.29}'); song_hi=$(awk 'BEGIN{printf "%.6f", 600/335.29}')
curve wang 3.219 "$song_lo" "$song_hi" 0 1 43642 0.41 0.005 0.015 csv > wang2018_psd_reconstructed.csv
curve wang 3.219 "$song_lo" "$song_hi" 0 1 43642 0.41 0.005 0.015 count >&2
# H3 (issue 31): the same shape and count with the top size at L/10 = 0.5 mm, the maximum the
# text calls essential (Sec. 3.2), against the reconstruction's 0.78 mm (L/6.4): d_hi / d_c is
# iterated until the solved d_c puts d_hi at 0.5 mm (12 passes: 0.5000 mm, d50 0.371 mm).
hi_l10=$song_hi
for pass in $(seq 1 12); do
  dc_l10=$(curve wang 3.219 "$song_lo" "$hi_l10" 0 1 43642 0.41 0.005 0.015 count | sed 's/.*d_c=\([^ ]*\) m.*/\1/')
  hi_l10=$(awk -v dc="$dc_l10" 'BEGIN{printf "%.6f", 0.5e-3 / dc}')
done
curve wang 3.219 "$song_lo" "$hi_l10" 0 1 43642 0.41 0.005 0.015 csv > wang2018_psd_dmax_l10.csv
curve wang_dmax_l10 3.219 "$song_lo" "$hi_l10" 0 1 43642 0.41 0.005 0.015 count >&2
# Huang: solve the cut curve's scale, then write the same curve uncut (the tail) with that d_c.
curve huang 3.219 0.01 2 1e-4 2.5 37595 0.40 0.010 0.0372 csv > huang2013_psd_reconstructed.csv
curve huang 3.219 0.01 2 1e-4 2.5 37595 0.40 0.010 0.0372 count >&2
dc_h=$(curve huang 3.219 0.01 2 1e-4 2.5 37595 0.40 0.010 0.0372 count 2>&1 | sed 's/.*d_c=\([^ ]*\) m.*/\1/')
# The uncut curve: d_lo = 0.01 mm exactly (Sec. 5.3.2), same d_c, m and d_hi.
awk -v dc="$dc_h" 'function F(d) { return 1 - exp(-(d / dc) ^ 3.219) }
BEGIN { lo = 1e-5; hi = 2 * dc;
  printf "# diameter_m,percent_passing  (reconstructed: see make_ch5_inputs.sh and the .meta.json)\n";
  print "diameter_m,percent_passing";
  for (i = 0; i < 41; i++) { d = (i == 0) ? lo : (i == 40 ? hi : lo * exp(i / 40 * log(hi / lo)));
    pp = 100 * (F(d) - F(lo)) / (F(hi) - F(lo)); if (i == 0) pp = 0; if (i == 40) pp = 100;
    printf "%.6e,%.4f\n", d, pp } }' > huang2013_psd_tail.csv

# rate NAME PEAK RISE PLATEAU_END FALL_END DT
rate() {
  awk -v peak="$2" -v rise="$3" -v pend="$4" -v fend="$5" -v dt="$6" 'function s(x) { return x * x * (3 - 2 * x) }
  BEGIN { print "# time_s,strain_rate  (reconstructed: see make_ch5_inputs.sh and the .meta.json)";
    print "time_s,strain_rate";
    for (t = 0; t <= fend + 1e-12; t += dt) {
      if (t < rise) r = peak * s(t / rise); else if (t <= pend) r = peak;
      else r = peak * (1 - s((t - pend) / (fend - pend)));
      printf "%.6e,%.6g\n", t, r } }'
}
rate wang 1200 20e-6 130e-6 150e-6 1e-6 > wang2018_strain_rate_reconstructed.csv
rate wang 1200 20e-6 400e-6 420e-6 1e-6 > wang2018_strain_rate_held.csv
rate huang 700 20e-6 280e-6 300e-6 1e-6 > huang2013_strain_rate_700_reconstructed.csv
