#!/usr/bin/env python3
"""Times one nip with prescribed theta0 and one with prescribed load on the
default scene (parameters/batra1980.prm: run-30 geometry, Rbar = 76.2 mm) at
several mesh levels, and prints a table; also written as CSV to
benchmarks/results/.

Usage: python3 benchmarks/contact_benchmark.py [N [LEVELS]]
    N       timed runs per case, default 3 (the table shows the median)
    LEVELS  comma-separated Mesh/Global refinements, default 1,2

Uses build/rollnip (build it with: bash scripts/setup.sh), or $ROLLNIP_BIN. Each run reads a
copy of batra1980.prm with one Contact/Values entry, no linear companion and
no VTU, writing into a temporary directory.

Columns: DoFs; wall s (whole process, median of N); load steps, Newton
iterations, factorisations (numeric), analyses (symbolic) from summary.txt;
inverse solves (contact iterations' outer loop: 1 for a prescribed theta0);
contact its (Newton iterations of the last inverse solve); ratio = wall s /
(one assembly + one factorisation), with one assembly = time_assembly_s /
assemblies and one factorisation = time_linear_solve_s / linear_solves (the
linear-solve time includes the sensitivity back-substitutions, so this
overstates one factorisation a little and the ratio is a lower bound).
"""

import csv
import os
import re
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROLLNIP = os.environ.get("ROLLNIP_BIN", os.path.join(ROOT, "build", "rollnip"))
BASE = os.path.join(ROOT, "parameters", "batra1980.prm")
CASES = [("theta0 = 8 deg", "nip angle", "8"), ("P = 10 N/mm", "load", "10")]


def fail(message):
    print("contact_benchmark: error: " + message, file=sys.stderr)
    sys.exit(1)


def key_values(path):
    values = {}
    with open(path) as f:
        for line in f:
            if " = " in line and not line.startswith("#"):
                k, v = line.split(" = ", 1)
                values[k.strip()] = v.strip()
    return values


def make_prm(directory, level, mode, value):
    text = open(BASE).read()
    text += f"""
# --- benchmark overrides ---
subsection Mesh
  set Global refinements = {level}
end
subsection Contact
  set Mode = {mode}
  set Values = {value}
  set Compare with linear theory = false
end
subsection Output
  set Directory = {directory}/out
  set Write VTU = false
  set Print timing = false
end
"""
    path = os.path.join(directory, "run.prm")
    with open(path, "w") as f:
        f.write(text)
    return path


def run_once(directory, prm):
    shutil.rmtree(os.path.join(directory, "out"), ignore_errors=True)
    t0 = time.perf_counter()
    p = subprocess.run([ROLLNIP, prm], capture_output=True, text=True)
    wall = time.perf_counter() - t0
    if p.returncode != 0:
        fail(f"rollnip failed on {prm}:\n" + p.stdout[-2000:] + p.stderr[-2000:])
    summary = key_values(os.path.join(directory, "out", "summary.txt"))
    contact = key_values(os.path.join(directory, "out", "contact.txt"))
    inverse_solves = len(re.findall(r"^Contact iteration, theta0", p.stdout, re.M))
    return wall, summary, contact, inverse_solves


def main():
    n = int(sys.argv[1]) if len(sys.argv) > 1 else 3
    levels = [int(x) for x in (sys.argv[2] if len(sys.argv) > 2 else "1,2").split(",")]
    if n < 1:
        fail("N must be a positive integer")
    if not os.access(ROLLNIP, os.X_OK):
        fail(f"{ROLLNIP} not found; build it with: bash scripts/setup.sh")
    commit = subprocess.run(["git", "-C", ROOT, "rev-parse", "--short", "HEAD"],
                            capture_output=True, text=True).stdout.strip()
    print(f"rollnip contact benchmark: {os.path.relpath(BASE, ROOT)}, levels {levels}, "
          f"{n} run(s) per case (median), 1 MPI process, commit {commit}, nproc {os.cpu_count()}")
    header = ["level", "case", "DoFs", "wall s", "min s", "max s", "load steps", "Newton",
              "factorisations", "analyses", "inverse solves", "contact its",
              "assembly s", "one assembly s", "one factorisation s", "ratio", "P N/mm", "theta0 deg"]
    rows = []
    with tempfile.TemporaryDirectory(prefix="rollnip-contact-bench.") as tmp:
        for level in levels:
            for name, mode, value in CASES:
                prm = make_prm(tmp, level, mode, value)
                runs = [run_once(tmp, prm) for _ in range(n)]
                walls = sorted(r[0] for r in runs)
                median_wall = statistics.median(walls)
                wall, s, c, inverse = min(runs, key=lambda r: abs(r[0] - median_wall))
                one_assembly = float(s["time_assembly_s"]) / int(s["assemblies"])
                one_factorisation = float(s["time_linear_solve_s"]) / int(s["linear_solves"])
                rows.append([level, name, s["dofs"], f"{median_wall:.2f}", f"{walls[0]:.2f}",
                             f"{walls[-1]:.2f}", s["load_steps"], s["newton_iterations"],
                             s["linear_solves"], s.get("symbolic_factorisations", "-"), inverse,
                             c["contact_iterations"], f"{float(s['time_assembly_s']):.2f}",
                             f"{one_assembly:.4f}", f"{one_factorisation:.4f}",
                             f"{median_wall / (one_assembly + one_factorisation):.0f}",
                             c["nip_load_P_N_per_mm"], c["half_nip_angle_theta0_deg"]])
                print("| " + " | ".join(str(x) for x in rows[-1]) + " |", flush=True)
    print()
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for r in rows:
        print("| " + " | ".join(str(x) for x in r) + " |")
    os.makedirs(os.path.join(ROOT, "benchmarks", "results"), exist_ok=True)
    out = os.path.join(ROOT, "benchmarks", "results",
                       time.strftime("contact-%Y%m%d-%H%M%S.csv"))
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)
    print(f"\nwritten: {os.path.relpath(out, ROOT)}")


if __name__ == "__main__":
    main()
