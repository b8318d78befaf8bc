#!/usr/bin/env bash
# Installs the Debian packages kolsky needs, and only those that are missing.
# Idempotent: a second run installs nothing and does not call apt-get at all.
# Usage: scripts/install-deps.sh [--check] [--bench-peers]
#   --check        report what is missing, install nothing
#   --bench-peers  also the optional peer DEM codes for benchmarks/lammps/run.sh (LAMMPS and
#                  LIGGGHTS, Debian bookworm packages `lammps`, `liggghts`); only run.sh passes
#                  it: the build, `make test` and CI never need them (docs/dem.md, Performance)
set -euo pipefail

check=0
peers=0
for arg in "$@"; do
  case "$arg" in
    --check) check=1 ;;
    --bench-peers) peers=1 ;;
    *) echo "install-deps: unknown option '$arg' (use --check, --bench-peers)" >&2; exit 2 ;;
  esac
done

packages=(
  build-essential cmake pkg-config git       # toolchain
  libeigen3-dev                              # Eigen3 (small dense linear algebra)
  libgsl-dev                                 # GSL (least squares, minimisers)
  libboost-dev                               # Boost headers (Odeint)
  libgtest-dev libgmock-dev                  # GoogleTest
  libbenchmark-dev                           # Google Benchmark
  libhdf5-dev hdf5-tools                     # HDF5 C library and h5dump
  nlohmann-json3-dev                         # JSON scenes
  gnuplot-nox                                # plots (pngcairo terminal)
  clang-14 libclang-rt-14-dev                # make fuzz, make check-sanitize (libFuzzer,
                                             # ASan/UBSan runtimes; not a clang-14 dependency)
  libomp-14-dev                              # OpenMP for clang (the sanitized DEM kernels)
  libopenmpi-dev openmpi-bin                 # MPI ensembles (docs/scale-out.md; plain C API)
)
if [ "$peers" -eq 1 ]; then
  # lmp (LAMMPS 2022, GRANULAR, Open MPI) and liggghts (3.8.0); mpirun comes with openmpi-bin
  # (a base package since the MPI ensembles).
  packages+=(lammps liggghts)
fi

missing=()
for p in "${packages[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ ${#missing[@]} -eq 0 ]; then
  echo "install-deps: all ${#packages[@]} packages present"
  exit 0
fi

echo "install-deps: missing: ${missing[*]}"
if [ "$check" -eq 1 ]; then exit 1; fi

if [ "$(id -u)" -ne 0 ]; then
  if command -v sudo >/dev/null 2>&1; then SUDO=sudo; else
    echo "install-deps: need root (or sudo) to install: ${missing[*]}" >&2; exit 1
  fi
else
  SUDO=""
fi

export DEBIAN_FRONTEND=noninteractive
echo "install-deps: apt-get update"
if ! $SUDO apt-get update -q >/dev/null; then
  echo "install-deps: 'apt-get update' failed: is the Debian mirror reachable?" >&2; exit 1
fi
echo "install-deps: apt-get install -y ${missing[*]}"
if ! $SUDO apt-get install -y -q --no-install-recommends "${missing[@]}" >/dev/null; then
  echo "install-deps: 'apt-get install' failed for: ${missing[*]}" >&2; exit 1
fi
echo "install-deps: installed ${#missing[@]} package(s)"
