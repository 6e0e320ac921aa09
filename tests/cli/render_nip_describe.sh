#!/usr/bin/env bash
# The parts of scripts/render_nip.py that need no ParaView (its --describe
# mode and its helpers), run with python3 where pvpython is missing too:
# the title, the nip it frames, the scale bar and the rounded colour-bar
# limits.
#
# Usage: bash render_nip_describe.sh ROLLNIP RENDER_SCRIPT
#
# Checks:
#   - on a 40 kN/m nip (the quick form of engineering_nip.prm's roll) the
#     title gives the load in kN/m, the nip width and indentation of
#     nip_report.csv, the roll diameter and a rigid mating roll;
#   - the framed half-width b is that of nip_report.csv (2b / 2, 1e-6);
#   - the frame is centred on the nip and the scale bar is a round length
#     (1, 2 or 5 x 10^k mm) between a tenth and half of the frame's width;
#   - the colour-bar limits are round and contain the data: 2.8e-06 to
#     2.4731 becomes 0 to 2.5, -1.83 to 0.02 becomes -2 to 0.5.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 2 ] || fail "usage: render_nip_describe.sh ROLLNIP RENDER_SCRIPT"
rollnip="$1"
script="$2"
require_executable rollnip "$rollnip"
start_test render_nip_describe

"$rollnip" nip --diameter 250 --cover 13.5 --hardness 60A --mate 300 --load 40kN/m \
  --output out >run.log 2>&1 || { tail run.log; fail "the nip run failed"; }
python3 "$script" --describe out --size 1200x800 >describe.txt || fail "--describe failed"
cat describe.txt
python3 - "$script" <<'PY' || fail "render_nip.py description"
import csv, importlib.util, math, re, sys
spec = importlib.util.spec_from_file_location("render_nip", sys.argv[1])
render = importlib.util.module_from_spec(spec)
spec.loader.exec_module(render)
def check(ok, message):
    print(("ok:   " if ok else "FAIL: ") + message)
    if not ok:
        sys.exit(1)
text = open("describe.txt").read()
row = list(csv.DictReader(open("out/nip_report.csv")))[0]
width = float(row["nip_width_2b_mm"])
title = text.splitlines()[0]
for part in ("P = 40 kN/m", f"nip width 2b = {width:.4g} mm",
             f"indentation {float(row['indentation_u0_mm']):.3g} mm", "roll \u00d8250 mm",
             "against a rigid roll"):
    check(part in title, f"title has '{part}'")
b = float(re.search(r"half-width b = (\S+) mm", text).group(1))
check(abs(2 * b / width - 1) < 1e-6, f"framed half-width {b} mm = 2b/2 of nip_report.csv ({width / 2})")
frame = float(re.search(r"frame: (\S+) mm wide", text).group(1))
check(abs(frame - 2 * 1.5 * b * 1200 / 800) < 1e-6 * frame, f"frame {frame} mm = 2 zoom b x aspect")
bar = float(re.search(r"scale bar (\S+) mm", text).group(1))
mantissa = bar / 10 ** math.floor(math.log10(bar))
check(any(abs(mantissa - m) < 1e-9 for m in (1, 2, 5)) and frame / 10 <= bar <= frame / 2,
      f"scale bar {bar:g} mm: round, between a tenth and half of the frame")
for lo, hi, expected in ((2.8e-06, 2.4731, (0.0, 2.5)), (-1.83, 0.02, (-2.0, 0.5)),
                         (0.98, 1.02, (0.98, 1.02))):
    got = render.nice_range(lo, hi)
    check(all(abs(g - e) < 1e-12 for g, e in zip(got, expected)) and got[0] <= lo and got[1] >= hi,
          f"colour bar {lo:g} to {hi:g} -> {got[0]:g} to {got[1]:g}")
PY
