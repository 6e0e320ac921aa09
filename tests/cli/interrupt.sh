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
