#!/usr/bin/env bash
# A unit test program under MPIEXEC -np 2 (the test itself asserts its
# numbers; this script only starts it as Open MPI needs it here).
#
# Usage: bash mpi_unit.sh ROLLNIP MPIEXEC TEST_PROGRAM
#   ROLLNIP is not used (every cli test gets it first).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 3 ] || fail "usage: mpi_unit.sh ROLLNIP MPIEXEC TEST_PROGRAM"
require_executable mpiexec "$2"
require_executable "test program" "$3"
mpi_setup "$2"
"$2" "${mpi_flags[@]}" -np 2 "$3"
