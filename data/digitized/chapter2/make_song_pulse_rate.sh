#!/usr/bin/env bash
# Reconstructs the incident stress pulse of a Song et al. (2009) test at strain rate RATE (default 900/s,
# Sec. 2.3.4) by the inverse design of ../bars/make_song_pulse.sh with the plateau rate changed.
# The text prints only the plateau rates (480/s from 125 us to 350 us; 900/s) and no pulse shape.
# Method (inverse design under equilibrium, for a 1-D elastic stand-in of D = 230 MPa):
#   target rate r(t): R * sin^2(pi t / 250 us) rise on [0, 125] us, R on [125, 350] us,
#   R * cos^2(pi (t - 350 us) / 200 us) fall on [350, 450] us, 0 after;
#   strain e(t) = int r dt;  specimen stress s = D e;
#   equilibrium + characteristic bar relations: v_front - v_back = L r,
#   v_front = (2 s_i - s)/(rho c), v_back = s/(rho c)  =>  s_i = rho c L r / 2 + s;
#   after 450 us the pulse ramps linearly to zero over 100 us.
# t = 0 is the arrival at the specimen face; applied at the free end the same table is simply
# delayed by L_I / c. Usage: RATE=900 make_song_pulse_rate.sh > song2009_incident_900_reconstructed.csv
# RISE_US (default 125, the text's) moves the end of the sin^2 rise, for the Chapter 3 face-stress
# study (scripts/study-ringing.sh); no reproduction uses another value.
set -euo pipefail
awk -v R="${RATE:-900}" -v T="${RISE_US:-125}" 'BEGIN {
  pi = 3.141592653589793; rho = 8100; c = sqrt(200e9 / 8100); L = 0.0093; D = 230e6;
  dt = 1e-6; e = 0; r_prev = 0;
  print "# time_s,stress_pa  (reconstructed: see make_song_pulse_rate.sh and the .meta.json)";
  print "time_s,stress_pa";
  for (i = 0; i <= 550; i++) {
    t = i * dt; us = i;
    if (us <= T) r = 480 * sin(pi * us / (2 * T)) ^ 2;
    else if (us <= 350) r = R;
    else if (us <= 450) r = 480 * cos(pi * (us - 350) / 200) ^ 2;
    else r = 0;
    if (i > 0) e += 0.5 * (r + r_prev) * dt;
    r_prev = r;
    s = rho * c * L * r / 2 + D * e;
    if (us > 450) { if (us == 451) s450 = s_last; s = s450 * (550 - us) / 100 }
    s_last = s;
    printf "%.6e,%.6e\n", t, s;
  }
}'
