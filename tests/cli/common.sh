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

# An awk function number(x): x is a finite decimal number. mawk takes
# "nan" for a number whose comparisons all hold, so without it a check
# would pass on a nan (or on an empty value against 0).
awk_number='function number(x) {
  return x ~ /^[ \t]*[-+]?([0-9]+[.]?[0-9]*|[.][0-9]+)([eE][-+]?[0-9]+)?[ \t]*$/ }'

# check_abs_below NAME VALUE LIMIT: |VALUE| < LIMIT.
check_abs_below()
{
  if awk -v v="$2" -v l="$3" "$awk_number"'
       BEGIN { exit !(number(v) && (v < 0 ? -v : v) < l) }'; then
    pass "|$1| = |$2| < $3"
  else
    fail "|$1| = |$2| is not below $3"
  fi
}

# check_close NAME VALUE EXPECTED ABS_TOL: |VALUE - EXPECTED| <= ABS_TOL.
check_close()
{
  if awk -v v="$2" -v e="$3" -v t="$4" "$awk_number"'
       BEGIN { d = v - e; exit !(number(v) && number(e) && (d < 0 ? -d : d) <= t) }'; then
    pass "$1 = $2, expected $3 within $4"
  else
    fail "$1 = $2, expected $3 within $4"
  fi
}

# check_rel_close NAME VALUE EXPECTED REL_TOL: |VALUE/EXPECTED - 1| <= REL_TOL
# (VALUE = 0 exactly when EXPECTED is 0).
check_rel_close()
{
  if awk -v v="$2" -v e="$3" -v t="$4" "$awk_number"'
       BEGIN { if (!number(v) || !number(e)) exit 1
               if (e == 0) exit !(v == 0)
               d = v / e - 1; exit !((d < 0 ? -d : d) <= t) }'; then
    pass "$1 = $2, expected $3 within relative $4"
  else
    fail "$1 = $2, expected $3 within relative $4"
  fi
}

# check_less NAME VALUE LIMIT: VALUE < LIMIT.
check_less()
{
  if awk -v v="$2" -v l="$3" "$awk_number"'
       BEGIN { exit !(number(v) && number(l) && v < l) }'; then
    pass "$1 = $2 < $3"
  else
    fail "$1 = $2 is not below $3"
  fi
}

# mpi_setup MPIEXEC: the flags of MPIEXEC in the array mpi_flags. Open MPI
# refuses to start as root unless told (containers, CI), and gets
# --oversubscribe so that two or more ranks start on a one-core machine.
mpi_setup()
{
  if [ "$(id -u)" -eq 0 ]; then
    export OMPI_ALLOW_RUN_AS_ROOT=1 OMPI_ALLOW_RUN_AS_ROOT_CONFIRM=1
  fi
  mpi_flags=()
  local version
  version="$("$1" --version 2>&1 || true)"
  if [[ "$version" == *"Open MPI"* || "$version" == *OpenRTE* ||
        "$version" == *open-mpi* ]]; then
    mpi_flags+=(--oversubscribe)
  fi
}

# quiet_output [DIR]: the .prm lines that send a run's files to DIR
# (default out/), without VTU files or timing tables (what most tests want
# of the output).
quiet_output()
{
  cat <<PRM
subsection Output
  set Directory    = ${1:-out}
  set Write VTU    = false
  set Print timing = false
end
PRM
}

# run_named NAME: runs $rollnip on NAME.prm, its screen into NAME.txt and
# NAME.err; fails, showing NAME.err, if the run is refused or fails.
run_named()
{
  "$rollnip" "$1.prm" > "$1.txt" 2> "$1.err" || {
    cat "$1.err"
    fail "$1: the run was refused or failed"
  }
}

# run_quiet_scene NAME: appends to NAME.prm an Accuracy block without the
# error estimate (its companion solve is not what these tests check) and
# quiet output into NAME/, then runs it with run_named.
run_quiet_scene()
{
  printf 'subsection Accuracy\n  set Error estimate = false\nend\n' \
    >> "$1.prm"
  quiet_output "$1" >> "$1.prm"
  run_named "$1"
}

# contact_value NAME KEY: KEY's value in NAME/contact.txt.
contact_value() { summary_value "$1/contact.txt" "$2"; }

# write_long_sweep SCENE FILE: SCENE with 30 load targets (2, 4, .., 60) on
# a small mesh, without VTU, into FILE: a sweep long enough to interrupt.
write_long_sweep()
{
  cp "$1" "$2"
  cat >> "$2" <<PRM

# --- overrides of tests/cli/common.sh (write_long_sweep): many targets, a
# small mesh
subsection Mesh
  set Global refinements = 1
end
subsection Contact
  set Values = $(seq -s ', ' 2 2 60)
  set Compare with linear theory = false
end
PRM
  quiet_output >> "$2"
}

# start_until_nip2 COMMAND...: runs COMMAND run.prm in the background into
# stdout.txt and stderr.txt (its pid in $pid) and returns once nip 2 has
# converged; fails if the run ends or 90 s pass first.
start_until_nip2()
{
  rm -rf out stdout.txt stderr.txt
  "$@" run.prm > stdout.txt 2> stderr.txt &
  pid=$!
  for _ in $(seq 1 900); do
    if grep -q '^Nip 2: P from' stdout.txt 2> /dev/null; then return 0; fi
    kill -0 "$pid" 2> /dev/null || break
    sleep 0.1
  done
  cat stdout.txt stderr.txt
  fail "the sweep did not reach nip 2"
}

# engineer_roll_scene: the Geometry and Mesh of the engineer's 250 mm roll
# with a 13.5 mm cover (a 90 deg sector, mesh level 1) on stdout.
engineer_roll_scene()
{
  cat <<'PRM'
subsection Geometry
  set Roll diameter   = 250
  set Cover thickness = 13.5
  set Sector angle    = 90
end
subsection Mesh
  set Radial cells          = 8
  set Circumferential cells = 18
  set Global refinements    = 1
end
PRM
}

# scene_test_args NAME PRM_KIND ROLLNIP PRM: the arguments of a script run
# as NAME.sh ROLLNIP PRM; sets rollnip and scene, checks that both exist
# and starts test NAME.
scene_test_args()
{
  local name="$1" kind="$2"
  shift 2
  [ $# -eq 2 ] || fail "usage: $name.sh ROLLNIP $kind"
  rollnip="$1"
  scene="$2"
  require_executable rollnip "$rollnip"
  [ -f "$scene" ] || fail "parameter file '$scene' not found"
  start_test "$name"
}

# files_agree NUMDIFF REL ABS A B: whether files A and B agree to the
# relative and absolute tolerances (fields split at blanks, commas and
# '='); if not, the last 30 lines of numdiff's report are printed.
files_agree()
{
  local numdiff="$1" rel="$2" abs="$3" a="$4" b="$5"
  "$numdiff" --quiet -r "$rel" -a "$abs" -s $' \t\n,=' "$a" "$b" > /dev/null && return 0
  "$numdiff" -r "$rel" -a "$abs" -s $' \t\n,=' "$a" "$b" | tail -n 30 || true
  return 1
}

# gmsh_mesh GMSH DIMENSION GEO OUT [ARGS...]: meshes GEO with GMSH in
# DIMENSION (2 or 3) into OUT (msh2), passing ARGS (e.g. -setnumber NR 8);
# fails, showing gmsh's log, if gmsh cannot or writes nothing.
gmsh_mesh()
{
  local gmsh="$1" dimension="$2" geo="$3" out="$4"
  shift 4
  "$gmsh" "-$dimension" -format msh2 "$@" "$geo" -o "$out" > "$out.log" 2>&1 ||
    { cat "$out.log"; fail "gmsh could not mesh $geo"; }
  [ -s "$out" ] || fail "gmsh wrote no $out"
  pass "gmsh meshed $(basename "$geo") into $out"
}
