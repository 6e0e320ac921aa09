#!/usr/bin/env bash
# The study mode (Study/Refinement levels) on a small contact scene: the
# run-30 geometry of parameters/batra1980.prm with one nip, theta0 =
# 7.371101 deg (a vertex of the coarse mesh, so a surface node on every
# level: the discrete P(theta0) jumps where theta0 crosses a node, see
# doc/intro.md section 7), levels 0..3.
#
# Usage: bash refinement_study.sh ROLLNIP BATRA_PRM PLOT_STUDY_SH
#
# Checks, against independent expectations:
#   - study.csv has one row per level, with cells x4 and wall time and
#     memory filled in;
#   - the successive differences of P contract and its observed order
#     (printed in study.txt) lies in [0.9, 2.2]: P at a fixed theta0
#     converges at about first order (tests/unit/contact_nip_angle.cc:
#     1.12, 1.17), limited by the square-root edge of the pressure;
#   - the nip half-width b converges faster (it is fixed by theta0 up to the
#     motion of the surface): order in [1.5, 3.5];
#   - the extrapolated P agrees with the limit found from both sides of the
#     node in contact_nip_angle (8.3954 ... 8.3985 N/mm) to 0.1 %;
#   - plot_study.sh draws the speed-accuracy front (a non-empty PNG);
#   - variants (Study/Sector angles = 90, 180 and Initial load steps = 1,
#     10 at levels 0, 1): one row per variant and level; the number of
#     initial load steps does not change the converged state (hyperelastic,
#     path independent: P agrees to 1e-6); the 90 deg sector agrees with the
#     half roll to 0.1 % in P (tests/unit/sector_truncation.cc measured
#     0.01 %); the half roll has more cells and 1 initial step fewer load
#     steps than 10 (the settings were applied); and the comparison block of
#     study.txt lists all four.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 3 ] || fail "usage: refinement_study.sh ROLLNIP BATRA_PRM PLOT_STUDY_SH"
rollnip="$1"
base_prm="$2"
plot_study="$3"
require_executable rollnip "$rollnip"
start_test refinement_study

cp "$base_prm" study.prm
cat >>study.prm <<PRM
subsection Contact
  set Values = 7.371101
  set Conformity tolerance = 1e-7
end
subsection Study
  set Refinement levels = 0, 1, 2, 3
end
subsection Output
  set Directory = out
  set Write VTU = false
end
PRM
"$rollnip" study.prm >log.txt 2>&1 || { tail -20 log.txt; fail "rollnip study run failed"; }
[ -f out/study.csv ] && [ -f out/study.txt ] || fail "study.csv or study.txt missing"
pass "study.csv and study.txt written"

# The Python checks below start with this: the study's rows and text, and
# check(), which prints and stops at the first failure.
cat >study_checks.py <<'PY'
import csv, sys
rows = list(csv.DictReader(open(sys.argv[1])))
text = open(sys.argv[2]).read()
def check(ok, message):
    print(("ok:   " if ok else "FAIL: ") + message)
    if not ok:
        sys.exit(1)
PY

python3 - out/study.csv out/study.txt <<'PY' || fail "study table checks"
import re
exec(open("study_checks.py").read())
check(len(rows) == 4, f"{len(rows)} rows for 4 levels")
cells = [int(r["cells"]) for r in rows]
check(all(b == 4 * a for a, b in zip(cells, cells[1:])), f"cells {cells} grow x4")
check(all(float(r["wall_s"]) > 0 and float(r["process_peak_memory_MB"]) > 0 for r in rows),
      "wall time and memory recorded")
P_levels = [float(r["P_N_per_mm"]) for r in rows]
d = [abs(b - a) for a, b in zip(P_levels, P_levels[1:])]
check(all(b < a for a, b in zip(d, d[1:])), f"successive differences of P contract: {d}")
orders = dict(re.findall(r"^  (P|b) \[[^]]*\]\s+\S+\s+order (\S+)", text, re.M))
check("P" in orders and 0.9 <= float(orders["P"]) <= 2.2, f"observed order of P {orders.get('P')} in [0.9, 2.2]")
check("b" in orders and 1.5 <= float(orders["b"]) <= 3.5, f"observed order of b {orders.get('b')} in [1.5, 3.5]")
P = float(re.search(r"^  P \[N/mm\]\s+(\S+)", text, re.M).group(1))
check(abs(P / 8.397 - 1) < 1e-3, f"extrapolated P = {P} N/mm within 0.1 % of 8.397 N/mm")
PY

bash "$plot_study" out >/dev/null || fail "plot_study.sh failed"
[ -s out/plots/study_front.png ] || fail "study_front.png missing or empty"
pass "speed-accuracy front drawn"

cp "$base_prm" variants.prm
cat >>variants.prm <<PRM
subsection Contact
  set Values = 7.371101
end
subsection Study
  set Refinement levels = 0, 1
  set Sector angles = 90, 180
  set Initial load steps = 1, 10
end
subsection Output
  set Directory = out_variants
  set Write VTU = false
end
PRM
"$rollnip" variants.prm >log_variants.txt 2>&1 ||
  { tail -20 log_variants.txt; fail "rollnip study with variants failed"; }
python3 - out_variants/study.csv out_variants/study.txt <<'PY' || fail "study variant checks"
exec(open("study_checks.py").read())
check(len(rows) == 8, f"{len(rows)} rows for 2 sectors x 2 step counts x 2 levels")
P = {(float(r["sector_deg"]), int(r["initial_steps"]), int(r["level"])): float(r["P_N_per_mm"]) for r in rows}
for s in (90.0, 180.0):
    for l in (0, 1):
        d = abs(P[(s, 1, l)] / P[(s, 10, l)] - 1)
        check(d < 1e-6, f"sector {s}, level {l}: 1 and 10 initial steps give P within {d:.2e} < 1e-6")
for l in (0, 1):
    d = abs(P[(90.0, 10, l)] / P[(180.0, 10, l)] - 1)
    check(d < 1e-3, f"level {l}: 90 deg sector within {100 * d:.3f} % of the half roll (< 0.1 %)")
cells = {(float(r["sector_deg"]), int(r["initial_steps"]), int(r["level"])): int(r["cells"]) for r in rows}
for l in (0, 1):
    check(cells[(180.0, 10, l)] > cells[(90.0, 10, l)],
          f"level {l}: the half roll has more cells ({cells[(180.0, 10, l)]}) than the 90 deg sector ({cells[(90.0, 10, l)]})")
def load_steps(tag):
    for line in open(f"out_variants/study/{tag}/summary.txt"):
        if line.startswith("load_steps ="):
            return int(line.split("=")[1])
n1, n10 = load_steps("Q1-P0-sector-90-steps-1-level-1"), load_steps("Q1-P0-sector-90-steps-10-level-1")
check(n1 < n10, f"1 initial step took fewer load steps ({n1}) than 10 ({n10}): the setting was applied")
block = text.split("Variants compared")[-1]
check(all(f"sector {s} deg, {n} initial load steps" in block for s in (90, 180) for n in (1, 10)),
      "the comparison block lists the four variants")
PY
pass "study variants: sector angles and load-step counts"
