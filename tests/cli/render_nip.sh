#!/usr/bin/env bash
# scripts/render_nip.py draws a nip with ParaView: run a small contact nip,
# render it coloured by sigma_rr, the whole model with its cell edges
# (--edges --zoom 0), and by an unknown field, and check that the
# PNG is written (a real image of the requested size) and that a missing
# array is refused with a one-line message. Skipped (exit 77) where
# pvpython is not installed (ROLLNIP_WITH_PARAVIEW=1 bash scripts/setup.sh
# installs it).
#
# Usage: bash render_nip.sh ROLLNIP RENDER_SCRIPT
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 2 ] || fail "usage: render_nip.sh ROLLNIP RENDER_SCRIPT"
rollnip="$1"
script="$2"
if ! command -v pvpython >/dev/null 2>&1; then
  echo "skipped: pvpython (ParaView) is not installed; ROLLNIP_WITH_PARAVIEW=1 bash scripts/setup.sh installs it"
  exit 77
fi
require_executable rollnip "$rollnip"
start_test render_nip

# ParaView needs an X display that opens and stays. Where Xvfb is
# installed the test starts its own: Xvfb picks a free display number
# itself (-displayfd, so two servers never race for one number, as a
# fixed :99 or a probed number did on a shared CI machine) and reports it
# once it accepts connections; -noreset keeps it up between the pvpython
# runs. Without Xvfb an existing DISPLAY is used if it opens. A machine
# with neither cannot render, which is a skip, not a failure of
# render_nip.py.
probe='import ctypes, sys
x = ctypes.CDLL("libX11.so.6")
x.XOpenDisplay.restype = ctypes.c_void_p
sys.exit(0 if x.XOpenDisplay(None) else 1)'
display_opens() { python3 -c "$probe" 2>/dev/null; }
if command -v Xvfb >/dev/null 2>&1; then
  Xvfb -displayfd 3 -screen 0 1280x1024x24 -nolisten tcp -noreset 3> display.txt > xvfb.log 2>&1 &
  xvfb_pid=$!
  trap 'status=$?; kill "$xvfb_pid" 2>/dev/null; wait "$xvfb_pid" 2>/dev/null; (exit $status); finish_test' EXIT
  for _ in $(seq 150); do [ -s display.txt ] && break; sleep 0.1; done
  n="$(tr -dc 0-9 < display.txt)"
  [ -n "$n" ] && kill -0 "$xvfb_pid" 2>/dev/null || {
    echo "skipped: Xvfb reported no display within 15 s:"
    cat xvfb.log
    exit 77
  }
  export DISPLAY=":$n"
  echo "Xvfb of this test on $DISPLAY"
  display_opens || { cat xvfb.log; fail "the Xvfb started on $DISPLAY accepts no connection"; }
elif [ -z "${DISPLAY:-}" ] || ! display_opens; then
  echo "skipped: no X display opens (DISPLAY='${DISPLAY:-}') and Xvfb is not installed; ROLLNIP_WITH_PARAVIEW=1 bash scripts/setup.sh installs it"
  exit 77
fi

# render LOG ARGS...: run render_nip.py with pvpython. A lost X server
# (pvpython aborts with "bad X server connection") is a fault of the
# machine, not of the script: try once more, then skip with Xvfb's log.
render()
{
  local log="$1"
  shift
  for attempt in 1 2; do
    pvpython "$script" "$@" > "$log" 2>&1 && return 0
    grep -q "bad X server connection" "$log" || return 1
    echo "pvpython lost the X server on DISPLAY=$DISPLAY (attempt $attempt)"
    sleep 1
  done
  echo "skipped: the X server on DISPLAY=$DISPLAY went away during the test; Xvfb's log:"
  cat xvfb.log 2>/dev/null || true
  exit 77
}

cat > nip.prm <<PRM
subsection Mesh
  set Global refinements = 1
end
subsection Contact
  set Mode = nip angle
  set Values = 8
  set Indenter radius = 76.2
end
subsection Output
  set Directory = out
end
PRM
"$rollnip" nip.prm > run.txt 2>&1 || { cat run.txt; fail "the nip run failed"; }
pass "a nip at theta0 = 8 deg ran"

render render.txt out --field sigma_rr --output nip.png --size 800x600 ||
  { cat render.txt; fail "render_nip.py failed"; }
[ -s nip.png ] || fail "nip.png was not written"
size="$(python3 -c "import struct; d=open('nip.png','rb').read(24); print(*struct.unpack('>II', d[16:24]))")"
[ "$size" = "800 600" ] || fail "nip.png is $size pixels, not 800 600"
pass "nip.png written, 800 x 600 pixels"

render edges.txt out --field von_mises --zoom 0 --edges --output mesh.png --size 640x480 ||
  { cat edges.txt; fail "render_nip.py --edges --zoom 0 failed"; }
size="$(python3 -c "import struct; d=open('mesh.png','rb').read(24); print(*struct.unpack('>II', d[16:24]))")"
[ "$size" = "640 480" ] || fail "mesh.png is $size pixels, not 640 480"
pass "--edges --zoom 0 (the whole mesh) writes mesh.png, 640 x 480 pixels"

rc=0
render bad.txt out --field no_such_field --output x.png || rc=$?
[ "$rc" -ne 0 ] || fail "an unknown field was accepted"
grep -q "no point array 'no_such_field'" bad.txt || { cat bad.txt; fail "no clear message for an unknown field"; }
pass "an unknown field is refused: $(grep "no point array" bad.txt | cut -c1-60)..."
