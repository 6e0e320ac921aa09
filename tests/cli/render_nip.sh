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

# ParaView needs an X display that opens. CI machines may set DISPLAY=:99
# with no server behind it. Without a working DISPLAY the test starts an
# Xvfb of its own on a free display number and waits until it accepts a
# connection (under xvfb-run -a, pvpython at times found no server yet and
# aborted). A machine where neither gives a display cannot render, which
# is a skip, not a failure of render_nip.py.
probe='import ctypes, sys
x = ctypes.CDLL("libX11.so.6")
x.XOpenDisplay.restype = ctypes.c_void_p
sys.exit(0 if x.XOpenDisplay(None) else 1)'
display_opens() { python3 -c "$probe" 2>/dev/null; }
if [ -z "${DISPLAY:-}" ] || ! display_opens; then
  command -v Xvfb >/dev/null 2>&1 || {
    echo "skipped: no X display opens (DISPLAY='${DISPLAY:-}') and Xvfb is not installed; ROLLNIP_WITH_PARAVIEW=1 bash scripts/setup.sh installs it"
    exit 77
  }
  n=140
  while [ -e "/tmp/.X$n-lock" ] || [ -e "/tmp/.X11-unix/X$n" ]; do n=$((n + 1)); done
  Xvfb ":$n" -screen 0 1280x1024x24 -nolisten tcp > xvfb.log 2>&1 &
  xvfb_pid=$!
  trap 'status=$?; kill "$xvfb_pid" 2>/dev/null; wait "$xvfb_pid" 2>/dev/null; (exit $status); finish_test' EXIT
  export DISPLAY=":$n"
  for _ in $(seq 100); do display_opens && break; sleep 0.1; done
  display_opens || {
    echo "skipped: the Xvfb started on $DISPLAY accepts no connection:"
    cat xvfb.log
    exit 77
  }
fi
pv=(pvpython)

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

"${pv[@]}" "$script" out --field sigma_rr --output nip.png --size 800x600 > render.txt 2>&1 ||
  { cat render.txt; fail "render_nip.py failed"; }
[ -s nip.png ] || fail "nip.png was not written"
size="$(python3 -c "import struct; d=open('nip.png','rb').read(24); print(*struct.unpack('>II', d[16:24]))")"
[ "$size" = "800 600" ] || fail "nip.png is $size pixels, not 800 600"
pass "nip.png written, 800 x 600 pixels"

"${pv[@]}" "$script" out --field von_mises --zoom 0 --edges --output mesh.png --size 640x480 > edges.txt 2>&1 ||
  { cat edges.txt; fail "render_nip.py --edges --zoom 0 failed"; }
size="$(python3 -c "import struct; d=open('mesh.png','rb').read(24); print(*struct.unpack('>II', d[16:24]))")"
[ "$size" = "640 480" ] || fail "mesh.png is $size pixels, not 640 480"
pass "--edges --zoom 0 (the whole mesh) writes mesh.png, 640 x 480 pixels"

rc=0
"${pv[@]}" "$script" out --field no_such_field --output x.png > bad.txt 2>&1 || rc=$?
[ "$rc" -ne 0 ] || fail "an unknown field was accepted"
grep -q "no point array 'no_such_field'" bad.txt || { cat bad.txt; fail "no clear message for an unknown field"; }
pass "an unknown field is refused: $(grep "no point array" bad.txt | cut -c1-60)..."
