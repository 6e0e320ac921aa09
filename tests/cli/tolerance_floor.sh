#!/usr/bin/env bash
# Tolerances below round-off: Contact/Control tolerance = 0, Conformity
# tolerance = 1e-16 and the Newton tolerances = 0 are raised to the floors
# of doc/robustness.md with one warning line each (exit 0), and the
# load-controlled nip reaches its target to the raised Control tolerance
# (before, 1e-15 read as "out of reach" and 0 as "the outer surface has no
# node on the line of centres").
#
# Usage: bash tolerance_floor.sh ROLLNIP LOAD_PRM
#   LOAD_PRM  parameters/load_controlled.prm
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

scene_test_args tolerance_floor LOAD_PRM "$@"

cp "$scene" run.prm
cat >> run.prm <<PRM

# --- overrides of tests/cli/tolerance_floor.sh
subsection Mesh
  set Global refinements = 1
end
subsection Nonlinear solver
  set Residual tolerance   = 0
  set Increment tolerance  = 0
  set Constraint tolerance = 0
end
subsection Contact
  set Values                     = 10
  set Control tolerance          = 0
  set Conformity tolerance       = 1e-16
  set Compare with linear theory = false
end
subsection Accuracy
  set Error estimate = false
end
PRM
quiet_output >> run.prm

rc=0
"$rollnip" run.prm > stdout.txt 2> stderr.txt || rc=$?
echo "--- standard error:"
cat stderr.txt
echo "---"
[ "$rc" -eq 0 ] || { tail -5 stdout.txt; fail "exit code $rc, expected 0"; }
pass "exit code 0"
for entry in "Nonlinear solver/Residual tolerance = 0" \
  "Nonlinear solver/Increment tolerance = 0" \
  "Nonlinear solver/Constraint tolerance = 0" \
  "Contact/Conformity tolerance = 1e-16" "Contact/Control tolerance = 0"; do
  grep -q "^rollnip: warning: $entry is below what double precision resolves; using 2.22e-1[02]" stderr.txt ||
    fail "no warning for $entry"
done
[ "$(wc -l < stderr.txt)" -eq 5 ] || fail "expected five warning lines"
pass "five one-line warnings naming the entries and the floors"
P="$(csv_value out/nip_characteristic.csv P_N_per_mm 1)"
# The CSV carries 10 digits: 1e-9 is what it can show of the 2.22e-10.
awk -v p="$P" 'BEGIN { e = p / 10 - 1; if (e < 0) e = -e; exit !(e <= 1e-9) }' ||
  fail "P = $P N/mm, not 10 N/mm to the CSV's 10 digits"
pass "P = $P N/mm: the target 10 N/mm to the CSV's 10 digits"
