#!/usr/bin/env bash
# Installs what rollnip needs (Debian packages), then configures and builds it
# in build/. Safe to run again: apt is skipped when every package is already
# installed, cmake configures only once, and the build is incremental.
#
# Usage: bash scripts/setup.sh        (from any directory)
#        ROLLNIP_WITH_PARAVIEW=1 bash scripts/setup.sh
#                                     also installs ParaView (pvpython, for
#                                     scripts/render_nip.py; about 450 MB)
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo_root"

packages=(
  libdeal.ii-dev  # deal.II 9.4 with Trilinos, p4est, MPI
  libeigen3-dev   # small dense systems
  libopenblas0-serial  # optimised BLAS/LAPACK for MUMPS (Debian's
                       # alternatives make it the default over the reference
                       # BLAS): 15-20 % less CPU on the larger sparse solves
  gmsh            # meshes/*.geo
  numdiff         # test output comparison
  cmake
  g++
  make
  openmpi-bin     # mpirun, for parallel runs and the MPI tests
  gnuplot-nox     # plots of the CSV tables
  python3
)
if [ "${ROLLNIP_WITH_PARAVIEW:-0}" = 1 ]; then
  packages+=(paraview python3-paraview xvfb xauth)
fi

is_installed() {
  [ "$(dpkg-query -W -f='${Status}' "$1" 2>/dev/null || true)" = \
    "install ok installed" ]
}

missing=()
for p in "${packages[@]}"; do
  is_installed "$p" || missing+=("$p")
done

if [ "${#missing[@]}" -gt 0 ]; then
  echo "setup: installing ${missing[*]}"
  if [ "$(id -u)" -eq 0 ]; then
    as_root=()
  elif command -v sudo >/dev/null 2>&1; then
    as_root=(sudo)
  else
    echo "setup: error: need root or sudo to install ${missing[*]}" >&2
    exit 1
  fi
  ${as_root[@]+"${as_root[@]}"} env DEBIAN_FRONTEND=noninteractive apt-get update
  ${as_root[@]+"${as_root[@]}"} env DEBIAN_FRONTEND=noninteractive \
    apt-get install -y --no-install-recommends "${missing[@]}"
else
  echo "setup: all required packages are installed"
fi

if [ ! -f build/CMakeCache.txt ]; then
  cmake -S . -B build -DCMAKE_BUILD_TYPE=Release
fi
cmake --build build -j"$(nproc)"
echo "setup: built $repo_root/build/rollnip"
