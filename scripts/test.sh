#!/usr/bin/env bash
# Sets everything up (scripts/setup.sh) and runs the test suite with ctest.
#
# Usage: bash scripts/test.sh [ctest arguments...]
#   e.g. bash scripts/test.sh -L mpi      (only the MPI tests)
#        bash scripts/test.sh -R material (tests whose name matches)
set -euo pipefail

repo_root="$(cd "$(dirname "${BASH_SOURCE[0]}")/.." && pwd)"
cd "$repo_root"

bash scripts/setup.sh

# The MPI tests call mpirun; Open MPI refuses to run as root unless told.
export OMPI_ALLOW_RUN_AS_ROOT=1
export OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1

ctest --test-dir build --output-on-failure -j2 "$@"
