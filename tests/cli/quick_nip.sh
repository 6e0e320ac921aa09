#!/usr/bin/env bash
# The quick form `rollnip nip ...`, the README's minimal template and
# scripts/run.sh called from another directory.
#
# Usage: bash quick_nip.sh ROLLNIP REPOSITORY_ROOT
#
# Checks:
#   - the quick form of parameters/engineering_nip.prm (250 mm roll,
#     13.5 mm of 60 Shore A, 300 mm mate, 20, 40, 60 kN/m, 600 m/min)
#     prints the nip report and gives the nip report of that file, every
#     number to 1e-9: it builds the same scene;
#   - the file it writes (--write-prm), run as an ordinary parameter file,
#     gives its numbers to 1e-12;
#   - the same nip in inches, pli and fpm (40 kN/m = 228.40584 pli,
#     600 m/min = 1968.5039 fpm) gives 2b and u0 to 1e-5 and the dwell time
#     to 1e-5 (unit conversions of the flags);
#   - bad flags end with exit 1 and one line `rollnip: error:` naming the
#     flag;
#   - the README's template runs and its nip (the default, coarser mesh)
#     agrees with the quick form of the same nip within three times the
#     sum of their estimated errors;
#   - scripts/run.sh, called from a temporary directory with a relative
#     parameter file and a relative Output/Directory, writes there and not
#     into the repository.
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 2 ] || fail "usage: quick_nip.sh ROLLNIP REPOSITORY_ROOT"
rollnip="$1"
root="$2"
require_executable rollnip "$rollnip"
start_test quick_nip

"$rollnip" nip --diameter 250 --cover 13.5 --hardness 60A --mate 300 \
  --load 20,40,60kN/m --speed 600m/min --output quick --write-prm quick.prm \
  >quick.log 2>quick.err || { cat quick.err; fail "quick form failed"; }
[ ! -s quick.err ] || { cat quick.err; fail "quick form wrote to stderr"; }
grep -q '^Nip report' quick.log || fail "the quick form printed no nip report"
grep -q '^ *60.000 ' quick.log || fail "the nip report has no 60 kN/m row"
pass "quick form: nip report printed, 3 nips"

sed 's|^\( *set Directory *=\).*|\1 from_file|' quick.prm >from_file.prm
"$rollnip" from_file.prm >from_file.log 2>&1 || fail "the written file did not run"
sed 's|^\( *set Directory *=\).*|\1 shipped|' "$root/parameters/engineering_nip.prm" >shipped.prm
"$rollnip" shipped.prm >shipped.log 2>&1 || fail "engineering_nip.prm did not run"

"$rollnip" nip --diameter 9.842519685in --cover 0.531496063in --hardness 60 \
  --mate 11.81102362in --load 228.40584 pli --speed=1968.503937fpm --output us \
  >us.log 2>&1 || { tail us.log; fail "quick form in inches, pli and fpm failed"; }

python3 - <<'PY' || fail "quick form numbers"
import csv, sys
def rows(path):
    return list(csv.DictReader(open(path)))
def check(ok, message):
    print(("ok:   " if ok else "FAIL: ") + message)
    if not ok:
        sys.exit(1)
keys = ["line_load_N_per_mm", "nip_width_2b_mm", "indentation_u0_mm", "peak_pressure_MPa",
        "mean_pressure_MPa", "dwell_time_ms", "youngs_modulus_E_MPa", "nip_width_2b_err_mm"]
quick, written, shipped = (rows(f"{d}/nip_report.csv") for d in ("quick", "from_file", "shipped"))
check(len(quick) == 3, "3 nips")
for name, other, tol in (("engineering_nip.prm", shipped, 1e-9), ("the written file", written, 1e-12)):
    worst = max(abs(float(q[k]) / float(o[k]) - 1) for q, o in zip(quick, other) for k in keys)
    check(worst <= tol, f"quick form = {name}: largest relative difference {worst:.1e} <= {tol:g}")
us = rows("us/nip_report.csv")[0]
check("line_load_pli" in us and abs(float(us["line_load_pli"]) / 228.40584 - 1) < 1e-6,
      f"pli run reports its load in pli ({us.get('line_load_pli')})")
for k in ("nip_width_2b_mm", "indentation_u0_mm", "dwell_time_ms"):
    d = abs(float(us[k]) / float(quick[1][k]) - 1)
    check(d < 1e-5, f"inches/pli/fpm: {k} {us[k]} = {quick[1][k]} at 40 kN/m ({d:.1e})")
PY

bad_flag() # REGEX ARGS...: exit 1, one stderr line naming the flag
{
  local regex="$1" code=0
  shift
  "$rollnip" nip "$@" >bad.out 2>bad.err || code=$?
  [ "$code" -eq 1 ] || fail "rollnip nip $*: exit code $code, not 1"
  [ "$(wc -l <bad.err)" -eq 1 ] || { cat bad.err; fail "rollnip nip $*: not one stderr line"; }
  grep -Eq "^rollnip: error: .*$regex" bad.err ||
    { cat bad.err; fail "rollnip nip $*: the error does not match '$regex'"; }
  pass "rollnip nip $*: $(cat bad.err)"
}
ok=(--cover 20 --hardness 70A --mate 300 --load 40kN/m)
bad_flag "'--diamter'" --diamter 400 "${ok[@]}"
bad_flag "--diameter is missing" "${ok[@]}"
bad_flag "--load: give the unit" --diameter 400 --cover 20 --hardness 70A --mate 300 --load 40
bad_flag "--load: unknown unit 'kg'" --diameter 400 --cover 20 --hardness 70A --mate 300 --load 40kg
bad_flag "--hardness: unknown scale 'X'" --diameter 400 --cover 20 --hardness 70X --mate 300 --load 40kN/m
bad_flag "--cover: the cover" --diameter 400 --cover 250 --hardness 70A --mate 300 --load 40kN/m
bad_flag "--speed: unknown unit 'knots'" --diameter 400 "${ok[@]}" --speed 3knots
bad_flag "--diameter: 'big'" --diameter big "${ok[@]}"
bad_flag "--hardness or --modulus" --diameter 400 --cover 20 --mate 300 --load 40kN/m

# The README's template: the first code block after '## A first nip'.
awk '/^## A first nip/ { f = 1 } f && /^```/ { n++; next } f && n == 1' "$root/README.md" >my_nip.prm
[ "$(grep -c '^subsection' my_nip.prm)" -eq 3 ] || { cat my_nip.prm; fail "README template not found"; }
"$rollnip" my_nip.prm >template.log 2>&1 || { tail template.log; fail "the README template did not run"; }
"$rollnip" nip --diameter 400 --cover 20 --hardness 70A --mate 300 --load 40kN/m --output q400 \
  >q400.log 2>&1 || fail "quick form of the template's nip failed"
python3 - <<'PY' || fail "template against the quick form"
import csv, sys
t = list(csv.DictReader(open("output/nip_report.csv")))[0]
q = list(csv.DictReader(open("q400/nip_report.csv")))[0]
for k in ("nip_width_2b", "indentation_u0"):
    a, b = float(t[k + "_mm"]), float(q[k + "_mm"])
    bound = 3 * (float(t[k + "_err_mm"]) + float(q[k + "_err_mm"]))
    ok = abs(a - b) <= bound
    print(("ok:   " if ok else "FAIL: ") +
          f"README template {k} {a:.4f} mm, quick form {b:.4f} mm: |difference| {abs(a - b):.4f} <= {bound:.4f} mm")
    if not ok:
        sys.exit(1)
PY

# scripts/run.sh from another directory: relative paths are the caller's.
mkdir -p caller/sub
sed 's|^\( *set Values *=\).*|\1 20|' "$root/parameters/engineering_nip.prm" |
  sed 's|^\( *set Directory *=\).*|\1 results/run_sh|' >caller/sub/run.prm
before="$(ls "$root")"
(cd caller && ROLLNIP_BIN="$rollnip" bash "$root/scripts/run.sh" sub/run.prm >run.log 2>&1) ||
  { tail caller/run.log; fail "scripts/run.sh failed"; }
[ -f caller/results/run_sh/nip_report.csv ] ||
  fail "scripts/run.sh did not write caller/results/run_sh/nip_report.csv"
[ -s caller/results/run_sh/plots/nip_report.png ] || fail "scripts/run.sh drew no plots there"
[ "$(ls "$root")" = "$before" ] && [ ! -e "$root/results" ] ||
  fail "scripts/run.sh wrote into the repository"
grep -q "results are in $PWD/caller/results/run_sh" caller/run.log ||
  fail "scripts/run.sh does not say where the results went"
pass "scripts/run.sh: relative output directory taken from the caller's directory"
