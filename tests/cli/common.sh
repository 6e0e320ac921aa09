# shellcheck shell=bash
# Helpers shared by the command-line test scripts of tests/cli (sourced, not
# run). Every script calls start_test first: it makes a fresh working
# directory, cds into it, and removes it again when the script succeeds (it
# is kept, and its path printed, when a check fails).

# fail MESSAGE...: print the message and stop the test with exit code 1.
fail()
{
  echo "FAIL: $*" >&2
  exit 1
}

# pass MESSAGE...: report a check that held.
pass()
{
  echo "ok:   $*"
}

# EXIT trap of start_test: remove the working directory if all went well.
finish_test()
{
  local exit_code=$?
  if [ "$exit_code" -eq 0 ]; then
    rm -rf "$work_dir"
  else
    echo "(files kept in $work_dir)" >&2
  fi
}

# start_test NAME: fresh temporary working directory, cleaned up on success.
start_test()
{
  test_name="$1"
  work_dir="$(mktemp -d "${TMPDIR:-/tmp}/rollnip-${test_name}.XXXXXX")"
  trap finish_test EXIT
  cd "$work_dir" || exit 1
  echo "test $test_name in $work_dir"
}

# require_executable NAME PATH: PATH must be an executable file.
require_executable()
{
  if [ -z "$2" ] || [[ "$2" == *NOTFOUND ]] || [ ! -x "$2" ]; then
    fail "$1 not found (got '$2'); install it or tell CMake where it is"
  fi
}

# summary_value FILE KEY: the value of 'KEY = value' in a summary.txt.
summary_value()
{
  local value
  value="$(awk -v key="$2" -F' = ' '$1 == key { print $2; found = 1 }
                                     END { exit !found }' "$1")" ||
    fail "'$2' missing from $1"
  echo "$value"
}

# csv_value FILE COLUMN ROW: the value in the first column named COLUMN of
# a CSV table with a header line (ROW counts the data rows from 1).
csv_value()
{
  local value
  value="$(awk -F, -v name="$2" -v row="$3" '
             NR == 1 { for (i = NF; i >= 1; --i) if ($i == name) c = i }
             c && NR == row + 1 { print $c; found = 1 }
             END { exit !found }' "$1")" ||
    fail "no column '$2' with a row $3 in $1"
  echo "$value"
}

# check_abs_below NAME VALUE LIMIT: |VALUE| < LIMIT.
check_abs_below()
{
  if awk -v v="$2" -v l="$3" 'BEGIN { exit !((v < 0 ? -v : v) < l) }'; then
    pass "|$1| = |$2| < $3"
  else
    fail "|$1| = |$2| is not below $3"
  fi
}

# check_close NAME VALUE EXPECTED ABS_TOL: |VALUE - EXPECTED| <= ABS_TOL.
check_close()
{
  if awk -v v="$2" -v e="$3" -v t="$4" \
       'BEGIN { d = v - e; exit !((d < 0 ? -d : d) <= t) }'; then
    pass "$1 = $2, expected $3 within $4"
  else
    fail "$1 = $2, expected $3 within $4"
  fi
}

# check_rel_close NAME VALUE EXPECTED REL_TOL: |VALUE/EXPECTED - 1| <= REL_TOL.
check_rel_close()
{
  if awk -v v="$2" -v e="$3" -v t="$4" \
       'BEGIN { d = v / e - 1; exit !((d < 0 ? -d : d) <= t) }'; then
    pass "$1 = $2, expected $3 within relative $4"
  else
    fail "$1 = $2, expected $3 within relative $4"
  fi
}

# check_less NAME VALUE LIMIT: VALUE < LIMIT.
check_less()
{
  if awk -v v="$2" -v l="$3" 'BEGIN { exit !(v < l) }'; then
    pass "$1 = $2 < $3"
  else
    fail "$1 = $2 is not below $3"
  fi
}
