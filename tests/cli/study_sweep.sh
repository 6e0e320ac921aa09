#!/usr/bin/env bash
# The study mode over a sweep (Study/Values): parameters/engineering_nip.prm
# at 20 and 60 kN/m, levels 0, 1, 2.
#
# Usage: bash study_sweep.sh ROLLNIP ENGINEERING_PRM PLOT_STUDY_SH
#
# Checks, against independent expectations:
#   - every value of Contact/Values is studied (not only the first), and the
#     screen says which nip and load each run is ("Study: nip 2 of 2, P =
#     60 kN/m, Q1-P0, level 1");
#   - study.csv has the nip and the prescribed load in kN/m, 2 nips x 3
#     levels, and each row's computed P equals its prescribed load (load
#     control, Contact/Control tolerance 1e-6);
#   - the study's level-2 run of 60 kN/m is the nip of an ordinary run of
#     the file at 60 kN/m (same mesh level): the same half-width b and u0
#     to 1e-5 (both within the control tolerance of the same target);
#   - Study/Values = 60 studies that nip alone, with the same numbers as
#     nip 2 of the whole sweep (1e-9);
#   - plot_study.sh draws one curve per nip, labelled by its load.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 3 ] || fail "usage: study_sweep.sh ROLLNIP ENGINEERING_PRM PLOT_STUDY_SH"
rollnip="$1"
base_prm="$2"
plot_study="$3"
require_executable rollnip "$rollnip"
start_test study_sweep

write_prm() # FILE DIRECTORY [EXTRA...]
{
  local file="$1" dir="$2"
  shift 2
  cp "$base_prm" "$file"
  cat >>"$file" <<PRM
subsection Contact
  set Values = 20, 60
end
subsection Output
  set Directory = $dir
  set Write VTU = false
end
PRM
  for extra in "$@"; do printf '%s\n' "$extra" >>"$file"; done
}

write_prm study.prm out_study "subsection Study" "  set Refinement levels = 0, 1, 2" "end"
"$rollnip" study.prm >log.txt 2>&1 || { tail -20 log.txt; fail "study run failed"; }
grep -q '^Study: nip 1 of 2, P = 20 kN/m, Q1-P0, level 0$' log.txt ||
  fail "the screen does not say 'Study: nip 1 of 2, P = 20 kN/m, Q1-P0, level 0'"
grep -q '^Study: nip 2 of 2, P = 60 kN/m, Q1-P0, level 2$' log.txt ||
  fail "the screen does not say 'Study: nip 2 of 2, P = 60 kN/m, Q1-P0, level 2'"
pass "the screen names each nip and its load"

write_prm single.prm out_single "subsection Study" "  set Refinement levels = 0, 1, 2" \
  "  set Values = 60" "end"
"$rollnip" single.prm >log_single.txt 2>&1 || { tail -20 log_single.txt; fail "Study/Values = 60 run failed"; }
grep -q '^Study: nip 1 of 1, P = 60 kN/m, Q1-P0, level 2$' log_single.txt ||
  fail "Study/Values = 60: the screen does not say 'nip 1 of 1, P = 60 kN/m'"

write_prm plain.prm out_plain "subsection Accuracy" "  set Error estimate = false" "end"
"$rollnip" plain.prm >log_plain.txt 2>&1 || { tail -20 log_plain.txt; fail "ordinary run failed"; }

python3 - <<'PY' || fail "study sweep checks"
import csv, sys
def rows(path):
    return list(csv.DictReader(open(path)))
def check(ok, message):
    print(("ok:   " if ok else "FAIL: ") + message)
    if not ok:
        sys.exit(1)
study = rows("out_study/study.csv")
check(len(study) == 6, f"{len(study)} rows for 2 nips x 3 levels")
check([r["nip"] for r in study] == ["1"] * 3 + ["2"] * 3, "nip column 1, 1, 1, 2, 2, 2")
check([float(r["prescribed_line_load_kN_per_m"]) for r in study] == [20.0] * 3 + [60.0] * 3,
      "prescribed_line_load_kN_per_m 20 then 60")
for r in study:
    d = abs(float(r["P_N_per_mm"]) / float(r["prescribed_line_load_kN_per_m"]) - 1)
    check(d < 2e-6, f"nip {r['nip']} level {r['level']}: P = {r['P_N_per_mm']} N/mm is the prescribed load ({d:.1e})")
plain = rows("out_plain/nip_characteristic.csv")[1]
mine = [r for r in study if r["nip"] == "2" and r["level"] == "2"][0]
for key in ("half_chord_mm", "u0_mm"):
    a, b = float(mine[key]), float(plain[key])
    check(abs(a / b - 1) < 1e-5, f"60 kN/m level 2: study {key} {a} = ordinary run {b} ({abs(a / b - 1):.1e})")
single = rows("out_single/study.csv")
check(len(single) == 3 and all(r["prescribed_line_load_kN_per_m"] == "60" for r in single),
      "Study/Values = 60: 3 rows, all at 60 kN/m")
for s, w in zip(single, [r for r in study if r["nip"] == "2"]):
    for key in ("P_N_per_mm", "half_chord_mm", "peak_pressure_MPa"):
        d = abs(float(s[key]) / float(w[key]) - 1)
        check(d < 1e-9, f"Study/Values = 60, level {s['level']}: {key} as nip 2 of the sweep ({d:.1e})")
PY
text="$(cat out_study/study.txt)"
[[ "$text" == *"Refinement study, nip 2 (P = 60 kN/m), Q1-P0"* ]] ||
  fail "study.txt has no table headed 'nip 2 (P = 60 kN/m)'"
pass "study.txt has a table per nip"

bash "$plot_study" out_study >/dev/null || fail "plot_study.sh failed"
[ -s out_study/plots/study_front.png ] || fail "study_front.png missing"
grep -q 'P = 60 kN/m, Q1-P0: P' out_study/plots/study_front.svg ||
  fail "the front plot has no curve labelled 'P = 60 kN/m, Q1-P0: P'"
pass "front plot: one curve per nip, labelled by its load"
