#!/usr/bin/env python3
"""P at a prescribed theta0 with the cells about the contact edge refined.

With Mode = nip angle the contact edge is a vertex of the nip-fitted mesh,
and the size of the cells touching it sets a first-order error of P and u0
(doc/accuracy.md, "Refinement at the contact edge"). This runs the default
scene (parameters/batra1980.prm) at theta0 = 4, 8, 12 deg (Control and
Conformity tolerance 1e-9, no error estimate) with Mesh/Edge refinements
K: Q2-P1 at levels 0-2 for K = 0 to 6, Q1-P0 at levels 0-2 for K = 0 and
4, and Q2-P1 on the halved coarse mesh of Accuracy/Target (4 x 11 cells,
5 in the nip) at levels 0-3 for K = 4. It prints, against the reference,
each run's relative error of P, and the P that an accuracy target
extrapolates at order 1 from levels L-1 and L, with its estimate from
level L-2 (every L from 2 up) (over 2^2 - 1 for Q2-P1, 2^1.5 - 1 for Q1-P0) and the
effectivity (estimate over |error|).

The reference is that of benchmarks/nip_angle_reference.py, from the
other element family for each run: Q1-P0 at levels 3 to 5 extrapolated
at orders 1 and 2 (for Q2-P1 runs) and Q2-P1 at levels 2 to 4 the same
way (for Q1-P0 runs); they differ by 3e-6 to 2e-5.

With --target it then runs Accuracy/Target = 1 %, 0.1 % and 0.01 % on P
at the three nips (one thread; CPU time per nip of the whole run, start-up
included, median of ROLLNIP_REPEAT runs, 1 by default) and measures the
answer against the reference; --target-only runs those alone.

Usage: python3 benchmarks/edge_refinements.py [--target | --target-only]
Uses build/rollnip or $ROLLNIP_BIN (about 5 min on one core). Prints
Markdown tables.
"""

import csv
import os
import re
import resource
import statistics
import subprocess
import sys
import tempfile

sys.path.insert(0, os.path.dirname(os.path.abspath(__file__)))
from nip_angle_reference import THETA0, write_prm  # noqa: E402

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROLLNIP = os.environ.get("ROLLNIP_BIN", os.path.join(ROOT, "build", "rollnip"))
BASE = os.path.join(ROOT, "parameters", "batra1980.prm")
# P [N/mm] at theta0 from benchmarks/nip_angle_reference.py, per family.
REFERENCE = {"Q1-P0": {4: 1.8805032, 8: 10.5761461, 12: 41.7311353},
             "Q2-P1": {4: 1.8805088, 8: 10.5762384, 12: 41.7319318}}
NEXT_ORDER = {"Q1-P0": 1.5, "Q2-P1": 2}
HALVED_MESH = """  set Radial cells          = 4
  set Circumferential cells = 11
  set Nip cells             = 5
"""
CASES = ([("Q2-P1", k, "file", 3) for k in range(7)] +
         [("Q1-P0", k, "file", 3) for k in (0, 4)] +
         [("Q2-P1", 4, "halved", 4)])


def reference(element, t):
    """The other family's reference P at theta0 = t."""
    return REFERENCE["Q1-P0" if element == "Q2-P1" else "Q2-P1"][t]


def run(element, k, mesh, level, work):
    """P at each theta0 of one run: {theta0: P}."""
    name = f"{element}-{mesh}-k{k}-{level}"
    out = os.path.join(work, name)
    write_prm(os.path.join(work, name + ".prm"), out, base=BASE, extra=f"""
subsection Mesh
  set Global refinements = {level}
  set Edge refinements   = {k}
{HALVED_MESH if mesh == "halved" else ""}end
subsection Discretization
  set Element = {element}
end
subsection Accuracy
  set Error estimate = false
end
""")
    subprocess.run([ROLLNIP, os.path.join(work, name + ".prm")], check=True,
                   stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "nip_characteristic.csv")) as f:
        return {round(float(r["theta0_deg"])): float(r["P_N_per_mm"])
                for r in csv.DictReader(f)}


def targets():
    """Accuracy/Target on P at the three nips against the reference."""
    repeat = int(os.environ.get("ROLLNIP_REPEAT", "1"))
    print("\n| target | chosen | CPU s per nip | largest estimate | "
          "largest error |")
    print("|---|---|---|---|---|")
    for target in ["1 %", "0.1 %", "0.01 %"]:
        times = []
        with tempfile.TemporaryDirectory() as work:
            out = os.path.join(work, "out")
            prm = os.path.join(work, "target.prm")
            write_prm(prm, out, base=BASE, extra=f"""
subsection Accuracy
  set Target = {target}
  set Target quantities = P
end
""")
            for _ in range(repeat):
                before = resource.getrusage(resource.RUSAGE_CHILDREN)
                screen = subprocess.run(
                    [ROLLNIP, prm], check=True, capture_output=True,
                    text=True, env=dict(os.environ, OMP_NUM_THREADS="1",
                                        DEAL_II_NUM_THREADS="1")).stdout
                after = resource.getrusage(resource.RUSAGE_CHILDREN)
                times.append(after.ru_utime + after.ru_stime -
                             before.ru_utime - before.ru_stime)
            chosen = re.search(r"met with (.*) after", screen)
            element = "Q1-P0" if "Q1-P0" in (chosen.group(1) if chosen
                                             else "") else "Q2-P1"
            values = os.path.join(out, "accuracy_target_values.csv")
            path = values if os.path.exists(values) else \
                os.path.join(out, "nip_characteristic.csv")
            with open(path) as f:
                rows = list(csv.DictReader(f))
        error = max(abs(float(r["P_N_per_mm"]) /
                        reference(element, round(float(r["theta0_deg"]))) -
                        1) for r in rows)
        estimate = max(float(r["P_err_N_per_mm"]) / abs(float(r["P_N_per_mm"]))
                       for r in rows)
        print(f"| {target} | {chosen.group(1) if chosen else 'not met'} | "
              f"{statistics.median(times) / len(rows):.2f} | "
              f"{estimate:.1e} | {error:.1e} |")


def main():
    if "--target-only" in sys.argv[1:]:
        targets()
        return
    with tempfile.TemporaryDirectory() as work:
        runs = {(e, k, m): [run(e, k, m, level, work) for level in range(n)]
                for e, k, m, n in CASES}

    print("| element | mesh | edge refinements | theta0 [deg] | "
          "P error at levels 0, 1, ... | extrapolated from levels | error | "
          "estimate | effectivity |")
    print("|---|---|---|---|---|---|---|---|---|")
    for (e, k, m), levels in runs.items():
        f = 2 ** NEXT_ORDER[e] - 1
        for t in THETA0:
            ref = reference(e, t)
            v = [r[t] for r in levels]
            errors = ", ".join(f"{x / ref - 1:+.1e}" for x in v)
            x = [2 * v[i + 1] - v[i] for i in range(len(v) - 1)]
            for last in range(2, len(v)):
                estimate = abs(x[last - 1] - x[last - 2]) / f / abs(x[last - 1])
                error = x[last - 1] / ref - 1
                print(f"| {e} | {m} | {k} | {t} | {errors} | {last - 2} to "
                      f"{last} | {error:+.1e} | {estimate:.1e} | "
                      f"{estimate / abs(error):.2f} |")

    if "--target" in sys.argv[1:]:
        targets()


if __name__ == "__main__":
    main()
