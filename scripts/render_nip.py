"""Renders one nip of a rollnip run with ParaView: the whole nip (the
modelled half and its mirror image), warped by the displacement, coloured
by a field with rounded colour-bar limits, the rigid indenter's outline or
a covered mating roll, framed on the nip, with a scale bar in mm and the
load and the scene in the title. Run it with pvpython (bash
scripts/setup.sh installs ParaView when ROLLNIP_WITH_PARAVIEW=1 is set);
without a display, under xvfb-run:

  xvfb-run -a pvpython scripts/render_nip.py output/batra1980/nip-03 \
      --field sigma_rr --output nip.png [--edges] [--zoom 0]

NIP_DIR is a directory with solution.pvd (and indenter.csv for a rigid
indenter, mating_roll/solution.pvd for two covered rolls). The last time of
the PVD (the converged nip) is drawn. The pure helpers (nip geometry, title,
rounded limits) need no ParaView: `python3 scripts/render_nip.py --describe
NIP_DIR` prints what the picture would say.
"""

import argparse
import csv
import math
import os
import sys

# Components that change sign in the mirror image about the line of
# centres (shear stresses in the x1-x2 plane).
ANTISYMMETRIC = ("sigma_rtheta", "sigma_xy")


def parse_arguments():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("nip_dir", help="a directory with solution.pvd")
    p.add_argument("--field", default="sigma_rr",
                   help="point array to colour by (default sigma_rr; any "
                        "VTU array, e.g. von_mises, pressure_unknown_q_smoothed)")
    p.add_argument("--output", default="nip.png", help="PNG file to write")
    p.add_argument("--zoom", type=float, default=1.5,
                   help="half-height of the picture in nip half-widths "
                        "(default 1.5; 0: the whole model)")
    p.add_argument("--size", default="1200x800", help="pixels, WxH")
    p.add_argument("--edges", action="store_true",
                   help="draw the cell edges (the mesh) over the colours")
    p.add_argument("--describe", action="store_true",
                   help="print the title, the nip geometry and the scale "
                        "bar, then exit (no ParaView needed)")
    return p.parse_args()


def unit_of(field):
    """The unit of a VTU array, for the colour bar."""
    if field.startswith(("sigma_", "cauchy_stress", "pressure_unknown_q")) or \
            field in ("von_mises", "hydrostatic_pressure"):
        return "MPa"
    if field == "displacement":
        return "mm"
    if field in ("material_id", "subdomain"):
        return "index"
    return "dimensionless"


def nice_step(span, parts=5):
    """A round step (1, 2 or 5 times a power of ten) that cuts span into
    about @p parts pieces."""
    if not span > 0:
        return 1.0
    raw = span / parts
    power = 10.0 ** math.floor(math.log10(raw))
    for m in (1.0, 2.0, 5.0, 10.0):
        if raw <= m * power * (1 + 1e-9):
            return m * power
    return 10.0 * power


def nice_range(lo, hi):
    """[lo, hi] widened to multiples of a round step, so that the colour
    bar reads 0 to 2.5 MPa rather than 2.8e-06 to 2.4731."""
    if hi < lo:
        lo, hi = hi, lo
    if hi == lo:
        pad = abs(hi) if hi != 0 else 1.0
        lo, hi = lo - 0.5 * pad, hi + 0.5 * pad
    step = nice_step(hi - lo)
    return (math.floor(lo / step + 1e-9) * step,
            math.ceil(hi / step - 1e-9) * step)


def scale_bar_length(view_width_mm):
    """A round length (1, 2 or 5 times a power of ten) [mm] of about a
    fifth of the picture's width."""
    target = view_width_mm / 5.0
    power = 10.0 ** math.floor(math.log10(target))
    best = power
    for m in (1.0, 2.0, 5.0, 10.0):
        if m * power <= target * 1.5:
            best = m * power
    return best


def read_rows(path):
    with open(path) as f:
        return list(csv.DictReader(f))


def read_outline(path):
    """The indenter outline [(x, y)] of indenter.csv, mirrored about the
    line of centres (the model is the half above it)."""
    points = [(float(r["x_mm"]), float(r["y_mm"])) for r in read_rows(path)]
    lower = [(x, -y) for (x, y) in reversed(points) if y > 0]
    return lower + points


def nip_geometry(nip_dir):
    """(apex_x, b, R0) [mm]: the deformed surface on the line of centres,
    the deformed half-chord (the largest y of the loaded surface nodes)
    and the undeformed outer radius, from outer_surface.csv; b is None
    without a loaded zone."""
    rows = read_rows(os.path.join(nip_dir, "outer_surface.csv"))
    apex = float(rows[0]["x_mm"])
    r0 = math.hypot(float(rows[0]["X_mm"]), float(rows[0]["Y_mm"]))
    loaded = [float(r["y_mm"]) for r in rows
              if float(r.get("applied_pressure_MPa", 0) or 0) > 0]
    contact = os.path.join(nip_dir, "contact_pressure.csv")
    if os.path.isfile(contact):
        theta0 = max(float(r["theta_deg"]) for r in read_rows(contact))
        loaded = [float(r["y_mm"]) for r in rows
                  if float(r["theta_deg"]) <= theta0 * (1 + 1e-9)]
    b = max(loaded) if loaded and max(loaded) > 0 else None
    return apex, b, r0


def report_row(nip_dir):
    """This nip's row of the run's nip_report.csv (in the run directory,
    the parent of nip-NN/ for a sweep) and the name of its load column,
    or (None, None)."""
    here = os.path.abspath(nip_dir)
    name = os.path.basename(here)
    if name.startswith("nip-") and name[4:].isdigit():
        path, row = os.path.join(os.path.dirname(here), "nip_report.csv"), int(name[4:])
    else:
        path, row = os.path.join(here, "nip_report.csv"), 1
    if not os.path.isfile(path):
        return None, None
    with open(path) as f:
        reader = csv.reader(f)
        header = next(reader)
        rows = list(reader)
    if row > len(rows) or len(header) < 2:
        return None, None
    return dict(zip(header, rows[row - 1])), header[1]


def load_text(column, value):
    """'P = 40 kN/m' from the load column's name and value."""
    if column.startswith("total_force_"):
        symbol, unit = "F", column[len("total_force_"):]
    else:
        symbol, unit = "P", column.replace("line_load_", "", 1)
    return f"{symbol} = {float(value):.4g} {unit.replace('_per_', '/')}"


def title_text(nip_dir, two_rolls):
    """The picture's title: the load and the nip's answer, the scene."""
    apex, b, r0 = nip_geometry(nip_dir)
    row, column = report_row(nip_dir)
    parts = []
    if row is not None:
        parts.append(load_text(column, row[column]))
        width = row.get("nip_width_2b_mm")
        if width:
            parts.append(f"nip width 2b = {float(width):.4g} mm")
        u0 = row.get("indentation_u0_mm")
        if u0:
            parts.append(f"indentation {float(u0):.3g} mm")
    elif b is not None:
        parts.append(f"nip width 2b = {2 * b:.4g} mm")
    scene = f"roll \u00d8{2 * r0:.4g} mm"
    if row is not None and row.get("youngs_modulus_E_MPa"):
        estimated = row.get("E_estimated_from_hardness", "") == "yes"
        scene += (f", E = {float(row['youngs_modulus_E_MPa']):.3g} MPa"
                  + (" (from hardness)" if estimated else ""))
    scene += ", against a covered roll" if two_rolls else \
        (", against a rigid roll" if os.path.isfile(
            os.path.join(nip_dir, "indenter.csv")) else "")
    return "; ".join(parts) + ("\n" if parts else "") + scene


def data_range(source, field):
    """The range of @p field (its magnitude for a vector) on @p source."""
    array = source.PointData[field]
    component = -1 if array.GetNumberOfComponents() > 1 else 0
    return array.GetRange(component)


def set_attribute_type(calculator):
    for name in ("AttributeType", "AttributeMode"):  # ParaView >= 5.8, older
        try:
            setattr(calculator, name, "Point Data")
            return
        except AttributeError:
            continue


def show_body(pv, pvd, field, last, view, lut, edges):
    """One roll's cover from @p pvd: warped, and mirrored about the line of
    centres (antisymmetric fields with their sign changed); returns the
    warped source and its mirror image, both shown."""
    reader = pv.OpenDataFile(pvd)
    reader.UpdatePipeline(last)
    if field not in reader.PointData.keys():
        sys.exit(f"render_nip.py: no point array '{field}' in {pvd}; "
                 f"there are: {', '.join(reader.PointData.keys())}")
    warp = pv.WarpByVector(Input=reader)
    warp.Vectors = ["POINTS", "displacement"]
    warp.ScaleFactor = 1.0
    mirror = pv.Reflect(Input=warp)
    mirror.Plane = "Y"
    mirror.Center = 0.0
    mirror.CopyInput = 0
    shown_name = field
    mirrored = mirror
    if field in ANTISYMMETRIC:
        mirrored = pv.Calculator(Input=mirror)
        set_attribute_type(mirrored)
        shown_name = field + "_mirrored"
        mirrored.ResultArrayName = shown_name
        mirrored.Function = "-" + field
    for source, name in ((warp, field), (mirrored, shown_name)):
        display = pv.Show(source, view)
        pv.ColorBy(display, ("POINTS", name))
        display.LookupTable = lut
        display.SetScalarBarVisibility(view, False)
        if edges:
            display.SetRepresentationType("Surface With Edges")
            display.EdgeColor = [0.25, 0.25, 0.25]
    warp.UpdatePipeline(last)
    mirrored.UpdatePipeline(last)
    return warp, mirrored, shown_name


def set_location(shown, names):
    """The first of @p names the text display accepts (the spellings
    changed in ParaView 5.10: 'Upper Center', before 'UpperCenter')."""
    for name in names:
        try:
            shown.WindowLocation = name
            return
        except (ValueError, AttributeError):
            continue


def add_text(pv, view, text, position=None, size=None):
    """Black text at the top centre, or at @p position (viewport
    fractions from the lower left)."""
    label = pv.Text(Text=text)
    shown = pv.Show(label, view)
    shown.Color = [0, 0, 0]
    if size:
        shown.FontSize = size
    if position is None:
        set_location(shown, ("Upper Center", "UpperCenter"))
        return
    set_location(shown, ("Any Location", "AnyLocation"))
    shown.Position = position


def add_scale_bar(pv, view, focus, scale, width, height):
    """A bar of a round length in mm at the lower left of the picture,
    with its length written above it (the camera is known: the picture
    is 2 scale high and 2 scale width/height wide, centred on focus, the
    line of centres pointing up)."""
    half_w = scale * width / height
    length = scale_bar_length(2 * half_w)
    # Screen right is -y with the line of centres (x) pointing up.
    x = focus[0] - 0.85 * scale
    y0 = focus[1] + 0.92 * half_w
    bar = pv.PolyLineSource(Points=[x, y0, 0.0, x, y0 - length, 0.0])
    drawn = pv.Show(bar, view)
    drawn.DiffuseColor = drawn.AmbientColor = [0, 0, 0]
    drawn.LineWidth = 4.0
    add_text(pv, view, f"{length:g} mm", position=[0.04, 0.1])


def describe(args):
    nip_dir = args.nip_dir
    two_rolls = os.path.isfile(os.path.join(nip_dir, "mating_roll", "solution.pvd"))
    apex, b, r0 = nip_geometry(nip_dir)
    width, height = (int(v) for v in args.size.split("x"))
    print("title: " + title_text(nip_dir, two_rolls).replace("\n", " | "))
    print(f"nip: apex x = {apex:.9g} mm, half-width b = {b:.9g} mm, R0 = {r0:.9g} mm"
          if b else f"nip: apex x = {apex:.6g} mm, no loaded zone")
    if b and args.zoom > 0:
        half_w = args.zoom * b * width / height
        print(f"frame: {2 * half_w:.9g} mm wide, centred on the nip; "
              f"scale bar {scale_bar_length(2 * half_w):g} mm")


def main():
    args = parse_arguments()
    if args.describe:
        describe(args)
        return
    from paraview import simple as pv

    pvd = os.path.join(args.nip_dir, "solution.pvd")
    if not os.path.isfile(pvd):
        sys.exit(f"render_nip.py: no solution.pvd in '{args.nip_dir}' "
                 "(Output/Write VTU must be true)")
    mate_pvd = os.path.join(args.nip_dir, "mating_roll", "solution.pvd")
    two_rolls = os.path.isfile(mate_pvd)
    width, height = (int(v) for v in args.size.split("x"))

    reader = pv.OpenDataFile(pvd)
    try:
        times = [float(t) for t in reader.TimestepValues]
    except TypeError:  # a single time is a scalar property
        times = [float(reader.TimestepValues)]
    last = times[-1] if times else 0.0
    reader.UpdatePipeline(last)
    arrays = reader.PointData.keys()
    if args.field not in arrays:
        sys.exit(f"render_nip.py: no point array '{args.field}'; "
                 f"there are: {', '.join(arrays)}")

    view = pv.CreateView("RenderView")
    view.ViewSize = [width, height]
    view.ViewTime = last
    view.OrientationAxesVisibility = 0
    view.Background = [1, 1, 1]
    try:
        view.UseColorPaletteForBackground = 0
    except AttributeError:
        pass

    lut = pv.GetColorTransferFunction(args.field)
    bodies = [show_body(pv, pvd, args.field, last, view, lut, args.edges)]
    if two_rolls:
        bodies.append(show_body(pv, mate_pvd, args.field, last, view, lut,
                                args.edges))
    lo, hi = math.inf, -math.inf
    for warp, mirrored, shown_name in bodies:
        for source, name in ((warp, args.field), (mirrored, shown_name)):
            a, b_ = data_range(source, name)
            lo, hi = min(lo, a), max(hi, b_)
    lo, hi = nice_range(lo, hi)
    try:
        lut.AutomaticRescaleRangeMode = "Never"
    except AttributeError:
        pass
    lut.RescaleTransferFunction(lo, hi)
    bar = pv.GetScalarBar(lut, view)
    bar.Title = f"{args.field} ({unit_of(args.field)})"
    bar.TitleColor = bar.LabelColor = [0, 0, 0]
    for name, value in (("ComponentTitle", ""), ("RangeLabelFormat", "%-#.3g"),
                        ("AutomaticLabelFormat", 0), ("LabelFormat", "%-#.3g")):
        try:
            setattr(bar, name, value)
        except AttributeError:
            pass
    bar.Visibility = 1

    outline_file = os.path.join(args.nip_dir, "indenter.csv")
    if os.path.isfile(outline_file):
        outline = read_outline(outline_file)
        line = pv.PolyLineSource(
            Points=[c for (x, y) in outline for c in (x, y, 0.0)])
        drawn = pv.Show(line, view)
        drawn.DiffuseColor = drawn.AmbientColor = [0, 0, 0]
        drawn.LineWidth = 2.0

    apex, half_width, _ = nip_geometry(args.nip_dir)
    view.InteractionMode = "2D"
    # The line of centres points up, the nip runs across the picture.
    view.CameraFocalPoint = [0.0, 0.0, 0.0]
    view.CameraPosition = [0.0, 0.0, 1000.0]
    view.CameraViewUp = [1.0, 0.0, 0.0]
    pv.ResetCamera(view)
    if half_width and args.zoom > 0:
        scale = args.zoom * half_width
        focus = [apex, 0.0, 0.0]
        view.CameraFocalPoint = focus
        view.CameraPosition = [focus[0], focus[1], focus[2] + 1000.0]
        view.CameraParallelScale = scale
        add_scale_bar(pv, view, focus, scale, width, height)
    add_text(pv, view, title_text(args.nip_dir, two_rolls), size=14)
    pv.Render(view)
    pv.SaveScreenshot(args.output, view, ImageResolution=[width, height])
    print(f"render_nip.py: wrote {args.output} ({args.field}, "
          f"time {last} of {pvd}; colour bar {lo:g} to {hi:g})")


if __name__ == "__main__":
    main()
