#!/usr/bin/env bash
# Installs every Debian 12 package planarbench needs to build, test and report.
# Idempotent: apt-get skips what is already installed. Run as root or with sudo.
set -euo pipefail

PACKAGES=(
  build-essential cmake ninja-build pkg-config git
  libeigen3-dev
  libmujoco-dev libqhull-dev   # mujocoConfig.cmake names /usr/include/libqhull_r
  libbox2d-dev
  libode-dev
  libcgal-dev                  # convex pieces of concave bodies (CGAL 2-D polygon partitioning)
  libboost-dev                 # Boost.Odeint and Boost.Math (header-only): the independent truth
  libhdf5-dev hdf5-tools
  zlib1g-dev                   # results-file chunks deflated in parallel
  libbenchmark-dev
  libgtest-dev libgmock-dev
  libcli11-dev
  libtomlplusplus-dev
  nlohmann-json3-dev
  libfmt-dev
  libmatio-dev                 # measured impacts: MAT v5 files (core/impacts)
  libnlopt-cxx-dev             # measured impacts: parameter fits (core/impacts)
  python3-h5py python3-numpy
  python3-scipy                # tests/impacts: an independent reading of the MAT file
  clang libclang-rt-14-dev     # scripts/fuzz.sh: Clang and libFuzzer's runtime
  lld                          # the asan-ubsan preset links with LLVM's lld (4x GNU ld's speed there)
  slurm-wlm munge              # tests/slurm: campaigns on a local single-node Slurm
)

SUDO=""
if [ "$(id -u)" -ne 0 ]; then SUDO="sudo"; fi

missing=()
for p in "${PACKAGES[@]}"; do
  if ! dpkg-query -W -f='${Status}' "$p" 2>/dev/null | grep -q "install ok installed"; then
    missing+=("$p")
  fi
done

if [ "${#missing[@]}" -eq 0 ]; then
  echo "setup: all ${#PACKAGES[@]} packages already installed"
  exit 0
fi

echo "setup: installing ${missing[*]}"
export DEBIAN_FRONTEND=noninteractive
$SUDO apt-get update -qq
$SUDO apt-get install -y -qq --no-install-recommends "${missing[@]}"
