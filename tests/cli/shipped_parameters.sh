#!/usr/bin/env bash
# A parameter file shipped in parameters/ runs as a user runs it: exit code
# 0, no error or warning, and its results written.
#
# Usage: bash shipped_parameters.sh ROLLNIP PRM
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 2 ] || fail "usage: shipped_parameters.sh ROLLNIP PRM"
rollnip="$1"
prm="$2"
require_executable rollnip "$rollnip"
[ -f "$prm" ] || fail "no parameter file '$prm'"
start_test "shipped-$(basename "$prm" .prm)"

rc=0
"$rollnip" "$prm" > stdout.txt 2> stderr.txt || rc=$?
[ "$rc" -eq 0 ] || { cat stderr.txt; fail "exit code $rc, expected 0"; }
pass "$(basename "$prm") runs, exit code 0"
[ ! -s stderr.txt ] || { cat stderr.txt; fail "standard error is not empty"; }
pass "nothing on standard error"
n="$(find output -name summary.txt | wc -l)"
[ "$n" -ge 1 ] || fail "no summary.txt written under output/"
pass "$n summary.txt file(s) written"
