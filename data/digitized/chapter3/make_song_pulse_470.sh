#!/usr/bin/env bash
# Incident stress pulse of the Song et al. (2009) steel-tube test at the ~470/s of Chapter 3
# (Secs. 3.1, 3.2, 3.5; Chs. 2 and 5 say 480/s for the same test, targets.md 3e.5): the inverse
# design of ../chapter2/make_song_pulse_rate.sh with the plateau rate 470/s.
# Usage: make_song_pulse_470.sh > song2009_incident_470_reconstructed.csv
set -euo pipefail
RATE=470 exec "$(cd "$(dirname "$0")" && pwd)/../chapter2/make_song_pulse_rate.sh"
