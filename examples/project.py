#!/usr/bin/env python3
# SPDX-License-Identifier: BSD-3-Clause
"""Projects a curve onto a surface with the projcurve Python package.

    examples/project.py                    # the built-in patch and segment
    examples/project.py MODEL.igs [-o OUT.igs] [--dir X Y Z]

With a model file it projects the file's first curve onto its first
surface (along --dir, default -z; --ortho for the orthogonal projection)
and writes the result as IGES when -o is given. Prints each branch: its
curve-parameter range, why it starts and ends, its traced points and
pieces, and how many poles its compact curves have.
"""
import argparse
import sys

import projcurve as pc


def built_in():
    """A bilinear patch z = x y over the unit square and a segment above it."""
    s = pc.Surface.from_nurbs(degree=(1, 1), shape=(2, 2),
                              control_points=[[0, 0, 0], [1, 0, 0], [0, 1, 0], [1, 1, 1]],
                              knots=([0, 0, 1, 1], [0, 0, 1, 1]))
    c = pc.Curve.from_nurbs(degree=1, control_points=[[0.1, 0.2, 2], [0.9, 0.7, 2]],
                            knots=[0, 0, 1, 1])
    return s, c, None


def main():
    ap = argparse.ArgumentParser(description=__doc__.splitlines()[0])
    ap.add_argument("model", nargs="?", help="an IGES, STEP or G+Smo XML file")
    ap.add_argument("-o", "--output", help="write the result to this IGES file")
    ap.add_argument("--dir", nargs=3, type=float, default=(0, 0, -1), metavar=("X", "Y", "Z"))
    ap.add_argument("--ortho", action="store_true", help="orthogonal projection")
    ap.add_argument("--tol", type=float, help="distance tolerance eps_D (model units)")
    args = ap.parse_args()

    if args.model:
        model = pc.Model.read(args.model)
        if not model.surfaces or not model.curves:
            print("%s: needs a surface and a curve" % args.model, file=sys.stderr)
            return 1
        surface, curve = model.surfaces[0], model.curves[0]
    else:
        surface, curve, model = built_in()

    options = pc.Options()
    if args.tol is not None:
        options.tol_distance = args.tol
    try:
        if args.ortho:
            result = pc.project_orthogonal(surface, curve, options)
        else:
            result = pc.project_directional(surface, curve, args.dir, options)
    except pc.Error as e:
        print("projection failed: %s" % e, file=sys.stderr)
        return 1

    print("library %s (%s), eps_D %.3g"
          % (pc.library_version(), pc.library_path(), result.stat("tol_distance")))
    print("%d branch(es), %d failure(s)" % (len(result.branches), result.failure_count))
    for b in result.branches:
        line = ("  branch %d: t %.6g..%.6g, %s -> %s, %d points, %d pieces"
                % (b.index, b.t_range[0], b.t_range[1], b.start.name.lower(),
                   b.end.name.lower(), b.n_points, b.n_pieces))
        if b.n_pieces:
            line += (", compact: pcurve %d poles, curve %d poles (within %.2g)"
                     % (b.compact_pcurve().info.n_control_points,
                        b.compact_curve().info.n_control_points, b.compact_info().curve_error))
        print(line)
        first = b.points()[0]
        print("    starts at (%.6g, %.6g, %.6g)" % first)
    if args.output:
        with pc.IgesWriter() as w:
            if model is not None and model.length_unit:
                w.set_length_unit(model.length_unit)
            w.add_result(surface, result)
            w.write(args.output)
        print("wrote %s" % args.output)
    return 0


if __name__ == "__main__":
    sys.exit(main())
