#!/usr/bin/env python3
"""Accuracy of the default scene against an independent reference.

The run-30 scene (parameters/batra1980.prm: R1 = 47.2, R0 = 60.7, Rbar =
76.2 mm, C1 + C2 = 0.5 MPa) under indentation control at u0 = 0.5, 1, 2, 3
mm. The reference is another element family: Q2-P1 on the fixed graded
mesh (Nip fitting = off, 6 x 24 coarse cells, grading 10) at levels
REF_LEVELS, the finest taken as the reference and the change from the one
before printed as its own error bound. Every Q1-P0 (and Q2-P1) run of the
table is measured against it, on the nip-fitted and on the fixed mesh.

Each run under test also reports its own error estimate (Accuracy/Error
estimate); the table gives, per nip, the true relative error, the
estimated one and their ratio, the effectivity.

Usage: [ROLLNIP_SCENE=run30|layered] [ROLLNIP_REFERENCE=fixed|fitted]
       python3 benchmarks/accuracy_reference.py
           [--quick] [--front] [--target] [KEY=VALUE ...]
    --quick     reference at level 2 only (minutes less; for tuning)
    --front     the speed-accuracy front instead: every element, mesh
                (nip-fitted, fixed), level and control mode (indentation
                at the reference's u0, load at its P, nip angle at its
                theta0), timed without the error estimate, with the
                largest true error of P, u0, b, the peak pressure and the
                bond shear stress over the nips; writes the table as CSV
                and doc-style figure data to benchmarks/results/; then the
                time per nip to reach 1 %, 0.1 % and 0.01 % in P and in b
                per element, mesh and mode, read off that table
    --target    Accuracy/Target = 1 %, 0.1 %, 0.01 % on P in each mode:
                what the program chose, the runs it needed, its wall and
                CPU time per nip on one thread (DEAL_II_NUM_THREADS=1,
                start-up subtracted; median of ROLLNIP_REPEAT runs, 3 by
                default) and the true error of P; ROLLNIP_MODES and
                ROLLNIP_TARGETS (comma-separated) limit the modes and
                targets, e.g. ROLLNIP_MODES="nip angle" ROLLNIP_TARGETS="1 %";
                ROLLNIP_QUANTITIES="P, 2b" targets b too and gives its
                true error against Q2-P1 with 6 edge refinements at levels
                2 and 3, extrapolated; ROLLNIP_BEFORE=<another build> runs
                it in turn with this one and adds its CPU time per nip
                and the ratio
    KEY=VALUE   extra Mesh entries for the runs under test, e.g.
                "Nip cells=6"

Uses build/rollnip or $ROLLNIP_BIN. Prints a Markdown table (relative error
of P, of the nip half-width b and of the peak pressure at each u0) and
writes it as CSV to benchmarks/results/.
"""

import csv
import json
import os
import re
import resource
import shutil
import statistics
import subprocess
import sys
import tempfile
import time

from prm_run import run_prm

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
ROLLNIP = os.environ.get("ROLLNIP_BIN", os.path.join(ROOT, "build", "rollnip"))
BASE = os.path.join(ROOT, "parameters", "batra1980.prm")
U0 = [0.5, 1, 2, 3]  # mm
# The scenes: extra .prm text over BASE and the indentations [mm].
SCENES = {
    "run30": ("", [0.5, 1, 2, 3]),
    # A 3.5 mm top layer 5 times stiffer than its 10 mm base.
    "layered": ("""
subsection Material
  set C1 = 0.25, 1.25
  set C2 = 0.25, 1.25
  set Layer thicknesses = 10, 3.5
end
""", [1, 1.5, 2]),
}
SCENE = os.environ.get("ROLLNIP_SCENE", "run30")
# The reference: Q2-P1 on the fixed graded mesh (Nip fitting = off) or on
# the nip-fitted mesh, whose P(u0) and b(u0) are smooth.
REFERENCE = os.environ.get("ROLLNIP_REFERENCE", "fixed")
SCENE_TEXT, U0 = SCENES[SCENE]
KEYS = ("P_N_per_mm", "half_chord_mm", "peak_pressure_MPa",
        "bond_sigma_rtheta_max_MPa")
ERR_KEYS = ("P_err_N_per_mm", "half_chord_err_mm", "peak_pressure_err_MPa",
            "bond_sigma_rtheta_max_err_MPa")
NAMES = ("P", "b", "peak", "bond shear")


def fail(message):
    print("accuracy_reference: error: " + message, file=sys.stderr)
    sys.exit(1)


def solve(tmp, element, level, fitting, mesh_extra=(), estimate=False,
          mode="indentation", values=None, keys=KEYS, tight=True,
          must_converge=True, accuracy="", log=None, binary=None):
    """[values] and [estimated errors] at each target (keys, ERR_KEYS), and
    the DoFs and wall time of the run. The targets are U0 unless given
    (in the unit of the mode: mm, N/mm, deg); tight: control and
    conformity tolerances 1e-9, otherwise the parameter file's. A run
    that fails returns None for its values unless must_converge.
    accuracy: more lines of subsection Accuracy; log: a dict that gets
    the run's standard output as "stdout" and its CPU time as "cpu";
    binary: another rollnip than ROLLNIP."""
    values = U0 if values is None else values
    tolerances = """
  set Control tolerance = 1e-9
  set Conformity tolerance = 1e-9""" if tight else ""
    mesh = "\n".join(f"  set {k} = {v}" for k, v in mesh_extra)
    text = open(BASE).read() + SCENE_TEXT + f"""
subsection Mesh
  set Global refinements = {level}
  set Nip fitting = {fitting}
{mesh}
end
subsection Discretization
  set Element = {element}
end
subsection Contact
  set Mode = {mode}
  set Values = {', '.join(f'{v:.12g}' for v in values)}
  set Compare with linear theory = false{tolerances}
end
subsection Accuracy
  set Error estimate = {'true' if estimate else 'false'}
{accuracy}
end
"""
    wall, cpu, p = run_prm(binary or ROLLNIP, tmp, text)
    if log is not None:
        log["stdout"] = p.stdout
        log["cpu"] = cpu
    if p.returncode != 0:
        if not must_converge:
            return None, None, 0, wall
        fail(f"{element} level {level} fitting {fitting} failed:\n"
             + p.stderr[-2000:])
    dofs = re.search(r"Mesh: \d+ cells, (\d+) DoFs", p.stdout)
    with open(os.path.join(tmp, "out", "nip_characteristic.csv")) as f:
        rows = list(csv.DictReader(f))
    # An accuracy target met by extrapolation: its numbers, not the finest
    # level's.
    extrapolated = os.path.join(tmp, "out", "accuracy_target_values.csv")
    if os.path.exists(extrapolated):
        with open(extrapolated) as f:
            for row, x in zip(rows, csv.DictReader(f)):
                row.update({k: v for k, v in x.items() if k in keys})
    results = [[float(row[k]) for k in keys] for row in rows]
    errors = [[float(row.get(k, "nan")) for k in ERR_KEYS] for row in rows]
    if len(results) != len(values):
        fail(f"{element} level {level}: {len(results)} nips of {len(values)}")
    return results, errors, int(dofs.group(1)) if dofs else 0, wall


def reference(tmp, levels, keys=KEYS, mesh_extra=(), mesh=None):
    """The reference runs (values of keys only) on the mesh REFERENCE
    (or mesh: "fitted", "fixed"), cached in benchmarks/results by scene,
    mesh, level, keys and the extra Mesh entries: they take minutes and
    do not change."""
    mesh = mesh or REFERENCE
    cache = os.path.join(ROOT, "benchmarks", "results",
                         f"reference-{SCENE}-{mesh}.json")
    known = json.load(open(cache)) if os.path.exists(cache) else {}
    key = ",".join(f"{u:g}" for u in U0)
    out = []
    for level in levels:
        tag = f"{key}@{level}" + ("" if keys == KEYS else "/" + ",".join(keys))
        tag += "".join(f"/{k}={v}" for k, v in mesh_extra)
        if tag not in known:
            known[tag] = solve(tmp, "Q2-P1", level,
                               "on" if mesh == "fitted" else "off",
                               mesh_extra, keys=keys)[0]
            os.makedirs(os.path.dirname(cache), exist_ok=True)
            json.dump(known, open(cache, "w"))
        out.append(known[tag])
    return out


# The speed-accuracy front (--front): the reference's columns, the
# quantities whose errors it tabulates (indices into FRONT_KEYS), and the
# control modes with the reference column each prescribes.
FRONT_KEYS = ("theta0_deg", "P_N_per_mm", "u0_mm", "half_chord_mm",
              "peak_pressure_MPa", "bond_sigma_rtheta_max_MPa")
FRONT_NAMES = {1: "P", 2: "u0", 3: "b", 4: "peak", 5: "bond shear"}
FRONT_MODES = {"indentation": 2, "load": 1, "nip angle": 0}


def half_chord_reference(tmp):
    """b at each u0 from Q2-P1 on the nip-fitted mesh with 6 edge
    refinements at levels 2 and 3, extrapolated at order 1: the
    reference's own b (level 3 without them) converges at first order
    from the contact edge and is 2.6e-4 to 6.5e-4 too large (doc/accuracy.md,
    "Refinement at the contact edge", where Q1-P0 agrees with it)."""
    # Edge refinements exist on the nip-fitted mesh only, whatever
    # REFERENCE is.
    fine = reference(tmp, [2, 3], ("half_chord_mm",),
                     (("Edge refinements", 6),), mesh="fitted")
    return [2 * b3[0] - b2[0] for b2, b3 in zip(*fine)]


def start_up_seconds(cpu=False):
    """The wall (or CPU) time of a run that does no work (median of 3):
    the shared libraries and the parameter declaration."""
    times = []
    for _ in range(3):
        t0 = time.perf_counter()
        r0 = resource.getrusage(resource.RUSAGE_CHILDREN)
        subprocess.run([ROLLNIP, "--help"], capture_output=True)
        r1 = resource.getrusage(resource.RUSAGE_CHILDREN)
        times.append((r1.ru_utime - r0.ru_utime) + (r1.ru_stime - r0.ru_stime)
                     if cpu else time.perf_counter() - t0)
    return sorted(times)[1]


def front(tmp, ref_levels):
    """Every element, mesh, level and mode against the reference: the
    wall time per nip (start-up subtracted) and the largest relative error
    of each quantity over the nips."""
    refs = reference(tmp, ref_levels, FRONT_KEYS)
    ref = refs[-1]
    uncertainty = {i: max(abs(a[i] / b[i] - 1) for a, b in zip(refs[0], ref))
                   for i in FRONT_NAMES} if len(refs) > 1 else {}
    print(f"reference: Q2-P1, {REFERENCE} mesh, level {ref_levels[-1]};"
          " its change from the level before: "
          + ", ".join(f"{FRONT_NAMES[i]} {u:.1e}"
                      for i, u in uncertainty.items()))
    start = start_up_seconds()
    print(f"start-up (rollnip --help, median of 3): {start:.2f} s")
    runs = [("Q1-P0", f, l) for f in ("on", "off") for l in (0, 1, 2, 3)] + \
           [("Q2-P1", f, l) for f in ("on", "off") for l in (0, 1, 2)]
    header = ["scene", "mode", "element", "mesh", "level", "DoFs",
              "s per nip"] + [f"{n} err" for n in FRONT_NAMES.values()]
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    rows = []
    for mode, column in FRONT_MODES.items():
        targets = [r[column] for r in ref]
        for element, fitting, level in runs:
            res, _, dofs, wall = solve(tmp, element, level, fitting,
                                       mode=mode, values=targets,
                                       keys=FRONT_KEYS, tight=False,
                                       must_converge=False)
            row = [SCENE, mode, element,
                   "fitted" if fitting == "on" else "fixed", level, dofs]
            if res is None:  # a target the control did not reach
                row += ["failed"] + ["-"] * len(FRONT_NAMES)
            else:
                row += [f"{max(wall - start, 0) / len(targets):.3f}"]
                row += [f"{max(abs(a[i] / b[i] - 1) for a, b in zip(res, ref)):.1e}"
                        for i in FRONT_NAMES]
            rows.append(row)
            print("| " + " | ".join(str(x) for x in row) + " |", flush=True)
    return header, rows


def time_to_reach(header, rows):
    """From the front: the least time per nip at which each element, mesh
    and mode reaches 1 %, 0.1 % and 0.01 % in P and in b."""
    col = {name: i for i, name in enumerate(header)}
    out = []
    for mode in FRONT_MODES:
        for element in ("Q1-P0", "Q2-P1"):
            for mesh in ("fitted", "fixed"):
                mine = [r for r in rows if r[1] == mode and r[2] == element
                        and r[3] == mesh and r[6] != "failed"]
                line = [mode, element, mesh]
                # Under load control P is prescribed: u0 is its answer.
                first = "u0 err" if mode == "load" else "P err"
                for name in (first, "b err"):
                    for level in (1e-2, 1e-3, 1e-4):
                        t = [float(r[6]) for r in mine
                             if float(r[col[name]]) <= level]
                        line.append(f"{min(t):.2f}" if t else "-")
                out.append(line)
    head = ["mode", "element", "mesh"] + [
        f"{q} {lv}" for q in ("P", "b") for lv in ("1 %", "0.1 %", "0.01 %")]
    print("\ntime per nip [s] to reach a relative error in P (u0 under load"
          " control) and b")
    print("| " + " | ".join(head) + " |")
    print("|" + "---|" * len(head))
    for line in out:
        print("| " + " | ".join(line) + " |")


def plot_front(header, rows, png):
    """The front as a figure (gnuplot, if installed): the true error of P
    (of u0 under load control, where P is prescribed) and of b against
    the time per nip, indentation and load control, one curve per element
    and mesh."""
    if not shutil.which("gnuplot"):
        print("(gnuplot not found: no figure)")
        return
    col = {name: i for i, name in enumerate(header)}
    tmp = tempfile.mkdtemp(prefix="rollnip-front-plot.")
    plots = {"P err": [], "b err": []}
    for mode in ("indentation", "load"):
        for element in ("Q1-P0", "Q2-P1"):
            for mesh in ("fitted", "fixed"):
                mine = [r for r in rows if r[1] == mode and r[2] == element
                        and r[3] == mesh and r[6] != "failed"]
                if not mine:
                    continue
                name = f"{mode}-{element}-{mesh}"
                first = col["u0 err" if mode == "load" else "P err"]
                with open(os.path.join(tmp, name + ".dat"), "w") as f:
                    for r in mine:
                        f.write(f"{r[6]} {r[first]} {r[col['b err']]}"
                                f" {r[4]}\n")
                style = "lp" if mesh == "fitted" else "lp dt 2"
                for k, c in (("P err", 2), ("b err", 3)):
                    plots[k].append(
                        f"'{tmp}/{name}.dat' using 1:{c} with {style} "
                        f"title '{element}, {mesh} mesh, {mode} control'")
    script = f"""set terminal pngcairo size 1100,480 font ',10'
set output '{png}'
set multiplot layout 1,2
set logscale xy
set grid
set xlabel 'wall time per nip [s]'
set key bottom left font ',8'
set format y '%.0e'
set ylabel 'relative error of P (indentation) or u0 (load)'
set title 'P or u0 against Q2-P1 level 3'
plot {', '.join(plots['P err'])}
set ylabel 'relative error of b'
set title 'nip half-width b against Q2-P1 level 3'
plot {', '.join(plots['b err'])}
unset multiplot
"""
    subprocess.run(["gnuplot"], input=script, text=True, check=False)
    shutil.rmtree(tmp, ignore_errors=True)
    print(f"figure: {os.path.relpath(png, ROOT)}")


def target_runs(tmp):
    """Accuracy/Target in each mode against the reference, on P (on u0
    under load control, where P is given). ROLLNIP_MODES and
    ROLLNIP_TARGETS (comma-separated, e.g. "nip angle" and "1 %") limit
    the modes and the targets; ROLLNIP_QUANTITIES="P, 2b" asks for b as
    well (its error against half_chord_reference())."""
    ref = reference(tmp, [3], FRONT_KEYS)[0]
    asked = [q.strip() for q in
             os.environ.get("ROLLNIP_QUANTITIES", "P").split(",")]
    with_b = "b" in asked or "2b" in asked
    b_ref = half_chord_reference(tmp) if with_b else None
    # One core: the cell loops on one thread (MUMPS and BLAS are serial).
    os.environ["DEAL_II_NUM_THREADS"] = "1"
    os.environ["OMP_NUM_THREADS"] = "1"
    repeat = int(os.environ.get("ROLLNIP_REPEAT", "3"))
    start, start_cpu = start_up_seconds(), start_up_seconds(cpu=True)
    print(f"start-up (rollnip --help, median of 3): {start:.2f} s wall,"
          f" {start_cpu:.2f} s CPU")
    before = os.environ.get("ROLLNIP_BEFORE")
    header = ["mode", "target", "chosen", "runs", "s per nip",
              "CPU s per nip", "P (u0) err"] + (["b err"] if with_b else [])
    if before:
        header += ["before: CPU s per nip", "CPU after / before"]
    modes = os.environ.get("ROLLNIP_MODES", ",".join(FRONT_MODES)).split(",")
    targets_asked = os.environ.get("ROLLNIP_TARGETS",
                                   "1 %,0.1 %,0.01 %").split(",")
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    rows = []
    for mode in modes:
        targets = [r[FRONT_MODES[mode]] for r in ref]
        column = 2 if mode == "load" else 1
        quantity = ", ".join("u0" if q == "P" and mode == "load" else q
                             for q in asked)
        keys = (FRONT_KEYS[column],) + (("half_chord_mm",) if with_b else ())
        for target in targets_asked:
            walls, cpus, before_cpus = [], [], []
            accuracy = (f"  set Target = {target}\n"
                        f"  set Target quantities = {quantity}")
            for _ in range(repeat):
                # The two builds in turn, so that both see the machine's
                # state of the same minutes.
                if before:
                    other = {}
                    solve(tmp, "Q1-P0", 2, "on", mode=mode, values=targets,
                          keys=keys, tight=False, must_converge=False,
                          accuracy=accuracy, log=other, binary=before)
                    before_cpus.append(other["cpu"])
                log = {}
                got, _, _, wall = solve(
                    tmp, "Q1-P0", 2, "on", mode=mode, values=targets,
                    keys=keys, tight=False,
                    must_converge=False,
                    accuracy=accuracy, log=log)
                walls.append(wall)
                cpus.append(log["cpu"])
                if got is None:
                    break
            wall = sorted(walls)[len(walls) // 2]
            cpu = sorted(cpus)[len(cpus) // 2]
            chosen = re.search(r"met with (\S+) at mesh level (\d+)"
                               r"( of the halved coarse mesh)?"
                               r"( with \d+ edge refinements)?"
                               r"( extrapolated at order 1)?[^,]* after "
                               r"(\d+) run", log["stdout"])
            if got is None or not chosen:
                row = [mode, target, "not met", "-",
                       f"{max(wall - start, 0) / len(targets):.2f}",
                       f"{max(cpu - start_cpu, 0) / len(targets):.2f}", "-"]
                row += ["-"] if with_b else []
            else:
                err = max(abs(a[0] / b[column] - 1)
                          for a, b in zip(got, ref))
                row = [mode, target,
                       f"{chosen.group(1)} level {chosen.group(2)}"
                       + (" (halved mesh)" if chosen.group(3) else "")
                       + (", edge-refined" if chosen.group(4) else "")
                       + (", extrapolated" if chosen.group(5) else ""),
                       chosen.group(6),
                       f"{max(wall - start, 0) / len(targets):.2f}",
                       f"{max(cpu - start_cpu, 0) / len(targets):.2f}",
                       f"{err:.1e}"]
                if with_b:
                    row.append(f"{max(abs(a[1] / b - 1) for a, b in zip(got, b_ref)):.1e}")
            if before:
                b_cpu = max(statistics.median(before_cpus) - start_cpu, 0)
                a_cpu = max(cpu - start_cpu, 0)
                row += [f"{b_cpu / len(targets):.2f}",
                        f"{a_cpu / b_cpu:.2f}" if b_cpu > 0 else "-"]
            rows.append(row)
            print("| " + " | ".join(row) + " |", flush=True)
    return header, rows


def write_csv(stem, header, rows):
    """The table as benchmarks/results/STEM-<date>.csv."""
    os.makedirs(os.path.join(ROOT, "benchmarks", "results"), exist_ok=True)
    out = os.path.join(ROOT, "benchmarks", "results",
                       time.strftime(f"{stem}-%Y%m%d-%H%M%S.csv"))
    with open(out, "w", newline="") as f:
        w = csv.writer(f)
        w.writerow(header)
        w.writerows(rows)
    print(f"\nwritten: {os.path.relpath(out, ROOT)}")


def main():
    args = [a for a in sys.argv[1:]
            if a not in ("--quick", "--front", "--target")]
    quick = "--quick" in sys.argv[1:]
    if "--front" in sys.argv[1:]:
        if not os.access(ROLLNIP, os.X_OK):
            fail(f"{ROLLNIP} not found; build it with: bash scripts/setup.sh")
        with tempfile.TemporaryDirectory(prefix="rollnip-front.") as tmp:
            header, rows = front(tmp, [2] if quick else [2, 3])
        write_csv(f"accuracy-front-{SCENE}", header, rows)
        time_to_reach(header, rows)
        plot_front(header, rows, os.path.join(
            ROOT, "benchmarks", "results", f"accuracy_front_{SCENE}.png"))
        return
    if "--target" in sys.argv[1:]:
        with tempfile.TemporaryDirectory(prefix="rollnip-target.") as tmp:
            header, rows = target_runs(tmp)
        write_csv(f"accuracy-target-{SCENE}", header, rows)
        return
    extra = []
    for a in args:
        if "=" not in a:
            fail(f"'{a}' is not KEY=VALUE")
        k, _, v = a.partition("=")
        extra.append((k.strip(), v.strip()))
    if not os.access(ROLLNIP, os.X_OK):
        fail(f"{ROLLNIP} not found; build it with: bash scripts/setup.sh")
    ref_levels = [2] if quick else [2, 3]
    header = ["scene", "element", "mesh", "level", "DoFs", "wall s", "u0 mm"]
    for n in NAMES:
        header += [f"{n} err", f"{n} est", f"{n} eff"]
    rows = []
    with tempfile.TemporaryDirectory(prefix="rollnip-accuracy.") as tmp:
        refs = reference(tmp, ref_levels)
        ref = refs[-1]
        print(f"reference: Q2-P1, {REFERENCE} mesh, level {ref_levels[-1]}")
        for u, r in zip(U0, ref):
            print(f"  u0 = {u:g} mm: P = {r[0]:.8g} N/mm, b = {r[1]:.8g} mm,"
                  f" peak = {r[2]:.8g} MPa, bond shear = {r[3]:.8g} MPa")
        if len(refs) > 1:
            for i, n in enumerate(NAMES):
                change = max(abs(a[i] / b[i] - 1)
                             for a, b in zip(refs[0], ref))
                print(f"  largest change of {n} from level {ref_levels[0]}:"
                      f" {change:.2e}")
        runs = [("Q1-P0", "on", l) for l in (0, 1, 2)] + \
               [("Q1-P0", "off", l) for l in (0, 1, 2)] + \
               [("Q2-P1", "on", l) for l in (0, 1)]
        for element, fitting, level in runs:
            res, est, dofs, wall = solve(tmp, element, level, fitting,
                                         extra if fitting == "on" else (),
                                         estimate=True)
            for u, r, e, q in zip(U0, res, est, ref):
                row = [SCENE, element,
                       "fitted" if fitting == "on" else "fixed", level, dofs,
                       f"{wall:.2f}", f"{u:g}"]
                for a, da, b in zip(r, e, q):
                    true = abs(a / b - 1)
                    rel = da / abs(b)
                    row += [f"{a / b - 1:+.2e}", f"{rel:.2e}",
                            f"{rel / true:.2f}" if true > 0 else "inf"]
                rows.append(row)
                print("| " + " | ".join(str(x) for x in row) + " |",
                      flush=True)
    print()
    print("| " + " | ".join(header) + " |")
    print("|" + "---|" * len(header))
    for r in rows:
        print("| " + " | ".join(str(x) for x in r) + " |")
    write_csv(f"accuracy-reference-{SCENE}", header, rows)


if __name__ == "__main__":
    main()
