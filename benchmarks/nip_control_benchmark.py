#!/usr/bin/env python3
"""What load and indentation control cost, and what the mesh gives for it,
on the default scene (parameters/batra1980.prm: run-30 geometry, Rbar =
76.2 mm, Q1-P0).

Usage: python3 benchmarks/nip_control_benchmark.py [N]
    N   timed runs per sweep, default 3 (the table shows the median wall time)

Uses build/rollnip, or $ROLLNIP_BIN (e.g. a build of an older version, for a
before/after). Prints two tables and writes them as CSV to
benchmarks/results/:

1. Sweeps: four indentations u0 = 0.5, 1, 2, 3 mm at level 1 and ten loads
   P = 1 ... 20 N/mm (geometric) at level 2, each one run of rollnip with
   all targets in Contact/Values. Columns: targets reached, contact solves
   per target (median and largest; a contact solve is one inverse iteration
   at one theta0, counted from the 'Contact iteration, theta0' lines), and
   the wall time of the whole process (median of N).
2. Accuracy: P, u0 and the peak pressure at theta0 = 2, 4, 6, 7.371101,
   10 and 12 deg (one run per mesh and level) at levels 0 to 3 with the
   nip-fitted mesh (Mesh/Nip fitting = on) and with the fixed graded mesh
   (off), against the nip-fitted level-4 values: the largest error over the
   six nips per mesh and level, and the error of P at each nip (on the
   fixed mesh it depends on where theta0 falls between surface nodes). A binary without the
   Nip fitting entry runs the fixed mesh only.
"""

import csv
import math
import os
import re
import statistics
import subprocess
import sys
import tempfile
import time

from prm_run import run_prm

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROLLNIP = os.environ.get("ROLLNIP_BIN", os.path.join(ROOT, "build", "rollnip"))
BASE = os.path.join(ROOT, "parameters", "batra1980.prm")
LOADS = [1 * 20 ** (i / 9) for i in range(10)]
SWEEPS = [("4 indentations", "indentation", [0.5, 1, 2, 3], 1),
          ("10 loads", "load", LOADS, 2)]
THETAS = [2, 4, 6, 7.371101, 10, 12]  # deg


def fail(message):
    print("nip_control_benchmark: error: " + message, file=sys.stderr)
    sys.exit(1)


def run(directory, mode, values, level, fitting=None):
    text = open(BASE).read() + f"""
# --- benchmark overrides ---
subsection Mesh
  set Global refinements = {level}
{f'  set Nip fitting = {fitting}' if fitting else ''}
end
subsection Contact
  set Mode = {mode}
  set Values = {', '.join(f'{v:.6g}' for v in values)}
  set Compare with linear theory = false
end
"""
    wall, _, p = run_prm(ROLLNIP, directory, text)
    return wall, p


def solves_per_target(stdout):
    """Contact solves before each 'Nip n:' line (one per reached target)."""
    counts, n = [], 0
    for line in stdout.splitlines():
        if line.startswith("Contact iteration, theta0"):
            n += 1
        elif re.match(r"Nip \d+: P from", line):
            counts.append(n)
            n = 0
    return counts


def nip_results(directory, n):
    """P [N/mm], u0 [mm] and peak f [MPa] of the nips 1..n, from their
    summary.txt (full precision)."""
    keys = ("nip_load_P_N_per_mm", "indentation_u0_mm",
            "peak_applied_pressure_MPa")
    results = []
    for i in range(1, n + 1):
        path = os.path.join(directory, "out", f"nip-{i:02d}", "summary.txt")
        values = {}
        if os.path.exists(path):
            for line in open(path):
                key, _, value = line.partition(" = ")
                values[key.strip()] = value.strip()
        results.append([float(values.get(k, "nan")) for k in keys])
    return results


def print_table(header, rows):
    """A Markdown table, as doc/accuracy.md quotes it."""
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for r in rows:
        print("| " + " | ".join(str(x) for x in r) + " |")


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    if n < 1:
        fail("N must be a positive integer")
    if not os.access(ROLLNIP, os.X_OK):
        fail(f"{ROLLNIP} not found; build it with: bash scripts/setup.sh")
    has_fitting = "Nip fitting" in subprocess.run(
        [ROLLNIP, "--print-parameters"], capture_output=True, text=True).stdout
    print(f"rollnip nip control benchmark: {ROLLNIP}, {n} run(s) per sweep "
          f"(median), 1 MPI process, nproc {os.cpu_count()}, nip-fitted mesh "
          f"{'available (default)' if has_fitting else 'not available'}")
    sweep_header = ["sweep", "level", "targets reached", "solves/target median",
                    "solves/target max", "wall s"]
    sweep_rows = []
    with tempfile.TemporaryDirectory(prefix="rollnip-control-bench.") as tmp:
        for name, mode, values, level in SWEEPS:
            runs = [run(tmp, mode, values, level) for _ in range(n)]
            counts = solves_per_target(runs[0][1].stdout)
            wall = statistics.median(r[0] for r in runs)
            sweep_rows.append([name, level, f"{len(counts)} of {len(values)}",
                               statistics.median(counts) if counts else "-",
                               max(counts) if counts else "-", f"{wall:.2f}"])
            print("| " + " | ".join(str(x) for x in sweep_rows[-1]) + " |",
                  flush=True)
        accuracy_header = ["mesh", "level", "DoFs", "max |error P|",
                           "max |error u0|", "max |error peak f|"]
        accuracy_rows, p_error_rows = [], []
        meshes = ["on", "off"] if has_fitting else [None]
        reference = None
        if has_fitting:
            _, p = run(tmp, "nip angle", THETAS, 4, "on")
            reference = nip_results(tmp, len(THETAS))
        for mesh in meshes:
            for level in range(4):
                _, p = run(tmp, "nip angle", THETAS, level, mesh)
                dofs = re.search(r"Mesh: \d+ cells, (\d+) DoFs", p.stdout)
                results = nip_results(tmp, len(THETAS))
                label = {"on": "nip-fitted", "off": "fixed", None: "fixed"}[mesh]
                row = [label, level, dofs.group(1) if dofs else "-"]
                if reference:
                    errors = [[v / r - 1 for v, r in zip(nip, ref)]
                              for nip, ref in zip(results, reference)]
                    # A nip that did not converge has no summary: "failed".
                    ok = [e for e in errors if all(math.isfinite(x) for x in e)]
                    row += [f"{max(abs(e[k]) for e in ok):.2e}" if ok else "-"
                            for k in range(3)]
                    if len(ok) < len(errors):
                        row[-1] += f" ({len(errors) - len(ok)} nip(s) failed)"
                    p_error_rows.append([label, level]
                                        + [f"{e[0]:+.2e}" if math.isfinite(e[0])
                                           else "failed" for e in errors])
                else:
                    row += ["-"] * 3
                accuracy_rows.append(row)
    print()
    print_table(sweep_header, sweep_rows)
    thetas = ", ".join(f"{t:g}" for t in THETAS)
    print(f"\nAccuracy over theta0 = {thetas} deg against the nip-fitted "
          "level 4 (largest relative error of the six nips)")
    print_table(accuracy_header, accuracy_rows)
    p_error_header = ["mesh", "level"] + [f"P error at {t:g} deg" for t in THETAS]
    if p_error_rows:
        print("\nRelative error of P at each theta0"
              + "".join(f"; reference P({t:g}) = {r[0]:.6f} N/mm"
                        for t, r in zip(THETAS, reference)))
        print_table(p_error_header, p_error_rows)
    os.makedirs(os.path.join(ROOT, "benchmarks", "results"), exist_ok=True)
    out = os.path.join(ROOT, "benchmarks", "results",
                       time.strftime("nip-control-%Y%m%d-%H%M%S.csv"))
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(sweep_header)
        w.writerows(sweep_rows)
        w.writerow([])
        w.writerow(accuracy_header)
        w.writerows(accuracy_rows)
        w.writerow([])
        w.writerow(p_error_header)
        w.writerows(p_error_rows)
    print(f"\nwritten: {os.path.relpath(out, ROOT)}")


if __name__ == "__main__":
    main()
