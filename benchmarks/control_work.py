#!/usr/bin/env python3
"""The work of load and indentation control on the default scene
(parameters/batra1980.prm: run-30 geometry, Rbar = 76.2 mm), counted and
timed, for one binary or two side by side.

Usage: python3 benchmarks/control_work.py [N]
    N   timed runs per case and binary, default 3 (median wall time)

Uses build/rollnip, or $ROLLNIP_BIN; with $ROLLNIP_BEFORE (another build,
e.g. of an older version) both run, their runs interleaved so that a busy
machine slows both alike, and the table gives the ratios.

Cases: u0 = 0.5, 1, 2, 3 mm under indentation control and P = 2.21, 6.33,
20.0, 41.1 N/mm under load control (the same nips), each with Q1-P0 at
level 2 (the default mesh) and with Q2-P1 at level 0 with 4 edge
refinements; and the accuracy target 0.1 % on "P, 2b" under both modes
(primary and error-estimate companion). Columns per binary: contact solves
(one inverse iteration at one theta0, counted from the screen), Newton
iterations of the run's own mesh (= factorisations, from the last nip's
summary.txt; a target run's companion solves are not in it) and the
median wall time of the whole process [s].
"""

import os
import re
import statistics
import sys
import tempfile

from prm_run import run_prm

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BASE = os.path.join(ROOT, "parameters", "batra1980.prm")
INDENTATIONS = "0.5, 1, 2, 3"
LOADS = "2.21, 6.33, 20.0, 41.1"
CASES = [  # name, mode, values, element, level, edge refinements, target
    ("indentation Q1-P0 level 2", "indentation", INDENTATIONS, "Q1-P0", 2, 0,
     None),
    ("load Q1-P0 level 2", "load", LOADS, "Q1-P0", 2, 0, None),
    ("indentation Q2-P1 level 0 K=4", "indentation", INDENTATIONS, "Q2-P1",
     0, 4, None),
    ("load Q2-P1 level 0 K=4", "load", LOADS, "Q2-P1", 0, 4, None),
    ("indentation target 0.1 % (P, 2b)", "indentation", INDENTATIONS,
     "Q1-P0", 2, 0, "0.1 %"),
    ("load target 0.1 % (P, 2b)", "load", LOADS, "Q1-P0", 2, 0, "0.1 %"),
]


def fail(message):
    print("control_work: error: " + message, file=sys.stderr)
    sys.exit(1)


def run(binary, directory, case):
    name, mode, values, element, level, k, target = case
    accuracy = (f"subsection Accuracy\n  set Target = {target}\n"
                f"  set Target quantities = P, 2b\nend\n" if target else "")
    text = open(BASE).read() + f"""
# --- benchmark overrides ---
subsection Mesh
  set Global refinements = {level}
  set Edge refinements = {k}
end
subsection Discretization
  set Element = {element}
end
subsection Contact
  set Mode = {mode}
  set Values = {values}
  set Compare with linear theory = false
end
{accuracy}"""
    wall, _, p = run_prm(binary, directory, text)
    if p.returncode != 0:
        fail(f"{binary} failed on '{name}': {p.stderr.strip()}")
    solves = sum(1 for line in p.stdout.splitlines()
                 if line.startswith("Contact iteration, theta0"))
    newton = None
    last = os.path.join(directory, "out", "nip-04", "summary.txt")
    for line in open(last):
        m = re.match(r"newton_iterations = (\d+)", line)
        if m:
            newton = int(m.group(1))
    return wall, solves, newton


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    if n < 1:
        fail("N must be a positive integer")
    binaries = [os.environ.get("ROLLNIP_BIN",
                               os.path.join(ROOT, "build", "rollnip"))]
    if os.environ.get("ROLLNIP_BEFORE"):
        binaries.insert(0, os.environ["ROLLNIP_BEFORE"])
    for b in binaries:
        if not os.access(b, os.X_OK):
            fail(f"{b} not found; build it with: bash scripts/setup.sh")
    print(f"rollnip control work: {n} run(s) per case (median wall time), "
          f"1 MPI process; binaries: {', '.join(binaries)}")
    header = ["case"]
    for i, _ in enumerate(binaries):
        tag = "" if len(binaries) == 1 else (" before", " after")[i]
        header += [f"solves{tag}", f"Newton{tag}", f"wall s{tag}"]
    if len(binaries) == 2:
        header += ["Newton after/before", "wall after/before"]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    with tempfile.TemporaryDirectory(prefix="rollnip-control-work.") as tmp:
        for case in CASES:
            results = [[] for _ in binaries]
            for _ in range(n):
                for i, b in enumerate(binaries):
                    results[i].append(run(b, tmp, case))
            row = [case[0]]
            summary = []
            for r in results:
                wall = statistics.median(x[0] for x in r)
                row += [r[0][1], r[0][2], f"{wall:.2f}"]
                summary.append((r[0][2], wall))
            if len(binaries) == 2:
                row += [f"{summary[1][0] / summary[0][0]:.2f}",
                        f"{summary[1][1] / summary[0][1]:.2f}"]
            print("| " + " | ".join(str(x) for x in row) + " |", flush=True)


if __name__ == "__main__":
    main()
