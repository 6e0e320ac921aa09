#!/usr/bin/env python3
"""Fuzzes rollnip's input: runs random mutations of the shipped parameter
files (parameters/*.prm) and sorts each run into a class. Not part of ctest.

Usage: python3 benchmarks/fuzz_inputs.py [N] [SEED] [--timeout S] [--kinds K,...]
  N        number of cases (default 300)
  SEED     random seed (default 1); the same N and SEED give the same cases
  --timeout S   seconds per run before it counts as a hang (default 60)
  --kinds K,... only these mutation kinds (default: all of them)
Uses build/rollnip, or $ROLLNIP_BIN. The binary is copied to a temporary
directory first, so that a relink during the run cannot mix two builds.
Runs one case at a time, one MPI process, DEAL_II_NUM_THREADS=1.

Each case is one shipped file with one mutation:
  value-negative, value-zero, value-huge (1e300, 1e308, 1e999),
  value-tiny (1e-300, 1e-320, 5e-324), value-nan-inf, value-text (text
  where a number, option or expression is expected): one numeric entry
  (one element of a list) or, for value-text, any entry;
  units-x1000, units-div1000 (m for mm, kPa for MPa, ...), units-x2 (a
  diameter given as a radius), units-rad-for-deg (an angle in radians);
  missing-key (a `set` line deleted), duplicate-key (a second `set` of the
  same key with another value after the first), wrong-subsection (a `set`
  line moved into another subsection), misspelled-key, truncated (the file
  cut at a random byte);
  mesh-empty, mesh-truncated, mesh-triangles, mesh-missing,
  mesh-wrong-radius: Mesh/Source = gmsh with a small generated msh2 file
  (empty, a valid quadrilateral mesh cut at a random byte, the same mesh
  split into triangles, a file that does not exist, a mesh 5 % too big).
The kinds of issue 20 (each on the shipped scenes it applies to):
  mate-limits (parameters/two_rolls.prm: the mating roll's sector angle 5
  or 10 deg, 12 refinements, a negative inner radius, C1 = 1e300, 0 radial
  cells), ignored-entries (Mating roll/Type = rigid with the covered roll
  described, Load/p0 and theta0 in a contact scene, Contact entries with
  Mode = none), narrow-load-zone (parameters/parabolic_pressure.prm with
  Load/theta0 = 0.1745, 0.01, 0.05 or 0.3 deg), tolerance-roundoff (a
  contact scene with a Contact or Newton tolerance of 0, 1e-15, 1e-16,
  1e-20 or 5e-324, or Contact or Mating roll/Maximum iterations = 1),
  metres-for-mm (every radius, diameter and thickness of a file divided by
  1000), force-on-face (parameters/engineering_nip.prm with Load unit N or
  kN on a Face length of 1e-300, 1e-6, 1 or 1e9 mm), long-expression (the
  parabolic pressure followed by 2000 terms ' + 0 * theta' (24 kB), 3000
  terms '+0*theta' (24 kB without blanks) or 140000 (1.1 MB)),
  grading-two-rolls (parameters/two_rolls.prm with Mesh/Adaptive grading
  passes = 1 or 2); not on parameters/crown.prm (the face model, whose
  summaries insanity() does not read). An exit-0 run of the first six must print a "rollnip:
  warning:" line naming what it did (EXPECT_WARNING), else it counts as
  "exit 0 but not sane" (silent).
Before the mutation every case is made cheap in place (the existing `set`
line is changed, or one is added to its subsection): Mesh/Global
refinements = 0 (and Mating roll/Mesh/Global refinements = 0), Output/Directory = out, Write VTU = false, Print timing =
false; a mutation of one of these keys replaces that override. Each case
runs in its own temporary directory (relative paths resolve there).

Classes (what rollnip prints on bad input: exactly one line on stderr,
"rollnip: error: <message>", and exit code 1):
  clean refusal     exit code 1..127, at most 3 non-empty stderr lines, the
                    last beginning with "rollnip: error", and none of the
                    noise markers below in stderr or stdout
  noisy refusal     exit code 1..127 otherwise: more lines, no "rollnip:
                    error" line last, or a noise marker (deal.II exception
                    block "-----...", "An error occurred", "Stacktrace",
                    "Amesos", "MUMPS", "MPI_ABORT", "terminate called")
  crash             killed by a signal (negative return code) or exit code
                    >= 128 (128 + signal number from a wrapper)
  hang              no exit within the timeout (the process group is killed)
  exit 0 and sane   exit code 0 and every check below passes
  exit 0 but not sane  exit code 0 and a check fails
Sanity checks (exit 0): at least one summary.txt under the case directory
(the top one, nip-NN/summary.txt and nip-NN/linear/summary.txt for contact
scenes); in each: status = converged, every numeric value finite,
max_abs_J_minus_1_gauss < 0.5, nip_load_P_N_per_mm = -2
load_resultant_x_N_per_mm to 1e-6 relative (plus 1e-12 N/mm absolute);
each contact.txt: status = converged, numbers finite,
penetration_outside_over_u0 <= 1e-6 (the default Conformity tolerance) and
conformity_max_gap_over_u0 <= 1e-2 (what Batra accepted; a huge Conformity
tolerance lets rollnip stop after one iteration with gaps of 80 % of u0);
each screen line "P from the applied pressure X N/mm, from the surface
stress Y N/mm (difference Z %)": X, Y finite and |Z| < 5, and a contact
scene must print at least one such line.

Text on stderr does not change the class of an exit-0 run (the checks judge
the results), but such runs are counted and listed apart ("exit 0 with text
on stderr": e.g. Amesos_Mumps ERROR lines from a factorisation that failed
and was recovered by a load cutback).

Output: the count per class, per mutation kind x class, and up to 20
failing cases (crash, hang, noisy refusal, exit 0 but not sane) with their
mutation, exit code and last stderr line. Every failing case and every
exit-0 run with text on stderr is kept in
benchmarks/results/fuzz-<timestamp>/case-NNN/ (case.prm, its mesh,
stdout.txt, stderr.txt; rerun it in that directory with rollnip case.prm);
cases.csv there lists all cases; the kind x class table goes to
benchmarks/results/fuzz-<timestamp>.csv.
"""

import argparse
import csv
import glob
import hashlib
import math
import os
import random
import re
import shutil
import signal
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROLLNIP = os.environ.get("ROLLNIP_BIN", os.path.join(ROOT, "build", "rollnip"))
RESULTS = os.path.join(ROOT, "benchmarks", "results")

KINDS = ["value-negative", "value-zero", "value-huge", "value-tiny", "value-nan-inf",
         "value-text", "units-x1000", "units-div1000", "units-x2", "units-rad-for-deg",
         "missing-key", "duplicate-key", "wrong-subsection", "misspelled-key", "truncated",
         "mesh-empty", "mesh-truncated", "mesh-triangles", "mesh-missing",
         "mesh-wrong-radius",
         # The classes of issue 20 (ISSUE20_KINDS below).
         "mate-limits", "ignored-entries", "narrow-load-zone", "tolerance-roundoff",
         "metres-for-mm", "force-on-face", "long-expression", "grading-two-rolls"]
# An exit-0 run of these kinds must say what it did with the odd input: a
# "rollnip: warning:" line matching the pattern, else it is "exit 0 but not
# sane" (a silent answer to a question the user did not mean to ask).
EXPECT_WARNING = {"mate-limits": r"Mating roll/",
                  "ignored-entries": r"ignored|Mating roll/|Load/|Contact/",
                  "narrow-load-zone": r"Load/",
                  "tolerance-roundoff": r"tolerance|iterations",
                  "metres-for-mm": r"mm|metre|unit",
                  "force-on-face": r"Face length|Load unit|N/mm"}
CLASSES = ["clean refusal", "noisy refusal", "crash", "hang", "exit 0 and sane",
           "exit 0 but not sane"]
FAILING = ["crash", "hang", "noisy refusal", "exit 0 but not sane"]
CHEAP = [("Mesh", "Global refinements", "0"), ("Output", "Directory", "out"),
         ("Output", "Write VTU", "false"), ("Output", "Print timing", "false")]
NOISE = ["An error occurred", "Stacktrace", "Amesos", "MUMPS", "MPI_ABORT",
         "terminate called"]
# Keys with a unit, for the units-* mutations.
RADII = {"Inner radius", "Outer radius", "Indenter radius",
         "Roll diameter", "Cover thickness", "Indenter diameter"}
DIMENSIONAL = RADII | {"C1", "C2", "p0", "Values"}
ANGLES = {"Sector angle", "theta0"}
TEXT = ["abc", "", "1,5", "12 mm", "1.2.3", "0x1A", "true", "--5", "1e", "\u221e"]
EXPRESSIONS = ["theta <", "p0 * (1 - ", "1/0", "sqrt(-1)", "foo(theta)", "", "theta0/0",
               "p0 * 1e308 * 10"]
P_LINE = re.compile(r"P from the applied pressure (\S+) N/mm, from the surface stress (\S+) "
                    r"N/mm \(difference (\S+) %\)")
PENETRATION_TOL = 1e-6
CONFORMITY_TOL = 1e-2


def declared_entries(binary):
    """{(subsection, key): allowed-text} from --print-parameters (one level deep)."""
    out = subprocess.run([binary, "--print-parameters"], capture_output=True, text=True,
                         timeout=120, check=True).stdout
    entries, sub, doc = {}, [], []
    for line in out.splitlines():
        s = line.strip()
        if s.startswith("#"):
            doc.append(s[1:].strip())
            continue
        if s.startswith("subsection "):
            sub.append(s[len("subsection "):].strip())
        elif s == "end":
            sub.pop()
        elif s.startswith("set ") and sub:
            text = " ".join(doc)
            entries[(sub[-1], s[4:].partition("=")[0].strip())] = \
                text.split("Allowed:", 1)[1].strip() if "Allowed:" in text else ""
        if s:
            doc = []
    return entries


def set_lines(lines):
    """[(index, subsection path, key, value)] of the `set` lines; nested subsections
    (Mating roll/Geometry) are joined by '/'."""
    found, path = [], []
    for i, line in enumerate(lines):
        s = line.split("#", 1)[0].strip()
        if s.startswith("subsection "):
            path.append(s[len("subsection "):].strip())
        elif s == "end":
            if path:
                path.pop()
        elif s.startswith("set ") and path:
            key, _, value = s[4:].partition("=")
            found.append((i, "/".join(path), key.strip(), value.strip()))
    return found


def put(lines, sub, key, value):
    """Sets sub/key = value in place: changes its `set` line, or adds one to sub."""
    for i, s, k, _ in set_lines(lines):
        if (s, k) == (sub, key):
            lines[i] = f"  set {key} = {value}"
            return
    add(lines, sub, key, value)


def add(lines, sub, key, value):
    """Adds a `set` line at the top of the subsection path sub (new blocks at the end
    if there is none)."""
    want, path = sub.split("/"), []
    for i, line in enumerate(lines):
        s = line.split("#", 1)[0].strip()
        if s.startswith("subsection "):
            path.append(s[len("subsection "):].strip())
            if path == want:
                lines.insert(i + 1, f"  set {key} = {value}")
                return
        elif s == "end" and path:
            path.pop()
    lines.extend([""] + [f"subsection {p}" for p in want] + [f"  set {key} = {value}"]
                 + ["end"] * len(want))


def entry_doc(entries, sub, key):
    """The allowed-text of sub/key (declared_entries knows the last subsection)."""
    return entries.get((sub.split("/")[-1], key), "")


def floats(value):
    """The numbers of a value (a comma list allowed), or None if it is not numeric."""
    try:
        return [float(v) for v in value.split(",")]
    except ValueError:
        return None


def fmt(x):
    return "inf" if math.isinf(x) else f"{x:.10g}"


def mutate_number(rng, kind, value):
    """One element of a numeric value replaced as kind says."""
    parts = [p.strip() for p in value.split(",")]
    j = rng.randrange(len(parts))
    x = float(parts[j])
    if kind == "value-negative":
        parts[j] = "-1" if x == 0 else ("-1e300" if x < 0 else "-" + parts[j])
    elif kind == "value-zero":
        parts[j] = "0"
    elif kind == "value-huge":
        parts[j] = rng.choice(["1e300", "1e308", "1e999"])
    elif kind == "value-tiny":
        parts[j] = rng.choice(["1e-300", "1e-320", "5e-324"])
    else:
        parts[j] = rng.choice(["nan", "inf", "-inf", "NaN", "infinity"])
    return ", ".join(parts)


def scale_units(kind, value):
    factor = {"units-x1000": 1000, "units-div1000": 1e-3, "units-x2": 2,
              "units-rad-for-deg": math.pi / 180}[kind]
    return ", ".join(fmt(x * factor) for x in floats(value))


def other_value(rng, allowed, key, value):
    """Another legal-looking value for a duplicate `set`."""
    if "Any one of" in allowed:
        options = [o.strip() for o in allowed.split("Any one of", 1)[1].split(",")]
        options = [o for o in options if o and o != value]
        if options:
            return rng.choice(options)
    if "boolean" in allowed:
        return "false" if value == "true" else "true"
    numbers = floats(value)
    if numbers is not None and all(math.isfinite(x) for x in numbers):
        if "integer" in allowed:
            return str(int(numbers[0]) + 1)  # +1, not x2: refinements stay cheap
        return ", ".join(fmt(x * rng.choice([0.5, 2])) for x in numbers)
    return {"Indenter radius": "100", "Pressure function": "p0",
            "Directory": "out2"}.get(key, value + "x")


def misspell(rng, key):
    while True:
        i = rng.randrange(len(key))
        how = rng.choice(["drop", "swap", "double", "case", "underscore", "plural", "space"])
        if how == "drop":
            new = key[:i] + key[i + 1:]
        elif how == "swap" and i + 1 < len(key):
            new = key[:i] + key[i + 1] + key[i] + key[i + 2:]
        elif how == "double":
            new = key[:i] + key[i] + key[i:]
        elif how == "case":
            new = key[:i] + key[i].swapcase() + key[i + 1:]
        elif how == "underscore" and " " in key:
            new = key.replace(" ", "_", 1)
        elif how == "space" and " " in key:
            new = key.replace(" ", "  ", 1)
        elif how == "plural":
            new = key + "s"
        else:
            continue
        if new != key and new.strip():
            return new


def quad_mesh(r1, r0, sector_deg, nr=3, nt=16, triangles=False):
    """A msh2 annulus sector with physical ids 0..3 on the boundaries, surface id 0;
    graded like the builtin mesh (far cell 8 x the nip cell) so that a contact
    zone of a few degrees holds enough surface nodes for the mesh to be usable."""
    q = 8 ** (1 / (nt - 1))
    theta = [math.radians(sector_deg) * (q ** j - 1) / (q ** nt - 1) for j in range(nt + 1)]
    node = lambda i, j: 1 + j * (nr + 1) + i  # noqa: E731
    nodes = [f"{node(i, j)} {r * math.cos(t):.15g} {r * math.sin(t):.15g} 0"
             for j in range(nt + 1) for i in range(nr + 1)
             for r, t in [(r1 + (r0 - r1) * i / nr, theta[j])]]
    elems = []
    for j in range(nt):
        elems.append((1, 0, node(0, j), node(0, j + 1)))       # inner arc
        elems.append((1, 1, node(nr, j), node(nr, j + 1)))     # outer arc
    for i in range(nr):
        elems.append((1, 2, node(i, 0), node(i + 1, 0)))       # symmetry edge
        elems.append((1, 3, node(i, nt), node(i + 1, nt)))     # far edge
    for j in range(nt):
        for i in range(nr):
            a, b, c, d = node(i, j), node(i + 1, j), node(i + 1, j + 1), node(i, j + 1)
            if triangles:
                elems += [(2, 0, a, b, c), (2, 0, a, c, d)]
            else:
                elems.append((3, 0, a, b, c, d))
    lines = ["$MeshFormat", "2.2 0 8", "$EndMeshFormat", "$Nodes", str(len(nodes))]
    lines += nodes + ["$EndNodes", "$Elements", str(len(elems))]
    lines += [f"{n + 1} {e[0]} 2 {e[1]} {e[1] + 1} " + " ".join(map(str, e[2:]))
              for n, e in enumerate(elems)]
    return "\n".join(lines + ["$EndElements"]) + "\n"


PARABOLIC = "theta < theta0 ? p0 * (1 - (theta/theta0)^2) : 0"


def issue20_case(rng, kind, base, lines):
    """Applies a mutation of the issue-20 kinds to lines; its description, or None
    when base is not a scene of the kind."""
    known = {(s, k): v for _, s, k, v in set_lines(lines)}
    mode = known.get(("Contact", "Mode"), "none")
    two_rolls = known.get(("Mating roll", "Type")) == "covered roll"
    if known.get(("Face", "Enabled")) == "true":
        return None  # the face model writes other summaries than insanity() reads
    if kind in ("mate-limits", "grading-two-rolls") and not two_rolls:
        return None
    if kind in ("narrow-load-zone", "long-expression") and base != "parabolic_pressure.prm":
        return None
    if kind == "force-on-face" and base != "engineering_nip.prm":
        return None
    if kind == "mate-limits":
        sub, key, value = rng.choice([
            ("Mating roll/Geometry", "Sector angle", "5"),
            ("Mating roll/Geometry", "Sector angle", "10"),
            ("Mating roll/Mesh", "Global refinements", "12"),
            ("Mating roll/Geometry", "Inner radius", "-10"),
            ("Mating roll/Material", "C1", "1e300"),
            ("Mating roll/Mesh", "Radial cells", "0")])
    elif kind == "ignored-entries":
        if two_rolls and rng.random() < 0.5:
            sub, key, value = "Mating roll", "Type", "rigid"
        elif mode != "none":
            put(lines, "Load", "p0", "0.3")
            sub, key, value = "Load", "theta0", "5"
        else:
            sub, key, value = "Contact", rng.choice(
                ["Conformity tolerance", "Control tolerance", "Maximum iterations"]), "1e-5"
            if key == "Maximum iterations":
                value = "10"
    elif kind == "narrow-load-zone":
        sub, key = "Load", "theta0"
        value = rng.choice(["0.1745", "0.01", "0.05", "0.3"])
    elif kind == "tolerance-roundoff":
        if mode == "none":
            return None
        choices = [("Contact", "Control tolerance"), ("Contact", "Conformity tolerance"),
                   ("Nonlinear solver", "Residual tolerance"),
                   ("Nonlinear solver", "Increment tolerance"),
                   ("Nonlinear solver", "Constraint tolerance")]
        sub, key = rng.choice(choices)
        value = rng.choice(["0", "1e-15", "1e-16", "1e-20", "5e-324"])
        if rng.random() < 0.25:
            sub, key, value = (("Mating roll", "Maximum iterations", "1") if two_rolls
                               else ("Contact", "Maximum iterations", "1"))
    elif kind == "metres-for-mm":
        changed = []
        for i, sub, key, value in set_lines(lines):
            numbers = floats(value)
            if key in RADII and numbers and sub.split("/")[-1] in ("Geometry", "Contact"):
                lines[i] = f"  set {key} = " + ", ".join(fmt(x / 1000) for x in numbers)
                changed.append(f"{sub}/{key}")
        return ("every length in m: " + ", ".join(changed)) if changed else None
    elif kind == "force-on-face":
        put(lines, "Contact", "Load unit", rng.choice(["N", "kN"]))
        sub, key = "Contact", "Face length"
        value = rng.choice(["1e-300", "1e-6", "1", "1e9"])
    elif kind == "long-expression":
        sub, key = "Load", "Pressure function"
        n, glue = rng.choice([(2000, " + 0 * theta"), (3000, "+0*theta"),
                              (140000, "+0*theta")])
        value = f"({PARABOLIC})" + glue * n
        put(lines, sub, key, value)
        return f"{sub}/{key}: the parabolic pressure and {n} x {glue!r} ({len(value)} bytes)"
    else:  # grading-two-rolls
        sub, key, value = "Mesh", "Adaptive grading passes", rng.choice(["1", "2"])
    put(lines, sub, key, value)
    return f"{sub}/{key} = {value}"


def make_case(rng, kind, base_lines, entries, base=""):
    """(prm text, description, {file name: content}) of one mutated case, or
    None when the base file has no entry the kind can mutate."""
    lines = list(base_lines)
    for sub, key, value in CHEAP:
        put(lines, sub, key, value)
    if any(e[1] == "Mating roll/Mesh" for e in set_lines(lines)):
        put(lines, "Mating roll/Mesh", "Global refinements", "0")
    if kind in EXPECT_WARNING or kind in ("long-expression", "grading-two-rolls"):
        what = issue20_case(rng, kind, base, lines)
        return None if what is None else ("\n".join(lines) + "\n", what, {})
    entries_here = set_lines(lines)
    nip_angle = any(e[1:] == ("Contact", "Mode", "nip angle") for e in entries_here)
    files = {}
    if kind.startswith("value-") or kind.startswith("units-"):
        if kind == "value-text":
            pool = entries_here
        elif kind.startswith("value-"):
            pool = [e for e in entries_here if floats(e[3]) is not None]
        else:
            pool = [e for e in entries_here if floats(e[3]) is not None
                    and all(math.isfinite(x) for x in floats(e[3]))
                    and {"units-x2": e[2] in RADII,
                         "units-rad-for-deg": e[2] in ANGLES or (e[2] == "Values" and nip_angle)
                         }.get(kind, e[2] in DIMENSIONAL)]
        if not pool:
            return None  # no entry of this kind in this file: the caller picks another
        for _ in range(50):
            i, sub, key, value = rng.choice(pool)
            if kind == "value-text":
                new = rng.choice(EXPRESSIONS if key == "Pressure function" else TEXT)
            elif kind.startswith("value-"):
                new = mutate_number(rng, kind, value)
            else:
                new = scale_units(kind, value)
            if new != value:
                break
        lines[i] = f"  set {key} = {new}"
        what = f"{sub}/{key}: {value!r} -> {new!r}"
    elif kind == "missing-key":
        i, sub, key, value = rng.choice(entries_here)
        del lines[i]
        what = f"deleted {sub}/{key} = {value}"
    elif kind == "duplicate-key":
        i, sub, key, value = rng.choice(entries_here)
        new = other_value(rng, entry_doc(entries, sub, key), key, value)
        lines.insert(i + 1, f"  set {key} = {new}")
        what = f"{sub}/{key} = {value}, then again = {new}"
    elif kind == "wrong-subsection":
        i, sub, key, value = rng.choice(entries_here)
        target = rng.choice(sorted({s for s, _ in entries} - {sub}))
        del lines[i]
        add(lines, target, key, value)
        what = f"{sub}/{key} = {value} moved to {target}"
    elif kind == "misspelled-key":
        i, sub, key, value = rng.choice(entries_here)
        new = misspell(rng, key)
        lines[i] = f"  set {new} = {value}"
        what = f"{sub}/{key} spelled {new!r}"
    elif kind == "truncated":
        text = "\n".join(lines) + "\n"
        cut = rng.randrange(len(text))
        tail = text[max(0, cut - 30):cut]
        return text[:cut], f"cut at byte {cut} of {len(text)} (...{tail!r})", files
    else:  # mesh-*
        known = {(s, k): v for _, s, k, v in entries_here}
        r1 = float(known.get(("Geometry", "Inner radius"), "47.2"))
        r0 = float(known.get(("Geometry", "Outer radius"), "60.7"))
        sector = float(known.get(("Geometry", "Sector angle"), "90"))
        name = "mesh.msh"
        if kind == "mesh-empty":
            files[name] = ""
            what = "empty mesh file"
        elif kind == "mesh-truncated":
            good = quad_mesh(r1, r0, sector)
            cut = rng.randrange(len(good))
            files[name] = good[:cut]
            what = f"valid quad mesh cut at byte {cut} of {len(good)}"
        elif kind == "mesh-triangles":
            files[name] = quad_mesh(r1, r0, sector, triangles=True)
            what = "triangle mesh (each quad split in two)"
        elif kind == "mesh-missing":
            name = "does_not_exist.msh"
            what = "mesh file does not exist"
        else:
            files[name] = quad_mesh(1.05 * r1, 1.05 * r0, sector)
            what = "quad mesh with radii 5 % too large"
        put(lines, "Mesh", "Source", "gmsh")
        put(lines, "Mesh", "Mesh file", name)
    return "\n".join(lines) + "\n", what, files


def run(binary, case_dir, timeout):
    """(return code or None on timeout, seconds, stdout, stderr)."""
    env = dict(os.environ, DEAL_II_NUM_THREADS="1", OMP_NUM_THREADS="1")
    start = time.time()
    with open(os.path.join(case_dir, "stdout.txt"), "w") as out, \
            open(os.path.join(case_dir, "stderr.txt"), "w") as err:
        # Own session: on timeout the whole group (MPI helpers too) is killed.
        proc = subprocess.Popen([binary, "case.prm"], cwd=case_dir, stdout=out, stderr=err,
                                stdin=subprocess.DEVNULL, env=env, start_new_session=True)
        try:
            rc = proc.wait(timeout=timeout)
        except subprocess.TimeoutExpired:
            os.killpg(proc.pid, signal.SIGKILL)
            proc.wait()
            rc = None
    seconds = time.time() - start
    read = lambda n: open(os.path.join(case_dir, n), errors="replace").read()  # noqa: E731
    return rc, seconds, read("stdout.txt"), read("stderr.txt")


def key_values(path):
    values = {}
    for line in open(path, errors="replace"):
        if "=" in line and not line.startswith("#"):
            k, _, v = line.partition("=")
            values[k.strip()] = v.strip()
    return values


def number(v):
    """The value as a float (its first word, so that '-nan (x)' counts), else None."""
    try:
        return float(v.split()[0])
    except (ValueError, IndexError):
        return None


def insanity(case_dir, stdout):
    """What is wrong with an exit-0 run ([] if nothing)."""
    problems = []
    summaries = sorted(glob.glob(os.path.join(case_dir, "**", "summary.txt"), recursive=True))
    contacts = sorted(glob.glob(os.path.join(case_dir, "**", "contact.txt"), recursive=True))
    if not summaries:
        problems.append("no summary.txt")
    for path in summaries + contacts:
        name = os.path.relpath(path, case_dir)
        kv = key_values(path)
        bad = [k for k, v in kv.items() if number(v) is not None and not math.isfinite(number(v))]
        if "total_force_N" in kv:
            # The face model's summary (written only when it converged).
            if bad:
                problems.append(f"{name}: not finite: {', '.join(bad)}")
            if not number(kv["total_force_N"]) or number(kv["total_force_N"]) <= 0:
                problems.append(f"{name}: total_force_N = {kv['total_force_N']}")
            continue
        if kv.get("dimension") == "3":
            # The 3D slice: converged, finite, P >= 0, the active set on
            # the indenter (penetration a round-off of u0).
            if kv.get("status") != "converged":
                problems.append(f"{name}: status = {kv.get('status')}")
            if bad:
                problems.append(f"{name}: not finite: {', '.join(bad)}")
            P = number(kv.get("nip_load_P_N_per_mm", "nan"))
            u0 = number(kv.get("indentation_u0_mm", "nan"))
            pen = number(kv.get("max_penetration_mm", "nan"))
            if P is None or not P >= 0:
                problems.append(f"{name}: nip_load_P_N_per_mm = {P}")
            if pen is None or u0 is None or not pen <= 1e-3 * max(u0, 1e-300):
                problems.append(f"{name}: max_penetration_mm = {pen} for u0 = {u0}")
            continue
        if kv.get("status") != "converged":
            problems.append(f"{name}: status = {kv.get('status')}")
        bad = [k for k, v in kv.items() if number(v) is not None and not math.isfinite(number(v))]
        if bad:
            problems.append(f"{name}: not finite: {', '.join(bad)}")
        if path in contacts:
            pen = number(kv.get("penetration_outside_over_u0", "0"))
            if pen is not None and pen > PENETRATION_TOL:
                problems.append(f"{name}: penetration_outside_over_u0 = {pen:g}")
            gap = number(kv.get("conformity_max_gap_over_u0", "0"))
            if gap is not None and gap > CONFORMITY_TOL:
                problems.append(f"{name}: conformity_max_gap_over_u0 = {gap:g}")
            continue
        j = number(kv.get("max_abs_J_minus_1_gauss", "nan"))
        if j is None or not j < 0.5:
            problems.append(f"{name}: max_abs_J_minus_1_gauss = {j}")
        p = number(kv.get("nip_load_P_N_per_mm", ""))
        rx = number(kv.get("load_resultant_x_N_per_mm", ""))
        if p is not None and rx is not None and \
                not abs(p + 2 * rx) <= 1e-6 * max(abs(p), abs(2 * rx)) + 1e-12:
            problems.append(f"{name}: P = {p:g} but -2 x resultant_x = {-2 * rx:g}")
    p_lines = P_LINE.findall(stdout)
    for applied, surface, diff in p_lines:
        x, y, z = number(applied), number(surface), number(diff)
        if None in (x, y, z) or not (math.isfinite(x) and math.isfinite(y) and abs(z) < 5):
            problems.append(f"P applied {applied}, from stress {surface}, difference {diff} %")
    if contacts and not p_lines:
        problems.append("contact scene without a 'P from the applied pressure' line")
    return problems


def classify(rc, stdout, stderr, case_dir, timeout, kind=""):
    """(class, detail)."""
    if rc is None:
        return "hang", f"no exit within {timeout:g} s"
    if rc < 0:
        return "crash", f"killed by {signal.Signals(-rc).name}"
    if rc >= 128:
        return "crash", f"exit code {rc} (signal {rc - 128}?)"
    lines = [line for line in stderr.splitlines() if line.strip()]
    if rc != 0:
        noise = [m for m in NOISE if m in stderr or m in stdout]
        if re.search(r"^-{20,}$", stderr + "\n" + stdout, re.M):
            noise.append("deal.II exception block")
        if not lines:
            return "noisy refusal", "no message on stderr"
        if len(lines) > 3 or noise or not lines[-1].startswith("rollnip: error"):
            why = [f"{len(lines)} stderr lines"] + noise
            return "noisy refusal", ", ".join(why)
        return "clean refusal", f"{len(lines)} stderr line(s)"
    problems = insanity(case_dir, stdout)
    if kind in EXPECT_WARNING and not any(
            line.startswith("rollnip: warning:") and re.search(EXPECT_WARNING[kind], line)
            for line in lines):
        problems.append(f"silent: no warning matching /{EXPECT_WARNING[kind]}/")
    if problems:
        return "exit 0 but not sane", "; ".join(problems)
    return "exit 0 and sane", ("stderr: " + lines[-1]) if lines else ""


def binary_stamp(path):
    st = os.stat(path)
    digest = hashlib.sha256(open(path, "rb").read()).hexdigest()[:12]
    return f"{time.strftime('%Y-%m-%d %H:%M:%S', time.localtime(st.st_mtime))}, sha256 {digest}"


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    parser.add_argument("n", nargs="?", type=int, default=300)
    parser.add_argument("seed", nargs="?", type=int, default=1)
    parser.add_argument("--timeout", type=float, default=60)
    parser.add_argument("--kinds", default="",
                        help="comma-separated mutation kinds to run (default: all)")
    args = parser.parse_args()
    kinds_run = [k.strip() for k in args.kinds.split(",") if k.strip()] or KINDS
    unknown = sorted(set(kinds_run) - set(KINDS))
    if unknown:
        parser.error(f"unknown kinds: {', '.join(unknown)}")
    rng = random.Random(args.seed)
    stamp = time.strftime("%Y%m%d-%H%M%S")
    keep_dir = os.path.join(RESULTS, f"fuzz-{stamp}")
    work = tempfile.mkdtemp(prefix="rollnip-fuzz-")
    binary = os.path.join(work, "rollnip")
    shutil.copy2(ROLLNIP, binary)
    used = binary_stamp(binary)
    print(f"rollnip: {ROLLNIP} ({used}), copied to {binary}")
    print(f"cases: {args.n}, seed {args.seed}, timeout {args.timeout:g} s, work in {work}")
    entries = declared_entries(binary)
    bases = {os.path.basename(p): open(p).read().splitlines()
             for p in sorted(glob.glob(os.path.join(ROOT, "parameters", "*.prm")))}
    # Kinds in shuffled rounds: every kind gets about N / len(KINDS) cases.
    kinds = []
    while len(kinds) < args.n:
        kinds += rng.sample(kinds_run, len(kinds_run))
    records, start = [], time.time()
    for n, kind in enumerate(kinds[:args.n], 1):
        case = None
        while case is None:
            base = rng.choice(sorted(bases))
            case = make_case(rng, kind, bases[base], entries, base)
        text, what, files = case
        case_dir = os.path.join(work, f"case-{n:03d}")
        os.makedirs(case_dir)
        open(os.path.join(case_dir, "case.prm"), "w").write(text)
        for name, content in files.items():
            open(os.path.join(case_dir, name), "w").write(content)
        rc, seconds, stdout, stderr = run(binary, case_dir, args.timeout)
        cls, detail = classify(rc, stdout, stderr, case_dir, args.timeout, kind)
        lines = [line for line in stderr.splitlines() if line.strip()]
        record = dict(case=n, base=base, kind=kind, mutation=what,
                      exit="timeout" if rc is None else rc, seconds=f"{seconds:.1f}",
                      cls=cls, detail=detail, last_stderr=lines[-1] if lines else "")
        records.append(record)
        print(f"{n:4d}/{args.n} {kind:18s} {base:24s} {cls:20s} {seconds:5.1f} s", flush=True)
        if cls in FAILING or (rc == 0 and lines):
            dest = os.path.join(keep_dir, f"case-{n:03d}")
            os.makedirs(dest)
            for name in ["case.prm", "stdout.txt", "stderr.txt"] + list(files):
                shutil.copy2(os.path.join(case_dir, name), dest)
        shutil.rmtree(case_dir)  # outputs are not needed once classified
    elapsed = time.time() - start

    print(f"\n{args.n} cases in {elapsed:.0f} s (seed {args.seed})\n")
    count = {c: sum(r["cls"] == c for r in records) for c in CLASSES}
    for c in CLASSES:
        print(f"  {c:22s} {count[c]:5d}")
    clean = [r for r in records if r["cls"] == "clean refusal"]
    multi = sum(not r["detail"].startswith("1 ") for r in clean)
    long = sum(len(r["last_stderr"]) > 300 for r in clean)
    print(f"  (clean refusals with more than one stderr line: {multi}, with a line over 300"
          f" characters: {long})")
    # The classes judge the results; text on stderr of a successful run is listed apart.
    chatty = [r for r in records if r["exit"] == 0 and r["last_stderr"]]
    print(f"  (exit 0 with text on stderr: {len(chatty)})")
    short = ["clean", "noisy", "crash", "hang", "sane", "not sane"]
    print("\n" + f"{'kind':20s}" + "".join(f"{s:>9s}" for s in short))
    table = []
    for kind in KINDS:
        row = [sum(r["kind"] == kind and r["cls"] == c for r in records) for c in CLASSES]
        table.append([kind] + row)
        print(f"{kind:20s}" + "".join(f"{x:9d}" for x in row))
    failing = [r for r in records if r["cls"] in FAILING]
    print(f"\nfailing cases: {len(failing)}" + (" (first 20)" if len(failing) > 20 else ""))
    for r in failing[:20]:
        print(f"  case-{r['case']:03d} [{r['cls']}] {r['kind']}, {r['base']}: {r['mutation']}")
        print(f"      exit {r['exit']}; {r['detail']}")
        print(f"      last stderr: {r['last_stderr'][:200]}")
    if chatty:
        more = " (first 20)" if len(chatty) > 20 else ""
        print(f"\nexit 0 with text on stderr: {len(chatty)}{more}")
    for r in chatty[:20]:
        print(f"  case-{r['case']:03d} [{r['cls']}] {r['kind']}, {r['base']}: {r['mutation']}")
        print(f"      last stderr: {r['last_stderr'][:200]}")
    os.makedirs(RESULTS, exist_ok=True)
    summary_csv = os.path.join(RESULTS, f"fuzz-{stamp}.csv")
    with open(summary_csv, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(["kind"] + CLASSES)
        w.writerows(table)
        w.writerow(["total"] + [count[c] for c in CLASSES])
    os.makedirs(keep_dir, exist_ok=True)
    with open(os.path.join(keep_dir, "cases.csv"), "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(records[0]) if records else ["case"])
        w.writeheader()
        w.writerows(records)
    shutil.rmtree(work)
    if not os.path.exists(ROLLNIP) or binary_stamp(ROLLNIP) != used:
        print(f"note: {ROLLNIP} changed during the run; the copy made at the start was used")
    print(f"\ntable: {summary_csv}\ncases: {keep_dir}/cases.csv"
          f" (failing cases kept there as case-NNN/)")
    only = f" --kinds {args.kinds}" if args.kinds else ""
    print(f"run: python3 benchmarks/fuzz_inputs.py {args.n} {args.seed}"
          f" --timeout {args.timeout:g}{only}; {elapsed:.0f} s")
    return 0


if __name__ == "__main__":
    sys.exit(main())
