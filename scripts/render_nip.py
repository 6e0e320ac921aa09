"""Renders one nip of a rollnip run with ParaView: the cover warped by its
displacement, coloured by a field, the indenter outline on top, zoomed on
the contact zone. Run it with pvpython (bash scripts/setup.sh installs
ParaView when ROLLNIP_WITH_PARAVIEW=1 is set); without a display, under
xvfb-run:

  xvfb-run -a pvpython scripts/render_nip.py output/batra1980/nip-03 \
      --field sigma_rr --output nip.png [--edges] [--zoom 0]

NIP_DIR is a directory with solution.pvd (and indenter.csv for contact
runs). The last time of the PVD (the converged nip) is drawn.
"""

import argparse
import csv
import math
import os
import sys

from paraview import simple as pv


def parse_arguments():
    p = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    p.add_argument("nip_dir", help="a directory with solution.pvd")
    p.add_argument("--field", default="sigma_rr",
                   help="point array to colour by (default sigma_rr; any "
                        "VTU array, e.g. von_mises, pressure_unknown_q_smoothed)")
    p.add_argument("--output", default="nip.png", help="PNG file to write")
    p.add_argument("--zoom", type=float, default=3.0,
                   help="half-height of the picture in nip half-widths "
                        "(default 3; 0: the whole model)")
    p.add_argument("--size", default="1200x800", help="pixels, WxH")
    p.add_argument("--edges", action="store_true",
                   help="draw the cell edges (the mesh) over the colours")
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


def read_outline(path):
    """The indenter outline [(x, y)] of indenter.csv, mirrored about the
    line of centres (the model is the half above it)."""
    with open(path) as f:
        points = [(float(r["x_mm"]), float(r["y_mm"])) for r in csv.DictReader(f)]
    lower = [(x, -y) for (x, y) in reversed(points) if y > 0]
    return lower + points


def main():
    args = parse_arguments()
    pvd = os.path.join(args.nip_dir, "solution.pvd")
    if not os.path.isfile(pvd):
        sys.exit(f"render_nip.py: no solution.pvd in '{args.nip_dir}' "
                 "(Output/Write VTU must be true)")
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

    warp = pv.WarpByVector(Input=reader)
    warp.Vectors = ["POINTS", "displacement"]
    warp.ScaleFactor = 1.0
    shown = pv.Show(warp, view)
    pv.ColorBy(shown, ("POINTS", args.field))
    shown.RescaleTransferFunctionToDataRange(True, False)
    shown.SetScalarBarVisibility(view, True)
    if args.edges:
        shown.SetRepresentationType("Surface With Edges")
        shown.EdgeColor = [0.25, 0.25, 0.25]
    bar = pv.GetScalarBar(pv.GetColorTransferFunction(args.field), view)
    bar.Title = f"{args.field} ({unit_of(args.field)})"
    bar.TitleColor = bar.LabelColor = [0, 0, 0]

    outline_file = os.path.join(args.nip_dir, "indenter.csv")
    half_width = None
    if os.path.isfile(outline_file):
        outline = read_outline(outline_file)
        line = pv.PolyLineSource(
            Points=[c for (x, y) in outline for c in (x, y, 0.0)])
        drawn = pv.Show(line, view)
        drawn.DiffuseColor = drawn.AmbientColor = [0, 0, 0]
        drawn.LineWidth = 2.0
        # The nip half-width from theta0, the last knot of the pressure.
        contact = os.path.join(args.nip_dir, "contact_pressure.csv")
        if os.path.isfile(contact):
            with open(contact) as f:
                theta0 = max(float(r["theta_deg"]) for r in csv.DictReader(f))
            apex = min(x for (x, y) in outline)
            half_width = apex * math.sin(math.radians(theta0))

    view.InteractionMode = "2D"
    pv.ResetCamera(view)
    if half_width and args.zoom > 0:
        bounds = warp.GetDataInformation().GetBounds()
        # The nip's edge of the picture at the right, the line of centres
        # near its bottom: the model is the half above that line.
        scale = args.zoom * half_width
        focus = [bounds[1], 0.9 * scale, 0.0]
        view.CameraFocalPoint = focus
        view.CameraPosition = [focus[0], focus[1], focus[2] + 1000.0]
        view.CameraViewUp = [0.0, 1.0, 0.0]
        view.CameraParallelScale = scale
    pv.Render(view)
    pv.SaveScreenshot(args.output, view, ImageResolution=[width, height])
    print(f"render_nip.py: wrote {args.output} ({args.field}, "
          f"time {last} of {pvd})")


if __name__ == "__main__":
    main()
