"""Prints a Three d/Core deflection expression from a tabulated bending
line: the piecewise linear v(z) through the rows of a CSV file whose first
two columns are z [mm] and v [mm] (with a header), as nested muparser
conditionals, constant beyond the last row. The elastic core's
core_deflection_along_axis.csv is such a file: with --up-to L (the cover
end, Three d/Slice thickness) only the rows with z <= L are used, so that
a rigid core can be bent along the elastic core's own deflection
(doc/three_d.md, "An elastic core"):

  python3 scripts/core_deflection_expression.py \
      output/elastic_core_3d/core_deflection_along_axis.csv --up-to 500

and in the .prm file: subsection Three d, set Core deflection = (what it
printed).
"""

import argparse
import csv
import sys


def read_table(path, up_to):
    """The (z, v) rows of PATH with z <= UP_TO (all if None), sorted by z."""
    rows = []
    with open(path, newline="") as f:
        reader = csv.reader(f)
        next(reader, None)  # the header
        for row in reader:
            if len(row) < 2:
                continue
            z, v = float(row[0]), float(row[1])
            if up_to is None or z <= up_to * (1 + 1e-12):
                rows.append((z, v))
    rows.sort()
    return rows


def piecewise_linear(rows):
    """The nested conditional of the line through ROWS, in z."""
    if len(rows) == 1:
        return repr(rows[0][1])
    parts = []
    for (z0, v0), (z1, v1) in zip(rows, rows[1:]):
        parts.append(
            "(z < %r ? %r + (%r) * (z - %r) / %r : "
            % (z1, v0, v1 - v0, z0, z1 - z0))
    return "".join(parts) + repr(rows[-1][1]) + ")" * (len(rows) - 1)


def main():
    parser = argparse.ArgumentParser(description=__doc__.split("\n\n")[0])
    parser.add_argument("table", help="CSV: z [mm], v [mm], with a header")
    parser.add_argument("--up-to", type=float, default=None,
                        help="use only the rows with z <= this [mm]")
    args = parser.parse_args()
    rows = read_table(args.table, args.up_to)
    if not rows:
        sys.exit("core_deflection_expression.py: no rows in %s%s" % (
            args.table,
            "" if args.up_to is None else " with z <= %g" % args.up_to))
    print(piecewise_linear(rows))


if __name__ == "__main__":
    main()
