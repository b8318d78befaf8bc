#!/usr/bin/env bash
# Issue 31, Chapter 3 face stresses (reproductions/chapter3/README.md, "The face stresses"): is the
# 1.5 x specimen's early front - back gap the inertia of a specimen the rising pulse accelerates?
# Three full-scale runs of the set's shifted case (~70 s each): packing seeds 1 and 2 with the
# set's pulse (sin^2 rise to 125 us), and seed 1 with the rise halved (62.5 us, the same inverse
# design and plateau: data/digitized/chapter2/make_song_pulse_rate.sh with RISE_US=62.5).
# Resumable (finished cases are kept). Usage: scripts/study-ringing.sh BUILD OUTDIR
set -euo pipefail
build=$1 out=$2
here="$(cd "$(dirname "$0")/.." && pwd)"
mkdir -p "$out"
RATE=470 RISE_US=62.5 bash "$here/data/digitized/chapter2/make_song_pulse_rate.sh" > "$out/pulse_rise62.csv"
export OMP_NUM_THREADS=1
run="$build/reproductions/study_ringing"
"$run" --out "$out" --label seed1 --seed 1
"$run" --out "$out" --label seed2 --seed 2
"$run" --out "$out" --label seed1_rise62 --seed 1 --pulse "$out/pulse_rise62.csv" --rise-end 62.5e-6
