#!/usr/bin/env bash
# SIGINT during a sweep: the run stops at the next load step, writes the
# nips that converged (nip_characteristic.csv whole, with one row each)
# and exits 1 with one line saying where it stopped.
#
# Usage: bash interrupt.sh ROLLNIP LOAD_PRM
#   LOAD_PRM  parameters/load_controlled.prm (a load-controlled sweep)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

scene_test_args interrupt LOAD_PRM "$@"

write_long_sweep "$scene" run.prm
# Interrupt the third nip or a later one.
start_until_nip2 "$rollnip"
kill -INT "$pid"
rc=0
wait "$pid" || rc=$?
echo "--- standard error:"
cat stderr.txt
echo "---"
[ "$rc" -eq 1 ] || fail "exit code $rc, expected 1"
pass "exit code 1"
[ "$(wc -l < stderr.txt)" -eq 1 ] || fail "expected one line on standard error"
line="$(cat stderr.txt)"
[[ "$line" =~ ^rollnip:\ error:.*interrupted\ by\ SIGINT\ during\ nip\ ([0-9]+)\ of\ 30\;\ ([0-9]+)\ converged ]] ||
  fail "the error line does not say where the sweep stopped"
stopped="${BASH_REMATCH[1]}"
converged="${BASH_REMATCH[2]}"
pass "stopped during nip $stopped of 30, $converged converged"
[ "$converged" -eq $((stopped - 1)) ] || fail "converged nips should be $((stopped - 1))"
[ -f out/nip_characteristic.csv ] || fail "out/nip_characteristic.csv not written"
rows=$(($(wc -l < out/nip_characteristic.csv) - 1))
[ "$rows" -eq "$converged" ] ||
  fail "nip_characteristic.csv has $rows rows, expected $converged"
pass "nip_characteristic.csv has one row per converged nip ($rows)"
for n in $(seq 1 "$converged"); do
  d="out/nip-$(printf %02d "$n")"
  [ "$(summary_value "$d/summary.txt" status)" = converged ] ||
    fail "$d/summary.txt is not a converged nip"
done
pass "nip-01 .. nip-$(printf %02d "$converged") are converged and whole"

# The same during an extrapolated accuracy target, whose two coarser mesh
# levels solve each nip before the run does: their tables keep the nips
# the run finished, no more (the signal lands in the run's own solve of
# nip 3, after they have solved it), and no estimate is reported.
{
  cat "$scene"
  cat <<PRM
subsection Contact
  set Mode   = nip angle
  set Values = $(seq -s ', ' 4 0.5 14)
  set Compare with linear theory = false
end
subsection Accuracy
  set Target            = 0.1 %
  set Target quantities = P
end
PRM
  quiet_output
} > run.prm
start_until_nip2 "$rollnip"
# Into the run's own solve of nip 3, which the coarser levels have solved.
for _ in $(seq 1 300); do
  awk '/^Nip 2: P from/ { two = 1 } two && /^Contact iteration/ { found = 1 }
       END { exit !found }' stdout.txt && break
  sleep 0.05
done
kill -INT "$pid"
rc=0
wait "$pid" || rc=$?
grep '^Accuracy target' stdout.txt
cat stderr.txt
[ "$rc" -eq 1 ] || fail "target: exit code $rc, expected 1"
grep -q 'extrapolated at order 1 from levels 0 to 2$' stdout.txt ||
  fail "target: the first candidate is not the extrapolated one"
[[ "$(cat stderr.txt)" =~ interrupted\ by\ SIGINT\ during\ nip\ [0-9]+\ of\ 21\;\ ([0-9]+)\ converged ]] ||
  fail "target: the error line does not say where the sweep stopped"
converged="${BASH_REMATCH[1]}"
for table in out/nip_characteristic.csv out/extrapolation/level-{0,1}/nip_characteristic.csv; do
  rows=$(($(wc -l < "$table") - 1))
  [ "$rows" -eq "$converged" ] ||
    fail "target: $table has $rows rows, expected $converged"
done
pass "target: the run's and both coarser levels' tables have the $converged converged nip(s)"
grep -Eq '^Accuracy target: .* nip\(s\)\): stopped$' stdout.txt ||
  fail "target: the attempt's line should end in 'stopped', without an estimate"
[ ! -e out/accuracy_target_values.csv ] ||
  fail "target: accuracy_target_values.csv written for a stopped run"
pass "target: the stopped attempt reports no estimate and no extrapolated values"
