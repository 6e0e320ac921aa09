#!/usr/bin/env python3
"""A sinusoidal ripple of the rigid core along the face against the local
law and the face model's non-local transfer (doc/three_d.md, "Bent core").

The run-30 cover of parameters/slice_3d.prm at the mean approach U0, its
core deflected by v(z) = A cos(2 pi z / lambda) away from the nip. The 3D
slice covers half a wavelength, z = 0 .. lambda/2, between two symmetry
planes (u_z = 0 at a crest and a trough of v), so no cover end enters.
For each wavelength it fits q(z) = c0 + c1 cos(k z) + c2 cos(2 k z) to the
3D line load of the node planes and prints the transfer T = the ripple of
q over the local law's ripple (the plane-strain slice on the same
cross-section mesh at U0 -+ A), and the face model's 1 / (1 + (k l)^2)
with l = 0.63 a (Face/Non-local length factor), a the 2D half-chord at U0.

Usage: python3 benchmarks/core_ripple.py [LEVEL]   (level 0: about a
minute; level 1: several minutes). Uses build/rollnip or $ROLLNIP_BIN;
$LAYERS (cells per half wavelength, 8), $WAVELENGTHS ("2000 400 120 60
30 15" mm), $U0 (1 mm), $AMPLITUDE (0.2 mm) and $HALF_CHORD (the 2D a at
U0, 7.323037 mm) override the defaults.
"""

import csv
import math
import os
import subprocess
import sys
import tempfile
import time

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROLLNIP = os.environ.get("ROLLNIP_BIN", os.path.join(ROOT, "build", "rollnip"))
U0 = float(os.environ.get("U0", "1"))        # mean approach [mm]
A = float(os.environ.get("AMPLITUDE", "0.2"))  # ripple amplitude [mm]
# The 2D half-chord at U0 [mm]: Q2-P1 on the nip-fitted mesh (level 2 at
# 1 mm; at another U0 give it as $HALF_CHORD).
A_2D = float(os.environ.get("HALF_CHORD", "7.323037"))
FACTOR = 0.63     # Face/Non-local length factor (default)
WAVELENGTHS = [float(x) for x in os.environ.get(
    "WAVELENGTHS", "2000 400 120 60 30 15").split()]  # [mm]
LAYERS_PER_HALF_WAVE = int(os.environ.get("LAYERS", "8"))

SCENE = """subsection Geometry
  set Inner radius = 47.2
  set Outer radius = 60.7
  set Sector angle = 90
end
subsection Mesh
  set Radial cells            = 8
  set Circumferential cells   = 18
  set Circumferential grading = 10
  set Global refinements      = {level}
end
subsection Material
  set C1     = 0.25
  set C2     = 0.25
  set Theory = nonlinear
end
subsection Boundary conditions
  set Far edge (id 3) = free
end
subsection Contact
  set Mode            = indentation
  set Values          = {values}
  set Indenter radius = 76.2
end
subsection Three d
  set Enabled         = true
  set Slice thickness = {thickness}
  set Layers          = {layers}
  set Approach step   = 0.5
  set Core deflection = {deflection}
end
subsection Output
  set Directory = {directory}
  set Write VTU = false
end
"""


def run(work, name, **entries):
    directory = os.path.join(work, name)
    prm = os.path.join(work, name + ".prm")
    with open(prm, "w") as f:
        f.write(SCENE.format(directory=directory, **entries))
    start = time.time()
    subprocess.run([ROLLNIP, prm], check=True, stdout=subprocess.DEVNULL)
    return directory, time.time() - start


def read_csv(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def solve3(m, r):
    """Gaussian elimination for a 3x3 system."""
    m = [row[:] + [x] for row, x in zip(m, r)]
    for i in range(3):
        p = max(range(i, 3), key=lambda k: abs(m[k][i]))
        m[i], m[p] = m[p], m[i]
        for k in range(i + 1, 3):
            f = m[k][i] / m[i][i]
            m[k] = [a - f * b for a, b in zip(m[k], m[i])]
    x = [0.0] * 3
    for i in reversed(range(3)):
        x[i] = (m[i][3] - sum(m[i][j] * x[j] for j in range(i + 1, 3))) / m[i][i]
    return x


def fit(z, q, k):
    """Least squares q = c0 + c1 cos(k z) + c2 cos(2 k z)."""
    basis = [[1.0, math.cos(k * s), math.cos(2 * k * s)] for s in z]
    m = [[sum(b[i] * b[j] for b in basis) for j in range(3)] for i in range(3)]
    r = [sum(b[i] * x for b, x in zip(basis, q)) for i in range(3)]
    return solve3(m, r)


def main():
    level = int(sys.argv[1]) if len(sys.argv) > 1 else 0
    work = tempfile.mkdtemp(prefix="core_ripple_")
    d, _ = run(work, "local", level=level, values=f"{U0 - A}, {U0}, {U0 + A}",
               thickness=1, layers=1, deflection=0)
    P = [float(r["P_N_per_mm"]) for r in read_csv(os.path.join(d, "slice_3d.csv"))]
    local = (P[2] - P[0]) / 2
    # The local law through the three approaches (quadratic in delta).
    def law(delta):
        s = (delta - U0) / A
        return P[1] + s * (P[2] - P[0]) / 2 + s * s * (P[2] - 2 * P[1] + P[0]) / 2
    l = FACTOR * A_2D
    print(f"level {level}, u0 = {U0} mm, A = {A} mm: plane-strain slice P = "
          f"{P[0]:.5f}, {P[1]:.5f}, {P[2]:.5f} N/mm at u0 = {U0 - A}, {U0}, "
          f"{U0 + A} mm; local ripple of q {local:.5f} N/mm; a = {A_2D} mm, "
          f"l = {FACTOR} a = {l:.3f} mm\n")
    print("| lambda [mm] | lambda/a | k l | DoFs | q0 [N/mm] | ripple of q [N/mm] "
          "| T 3D | T face model | l_3D/a | max q - local law [N/mm] | time [s] |")
    print("|---|---|---|---|---|---|---|---|---|---|---|")
    for wavelength in WAVELENGTHS:
        k = 2 * math.pi / wavelength
        d, seconds = run(work, f"ripple_{wavelength}", level=level, values=U0,
                         thickness=wavelength / 2, layers=LAYERS_PER_HALF_WAVE,
                         deflection=f"{A}*cos(2*pi*z/{wavelength})")
        rows = read_csv(os.path.join(d, "core_deflection_along_axis.csv"))
        z = [float(r["z_mm"]) for r in rows]
        q = [float(r["line_load_N_per_mm"]) for r in rows]
        c = fit(z, q, k)
        T = -c[1] / local
        l3 = math.sqrt(max(1 / T - 1, 0)) / k if T > 0 else float("nan")
        misfit = max(abs(x - law(float(r["local_approach_mm"])))
                     for x, r in zip(q, rows))
        summary = dict(line.split(" = ") for line in
                       open(os.path.join(d, "summary.txt")).read().splitlines()
                       if " = " in line)
        print(f"| {wavelength} | {wavelength / A_2D:.2f} | {k * l:.3f} | "
              f"{summary['n_dofs']} | {c[0]:.4f} | {-c[1]:.4f} | {T:.4f} | "
              f"{1 / (1 + (k * l) ** 2):.4f} | {l3 / A_2D:.3f} | {misfit:.4f} | "
              f"{seconds:.1f} |")


if __name__ == "__main__":
    main()
