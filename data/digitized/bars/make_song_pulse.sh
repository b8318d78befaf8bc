#!/usr/bin/env bash
# Reconstructs the incident stress pulse of the Song et al. (2009) 480/s test (Sec. 2.3.4): the
# inverse design of ../chapter2/make_song_pulse_rate.sh (method described there) at 480/s, the
# only numbers the text prints being a strain rate of about 480/s from 125 us to 350 us.
# Usage: make_song_pulse.sh > song2009_incident_480_reconstructed.csv
set -euo pipefail
RATE=480 exec "$(cd "$(dirname "$0")" && pwd)/../chapter2/make_song_pulse_rate.sh"
