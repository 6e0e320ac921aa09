#!/usr/bin/env bash
# A shear modulus outside the range of rubbers (0.01 to 100 MPa) is most
# likely a unit mistake, but a scaled modulus is also how the tests check
# that P/G does not depend on G (tests/unit/extreme_scenes.cc): it is
# warned about, once, before the mesh is built, and the run goes on.
#
# Usage: bash modulus_warning.sh ROLLNIP PRM
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 2 ] || fail "usage: modulus_warning.sh ROLLNIP PRM"
rollnip="$1"
prm="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"
require_executable rollnip "$rollnip"
start_test modulus_warning

rc=0
"$rollnip" --validate "$prm" > stdout.txt 2> stderr.txt || rc=$?
echo "--- standard error:"
cat stderr.txt
echo "---"
[ "$rc" -eq 0 ] || fail "exit code $rc, expected 0 (a warning, not an error)"
pass "exit code 0"
[ "$(wc -l < stderr.txt)" -eq 1 ] || fail "expected exactly one line on standard error"
line="$(head -n 1 stderr.txt)"
regex="^rollnip: warning: Material/C1 \+ C2: .* = 1000 MPa is outside 0\.01 to 100 MPa.*unit mistake"
[[ "$line" =~ $regex ]] || fail "the warning does not match /$regex/"
pass "one warning line naming C1 + C2, the modulus and a unit mistake"
