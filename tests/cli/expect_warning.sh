#!/usr/bin/env bash
# Input that is accepted with a warning: the run goes on, and the warning
# is exactly one line, printed before the mesh is built.
#
# Usage: bash expect_warning.sh ROLLNIP PRM LINE
#   ROLLNIP  the rollnip executable
#   PRM      the parameter file (warnings/*.prm)
#   LINE     the whole warning line expected on standard error, without
#            its 'rollnip: warning: ' beginning
#
# Runs 'rollnip --validate PRM' in a fresh temporary directory and asserts:
# exit code 0, exactly one line on standard error, equal to
# 'rollnip: warning: LINE', and printed before the 'Mesh:' line of the
# mesh that --validate builds.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 3 ] || fail "usage: expect_warning.sh ROLLNIP PRM LINE"
require_executable rollnip "$1"
rollnip="$(realpath "$1")"
prm="$(realpath "$2")"
expected="rollnip: warning: $3"
start_test "expect_warning-$(basename "$prm" .prm)"

rc=0
"$rollnip" --validate "$prm" > stdout.txt 2> stderr.txt || rc=$?
echo "--- standard error:"
cat stderr.txt
echo "---"
[ "$rc" -eq 0 ] || fail "exit code $rc, expected 0 (a warning, not an error)"
pass "exit code 0"
[ "$(wc -l < stderr.txt)" -eq 1 ] ||
  fail "expected exactly one line on standard error"
pass "one line on standard error"
[ "$(cat stderr.txt)" = "$expected" ] ||
  fail "the line differs from the expected one: $expected"
pass "it is the expected warning"
"$rollnip" --validate "$prm" > both.txt 2>&1 || true
warning_at="$(grep -n '^rollnip: warning' both.txt | head -n 1 | cut -d: -f1)"
mesh_at="$(grep -n '^Mesh:' both.txt | head -n 1 | cut -d: -f1)"
[ -n "$mesh_at" ] || fail "--validate printed no 'Mesh:' line"
[ "$warning_at" -lt "$mesh_at" ] ||
  fail "the warning (line $warning_at) comes after the mesh is built (line $mesh_at)"
pass "the warning comes before the mesh is built"
