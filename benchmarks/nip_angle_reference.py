#!/usr/bin/env python3
"""P and b at a prescribed theta0 against an independent reference.

With Mode = nip angle, P and the nip half-width b follow the contact edge
and converge at first order in the mesh size. This runs the default scene
(parameters/batra1980.prm) at theta0 = 4, 8, 12 deg with Q1-P0 at levels
0-5 and Q2-P1 at levels 0-4 (Control and Conformity tolerance 1e-9, the
error estimate on). Each element's reference is its three finest levels
extrapolated twice: at order 1 (X_L = 2 v_L - v_(L-1)) and then the last
two X at order 2 ((4 X_L - X_(L-1)) / 3). Every run is measured against
the *other* element's reference, whose uncertainty u is the two
families' difference plus the larger change of the second extrapolation.

Tables: the references; each run's true relative error and the
effectivity (estimate over |error|) of its error estimate; and the
numbers an accuracy target extrapolates from three levels (Accuracy/
Target, extrapolate_first_order()), with their estimates.

With --target it then runs Accuracy/Target = 1 %, 0.1 % and 0.01 % on P
at the same three nips (one thread; CPU time per nip of the whole run,
start-up included, median of ROLLNIP_REPEAT runs, 1 by default) and
measures each answer (the extrapolated one where the target chose
extrapolation) against the reference of the element family it did not
use.

Usage: [ROLLNIP_BASE=parameters/other.prm] python3
       benchmarks/nip_angle_reference.py [--target]
ROLLNIP_BASE: another scene, e.g. parameters/layered_cover.prm (its
Contact/Mode is replaced by nip angle).
Uses build/rollnip or $ROLLNIP_BIN (about 25 min on one core, 10 more
with --target). Prints Markdown tables and writes
benchmarks/results/nip_angle_reference[-SCENE].csv.
"""

import csv
import os
import re
import resource
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROLLNIP = os.environ.get("ROLLNIP_BIN", os.path.join(ROOT, "build", "rollnip"))
# The scene: parameters/batra1980.prm, or the parameter file in
# ROLLNIP_BASE (run with Mode = nip angle at THETA0).
BASE = os.environ.get("ROLLNIP_BASE",
                      os.path.join(ROOT, "parameters", "batra1980.prm"))
SCENE = os.path.splitext(os.path.basename(BASE))[0]
THETA0 = [4, 8, 12]  # deg
LEVELS = {"Q1-P0": range(6), "Q2-P1": range(5)}
# The order at which each element's order-1 extrapolation converges
# (extrapolated_order() in source/postprocess/error_estimate.cc).
NEXT_ORDER = {"Q1-P0": 1.5, "Q2-P1": 2}
QUANTITIES = [("P_N_per_mm", "P_err_N_per_mm", "P [N/mm]"),
              ("half_chord_mm", "half_chord_err_mm", "b [mm]")]


def write_prm(path, out, extra, base=BASE, tight=True):
    """The parameter file PATH: BASE at its nips THETA0 (Mode = nip angle)
    without the linear companion, its files in OUT without VTU or timing
    tables, then EXTRA; tight: Control and Conformity tolerance 1e-9."""
    tolerances = """
  set Control tolerance = 1e-9
  set Conformity tolerance = 1e-9""" if tight else ""
    with open(base) as b, open(path, "w") as f:
        f.write(b.read())
        f.write(f"""
subsection Contact
  set Mode = nip angle
  set Values = {", ".join(str(t) for t in THETA0)}
  set Compare with linear theory = false{tolerances}
end
subsection Output
  set Directory = {out}
  set Write VTU = false
  set Print timing = false
end
{extra}""")


def run(element, level, work):
    """The nip characteristic of one run: {theta0: row}."""
    out = os.path.join(work, f"{element}-{level}")
    prm = os.path.join(work, f"{element}-{level}.prm")
    write_prm(prm, out, f"""
subsection Mesh
  set Global refinements = {level}
end
subsection Discretization
  set Element = {element}
end
subsection Accuracy
  set Error estimate = true
end
""")
    subprocess.run([ROLLNIP, prm], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "nip_characteristic.csv")) as f:
        return {round(float(r["theta0_deg"])): r for r in csv.DictReader(f)}


def targets(reference):
    """Accuracy/Target on P at the three nips against the reference."""
    env = dict(os.environ, DEAL_II_NUM_THREADS="1", OMP_NUM_THREADS="1")
    repeat = int(os.environ.get("ROLLNIP_REPEAT", "1"))
    print("\n| target | chosen | CPU s per nip | largest estimate | "
          "largest true error of P |")
    print("|---|---|---|---|---|")
    for target in ["1 %", "0.1 %", "0.01 %"]:
        cpus = []
        for _ in range(repeat):
            with tempfile.TemporaryDirectory() as work:
                out = os.path.join(work, "out")
                prm = os.path.join(work, "target.prm")
                write_prm(prm, out, f"""
subsection Accuracy
  set Target = {target}
  set Target quantities = P
end
""", tight=False)
                r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
                p = subprocess.run([ROLLNIP, prm], env=env,
                                   capture_output=True, text=True)
                r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
                cpus.append(r1.ru_utime - r0.ru_utime
                            + r1.ru_stime - r0.ru_stime)
                chosen = re.search(r"met with (.*) after", p.stdout)
                values = os.path.join(out, "accuracy_target_values.csv")
                if not os.path.exists(values):
                    values = os.path.join(out, "nip_characteristic.csv")
                with open(values) as f:
                    rows = list(csv.DictReader(f))
                key = "P_err_N_per_mm"
                estimate = max(float(r.get(key) or "nan") /
                               float(r["P_N_per_mm"]) for r in rows)
                other = ("Q1-P0" if chosen and "Q2-P1" in chosen.group(1)
                         else "Q2-P1")
                error = max(abs(float(r["P_N_per_mm"]) /
                                reference[t, "P_N_per_mm"][other] - 1)
                            for r, t in zip(rows, THETA0))
        cpu = sorted(cpus)[len(cpus) // 2]
        print(f"| {target} | {chosen.group(1) if chosen else 'not met'} | "
              f"{cpu / len(THETA0):.2f} | {estimate:.1e} | {error:.1e} |",
              flush=True)


def main():
    with tempfile.TemporaryDirectory() as work:
        runs = {e: [run(e, l, work) for l in levels]
                for e, levels in LEVELS.items()}

    def values(e, t, key):
        return [float(r[t][key]) for r in runs[e]]

    def extrapolated(v):
        return [2 * v[i + 1] - v[i] for i in range(len(v) - 1)]

    reference = {}
    print("| theta0 [deg] | quantity | Q1-P0 reference | Q2-P1 reference "
          "| difference | u |")
    print("|---|---|---|---|---|---|")
    for t in THETA0:
        for key, _, label in QUANTITIES:
            ref, change = {}, 0
            for e in LEVELS:
                x = extrapolated(values(e, t, key))
                ref[e] = (4 * x[-1] - x[-2]) / 3
                change = max(change, abs(ref[e] / x[-1] - 1))
            d = ref["Q1-P0"] / ref["Q2-P1"] - 1
            reference[t, key] = dict(ref, u=abs(d) + change)
            print(f"| {t} | {label} | {ref['Q1-P0']:.7f} | "
                  f"{ref['Q2-P1']:.7f} | {d:+.1e} | {abs(d) + change:.1e} |")

    rows = []
    print("\n| element | level | theta0 [deg] | P error | estimate | "
          "effectivity | b error | estimate | effectivity |")
    print("|---|---|---|---|---|---|---|---|---|")
    for e in LEVELS:
        other = "Q2-P1" if e == "Q1-P0" else "Q1-P0"
        for level, r in enumerate(runs[e]):
            for t in THETA0:
                row = {"element": e, "level": level, "theta0_deg": t}
                cells = []
                for key, err_key, _ in QUANTITIES:
                    v = float(r[t][key])
                    error = v / reference[t, key][other] - 1
                    estimate = float(r[t][err_key]) / abs(v)
                    row[key + "_relative_error"] = error
                    row[key + "_estimate"] = estimate
                    cells += [f"{error:+.2e}", f"{estimate:.2e}",
                              f"{estimate / abs(error):.2f}"]
                if level >= 2:
                    # What an accuracy target extrapolates from levels
                    # level-2 to level.
                    f = 2 ** NEXT_ORDER[e] - 1
                    for key, _, _ in QUANTITIES:
                        v = values(e, t, key)[level - 2:level + 1]
                        x = 2 * v[2] - v[1]
                        row[key + "_extrapolated_relative_error"] = \
                            x / reference[t, key][other] - 1
                        row[key + "_extrapolated_estimate"] = \
                            abs(x - (2 * v[1] - v[0])) / f / abs(x)
                rows.append(row)
                print(f"| {e} | {level} | {t} | " + " | ".join(cells) + " |")

    print("\n| element | levels | theta0 [deg] | P error | estimate | "
          "effectivity | b error | estimate | effectivity |")
    print("|---|---|---|---|---|---|---|---|---|")
    for row in rows:
        if row["level"] < 2:
            continue
        cells = []
        for key, _, _ in QUANTITIES:
            error = row[key + "_extrapolated_relative_error"]
            estimate = row[key + "_extrapolated_estimate"]
            cells += [f"{error:+.1e}", f"{estimate:.1e}",
                      f"{estimate / abs(error):.2f}"]
        print(f"| {row['element']} | {row['level'] - 2} to {row['level']} | "
              f"{row['theta0_deg']} | " + " | ".join(cells) + " |")

    if "--target" in sys.argv[1:]:
        targets(reference)

    os.makedirs(os.path.join(ROOT, "benchmarks", "results"), exist_ok=True)
    path = os.path.join(ROOT, "benchmarks", "results",
                        "nip_angle_reference"
                        + ("" if SCENE == "batra1980" else "-" + SCENE)
                        + ".csv")
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[-1].keys()))
        w.writeheader()
        w.writerows(rows)
    print(f"\nwritten: {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
