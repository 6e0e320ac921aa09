#!/usr/bin/env bash
# The informational options.
#
# Usage: bash help_and_parameters.sh ROLLNIP
#
# Asserts: 'rollnip --help' exits 0, prints 'Usage:' on standard output and
# nothing on standard error; 'rollnip --print-parameters' exits 0 and prints
# every subsection; that output, written to a file, is read back by
# 'rollnip --validate FILE', which must exit 0, say the file is valid and
# print nothing on standard error (the listing is a valid parameter file,
# and the defaults make a valid run).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 1 ] || fail "usage: help_and_parameters.sh ROLLNIP"
rollnip="$1"
require_executable rollnip "$rollnip"
start_test help_and_parameters

rc=0
"$rollnip" --help > help.txt 2> help.err || rc=$?
[ "$rc" -eq 0 ] || fail "rollnip --help exited with $rc"
pass "rollnip --help exits 0"
grep -q '^Usage: rollnip' help.txt || fail "rollnip --help does not print 'Usage: rollnip'"
pass "it prints: $(grep '^Usage:' help.txt)"
[ ! -s help.err ] || { cat help.err; fail "rollnip --help wrote to standard error"; }
pass "nothing on standard error"

rc=0
"$rollnip" --print-parameters > all.prm 2> print.err || rc=$?
[ "$rc" -eq 0 ] || fail "rollnip --print-parameters exited with $rc"
[ ! -s print.err ] || { cat print.err; fail "--print-parameters wrote to standard error"; }
pass "rollnip --print-parameters exits 0, $(grep -c '^ *set ' all.prm) entries"
for section in Geometry Mesh Material Discretization 'Boundary conditions' \
               Load 'Load stepping' 'Nonlinear solver' 'Linear solver' Output; do
  grep -q "^subsection $section\$" all.prm ||
    fail "--print-parameters does not list subsection '$section'"
done
pass "the subsections Geometry ... Output are listed ($(grep -c '^subsection ' all.prm) in all)"

rc=0
"$rollnip" --validate all.prm > validate.txt 2> validate.err || rc=$?
cat validate.txt
[ ! -s validate.err ] || cat validate.err
[ "$rc" -eq 0 ] || fail "rollnip --validate on the printed parameters exited with $rc"
pass "rollnip --validate all.prm exits 0"
grep -q "^rollnip: 'all.prm' is valid" validate.txt ||
  fail "rollnip --validate did not say that all.prm is valid"
pass "it says: $(grep "is valid" validate.txt)"
[ ! -s validate.err ] || fail "rollnip --validate wrote to standard error"
pass "nothing on standard error"
