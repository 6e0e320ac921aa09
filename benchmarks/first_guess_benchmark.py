#!/usr/bin/env python3
"""What a cold load or indentation target costs: one rollnip run per target
(Contact/Values holds one value, so nothing is known before it), over a grid
of targets and four covers, at mesh level 2 (Error estimate off).

Usage: python3 benchmarks/first_guess_benchmark.py [LEVEL [COVER ...]]
    LEVEL   Mesh/Global refinements of every run, default 2
    COVER   thin, thick, layered or 'two rolls'; default all four

Uses build/rollnip, or $ROLLNIP_BIN (e.g. a build of an older version, for a
before/after). Covers:
    thin      parameters/batra1980.prm with Inner radius 57.7 (h = 3 mm),
              3 radial cells
    thick     parameters/batra1980.prm (Spengos run 30: R1 47.2, R0 60.7)
    layered   parameters/layered_cover.prm
    two rolls parameters/two_rolls.prm (a single target: the level-0
              guess with both rolls at level 0)
Targets: P = 0.5, 2, 5, 10, 20, 40, 80 N/mm; u0 = 1, 3, 10, 20, 30 % of the
cover thickness (the roll's; 10 % ... of 13.5 mm for two rolls).

For each target the table gives the contact solves on the run's mesh (the
'Outer iteration' lines), the contact solves on the level-0 mesh
that gave the first guess (from the 'First guess from mesh level 0' line;
0 for a binary without it), and the ratio of the solve time to that of one
nip-angle run at the theta0 found (both timed from the 'Mesh:' line to the
'Nip 1:' line of the run's standard output, so start-up and files are
out). The last rows are the means per cover and mode. The CSV goes to
benchmarks/results/.
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
ROLLNIP = os.environ.get("ROLLNIP_BIN", os.path.join(ROOT, "build", "rollnip"))
PRM = os.path.join(ROOT, "parameters")
THIN = """
subsection Geometry
  set Inner radius = 57.7
end
subsection Mesh
  set Radial cells = 3
end
"""
# name, parameter file, overrides, cover thickness [mm]
COVERS = [("thin", "batra1980.prm", THIN, 3.0),
          ("thick", "batra1980.prm", "", 13.5),
          ("layered", "layered_cover.prm", "", 13.5),
          ("two rolls", "two_rolls.prm", "", 13.5)]
LOADS = [0.5, 2, 5, 10, 20, 40, 80]
INDENTATION_FRACTIONS = [0.01, 0.03, 0.1, 0.2, 0.3]


def fail(message):
    print("first_guess_benchmark: error: " + message, file=sys.stderr)
    sys.exit(1)


def run(directory, cover, mode, value, level):
    """Runs one target; returns (stdout lines with their times, rc)."""
    _, prm, overrides, _ = cover
    text = open(os.path.join(PRM, prm)).read() + overrides + f"""
# --- benchmark overrides ---
subsection Mesh
  set Global refinements = {level}
end
subsection Contact
  set Mode = {mode}
  set Values = {value:.10g}
  set Compare with linear theory = false
end
subsection Accuracy
  set Error estimate = false
end
subsection Output
  set Directory = {directory}/out
  set Write VTU = false
  set Print timing = false
end
"""
    if "Mating roll" in text:
        text += f"""
subsection Mating roll
  subsection Mesh
    set Global refinements = {level}
  end
end
"""
    path = os.path.join(directory, "run.prm")
    with open(path, "w") as f:
        f.write(text)
    p = subprocess.Popen([ROLLNIP, path], stdout=subprocess.PIPE,
                         stderr=subprocess.PIPE, text=True, bufsize=1)
    lines = [(time.perf_counter(), line) for line in p.stdout]
    p.stderr.read()
    return lines, p.wait()


def solve_seconds(lines):
    """Time from the 'Mesh:' line to the 'Nip 1:' line, None if absent."""
    start = next((t for t, l in lines if l.startswith("Mesh:")), None)
    end = next((t for t, l in lines if l.startswith("Nip 1:")), None)
    return end - start if start is not None and end is not None else None


def found_theta0(directory):
    for line in open(os.path.join(directory, "out", "contact.txt")):
        key, _, value = line.partition(" = ")
        if key.strip() == "half_nip_angle_theta0_deg":
            return float(value)
    return None


def main():
    level = int(sys.argv[1]) if len(sys.argv) > 1 else 2
    names = sys.argv[2:] or [c[0] for c in COVERS]
    unknown = set(names) - {c[0] for c in COVERS}
    if unknown:
        fail(f"unknown cover(s): {', '.join(sorted(unknown))}")
    if not os.access(ROLLNIP, os.X_OK):
        fail(f"{ROLLNIP} not found; build it with: bash scripts/setup.sh")
    print(f"rollnip first-guess benchmark: {ROLLNIP}, level {level}, "
          f"1 MPI process, one run per cold target")
    header = ["cover", "mode", "target", "theta0 deg", "solves",
              "coarse solves", "time / nip-angle solve"]
    rows, means = [], []
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    with tempfile.TemporaryDirectory(prefix="rollnip-guess-bench.") as tmp:
        for cover in [c for c in COVERS if c[0] in names]:
            grids = [("load", LOADS),
                     ("indentation",
                      [round(f * cover[3], 4) for f in INDENTATION_FRACTIONS])]
            for mode, targets in grids:
                counts, ratios = [], []
                for target in targets:
                    lines, rc = run(tmp, cover, mode, target, level)
                    text = [l for _, l in lines]
                    solves = sum(l.startswith("Outer iteration") for l in text)
                    coarse = 0
                    for l in text:
                        m = re.match(r"First guess from mesh level 0: .*\((\d+) "
                                     r"coarse contact solves", l)
                        if m:
                            coarse = int(m.group(1))
                    if rc != 0:
                        row = [cover[0], mode, target, "failed", solves,
                               coarse, "-"]
                    else:
                        theta = found_theta0(tmp)
                        t_control = solve_seconds(lines)
                        angle, _ = run(tmp, cover, "nip angle", theta, level)
                        t_angle = solve_seconds(angle)
                        ratio = t_control / t_angle if t_control and t_angle \
                            else float("nan")
                        counts.append(solves)
                        ratios.append(ratio)
                        row = [cover[0], mode, target, f"{theta:.4f}", solves,
                               coarse, f"{ratio:.2f}"]
                    rows.append(row)
                    print("| " + " | ".join(str(x) for x in row) + " |",
                          flush=True)
                if counts:
                    means.append([cover[0], mode,
                                  f"{len(counts)} of {len(targets)}",
                                  f"{statistics.mean(counts):.2f}",
                                  max(counts),
                                  f"{statistics.mean(ratios):.2f}"])
    mean_header = ["cover", "mode", "targets reached", "mean solves",
                   "max solves", "mean time / nip-angle solve"]
    print("\nMeans per cover and mode")
    print("| " + " | ".join(mean_header) + " |")
    print("|" + "---|" * len(mean_header))
    for r in means:
        print("| " + " | ".join(str(x) for x in r) + " |")
    os.makedirs(os.path.join(ROOT, "benchmarks", "results"), exist_ok=True)
    out = os.path.join(ROOT, "benchmarks", "results",
                       time.strftime("first-guess-%Y%m%d-%H%M%S.csv"))
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)
        w.writerow([])
        w.writerow(mean_header)
        w.writerows(means)
    print(f"\nwritten: {os.path.relpath(out, ROOT)}")


if __name__ == "__main__":
    main()
