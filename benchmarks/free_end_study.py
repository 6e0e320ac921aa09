#!/usr/bin/env python3
"""The free cover end in 3D (doc/three_d.md, "The free cover end"): for
covers of several thicknesses h on the run-30 roll (R0 = 60.7 mm, rigid
indenter of radius 76.2 mm, C1 = C2 = 0.25 MPa) pressed uniformly along the
face, the length l over which the line load falls at a free end, against
a/h (a the 2D nip half-width). Each scene runs three times:

  2D     the cross-section, Q2-P1 at level 2 (nip-fitted): P_2D and a;
  slice  the 3D plane-strain slice of the same cross-section mesh (one
         layer, u_z = 0 on both faces): the discrete far-field line load;
  end    the 3D half face of length L, u_z = 0 at z = 0 (the middle) and a
         free end at z = L, layers graded towards the end.

Prints a Markdown table: q(0) of the end run against the slice and the 2D
P (L long enough leaves q(0) at the plane-strain value), the deficit
length l = int (1 - q/q(0)) dz, the 95 % rise distance, both over a, the
thin-layer values for a strip with a parabolic gap (l = 0.665 a, the
leading mode alone 2a/pi = 0.637 a, l^2 = 0.405 a^2; 95 % rise 1.95 a),
the end bulge and the bond stresses at the bonded corner against z = 0.

Usage: python3 benchmarks/free_end_study.py [--refine] [--np N] [NAME...]
    --refine  one mesh level more in the cross-section and twice the
              layers (the convergence of l)
    --np N    run the 3D runs on N MPI processes (mpirun)
    NAME      run only these scenes (h2, h6, ...)
Uses build/rollnip or $ROLLNIP_BIN; the outputs stay in
output/free_end_study[_refined]/NAME/. About 15 minutes on one core.
"""

import csv
import os
import subprocess
import sys
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROLLNIP = os.environ.get("ROLLNIP_BIN", os.path.join(ROOT, "build", "rollnip"))
R0 = 60.7

# name, h [mm], u0 [mm], sector [deg], far edge, radial cells,
# circumferential cells, circumferential grading, level, L [mm], layers,
# axial grading. Thin covers take a narrow sector (the cover a few h
# beyond the nip does not move) so that the nip gets cells.
SCENES = [
    ("h13.5", 13.5, 0.5, 90, "free", 8, 18, 10, 0, 108, 24, 20),
    ("h6", 6.0, 0.5, 45, "free", 6, 18, 10, 0, 48, 20, 15),
    ("h2", 2.0, 0.2, 20, "free", 4, 18, 10, 0, 30, 20, 12),
    ("h1", 1.0, 0.12, 12, "free", 4, 18, 8, 0, 20, 20, 10),
    ("h0.6", 0.6, 0.08, 10, "free", 4, 18, 8, 0, 16, 20, 10),
]

# Thin-layer strip: q(d)/q_far = 1 - sum w_n exp(-(2n+1) pi d / 2a).
THIN_DEFICIT = 0.665
THIN_RISE_95 = 1.95


def scene_prm(s, level, three_d):
    name, h, u0, sector, far_edge, nr, nc, grading = s[:8]
    text = f"""subsection Geometry
  set Inner radius = {R0 - h:.6f}
  set Outer radius = {R0}
  set Sector angle = {sector}
end
subsection Mesh
  set Source                  = builtin
  set Radial cells            = {nr}
  set Circumferential cells   = {nc}
  set Circumferential grading = {grading}
  set Global refinements      = {level}
end
subsection Material
  set C1     = 0.25
  set C2     = 0.25
  set Theory = nonlinear
end
subsection Boundary conditions
  set Inner arc (id 0)     = fixed
  set Symmetry edge (id 2) = symmetry
  set Far edge (id 3)      = {far_edge}
end
subsection Contact
  set Mode            = indentation
  set Values          = {u0}
  set Indenter radius = 76.2
end
subsection Output
  set Write VTU = false
end
"""
    return text + three_d


def run(prm_text, directory, np=1):
    os.makedirs(directory, exist_ok=True)
    prm = os.path.join(directory, "run.prm")
    with open(prm, "w") as f:
        f.write(prm_text + f"subsection Output\n  set Directory = {directory}\nend\n")
    command = [ROLLNIP, prm]
    if np > 1:
        command = ["mpirun", "-np", str(np)] + command
    start = time.time()
    with open(os.path.join(directory, "log.txt"), "w") as log:
        subprocess.run(command, stdout=log, stderr=subprocess.STDOUT, check=True)
    return time.time() - start


def summary(directory):
    values = {}
    with open(os.path.join(directory, "summary.txt")) as f:
        for line in f:
            if "=" in line and not line.startswith("#"):
                key, value = line.split("=", 1)
                values[key.strip()] = value.strip()
    return values


def two_d(s, out):
    d = os.path.join(out, "2d")
    run(scene_prm(s, 2, "subsection Discretization\n  set Element = Q2-P1\nend\n"), d)
    with open(os.path.join(d, "nip_report.csv")) as f:
        row = next(csv.DictReader(f))
    return float(row["line_load_N_per_mm"]), float(row["nip_width_2b_mm"]) / 2


def three_d(s, level, thickness, layers, grading, free, out, np):
    block = f"""subsection Three d
  set Enabled         = true
  set Slice thickness = {thickness}
  set Layers          = {layers}
  set Axial grading   = {grading}
  set Far face        = {"free" if free else "fixed axial"}
  set Approach step   = {s[2] / 2}
end
"""
    seconds = run(scene_prm(s, level, block), out, np)
    return summary(out), seconds


def main():
    args = sys.argv[1:]
    refine = "--refine" in args
    np = 1
    if "--np" in args:
        np = int(args[args.index("--np") + 1])
        del args[args.index("--np"):args.index("--np") + 2]
    names = [a for a in args if not a.startswith("--")]
    base = os.path.join(ROOT, "output", "free_end_study" + ("_refined" if refine else ""))
    print("| h [mm] | u0 [mm] | a [mm] | a/h | P_2D [N/mm] | slice P | q(0) | q(0)/slice - 1 "
          "| q(L)/q(0) | l [mm] | l/a | rise95/a | bulge u_z [mm] | corner shear [MPa] "
          "| middle shear [MPa] | cells | DoFs | time [s] |")
    print("|" + "---|" * 18)
    for s in SCENES:
        if names and s[0] not in names:
            continue
        name, h, u0 = s[:3]
        level, L, layers, grading = s[8:]
        if refine:
            level, layers = level + 1, 2 * layers
        out = os.path.join(base, name)
        P2d, a = two_d(s, out)
        sl, _ = three_d(s, level, 1.0, 1, 1, False, os.path.join(out, "slice"), np)
        end, seconds = three_d(s, level, L, layers, grading, True,
                               os.path.join(out, "end"), np)
        P_slice = float(sl["nip_load_P_N_per_mm"])
        q0 = float(end["line_load_middle_N_per_mm"])
        l = float(end["end_deficit_length_l_mm"])
        print(f"| {h} | {u0} | {a:.3f} | {a / h:.2f} | {P2d:.5g} | {P_slice:.5g} | {q0:.5g} "
              f"| {100 * (q0 / P_slice - 1):+.2f} % "
              f"| {float(end['line_load_end_N_per_mm']) / q0:.3f} | {l:.3f} | {l / a:.3f} "
              f"| {float(end['end_rise_95_mm']) / a:.2f} | {float(end['end_bulge_uz_mm']):.4f} "
              f"| {float(end['bond_shear_peak_MPa']):.4f} | {float(end['bond_shear_middle_MPa']):.4f} "
              f"| {end['n_cells']} | {end['n_dofs']} | {seconds:.0f} |", flush=True)
    print(f"\nThin-layer strip (a/h large): l/a = {THIN_DEFICIT}, rise95/a = {THIN_RISE_95}; "
          f"l^2 = 0.4 a^2 gives l/a = {0.4 ** 0.5:.3f}.")


if __name__ == "__main__":
    main()
