#!/usr/bin/env bash
# nip-NN directories of an earlier, longer sweep in the output directory
# are removed (and named on the screen) when a shorter sweep starts, so
# that every nip-NN beside the new nip_characteristic.csv is of this run:
# three nips, then two (nip-03 goes), then one (written to the directory
# itself: nip-01 and nip-02 go).
#
# Usage: bash stale_nips.sh ROLLNIP NIP_ANGLE_PRM
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

scene_test_args stale_nips NIP_ANGLE_PRM "$@"

# sweep VALUES: the scene on a small mesh at these nip angles, into out/.
sweep()
{
  cp "$scene" run.prm
  cat >> run.prm <<PRM
subsection Mesh
  set Global refinements = 0
end
subsection Contact
  set Values                     = $1
  set Compare with linear theory = false
end
subsection Accuracy
  set Error estimate = false
end
PRM
  quiet_output >> run.prm
  "$rollnip" run.prm > stdout.txt 2> stderr.txt || {
    cat stderr.txt
    fail "the sweep at $1 deg failed"
  }
}
listing() { (cd out && find . -maxdepth 1 -name 'nip-*' -type d | sort | tr '\n' ' '); }

sweep "4, 5, 6"
[ "$(listing)" = "./nip-01 ./nip-02 ./nip-03 " ] || fail "three nips: $(listing)"
sweep "4, 5"
grep -q "^Output: removed 1 nip directory of an earlier run from 'out' (nip-03), beyond the 2 of this run" stdout.txt ||
  fail "the removal is not named"
[ "$(listing)" = "./nip-01 ./nip-02 " ] || fail "after two nips: $(listing)"
[ "$(($(wc -l < out/nip_characteristic.csv) - 1))" -eq 2 ] || fail "two rows expected"
pass "two nips after three: nip-03 removed and named"
sweep "4"
grep -q "^Output: removed 2 nip directories of an earlier run from 'out' (nip-01 .. nip-02), beyond the 0 of this run" stdout.txt ||
  fail "the removal is not named"
[ -z "$(listing)" ] || fail "after one nip: $(listing)"
pass "one nip after two: nip-01 and nip-02 removed and named"
