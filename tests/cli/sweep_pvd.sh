#!/usr/bin/env bash
# The ParaView files of a sweep: a load-controlled sweep of three nips
# (5, 10, 20 N/mm, level 1, with the linear companion) writes
# solution_sweep.pvd and solution_sweep_linear.pvd at the top of its output
# directory. Each must be well-formed XML with one dataset per nip, time
# values equal to the nip loads of nip_characteristic.csv (so increasing),
# files that exist, and the time's meaning in a comment. The .vtu pieces
# carry the Cauchy stress and the Green-Lagrange strain as 9-component
# tensors (ParaView's tensor filters need them whole). Each nip of the
# nonlinear sweep also has the indenter outline (part 1) and the contact
# pressure along the deformed surface (part 2) as polylines; a two-roll
# sweep has the mating roll as part 1, and a single nip is a sweep of one.
#
# Usage: bash sweep_pvd.sh ROLLNIP
set -euo pipefail
source "$(dirname "${BASH_SOURCE[0]}")/common.sh"

[ $# -eq 1 ] || fail "usage: sweep_pvd.sh ROLLNIP"
rollnip="$1"
require_executable rollnip "$rollnip"
start_test sweep_pvd
command -v python3 >/dev/null || fail "python3 is needed to parse the XML"

# Runs rollnip on NAME.prm (output in NAME.out, NAME.err); exit 0 or fail.
run_ok()
{
  local rc=0
  "$rollnip" "$1.prm" > "$1.out" 2> "$1.err" || rc=$?
  [ "$rc" -eq 0 ] || { cat "$1.err"; fail "$1.prm: exit code $rc"; }
}

cat > sweep.prm <<PRM
subsection Mesh
  set Radial cells = 4
  set Circumferential cells = 16
  set Global refinements = 1
end
subsection Contact
  set Mode = load
  set Values = 5, 10, 20
  set Indenter radius = 76.2
  set Compare with linear theory = true
end
subsection Output
  set Directory = out
end
PRM
run_ok sweep
pass "the sweep runs"

python3 - <<'PY' || fail "the sweep PVD files are not what ParaView needs"
import csv, os, re, sys, xml.etree.ElementTree as ET
loads = [float(r["P_N_per_mm"]) for r in csv.DictReader(open("out/nip_characteristic.csv"))]
ok = True
for name in ["out/solution_sweep.pvd", "out/solution_sweep_linear.pvd"]:
    text = open(name).read()
    if "time = line load P [N/mm]" not in text:
        print(f"FAIL: {name} does not say what its time is"); ok = False
    every = list(ET.parse(name).iter("DataSet"))
    sets = [d for d in every if d.get("part") == "0"]
    times = [float(d.get("timestep")) for d in sets]
    if len(sets) != 3:
        print(f"FAIL: {name} has {len(sets)} part-0 datasets, not 3"); ok = False
    # The nonlinear sweep adds the indenter and the contact pressure.
    pieces = {"out/solution_sweep.pvd": [("1", "indenter.vtp"), ("2", "contact_pressure.vtp")]}.get(name, [])
    for part, file in pieces:
        got = [d for d in every if d.get("part") == part]
        if [float(d.get("timestep")) for d in got] != times or \
           not all(d.get("file").endswith(file) and os.path.isfile(os.path.join("out", d.get("file"))) for d in got):
            print(f"FAIL: {name} has no {file} as part {part} of every nip"); ok = False
            continue
        tree = ET.parse(os.path.join("out", got[-1].get("file")))
        n = int(tree.find(".//Piece").get("NumberOfPoints"))
        if n < 2:
            print(f"FAIL: {got[-1].get('file')} has {n} points"); ok = False
        if file == "contact_pressure.vtp":
            values = [float(v) for v in tree.find(".//PointData/DataArray").text.split()]
            if len(values) != n or not max(values) > 0 or min(values) < 0:
                print(f"FAIL: contact_pressure_MPa {values[:3]}... is not a pressure at {n} points"); ok = False
    if any(abs(t - p) > 1e-6 * p for t, p in zip(times, loads)):
        print(f"FAIL: {name} times {times} are not the loads {loads}"); ok = False
    if times != sorted(times):
        print(f"FAIL: {name} times {times} do not increase"); ok = False
    for d in sets:
        pvtu = os.path.join("out", d.get("file"))
        if not os.path.isfile(pvtu):
            print(f"FAIL: {pvtu} named in {name} does not exist"); ok = False
            continue
        vtu = pvtu.replace(".pvtu", ".0000.vtu")
        head = open(vtu, "rb").read(200000).decode("latin-1")
        for tensor in ["cauchy_stress", "green_lagrange_strain"]:
            if not re.search(f'Name="{tensor}" NumberOfComponents="9"', head):
                print(f"FAIL: {vtu} has no 9-component {tensor}"); ok = False
    print(f"  {name}: times {times}")
sys.exit(0 if ok else 1)
PY
pass "two sweep PVDs, one dataset per nip at the nip loads, tensors in the pieces, the indenter and the contact pressure as parts 1 and 2"

# Two covered rolls: the mating roll is part 1 of each nip, at the same time.
cat > two.prm <<PRM
subsection Mesh
  set Radial cells = 4
  set Circumferential cells = 16
end
subsection Contact
  set Mode = nip angle
  set Values = 4, 8
  set Compare with linear theory = false
end
subsection Mating roll
  set Type = covered roll
  subsection Mesh
    set Radial cells = 4
    set Circumferential cells = 16
  end
end
subsection Output
  set Directory = two
end
PRM
run_ok two
python3 - <<'PY' || fail "the two-roll sweep PVD does not hold both rolls"
import os, sys, xml.etree.ElementTree as ET
sets = list(ET.parse("two/solution_sweep.pvd").iter("DataSet"))
parts = [(float(d.get("timestep")), d.get("part"), d.get("file")) for d in sets]
ok = [p[1] for p in parts] == ["0", "1", "2", "0", "1", "2"] and \
     parts[0][0] == parts[1][0] == parts[2][0] and \
     parts[3][0] == parts[4][0] == parts[5][0] and \
     all("mating_roll/" in p[2] for p in parts if p[1] == "1") and \
     all(os.path.isfile(os.path.join("two", p[2])) for p in parts)
print(f"  two/solution_sweep.pvd: {parts}")
sys.exit(0 if ok else 1)
PY
pass "a two-roll sweep: the mating roll is part 1 and the contact pressure part 2 of every nip"

# A single nip is a sweep of one: the same three parts, paths relative to
# the output directory itself.
cat > one.prm <<PRM
subsection Mesh
  set Radial cells = 4
  set Circumferential cells = 16
end
subsection Contact
  set Mode = nip angle
  set Values = 6
  set Compare with linear theory = true
end
subsection Output
  set Directory = one
end
PRM
run_ok one
python3 - <<'PY' || fail "a single nip's PVD is not what ParaView needs"
import os, sys, xml.etree.ElementTree as ET
ok = True
for name, want in [("one/solution_sweep.pvd", ["0", "1", "2"]),
                   ("one/solution_sweep_linear.pvd", ["0"])]:
    parts = [(float(d.get("timestep")), d.get("part"), d.get("file"))
             for d in ET.parse(name).iter("DataSet")]
    print(f"  {name}: {parts}")
    ok &= [p[1] for p in parts] == want and all(p[0] == 6 for p in parts) and \
          all(os.path.isfile(os.path.join("one", p[2])) for p in parts)
sys.exit(0 if ok else 1)
PY
pass "a single nip: solution_sweep.pvd holds the cover, the indenter and the pressure at theta0 = 6, and the linear companion has its own"
