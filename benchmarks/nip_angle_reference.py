#!/usr/bin/env python3
"""P and b at a prescribed theta0 against an independent reference.

With Mode = nip angle, P and the nip half-width b follow the contact edge
and converge at first order in the mesh size. This runs the default scene
(parameters/batra1980.prm) at theta0 = 4, 8, 12 deg with Q1-P0 at levels
0-4 and Q2-P1 at levels 0-3 (Control and Conformity tolerance 1e-9, the
error estimate on), extrapolates each element's sequence at order 1
(P* = 2 P_L - P_(L-1)) and takes each element's finest extrapolation as
its reference. Each run is then measured against the *other* element's
reference: the true relative error, the program's estimate and their
ratio (the effectivity), and P extrapolated at order 1 from each pair of
levels. The reference's uncertainty u is the two families' difference
plus the last change of Q1-P0's extrapolation.

Usage: python3 benchmarks/nip_angle_reference.py
Uses build/rollnip or $ROLLNIP_BIN (about 3 min on one core). Prints
Markdown tables and writes benchmarks/results/nip_angle_reference.csv.
"""

import csv
import os
import subprocess
import sys
import tempfile

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROLLNIP = os.environ.get("ROLLNIP_BIN", os.path.join(ROOT, "build", "rollnip"))
BASE = os.path.join(ROOT, "parameters", "batra1980.prm")
THETA0 = [4, 8, 12]  # deg
LEVELS = {"Q1-P0": range(5), "Q2-P1": range(4)}
QUANTITIES = [("P_N_per_mm", "P_err_N_per_mm", "P [N/mm]"),
              ("half_chord_mm", "half_chord_err_mm", "b [mm]")]


def run(element, level, work):
    """The nip characteristic of one run: {theta0: row}."""
    out = os.path.join(work, f"{element}-{level}")
    prm = os.path.join(work, f"{element}-{level}.prm")
    with open(BASE) as base, open(prm, "w") as f:
        f.write(base.read())
        f.write(f"""
subsection Mesh
  set Global refinements = {level}
end
subsection Discretization
  set Element = {element}
end
subsection Contact
  set Values = {", ".join(str(t) for t in THETA0)}
  set Compare with linear theory = false
  set Control tolerance = 1e-9
  set Conformity tolerance = 1e-9
end
subsection Accuracy
  set Error estimate = true
end
subsection Output
  set Directory = {out}
  set Write VTU = false
end
""")
    subprocess.run([ROLLNIP, prm], check=True, stdout=subprocess.DEVNULL)
    with open(os.path.join(out, "nip_characteristic.csv")) as f:
        return {round(float(r["theta0_deg"])): r for r in csv.DictReader(f)}


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
            x1 = extrapolated(values("Q1-P0", t, key))
            x2 = extrapolated(values("Q2-P1", t, key))
            u = (abs(x1[-1] - x2[-1]) + abs(x1[-1] - x1[-2])) / abs(x1[-1])
            reference[t, key] = {"Q1-P0": x1[-1], "Q2-P1": x2[-1], "u": u}
            print(f"| {t} | {label} | {x1[-1]:.7f} | {x2[-1]:.7f} | "
                  f"{x1[-1] / x2[-1] - 1:+.1e} | {u:.1e} |")

    rows = []
    print("\n| element | level | theta0 [deg] | P error | estimate | "
          "effectivity | b error | estimate | effectivity | "
          "P order-1 extrapolated from level-1, level: error |")
    print("|---|---|---|---|---|---|---|---|---|---|")
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
                if level > 0:
                    p = values(e, t, "P_N_per_mm")
                    x = (2 * p[level] - p[level - 1]) / \
                        reference[t, "P_N_per_mm"][other] - 1
                    row["P_extrapolated_relative_error"] = x
                    cells.append(f"{x:+.1e}")
                else:
                    row["P_extrapolated_relative_error"] = ""
                    cells.append("-")
                rows.append(row)
                print(f"| {e} | {level} | {t} | " + " | ".join(cells) + " |")

    os.makedirs(os.path.join(ROOT, "benchmarks", "results"), exist_ok=True)
    path = os.path.join(ROOT, "benchmarks", "results",
                        "nip_angle_reference.csv")
    with open(path, "w", newline="") as f:
        w = csv.DictWriter(f, fieldnames=list(rows[0].keys()))
        w.writeheader()
        w.writerows(rows)
    print(f"\nwritten: {path}", file=sys.stderr)


if __name__ == "__main__":
    main()
