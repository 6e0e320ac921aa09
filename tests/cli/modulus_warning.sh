#!/usr/bin/env bash
# A shear modulus outside the range of rubbers (0.01 to 100 MPa) is most
# likely a unit mistake, but a scaled modulus is also how the tests check
# that P/G does not depend on G (tests/unit/extreme_scenes.cc): it is
# warned about, once, before the mesh is built, and the run goes on; too
# stiff (1000 MPa) and too soft (0.004 MPa) alike.
#
# Usage: bash modulus_warning.sh ROLLNIP PRM MODULUS
#   MODULUS  the shear modulus 2 (C1 + C2) of PRM as the warning prints it
#            [MPa], e.g. 1000 (too stiff) or 0.004 (too soft)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 3 ] || fail "usage: modulus_warning.sh ROLLNIP PRM MODULUS"
rollnip="$1"
prm="$(cd "$(dirname "$2")" && pwd)/$(basename "$2")"
require_executable rollnip "$rollnip"
modulus="$3"
start_test modulus_warning

rc=0
"$rollnip" --validate "$prm" > stdout.txt 2> stderr.txt || rc=$?
# Both streams in one file, in the order they were written.
"$rollnip" --validate "$prm" > both.txt 2>&1 || true
echo "--- standard error:"
cat stderr.txt
echo "---"
[ "$rc" -eq 0 ] || fail "exit code $rc, expected 0 (a warning, not an error)"
pass "exit code 0"
[ "$(wc -l < stderr.txt)" -eq 1 ] || fail "expected exactly one line on standard error"
line="$(head -n 1 stderr.txt)"
regex="^rollnip: warning: Material/C1 \+ C2: .* = ${modulus//./\\.} MPa is outside 0\.01 to 100 MPa.*unit mistake"
[[ "$line" =~ $regex ]] || fail "the warning does not match /$regex/"
pass "one warning line naming C1 + C2, the modulus and a unit mistake"
warning_at="$(grep -n '^rollnip: warning' both.txt | head -n 1 | cut -d: -f1)"
mesh_at="$(grep -n '^Mesh:' both.txt | head -n 1 | cut -d: -f1)"
[ -n "$mesh_at" ] || fail "--validate printed no 'Mesh:' line"
[ "$warning_at" -lt "$mesh_at" ] ||
  fail "the warning (line $warning_at) comes after the mesh is built (line $mesh_at)"
pass "the warning comes before the mesh is built (line $warning_at, mesh at line $mesh_at)"
