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

Usage: python3 benchmarks/free_end_study.py [--level N] [--layers K]
                                            [--np N] [--table] [NAME...]
    --level N   N mesh levels more in the cross-section (each halves the
                cells in r and theta)
    --layers K  K times the layers along the face (the same grading)
    --np N      run the 3D runs on N MPI processes (mpirun)
    --table     print the tables of the runs already made, run nothing
    NAME        only these scenes (h13.5, h6, h2, h1, h0.6)
Uses build/rollnip or $ROLLNIP_BIN; the outputs stay in
output/free_end_study[_levelN][_layersK]/NAME/. About 3 minutes on one
core at the base meshes on a shared machine, 14 for --level 1 --layers 2
h2 h1.
"""

import csv
import os
import subprocess
import sys

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROLLNIP = os.environ.get("ROLLNIP_BIN", os.path.join(ROOT, "build", "rollnip"))
R0 = 60.7

# name, h [mm], u0 [mm], sector [deg], far edge, radial cells,
# circumferential cells, circumferential grading, level, L [mm], layers,
# axial grading. Thin covers take a narrow sector (the cover a few h
# beyond the nip does not move) so that the nip gets cells. L is long
# enough that q(0) is the slice's P within about 0.1 %: the fall has a
# tail longer than its 95 % rise (h1 at L = 20 mm left q(0) 0.26 % low).
SCENES = [
    ("h13.5", 13.5, 0.5, 90, "free", 8, 18, 10, 0, 160, 28, 25),
    ("h6", 6.0, 0.5, 45, "free", 6, 18, 10, 0, 72, 24, 20),
    ("h2", 2.0, 0.2, 20, "free", 4, 18, 10, 0, 45, 24, 15),
    ("h1", 1.0, 0.12, 12, "free", 4, 18, 8, 0, 35, 26, 10),
    ("h0.6", 0.6, 0.08, 10, "free", 4, 18, 8, 0, 30, 26, 12),
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
    with open(os.path.join(directory, "log.txt"), "w") as log:
        subprocess.run(command, stdout=log, stderr=subprocess.STDOUT, check=True)


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
    run(scene_prm(s, level, block), out, np)


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def shear_from_end(directory, distance):
    """The largest bond shear of the plane at @p distance from the end
    (linear between planes) [MPa]."""
    rows = read_csv(os.path.join(directory, "bond_traction_along_axis.csv"))
    z = [float(r["z_mm"]) for r in rows]
    tau = [float(r["max_bond_shear_MPa"]) for r in rows]
    target = z[-1] - distance
    for j in range(len(z) - 1):
        if z[j] <= target <= z[j + 1]:
            t = (target - z[j]) / (z[j + 1] - z[j])
            return tau[j] + t * (tau[j + 1] - tau[j])
    return float("nan")


def table(base, names):
    """Prints the tables of the runs under @p base."""
    print("| h [mm] | u0 [mm] | a [mm] | a/h | P_2D [N/mm] | slice P [N/mm] "
          "| q(0)/slice - 1 | q(L)/q(0) | l [mm] | l/a | l_slice/a | rise95/a "
          "| cells | DoFs | time [s] |")
    print("|" + "---|" * 15)
    ends = []
    for s in SCENES:
        if names and s[0] not in names:
            continue
        name, h, u0 = s[:3]
        out = os.path.join(base, name)
        row = read_csv(os.path.join(out, "2d", "nip_report.csv"))[0]
        P2d, a = float(row["line_load_N_per_mm"]), float(row["nip_width_2b_mm"]) / 2
        P_slice = float(summary(os.path.join(out, "slice"))["nip_load_P_N_per_mm"])
        end = summary(os.path.join(out, "end"))
        q0 = float(end["line_load_middle_N_per_mm"])
        l = float(end["end_deficit_length_l_mm"])
        L = float(end["slice_thickness_mm"])
        # The same deficit against the plane-strain slice's P.
        l_slice = L * (1 - float(end["line_load_mean_N_per_mm"]) / P_slice)
        print(f"| {h} | {u0} | {a:.3f} | {a / h:.2f} | {P2d:.5g} | {P_slice:.5g} "
              f"| {100 * (q0 / P_slice - 1):+.2f} % "
              f"| {float(end['line_load_end_N_per_mm']) / q0:.3f} | {l:.3f} | {l / a:.3f} "
              f"| {l_slice / a:.3f} | {float(end['end_rise_95_mm']) / a:.2f} "
              f"| {end['n_cells']} | {end['n_dofs']} | {float(end['wall_time_s']):.0f} |")
        ends.append((h, u0, a, end, os.path.join(out, "end")))
    print(f"\nThin-layer strip (a/h large): l/a = {THIN_DEFICIT}, rise95/a = {THIN_RISE_95}; "
          f"l^2 = 0.4 a^2 gives l/a = {0.4 ** 0.5:.3f}.\n")
    print("| h [mm] | a/h | bulge u_z [mm] | bulge/u0 | at r [mm], theta [deg] "
          "| bond shear at corner node [MPa] | at h/2 from the end [MPa] "
          "| at z = 0 [MPa] | sigma_rr min [MPa] at z [mm] | at z = 0 [MPa] "
          "| sigma_rr max [MPa] at z [mm] |")
    print("|" + "---|" * 11)
    for h, u0, a, end, directory in ends:
        bulge = float(end["end_bulge_uz_mm"])
        print(f"| {h} | {a / h:.2f} | {bulge:.4f} | {bulge / u0:.2f} "
              f"| {float(end['end_bulge_r_mm']):.2f}, {float(end['end_bulge_theta_deg']):.2f} "
              f"| {float(end['bond_shear_peak_MPa']):.4f} "
              f"| {shear_from_end(directory, h / 2):.4f} "
              f"| {float(end['bond_shear_middle_MPa']):.4f} "
              f"| {float(end['bond_compression_peak_sigma_rr_MPa']):.4f} at "
              f"{float(end['bond_compression_peak_z_mm']):.1f} "
              f"| {float(end['bond_compression_middle_sigma_rr_MPa']):.4f} "
              f"| {float(end['bond_tension_peak_sigma_rr_MPa']):.4f} at "
              f"{float(end['bond_tension_peak_z_mm']):.1f} |")


def main():
    args = sys.argv[1:]
    options = {"--np": 1, "--level": 0, "--layers": 1}
    for key in options:
        if key in args:
            options[key] = int(args[args.index(key) + 1])
            del args[args.index(key):args.index(key) + 2]
    np, more_levels, layer_factor = options["--np"], options["--level"], options["--layers"]
    names = [a for a in args if not a.startswith("--")]
    suffix = (f"_level{more_levels}" if more_levels else "") + \
        (f"_layers{layer_factor}" if layer_factor > 1 else "")
    base = os.path.join(ROOT, "output", "free_end_study" + suffix)
    for s in SCENES:
        if "--table" in args or (names and s[0] not in names):
            continue
        level, L, layers, grading = s[8:]
        level, layers = level + more_levels, layers * layer_factor
        out = os.path.join(base, s[0])
        two_d(s, out)
        three_d(s, level, 1.0, 1, 1, False, os.path.join(out, "slice"), np)
        three_d(s, level, L, layers, grading, True, os.path.join(out, "end"), np)
        print(f"{s[0]} done", file=sys.stderr, flush=True)
    table(base, names)


if __name__ == "__main__":
    main()
