#!/usr/bin/env python3
"""What a second deformable roll costs: the nip of two identical covered
rolls against the nip of one of them on a rigid plane (the same nip, by
symmetry), with the same mesh on every roll, at theta0 = 4 and 8 deg and
Global refinements 1 to 3.

Usage: python3 benchmarks/two_roll_benchmark.py [N]
    N   timed runs per case, default 3 (the table shows the median wall time)

Uses build/rollnip, or $ROLLNIP_BIN. Columns: the DoFs of one roll, the
wall time of the whole process (median of N), the contact solves (inverse
iterations of the first roll, counted from the 'Contact iteration, theta0'
lines) and their Newton iterations (the rows of the iteration tables), the
two-roll passes, and P [N/mm]. Prints the table and writes it to
benchmarks/results/two_roll_benchmark.csv.
"""

import csv
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
BIN = os.environ.get("ROLLNIP_BIN", os.path.join(ROOT, "build", "rollnip"))


def scene(level, theta0, two_rolls, directory):
    mate = ("subsection Mating roll\n set Type = covered roll\n"
            " subsection Mesh\n  set Global refinements = %d\n end\nend\n"
            % level) if two_rolls else ""
    indenter = "" if two_rolls else " set Indenter radius = inf\n"
    return ("subsection Mesh\n set Global refinements = %d\nend\n"
            "subsection Contact\n set Mode = nip angle\n set Values = %g\n"
            " set Compare with linear theory = false\n%send\n%s"
            "subsection Output\n set Directory = %s\n set Write VTU = false\n"
            " set Print timing = false\nend\n"
            % (level, theta0, indenter, mate, directory))


def run(level, theta0, two_rolls, repeats):
    times, out = [], ""
    with tempfile.TemporaryDirectory() as tmp:
        prm = os.path.join(tmp, "scene.prm")
        with open(prm, "w") as f:
            f.write(scene(level, theta0, two_rolls, os.path.join(tmp, "out")))
        for _ in range(repeats):
            start = time.perf_counter()
            result = subprocess.run([BIN, prm], capture_output=True,
                                    text=True, check=True)
            times.append(time.perf_counter() - start)
            out = result.stdout
    dofs = int(re.search(r"(\d+) DoFs", out).group(1))
    solves = len(re.findall(r"^Contact iteration, theta0", out, re.M))
    newton = len(re.findall(r"^ +\d+ +\d\.\d+e[-+]\d+ +\d", out, re.M))
    passes = len(re.findall(r"^  pass \d+:", out, re.M))
    match = re.findall(r"^ +%.4f +(\d+\.\d+)" % theta0, out, re.M)
    load = float(match[-1]) if match else float("nan")
    return dict(dofs=dofs, wall_s=statistics.median(times), solves=solves,
                newton=newton, passes=passes, P=load)


def main():
    repeats = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    rows = []
    print("%6s %6s %-18s %7s %8s %7s %7s %7s %10s %12s" %
          ("level", "theta0", "scene", "DoFs", "wall s", "solves", "Newton",
           "passes", "P [N/mm]", "time ratio"))
    for level in (1, 2, 3):
        for theta0 in (4, 8):
            plane = run(level, theta0, False, repeats)
            two = run(level, theta0, True, repeats)
            for name, r in (("roll on plane", plane), ("two rolls", two)):
                ratio = r["wall_s"] / plane["wall_s"]
                print("%6d %6g %-18s %7d %8.2f %7d %7d %7d %10.5f %12.2f" %
                      (level, theta0, name, r["dofs"], r["wall_s"],
                       r["solves"], r["newton"], r["passes"], r["P"], ratio))
                rows.append(dict(level=level, theta0_deg=theta0, scene=name,
                                 time_ratio=ratio, **r))
    os.makedirs(os.path.join(ROOT, "benchmarks", "results"), exist_ok=True)
    with open(os.path.join(ROOT, "benchmarks", "results",
                           "two_roll_benchmark.csv"), "w", newline="") as f:
        writer = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        writer.writeheader()
        writer.writerows(rows)


if __name__ == "__main__":
    main()
