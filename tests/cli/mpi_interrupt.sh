#!/usr/bin/env bash
# Interrupts of a sweep under MPI, and signals in quick succession.
#  1. SIGINT to 'MPIEXEC -np 2' (what Ctrl-C does; Open MPI's mpirun sends
#     SIGTERM to the ranks and SIGKILL a second later): a non-zero exit,
#     the one line of one process (by SIGTERM), and nip_characteristic.csv
#     and nip_report.csv with one row per converged nip.
#  2. Two SIGTERMs 0.2 s apart to mpirun (it then exits at once and the
#     ranks' line may be lost; the ranks may go on for a few nips before
#     they stop, and are waited for): the tables, written after every nip,
#     are still whole and list at least the nips done before the first
#     signal.
#  3. Two SIGINTs 0.2 s apart to one process: the same.
#
# Usage: bash mpi_interrupt.sh ROLLNIP MPIEXEC LOAD_PRM
#   LOAD_PRM  parameters/load_controlled.prm (a load-controlled sweep)
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 3 ] || fail "usage: mpi_interrupt.sh ROLLNIP MPIEXEC LOAD_PRM"
rollnip="$1"
mpiexec="$2"
scene="$3"
require_executable rollnip "$rollnip"
require_executable "mpiexec (MPIEXEC_EXECUTABLE)" "$mpiexec"
[ -f "$scene" ] || fail "parameter file '$scene' not found"
start_test mpi_interrupt

mpi_setup "$mpiexec"
mpi=("$mpiexec" "${mpi_flags[@]}" -np 2)
write_long_sweep "$scene" run.prm

# check_tables AT_LEAST: both tables whole (every row as many fields as the
# header), the same number of rows, at least AT_LEAST, each a converged
# nip-NN; prints the number of rows.
check_tables()
{
  local n=-1 t rows fields
  for t in nip_characteristic nip_report; do
    [ -f "out/$t.csv" ] || fail "out/$t.csv not written"
    fields="$(head -1 "out/$t.csv" | awk -F, '{ print NF }')"
    awk -F, -v f="$fields" 'NF != f { exit 1 }' "out/$t.csv" ||
      fail "out/$t.csv has a row that is not whole"
    rows=$(($(wc -l < "out/$t.csv") - 1))
    [ "$n" -lt 0 ] || [ "$rows" -eq "$n" ] ||
      fail "nip_report.csv has $rows rows, nip_characteristic.csv $n"
    n="$rows"
  done
  [ "$n" -ge "$1" ] || fail "the tables list $n nips, expected at least $1"
  for k in $(seq 1 "$n"); do
    d="out/nip-$(printf %02d "$k")"
    [ "$(summary_value "$d/summary.txt" status)" = converged ] ||
      fail "$d/summary.txt is not a converged nip"
  done
  echo "$n"
}

# wait_for_ranks: after a second SIGTERM mpirun exits at once, and its
# ranks may go on for a few nips in out/ before they stop; wait for every
# rollnip process running in this directory to end (30 s, then SIGKILL),
# so that the next case starts on an empty directory of its own.
wait_for_ranks()
{
  local d left=""
  for _ in $(seq 1 300); do
    left=""
    for d in /proc/[0-9]*; do
      [ "$(cat "$d/comm" 2> /dev/null)" = rollnip ] &&
        [ "$(readlink "$d/cwd" 2> /dev/null)" = "$PWD" ] &&
        left="$left ${d#/proc/}"
    done
    [ -n "$left" ] || return 0
    sleep 0.1
  done
  # shellcheck disable=SC2086
  kill -KILL $left 2> /dev/null || true
}

# 1. One SIGINT to mpirun.
start_until_nip2 "${mpi[@]}" "$rollnip"
kill -INT "$pid"
rc=0
wait "$pid" || rc=$?
echo "--- standard error:"
cat stderr.txt
echo "---"
[ "$rc" -ne 0 ] || fail "exit code 0 after SIGINT"
pass "mpirun: exit code $rc"
# mpirun may add lines of its own (libevent's "[warn] Epoll MOD(1) on fd
# 25 failed ..." as it tears the job down): the ranks' lines are counted.
[ "$(grep -c '^rollnip:' stderr.txt)" -eq 1 ] ||
  fail "expected one line of rollnip on standard error"
line="$(grep '^rollnip:' stderr.txt)"
[[ "$line" =~ ^rollnip:\ error:\ contact:\ interrupted\ by\ SIG(INT|TERM)\ during\ nip\ ([0-9]+)\ of\ 30\;\ ([0-9]+)\ converged ]] ||
  fail "the error line does not say where the sweep stopped"
stopped="${BASH_REMATCH[2]}"
converged="${BASH_REMATCH[3]}"
[ "$converged" -eq $((stopped - 1)) ] || fail "converged nips should be $((stopped - 1))"
rows="$(check_tables 1)"
[ "$rows" -eq "$converged" ] || fail "the tables list $rows nips, the line $converged"
pass "mpirun: stopped during nip $stopped of 30; both tables list the $rows converged nips"
wait_for_ranks

# 2. Two SIGTERMs to mpirun, 0.2 s apart; 3. two SIGINTs to one process.
for launch in mpi single; do
  if [ "$launch" = mpi ]; then
    start_until_nip2 "${mpi[@]}" "$rollnip"
    signal=TERM
  else
    start_until_nip2 "$rollnip"
    signal=INT
  fi
  kill -"$signal" "$pid"
  sleep 0.2
  kill -"$signal" "$pid" 2> /dev/null || true
  rc=0
  wait "$pid" || rc=$?
  [ "$rc" -ne 0 ] || fail "$launch: exit code 0 after two signals"
  wait_for_ranks
  rows="$(check_tables 1)"
  pass "$launch: two SIG$signal 0.2 s apart: exit code $rc, both tables whole with $rows converged nips"
done
