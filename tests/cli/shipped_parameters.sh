#!/usr/bin/env bash
# A parameter file shipped in parameters/ runs as a user runs it (exit code
# 0, nothing on standard error), on a small mesh, and its headline numbers
# match the values pinned in data/shipped/NAME.expected.
#
# NAME.expected: '#' comments, one line 'global_refinements N', then lines
#   FILE  KEY  EXPECTED  RELATIVE_TOLERANCE
# FILE is relative to the run's output directory; KEY is the name of a
# 'key = value' line of a .txt file, or COLUMN[ROW] of a .csv table (ROW
# counts the data rows from 1). Every contact.txt and nip_report.csv the run
# writes, and a summary.txt at the top of the output, must be pinned, so a
# nip added to the file cannot go unchecked.
#
# Usage: bash shipped_parameters.sh ROLLNIP PRM [--update]
# --update writes the values of this run into the EXPECTED column (after a
# deliberate change of the results; say why in the commit).
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 2 ] || { [ $# -eq 3 ] && [ "$3" = --update ]; } ||
  fail "usage: shipped_parameters.sh ROLLNIP PRM [--update]"
require_executable rollnip "$1"
[ -f "$2" ] || fail "no parameter file '$2'"
# Absolute paths: start_test changes into the working directory.
rollnip="$(realpath "$1")"
prm="$(realpath "$2")"
update="${3:-}"
name="$(basename "$prm" .prm)"
expected="$(realpath "$(dirname "${BASH_SOURCE[0]}")")/data/shipped/$name.expected"
[ -f "$expected" ] ||
  fail "no expected values for parameters/$name.prm: add tests/cli/data/shipped/$name.expected"
level="$(awk '$1 == "global_refinements" { print $2; ++n } END { exit n != 1 }' \
           "$expected")" ||
  fail "$expected needs exactly one line 'global_refinements N'"
start_test "shipped-$name"

# A second Mesh and Output block at the end: ParameterHandler keeps the
# later value, so the shipped file itself is run otherwise unchanged.
cp "$prm" "$name.prm"
printf '\nsubsection Mesh\n  set Global refinements = %s\nend\n' "$level" >> "$name.prm"
# A covered mating roll has a mesh of its own: the same level for it.
if grep -q "^subsection Mating roll" "$name.prm"; then
  printf 'subsection Mating roll\n  subsection Mesh\n    set Global refinements = %s\n  end\nend\n' \
    "$level" >> "$name.prm"
fi
printf 'subsection Output\n  set Directory = output\nend\n' >> "$name.prm"

rc=0
"$rollnip" "$name.prm" > stdout.txt 2> stderr.txt || rc=$?
[ "$rc" -eq 0 ] || { cat stderr.txt; fail "exit code $rc, expected 0"; }
pass "$name.prm runs at Global refinements = $level, exit code 0"
[ ! -s stderr.txt ] || { cat stderr.txt; fail "standard error is not empty"; }
pass "nothing on standard error"
n="$(find output -name summary.txt | wc -l)"
[ "$n" -ge 1 ] || fail "no summary.txt written under output/"
pass "$n summary.txt file(s) written"

# result_value FILE KEY: 'KEY = value' of a .txt file, COLUMN[ROW] of a .csv.
result_value()
{
  case "$1" in
    *.csv)
      [[ "$2" =~ ^([A-Za-z0-9_]+)\[([0-9]+)\]$ ]] ||
        fail "key '$2' for $1 is not COLUMN[ROW]"
      csv_value "$1" "${BASH_REMATCH[1]}" "${BASH_REMATCH[2]}" ;;
    *) summary_value "$1" "$2" ;;
  esac
}

while IFS= read -r f; do
  f="${f#output/}"
  awk -v f="$f" '$1 == f { found = 1 } END { exit !found }' "$expected" ||
    fail "output/$f is written but $expected pins nothing in it"
done < <(find output \( -name contact.txt -o -name nip_report.csv \
                        -o -path output/summary.txt \) | sort)

checks=0
updated=expected.new
while IFS= read -r line; do
  read -r file key value tol extra <<< "$line"
  case "$file" in
    '' | '#'* | global_refinements)
      [ -z "$update" ] || printf '%s\n' "$line" >> "$updated"
      continue ;;
  esac
  if [ -z "$tol" ] || [ -n "$extra" ]; then
    fail "$expected: not 'FILE KEY EXPECTED TOL': $line"
  fi
  [ -f "output/$file" ] || fail "no output/$file (pinned in $expected)"
  actual="$(result_value "output/$file" "$key")"
  if [ -n "$update" ]; then
    printf '%-26s %-38s %-14s %s\n' "$file" "$key" "$actual" "$tol" >> "$updated"
  else
    check_rel_close "$file $key" "$actual" "$value" "$tol"
  fi
  checks=$((checks + 1))
done < "$expected"
[ "$checks" -ge 1 ] || fail "$expected pins no value"
if [ -n "$update" ]; then
  mv "$updated" "$expected"
  pass "$checks values written to $expected"
else
  pass "$checks values as pinned in $(basename "$expected")"
fi
