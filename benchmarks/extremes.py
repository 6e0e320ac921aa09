#!/usr/bin/env python3
"""Runs the default scene (parameters/batra1980.prm, one nip, mesh level 2,
no linear companion, no VTU) at the extremes of its parameters and prints a
Markdown table: what each scene gave, or the message it stopped with.
doc/extremes.md holds the table of one run and what it means.

Usage: python3 benchmarks/extremes.py [TEXT]   (about five minutes)
    TEXT  run only the scenes whose name contains it, e.g. "rolls"
Uses build/rollnip, or $ROLLNIP_BIN.
"""

import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROLLNIP = os.environ.get("ROLLNIP_BIN", os.path.join(ROOT, "build", "rollnip"))
BASE = os.path.join(ROOT, "parameters", "batra1980.prm")

# (name, overrides as {subsection: {entry: value or {entry: value}}})
R0 = 60.7
# The mating roll's mesh as the default roll's (parameters/batra1980.prm).
MATE_MESH = {"Radial cells": "6", "Circumferential cells": "24",
             "Circumferential grading": "10", "Global refinements": "2"}
CASES = [
    ("default: h/R0 = 0.22, theta0 = 8 deg", {}),
    ("thin cover h/R0 = 0.02, theta0 = 4 deg",
     {"Geometry": {"Inner radius": f"{R0 - 0.02 * R0:.6f}"}, "Contact": {"Values": "4"}}),
    ("thin cover h/R0 = 0.02, theta0 = 8 deg",
     {"Geometry": {"Inner radius": f"{R0 - 0.02 * R0:.6f}"}}),
    ("thick cover h/R0 = 0.8", {"Geometry": {"Inner radius": f"{R0 - 0.8 * R0:.6f}"},
                                "Mesh": {"Radial cells": "12"}}),
    ("almost solid roll, R1 = 1 mm", {"Geometry": {"Inner radius": "1"},
                                      "Mesh": {"Radial cells": "16", "Radial grading": "0.1"}}),
    ("tiny nip theta0 = 0.5 deg", {"Contact": {"Values": "0.5"}}),
    ("tiny nip theta0 = 0.25 deg", {"Contact": {"Values": "0.25"}}),
    ("large nip theta0 = 14 deg", {"Contact": {"Values": "14"}}),
    ("large nip theta0 = 16 deg", {"Contact": {"Values": "16"}}),
    ("large nip theta0 = 18 deg", {"Contact": {"Values": "18"}}),
    ("large nip theta0 = 20 deg", {"Contact": {"Values": "20"}}),
    ("C2/C1 = 0 (C1 = 0.5 MPa)", {"Material": {"C1": "0.5", "C2": "0"}}),
    ("C2/C1 = 99", {"Material": {"C1": "0.005", "C2": "0.495"}}),
    ("C1 = 0 (C2 = 0.5 MPa)", {"Material": {"C1": "0", "C2": "0.5"}}),
    ("thin hard top coat: 1 mm of G = 5 MPa on 12.5 mm of G = 1 MPa",
     {"Material": {"C1": "0.4, 2.0", "C2": "0.1, 0.5", "Layer thicknesses": "12.5, 1"}}),
    ("hard base: 3 mm of G = 5 MPa under 10.5 mm of G = 1 MPa",
     {"Material": {"C1": "2.0, 0.4", "C2": "0.5, 0.1", "Layer thicknesses": "3, 10.5"}}),
    ("very thin stiff top coat: 0.2 mm of G = 50 MPa on 13.3 mm of G = 1 MPa",
     {"Material": {"C1": "0.4, 20", "C2": "0.1, 5", "Layer thicknesses": "13.3, 0.2"}}),
    ("very thin stiff top coat at P = 10 N/mm (load control)",
     {"Material": {"C1": "0.4, 20", "C2": "0.1, 5", "Layer thicknesses": "13.3, 0.2"},
      "Contact": {"Mode": "load", "Values": "10"}}),
    ("two equal layers (= default)",
     {"Material": {"C1": "0.25, 0.25", "C2": "0.25, 0.25", "Layer thicknesses": "6.75, 6.75"}}),
    ("flat indenter (Rbar = inf)", {"Contact": {"Indenter radius": "inf"}}),
    ("two equal covered rolls (= flat indenter)",
     {"Mating roll": {"Type": "covered roll", "Mesh": MATE_MESH}}),
    ("soft roll against a 76.2 mm roll with a 16.2 mm cover of G = 30 MPa",
     {"Mating roll": {"Type": "covered roll", "Mesh": MATE_MESH,
                      "Geometry": {"Inner radius": "60", "Outer radius": "76.2"},
                      "Material": {"C1": "10", "C2": "5"}}}),
    ("soft roll against a 76.2 mm roll with a 16.2 mm cover of G = 1500 MPa (= rigid)",
     {"Mating roll": {"Type": "covered roll", "Mesh": MATE_MESH,
                      "Geometry": {"Inner radius": "60", "Outer radius": "76.2"},
                      "Material": {"C1": "500", "C2": "250"}}}),
    ("small indenter Rbar = 5 mm, theta0 = 2 deg",
     {"Contact": {"Indenter radius": "5", "Values": "2"}}),
    ("small indenter Rbar = 5 mm, theta0 = 4 deg",
     {"Contact": {"Indenter radius": "5", "Values": "4"}}),
    ("1 initial load step", {"Load stepping": {"Initial steps": "1"}}),
    ("100 initial load steps", {"Load stepping": {"Initial steps": "100"}}),
    ("stiff cover, C1 = C2 = 250 MPa", {"Material": {"C1": "250", "C2": "250"}}),
    ("soft cover, C1 = C2 = 0.0025 MPa", {"Material": {"C1": "0.0025", "C2": "0.0025"}}),
    ("same scene in m and Pa", {"Geometry": {"Inner radius": "0.0472", "Outer radius": "0.0607"},
                                "Material": {"C1": "250000", "C2": "250000"},
                                "Contact": {"Indenter radius": "0.0762"}}),
]


def subsections(entries, indent=""):
    """.prm text of {subsection: {entry: value or nested subsection}}."""
    text = ""
    for section, body in entries.items():
        text += f"{indent}subsection {section}\n"
        for k, v in body.items():
            if isinstance(v, dict):
                text += subsections({k: v}, indent + "  ")
            else:
                text += f"{indent}  set {k} = {v}\n"
        text += f"{indent}end\n"
    return text


def key_values(path):
    values = {}
    if os.path.exists(path):
        for line in open(path):
            if " = " in line and not line.startswith("#"):
                k, v = line.split(" = ", 1)
                values[k.strip()] = v.strip()
    return values


def main():
    if not os.access(ROLLNIP, os.X_OK):
        print(f"extremes: error: {ROLLNIP} not found; build it with: bash scripts/setup.sh",
              file=sys.stderr)
        sys.exit(1)
    print("| scene | exit | theta0 deg | P (N/mm) | u0 (mm) | max strain | min J | conformity | P from traction | wall s | message |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    with tempfile.TemporaryDirectory(prefix="rollnip-extremes.") as tmp:
        only = sys.argv[1] if len(sys.argv) > 1 else ""
        for name, overrides in (c for c in CASES if only in c[0]):
            out = os.path.join(tmp, "out")
            text = open(BASE).read() + "\n# --- extremes overrides ---\n"
            overrides = {**overrides}
            overrides.setdefault("Contact", {})
            overrides["Contact"] = {"Values": "8", "Compare with linear theory": "false",
                                    **overrides["Contact"]}
            overrides["Output"] = {"Directory": out, "Write VTU": "false",
                                   "Print timing": "false"}
            text += subsections(overrides)
            prm = os.path.join(tmp, "run.prm")
            open(prm, "w").write(text)
            subprocess.run(["rm", "-rf", out])
            t0 = time.perf_counter()
            p = subprocess.run([ROLLNIP, prm], capture_output=True, text=True)
            wall = time.perf_counter() - t0
            s = key_values(os.path.join(out, "summary.txt"))
            c = key_values(os.path.join(out, "contact.txt"))
            message = ""
            for line in p.stderr.splitlines():
                if line.startswith("rollnip: error:"):
                    message = line[len("rollnip: error:"):].strip()
            traction = ""
            nip = os.path.join(out, "nip_characteristic.csv")
            if os.path.exists(nip):
                rows = open(nip).read().splitlines()
                if len(rows) > 1:
                    head = rows[0].split(",")
                    row = dict(zip(head, rows[1].split(",")))
                    P = float(row["P_N_per_mm"])
                    traction = f"{100 * (float(row['P_from_traction_N_per_mm']) / P - 1):+.3f} %" if P else ""
            strain = s.get("max_principal_stretch", "")
            strain = f"{100 * (float(strain) - 1):.1f} %" if strain else ""
            print(f"| {name} | {p.returncode} | {c.get('half_nip_angle_theta0_deg', '')} | "
                  f"{c.get('nip_load_P_N_per_mm', '')} | {c.get('indentation_u0_mm', '')} | "
                  f"{strain} | {s.get('min_J_gauss', '')} | "
                  f"{c.get('conformity_max_gap_over_u0', '')} | {traction} | {wall:.1f} | "
                  f"{message.replace('|', '/')} |", flush=True)


if __name__ == "__main__":
    main()
