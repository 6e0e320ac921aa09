#!/usr/bin/env bash
# Material/Layer order: the layers of a layered cover are read from the core
# out unless the file says `top first`.
#
# Usage: bash layer_order.sh ROLLNIP LAYERED_PRM
#
# Checks, on parameters/layered_cover.prm (a 3 mm base of G = 5 MPa under
# 10.5 mm of G = 0.6 MPa) at 10 N/mm, mesh level 1:
#   - the file as shipped (Layer order = core first) runs without a warning;
#   - the same cover written top first (lists reversed, Layer order = top
#     first) gives the same nip, P, u0, b and peak pressure to 1e-12;
#   - the lists reversed without saying so give a different cover (the
#     soft layer on the core: u0 differs by more than 5 %; measured 8 %) and exactly one
#     `rollnip: warning:` line naming Material/Layer order and the two
#     outer layers;
#   - a hardness per layer written top first gives the core-first nip.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 2 ] || fail "usage: layer_order.sh ROLLNIP LAYERED_PRM"
rollnip="$1"
base_prm="$2"
require_executable rollnip "$rollnip"
start_test layer_order

# variant NAME ORDER C1 C2 THICKNESSES [HARDNESS]
variant()
{
  local name="$1" order="$2" c1="$3" c2="$4" t="$5" hardness="${6:-}"
  sed -e '/set Layer order/d' -e '/set C1 /d' -e '/set C2 /d' -e '/set Layer thicknesses/d' \
    -e 's|^\( *set Global refinements *=\).*|\1 1|' \
    -e 's|^\( *set Values *=\).*|\1 10|' \
    -e "s|^\\( *set Directory *=\\).*|\\1 $name|" "$base_prm" >"$name.prm"
  {
    echo "subsection Material"
    [ -n "$order" ] && echo "  set Layer order = $order"
    if [ -n "$hardness" ]; then
      echo "  set Hardness = $hardness"
    else
      echo "  set C1 = $c1"
      echo "  set C2 = $c2"
    fi
    echo "  set Layer thicknesses = $t"
    echo "end"
  } >>"$name.prm"
  "$rollnip" "$name.prm" >"$name.log" 2>"$name.err" || { cat "$name.err"; fail "$name run failed"; }
}

variant core "core first" "2.0, 0.25" "0.5, 0.05" "3, 10.5"
[ ! -s core.err ] || { cat core.err; fail "core first: stderr not empty"; }
pass "core first: no warning"
variant top "top first" "0.25, 2.0" "0.05, 0.5" "10.5, 3"
variant unstated "" "0.25, 2.0" "0.05, 0.5" "10.5, 3"
[ "$(wc -l <unstated.err)" -eq 1 ] && grep -q "^rollnip: warning: Material/Layer order is not stated.*layer 1 (10.5 mm, G = 0.6 MPa) on the core, layer 2 (3 mm, G = 5 MPa) the surface" unstated.err ||
  { cat unstated.err; fail "unstated order: not one warning naming Material/Layer order and the layers"; }
pass "unstated order: $(cat unstated.err)"
variant hard_core "core first" "" "" "3, 10.5" "90, 60"
variant hard_top "top first" "" "" "10.5, 3" "60, 90"

python3 - <<'PY' || fail "layer order numbers"
import csv, sys
def row(d):
    return list(csv.DictReader(open(f"{d}/nip_characteristic.csv")))[0]
def check(ok, message):
    print(("ok:   " if ok else "FAIL: ") + message)
    if not ok:
        sys.exit(1)
keys = ["P_N_per_mm", "u0_mm", "half_chord_mm", "peak_pressure_MPa"]
for a, b in (("core", "top"), ("hard_core", "hard_top")):
    worst = max(abs(float(row(a)[k]) / float(row(b)[k]) - 1) for k in keys)
    check(worst <= 1e-12, f"{b} = {a}: P, u0, b, peak pressure within {worst:.1e}")
d = abs(float(row("unstated")["u0_mm"]) / float(row("core")["u0_mm"]) - 1)
check(d > 0.05, f"the reversed lists unstated are another cover: u0 differs by {100 * d:.0f} %")
PY
