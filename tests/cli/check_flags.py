# SPDX-License-Identifier: BSD-3-Clause
"""The flags of projcurve project that choose what is projected and what is
printed (--surface, --curve, --line, --points, --interpolate, --quiet,
--progress, --timeout), the conical projection (--eye), with their errors, and the sizes projcurve info
prints; every figure is checked against the files themselves (read by
iges_geometry, an independent reader and evaluator), not the library's
own numbers. Used by check_cli.py (parts flags and info)."""
import json
import os
import re

import iges_geometry

BUMPY = "bumpy_bicubic_8x8_down"  # the plane [0, 100]^2, heights within +-8
DEG5 = "deg5_quintic_9x8_down"    # the same square, another surface and curve


def case_path(shared, name):
    return os.path.join(shared, "cases", name + ".igs")


def load_json(path, check, what):
    try:
        with open(path) as f:
            return json.load(f)
    except (OSError, ValueError) as e:
        check(False, f"{what}: no JSON report ({e})")
        return None


def pick_pairs(t, shared, work):
    """--surface / --curve: the pair chosen is the pair of the full run,
    numbered as info numbers the surfaces and curves across the files, and
    numbers out of range are refused naming the valid range."""
    files = [case_path(shared, BUMPY), case_path(shared, DEG5)]
    base = [t.exe, "project"] + files + ["--dir", "0,0,-1"]
    full = os.path.join(work, "all_pairs.json")
    if t.run(base + ["--json", full], 0, "all pairs").returncode:
        return
    everything = load_json(full, t.check, "all pairs")
    for s, c in ((1, 0), (0, 1), (1, 1)):
        out = os.path.join(work, f"pair_{s}_{c}.json")
        if t.run(base + ["--surface", str(s), "--curve", str(c), "--json", out], 0,
                 f"--surface {s} --curve {c}").returncode:
            continue
        got = load_json(out, t.check, f"pair {s} {c}")
        want = [b for b in everything["branches"] if (b["surface"], b["curve"]) == (s, c)]
        strip = lambda bs: [{k: v for k, v in b.items() if k != "residual"} for b in bs]
        t.check(len(want) == 1 and strip(got["branches"]) == strip(want),
                f"--surface {s} --curve {c}: {got['branches']} is not the full run's {want}")
    out = os.path.join(work, "surface_1.json")
    if t.run(base + ["--surface", "1", "--json", out], 0, "--surface 1").returncode == 0:
        got = load_json(out, t.check, "--surface 1")
        pairs = sorted((b["surface"], b["curve"]) for b in got["branches"])
        t.check(pairs == [(1, 0), (1, 1)], f"--surface 1: pairs {pairs}")
    for flag, value, message in (("--surface", "2", "surfaces 0 to 1"),
                                 ("--curve", "7", "curves 0 to 1"),
                                 ("--surface", "x", "surface number"),
                                 ("--surface", "-1", "surface number"),
                                 ("--curve", "1.5", "curve number")):
        proc = t.run(base + [flag, value], 2, f"{flag} {value}")
        t.check(message in proc.stderr, f"{flag} {value}: '{message}' not in {proc.stderr!r}")
    one = [t.exe, "project", files[0], "--dir", "0,0,-1"]
    proc = t.run(one + ["--surface", "1"], 2, "--surface 1 of one surface")
    t.check("one surface, number 0" in proc.stderr, f"--surface 1: {proc.stderr!r}")
    t.run(one + ["--surface", "0", "--surface", "0"], 2, "--surface twice")
    t.run(one + ["--surface"], 2, "--surface without a value")


def check_through(t, curve, points, what, tol):
    """The curve passes through points[i] at its chord-length parameter."""
    chords = [0.0]
    for a, b in zip(points, points[1:]):
        chords.append(chords[-1] + sum((x - y) ** 2 for x, y in zip(a, b)) ** 0.5)
    worst = max(sum((x - y) ** 2 for x, y in zip(curve.eval(c / chords[-1]), p)) ** 0.5
                for c, p in zip(chords, points))
    t.check(worst <= tol, f"{what}: the curve misses its points by {worst:.3g} (> {tol})")


def whole_branches(t, data, what):
    t.check(data is not None and all(b["start"] == "curve_start" and b["end"] == "curve_end"
                                     for b in data["branches"]),
            f"{what}: a branch does not cover its curve")


def given_curves(t, shared, work):
    """--line and --points [--interpolate]: the curve written to the IGES
    output is the one asked for (its control points are the points given;
    the interpolant passes through them), its projection is judged like a
    case's, and malformed values and files are refused with the line."""
    surface = case_path(shared, BUMPY)
    base = [t.exe, "project", surface, "--dir", "0,0,-1"]
    direction = {"tol_dist": "1e-3", "mode": "directional", "dir_x": "0", "dir_y": "0",
                 "dir_z": "-1"}
    # --line: one straight curve, projected whole (it stays above the square)
    igs, js = os.path.join(work, "line.igs"), os.path.join(work, "line.json")
    if t.run(base + ["--line", "10,10,20,90,80,20", "--tol", "1e-3", "-o", igs, "--json", js],
             0, "--line").returncode == 0:
        curves = iges_geometry.input_curves(igs)
        t.check(len(curves) == 1 and curves[0].degree == 1 and
                [p[:3] for p in curves[0].points] == [[10, 10, 20], [90, 80, 20]],
                "--line: the written curve is not the segment asked for")
        data = load_json(js, t.check, "--line")
        whole_branches(t, data, "--line")
        for b, w in zip(data["branches"], iges_geometry.branches(igs)):
            t.check_branch_geometry("--line", direction, b, w, curves[0])
        # -o NAME.step: the same job as STEP, read back by `info`: the
        # surface, the given curve and one compact 3D curve per branch
        step = os.path.join(work, "line.step")
        if t.run(base + ["--line", "10,10,20,90,80,20", "--tol", "1e-3", "-o", step], 0,
                 "-o .step").returncode == 0:
            proc = t.run([t.exe, "info", "--json", step], 0, "info of the STEP output")
            if proc.returncode == 0:
                back = json.loads(proc.stdout)
                t.check(back["surfaces"] == 1 and
                        back["curves"] == 1 + len(data["branches"]),
                        f"-o .step: read back {back['surfaces']} surface(s), "
                        f"{back['curves']} curve(s)")
    for value in ("10,10,20,90,80", "10,10,20,90,80,x", "1,2,3,1,2,3", "1,2,3,4,5,6,7"):
        proc = t.run(base + ["--line", value], 2, f"--line {value}")
        t.check("--line" in proc.stderr, f"--line {value}: {proc.stderr!r}")
    t.run(base + ["--line", "1,2,3,4,5,6", "--curve", "0"], 2, "--line with --curve")

    # --points: a polyline with comments, commas and blank lines
    points = [[10, 10, 20], [50, 30, 20], [90, 20, 20], [80, 80, 20], [20, 70, 25]]
    path = os.path.join(work, "points.txt")
    with open(path, "w") as f:
        f.write("# a polyline above the square\n10 10 20\n50,30,20\n\n90\t20 20  # a corner\n"
                "80, 80, 20\n20 70 25\n")
    igs, js = os.path.join(work, "points.igs"), os.path.join(work, "points.json")
    if t.run(base + ["--points", path, "--tol", "1e-3", "-o", igs, "--json", js], 0,
             "--points").returncode == 0:
        curves = iges_geometry.input_curves(igs)
        t.check([[p[:3] for p in c.points] for c in curves] ==
                [[a, b] for a, b in zip(points, points[1:])],
                "--points: the written curves are not the polyline's segments")
        data = load_json(js, t.check, "--points")
        whole_branches(t, data, "--points")
        t.check(sorted(b["curve"] for b in data["branches"]) == list(range(len(points) - 1)),
                f"--points: one branch per segment: {[b['curve'] for b in data['branches']]}")
        # segment i runs over the polyline's chord-length parameters
        ends = [c.t0 for c in curves] + [curves[-1].t1]
        t.check(ends[0] == 0 and ends[-1] == 1 and all(a < b for a, b in zip(ends, ends[1:])),
                f"--points: segment domains {ends}")
        check_through(t, _Polyline(curves), points, "--points", 1e-12 * 100)
        for b, w in zip(data["branches"], iges_geometry.branches(igs)):
            t.check_branch_geometry("--points", direction, b, w, curves[b["curve"]])
    # --interpolate: cubic from 4 points, quadratic from 3, a line from 2
    for count, degree in ((5, 3), (4, 3), (3, 2), (2, 1)):
        sub = points[:count]
        path_n = os.path.join(work, f"points{count}.txt")
        with open(path_n, "w") as f:
            f.writelines(" ".join(str(x) for x in p) + "\n" for p in sub)
        igs = os.path.join(work, f"interp{count}.igs")
        if t.run(base + ["--points", path_n, "--interpolate", "-o", igs], None,
                 f"--interpolate {count} points").returncode == 2:
            continue
        curves = iges_geometry.input_curves(igs)
        t.check(len(curves) == 1 and curves[0].degree == degree,
                f"--interpolate {count} points: degree {[c.degree for c in curves]}, "
                f"expected {degree}")
        if curves:
            # the model is ~100 wide: 1e-10 of it is far above rounding
            check_through(t, curves[0], sub, f"--interpolate {count} points", 1e-8)
    bad = (("10 10 20\n10 x 20\n", "2: 'x' is not a finite number"),
           ("10 10 20\n\n# c\n10 20\n", "4: expected 3 coordinates X Y Z, found 2"),
           ("10 10 20\n1 2 3 4\n", "2: expected 3 coordinates X Y Z, found more"),
           ("# only\n10 10 20\n", "needs at least 2 points, the file has 1"),
           ("1 2 3\n4 5 6\n\n4 5 6\n", "4: the point repeats the one before it (line 2)"),
           ("1 2 3\n1e999 5 6\n", "2: '1e999' is not a finite number"))
    for text, message in bad:
        bad_path = os.path.join(work, "bad_points.txt")
        with open(bad_path, "w") as f:
            f.write(text)
        for extra in ([], ["--interpolate"]):
            proc = t.run(base + ["--points", bad_path] + extra, 2, f"--points {text!r}")
            t.check(message in proc.stderr, f"--points {text!r}: '{message}' not in "
                                            f"{proc.stderr!r}")
    # Windows line ends, a comment longer than any buffer, no final newline
    odd = os.path.join(work, "odd_points.txt")
    with open(odd, "w", newline="") as f:
        f.write("# " + "x" * 100000 + "\r\n10 10 20\r\n50 30 20\r\n90,20,20")
    igs = os.path.join(work, "odd.igs")
    if t.run(base + ["--points", odd, "-o", igs], 0, "--points CRLF").returncode == 0:
        t.check([[p[:3] for p in c.points] for c in iges_geometry.input_curves(igs)] ==
                [[[10, 10, 20], [50, 30, 20]], [[50, 30, 20], [90, 20, 20]]],
                "--points with CRLF line ends: other curves")
    proc = t.run(base + ["--points", os.path.join(work, "missing.txt")], 2, "--points missing")
    t.check("cannot open" in proc.stderr, f"--points missing: {proc.stderr!r}")
    t.run(base + ["--interpolate"], 2, "--interpolate without --points")
    t.run(base + ["--points", path, "--line", "1,2,3,4,5,6"], 2, "--points and --line")
    t.run([t.exe, "project", "--dir", "0,0,-1", "--line", "1,2,3,4,5,6"], 2,
          "--line without a file for the surfaces")
    teapot = os.path.join(shared, "real", "teapot_newell_spd.txt")
    if os.path.isfile(teapot):
        # surfaces without curves: a curve from the command line is enough
        t.run([t.exe, "project", teapot, "--dir", "0,0,-1", "--line", "0,0,5,1,1,5",
               "--surface", "0", "--quiet"], None, "teapot with --line")


class _Polyline:
    """The segments of --points as one curve over [0, 1]."""

    def __init__(self, segments):
        self.segments = segments

    def eval(self, t):
        for c in self.segments:
            if t <= c.t1:
                return c.eval(max(t, c.t0))
        return self.segments[-1].eval(self.segments[-1].t1)


PROGRESS = re.compile(r"projcurve: +(\d+)% \(pair (\d+) of (\d+): curve \d+ onto surface \d+\)")


def printing(t, shared, work):
    """--quiet prints nothing on success and only errors otherwise;
    --progress shows the progress line (one line each when stderr is not a
    terminal, redrawn in place and erased on a terminal); without it and
    off a terminal, no progress at all; --timeout's cut is exit 3."""
    case = case_path(shared, BUMPY)
    base = [t.exe, "project", case, "--dir", "0,0,-1"]
    proc = t.run(base + ["--quiet"], 0, "--quiet")
    t.check(proc.stdout == "" and proc.stderr == "", f"--quiet printed {proc.stdout!r} "
                                                     f"{proc.stderr!r}")
    proc = t.run(base + ["--quiet", "--dir", "0,0,0"], 2, "--quiet with an error")
    t.check(proc.stdout == "" and "--dir is given twice" in proc.stderr,
            f"--quiet error: {proc.stdout!r} {proc.stderr!r}")
    proc = t.run([t.exe, "project", case, "--dir", "0,0,0", "--quiet"], 1, "--quiet failing")
    t.check(proc.stdout == "" and "curve 0 onto surface 0" in proc.stderr,
            f"--quiet projection failure: {proc.stdout!r} {proc.stderr!r}")
    t.run(base + ["--quiet", "--progress"], 2, "--quiet and --progress")
    proc = t.run(base, 0, "no progress off a terminal")
    t.check("%" not in proc.stderr, f"progress off a terminal: {proc.stderr!r}")
    two = [t.exe, "project", case, case_path(shared, DEG5), "--dir", "0,0,-1", "--progress"]
    proc = t.run(two, 0, "--progress")
    lines = proc.stderr.splitlines()
    found = [PROGRESS.fullmatch(line) for line in lines]
    t.check(lines and all(found), f"--progress: lines that are not progress: {lines}")
    if lines and all(found):
        t.check(found[-1].groups() == ("100", "4", "4"), f"--progress ends {lines[-1]!r}")
        pct = [int(m.group(1)) for m in found]
        t.check(pct == sorted(pct), f"--progress goes back: {pct}")
    t.check("branch(es)" in proc.stdout, "--progress: the summary is still printed")
    on_terminal(t, two)

    # --timeout: a cut call is reported, its partial result written, exit 3
    js, igs = os.path.join(work, "timeout.json"), os.path.join(work, "timeout.igs")
    svg = os.path.join(work, "timeout.svg")
    proc = t.run(base + ["--timeout", "1e-9", "--json", js, "-o", igs, "--svg", svg], 3,
                 "--timeout 1 ns")
    t.check(os.path.isfile(igs) and os.path.isfile(svg) and
            len(iges_geometry.input_curves(igs)) == 1,
            "--timeout: the IGES and SVG outputs are still written")
    t.check("stopped by --timeout" in proc.stderr and "time limit" in proc.stderr,
            f"--timeout: {proc.stderr!r}")
    data = load_json(js, t.check, "--timeout")
    if data:
        t.check(data["timeouts"] == 1 and data["failures"] >= 1,
                f"--timeout: timeouts {data['timeouts']}, failures {data['failures']}")
        t.check(all(b["end"] in ("limit", "curve_end") for b in data["branches"]),
                f"--timeout: ends {[b['end'] for b in data['branches']]}")
    proc = t.run(base + ["--timeout", "1e-9", "--quiet"], 3, "--timeout --quiet")
    t.check(proc.stdout == "", "--timeout --quiet: a summary")


def on_terminal(t, args):
    """The progress line on a terminal: redrawn with carriage returns and
    erased before the summary (stderr on a pseudo-terminal)."""
    try:
        import pty
    except ImportError:
        return
    import subprocess
    master, slave = pty.openpty()
    proc = subprocess.Popen(args, stdout=subprocess.PIPE, stderr=slave, text=True)
    os.close(slave)
    chunks = []
    while True:
        try:
            data = os.read(master, 4096)
        except OSError:  # the child closed its side
            break
        if not data:
            break
        chunks.append(data)
    proc.wait(timeout=240)
    os.close(master)
    text = b"".join(chunks).decode(errors="replace")
    t.check(proc.returncode == 0, f"--progress on a terminal: exit {proc.returncode}")
    t.check("\r" in text and "\n" not in text.replace("\r\n", "") and text.endswith("\r"),
            f"--progress on a terminal: not redrawn in place and erased: {text!r}")
    t.check(PROGRESS.search(text) is not None, f"--progress on a terminal: {text!r}")


def info_sizes(t, shared):
    """info's boxes, control point counts and spans of every surface and
    curve of each case, and the model's box, against the file's 128 and 126
    entities (the box of the control points)."""
    num = r"(-?[\d.e+-]+|-?inf|nan)"
    box_re = r"box \[{0}, {0}\] x \[{0}, {0}\] x \[{0}, {0}\]".format(num)
    for name in sorted(os.listdir(os.path.join(shared, "cases"))):
        if not name.endswith(".igs"):
            continue
        path = os.path.join(shared, "cases", name)
        out = t.run([t.exe, "info", path], 0, f"info {name}").stdout
        ents = iges_geometry.read_entities(path)
        surfaces = [iges_geometry.Surface(f) for _, (e, _, f) in sorted(ents.items()) if e == 128]
        curves = iges_geometry.input_curves(path)
        boxes = []
        for kind, items in (("surface", surfaces), ("curve", curves)):
            for i, item in enumerate(items):
                pts = [p for row in item.rows for p in row] if kind == "surface" else item.points
                xyz = [[p[k] / p[3] for k in range(3)] for p in pts]
                want = [v for k in range(3) for v in (min(p[k] for p in xyz),
                                                      max(p[k] for p in xyz))]
                boxes.append(want)
                m = re.search(rf"^  {kind} {i}: .*{box_re}$", out, re.M)
                if not m:
                    t.check(False, f"info {name}: no box for {kind} {i}:\n{out[:400]}")
                    continue
                got = [float(g) for g in m.groups()]
                # %g prints 6 significant digits
                t.check(all(abs(a - b) <= 1e-5 * (1 + abs(b)) for a, b in zip(got, want)),
                        f"info {name}: {kind} {i} box {got}, the control points' {want}")
                if kind == "curve":
                    spans = re.search(rf"^  curve {i}: degree \d+, (\d+) control points, "
                                      rf"(\d+) spans", out, re.M)
                    t.check(spans and (int(spans.group(1)), int(spans.group(2))) ==
                            (len(item.points), item.distinct_spans()),
                            f"info {name}: curve {i} poles/spans {spans and spans.groups()}")
        m = re.search(r"^  model " + box_re.replace("box ", "box: ", 1) + ", diagonal", out, re.M)
        union = [f(b[j] for b in boxes) for j in range(6) for f in [(min, max)[j % 2]]]
        t.check(m is not None and all(abs(float(a) - b) <= 1e-5 * (1 + abs(b))
                                      for a, b in zip(m.groups(), union)),
                f"info {name}: model box {m and m.groups()}, the union {union}")
        proc = t.run([t.exe, "info", "--json", path], 0, f"info --json {name}")
        try:
            doc = json.loads(proc.stdout)
        except ValueError:
            t.check(False, f"info --json {name}: not JSON")
            continue
        t.check(len(doc.get("surface_list", [])) == len(surfaces) and
                len(doc.get("curve_list", [])) >= len(curves),
                f"info --json {name}: surface_list / curve_list lengths")
        json_boxes = [s["box"] for s in doc.get("surface_list", [])]
        json_boxes += [c["box"] for c in doc.get("curve_list", [])][:len(curves)]
        for got, want in zip(json_boxes, boxes):
            reordered = [got[0], got[3], got[1], got[4], got[2], got[5]]
            t.check(all(abs(a - b) <= 1e-12 * (1 + abs(b)) for a, b in zip(reordered, want)),
                    f"info --json {name}: box {got} vs {want}")
        for s, item in zip(doc.get("surface_list", []), surfaces):
            t.check(s["poles"] == [len(item.rows[0]), len(item.rows)] and
                    s["degree"] == [item.pu, item.pv],
                    f"info --json {name}: surface poles/degree {s['poles']} {s['degree']}")
        t.check(doc.get("box") is not None and len(doc["box"]) == 6,
                f"info --json {name}: model box {doc.get('box')}")


def on_ray(t, what, eye, p, q, tol):
    """q lies within tol of the line from eye through p, and beyond p."""
    ray, d = [a - b for a, b in zip(p, eye)], [a - b for a, b in zip(q, eye)]
    cr = [ray[1] * d[2] - ray[2] * d[1], ray[2] * d[0] - ray[0] * d[2],
          ray[0] * d[1] - ray[1] * d[0]]
    norm = lambda v: sum(x * x for x in v) ** 0.5
    off = norm(cr) / norm(ray)
    beyond = sum((a - b) * r for a, b, r in zip(q, p, ray)) / norm(ray)
    t.check(off <= tol and beyond >= -tol,
            f"{what}: a point {off:.3g} off its ray from the eye (tol {tol}), "
            f"{beyond:.3g} beyond P(t)")


def eye_point(t, shared, work):
    """--eye X,Y,Z: the conical projection. Every branch written to IGES
    is judged from the file (S at its pcurve and its 3D curve within eps_D
    of the exact point on the ray from the eye, found by Newton, and at the
    quarters of its knot spans on that ray and beyond P(t)); the JSON's
    residuals are the corrector's; STEP, SVG and the usage errors."""
    surface = case_path(shared, BUMPY)
    eye = [50.0, 45.0, 200.0]
    base = [t.exe, "project", surface, "--eye", "50,45,200", "--line", "10,10,20,90,80,20",
            "--tol", "1e-3"]
    case = {"tol_dist": "1e-3", "mode": "conical", "eye_x": "50", "eye_y": "45",
            "eye_z": "200"}
    igs, js = os.path.join(work, "eye.igs"), os.path.join(work, "eye.json")
    svg, step = os.path.join(work, "eye.svg"), os.path.join(work, "eye.step")
    proc = t.run(base + ["-o", igs, "--json", js, "--svg", svg], 0, "--eye")
    if proc.returncode:
        return
    data = load_json(js, t.check, "--eye")
    curves = iges_geometry.input_curves(igs)
    written = iges_geometry.branches(igs)
    # the line stays above the square and inside the cone of the eye over
    # it: one branch over the whole line
    t.check(data is not None and len(data["branches"]) == 1 == len(written),
            f"--eye: {data and len(data['branches'])} branches, {len(written)} written")
    whole_branches(t, data, "--eye")
    for b, (s, pcurve, q) in zip(data["branches"], written):
        t.check_branch_geometry("--eye", case, b, (s, pcurve, q), curves[0])
        # traced points are corrector solutions: 1e-3 of eps_D is ample
        t.check(b["residual"] <= 1e-6, f"--eye: residual {b['residual']}")
        k = pcurve.knots
        lo, hi = k[pcurve.degree], k[-pcurve.degree - 1]
        for i in range(9):
            tt = lo + (hi - lo) * i / 8
            u, v, _ = pcurve.eval(tt)
            p = curves[0].eval(tt)
            on_ray(t, "--eye S(pcurve)", eye, p, s.eval(u, v), 1e-3)
            if q is not None:
                on_ray(t, "--eye 3D curve", eye, p, q.eval(tt), 1e-3)
    t.check_svg(svg, 1, 1, 1, "--eye")
    if t.run(base + ["-o", step], 0, "--eye -o .step").returncode == 0:
        proc = t.run([t.exe, "info", "--json", step], 0, "info of the --eye STEP output")
        if proc.returncode == 0:
            back = json.loads(proc.stdout)
            t.check(back["surfaces"] == 1 and back["curves"] == 2,
                    f"--eye -o .step: read back {back['surfaces']} surface(s), "
                    f"{back['curves']} curve(s)")
    # the usage errors and a curve through the eye
    for extra, message in ((["--dir", "0,0,-1"], "exactly one of"),
                           (["--orthogonal"], "exactly one of"),
                           (["--eye", "1,2,3"], "--eye is given twice")):
        proc = t.run(base + extra, 2, f"--eye with {extra}")
        t.check(message in proc.stderr, f"--eye with {extra}: {proc.stderr!r}")
    for value in ("1,2", "1,2,x", "1,2,3,4", "nan,0,0"):
        proc = t.run([t.exe, "project", surface, "--eye", value], 2, f"--eye {value}")
        t.check("--eye wants X,Y,Z" in proc.stderr, f"--eye {value}: {proc.stderr!r}")
    proc = t.run([t.exe, "project", surface, "--eye", "50,45,20", "--line",
                  "10,10,20,90,80,20"], 1, "--eye on the curve")
    t.check("passes through the eye" in proc.stderr and "curve 0 onto surface 0" in proc.stderr,
            f"--eye on the curve: {proc.stderr!r}")


FOLD = "fold_c_sheet_jump"  # a C-folded sheet: rays along -z hit it 0, 1, then 2 times


def hit_distances(curve, written, t):
    """(distance along -z from P(t), branch index) of every written branch
    whose t range holds t (S at its pcurve: the pcurve's parameter is t)."""
    out = []
    for k, (surface, pcurve, _) in enumerate(written):
        lo, hi = pcurve.knots[pcurve.degree], pcurve.knots[-pcurve.degree - 1]
        if lo <= t <= hi:
            u, v, _ = pcurve.eval(t)
            out.append((curve.eval(t)[2] - surface.eval(u, v)[2], k))
    return out


def near_an_end(written, t, margin):
    return any(abs(t - pc.knots[pc.degree]) <= margin or abs(t - pc.knots[-pc.degree - 1]) <= margin
               for _, pc, _ in written)


def hits(t, shared, work):
    """--nearest and --max-distance D on the folded sheet, judged against
    the run that keeps every hit (the complete set of ray hits, itself
    judged by cli_cases): at 201 parameters, away from branch ends, the
    nearest run holds exactly one point where the full run holds any, at
    the smallest distance of the full run's (to eps_D); the max-distance
    run holds exactly the full run's points within D, and every branch it
    cuts ends or starts at distance D."""
    case = case_path(shared, FOLD)
    base = [t.exe, "project", case, "--dir", "0,0,-1", "--tol", "1e-3"]
    tol, margin = 1e-3, 1e-6
    runs = {}
    for name, extra in (("all", []), ("nearest", ["--nearest"]),
                        ("max", ["--max-distance", "25"])):
        igs, js = os.path.join(work, f"hits_{name}.igs"), os.path.join(work, f"hits_{name}.json")
        if t.run(base + extra + ["-o", igs, "--json", js], 0, f"hits {name}").returncode:
            return
        runs[name] = (iges_geometry.branches(igs), load_json(js, t.check, f"hits {name}"))
    curve = iges_geometry.input_curves(case)[0]
    full, nearest, capped = runs["all"][0], runs["nearest"][0], runs["max"][0]
    ends = [b["end"] for b in runs["nearest"][1]["branches"]]
    t.check(len(full) == 2 and len(nearest) == 2 and "occluded" in ends,
            f"--nearest: {len(full)} branches of all hits, {len(nearest)} nearest, ends {ends}")
    worst = 0.0
    for i in range(201):
        s = i / 200
        if near_an_end(full + nearest + capped, s, margin):
            continue
        every = hit_distances(curve, full, s)
        kept = hit_distances(curve, nearest, s)
        t.check(len(kept) == (1 if every else 0),
                f"--nearest at t = {s}: {len(kept)} points kept of {len(every)} hits")
        if every and len(kept) == 1:
            worst = max(worst, abs(kept[0][0] - min(d for d, _ in every)))
        within = sorted(d for d, _ in every if d <= 25 - tol)
        got = sorted(d for d, _ in hit_distances(curve, capped, s))
        t.check(len(got) == len(within) and all(abs(a - b) <= tol for a, b in zip(got, within))
                and all(d <= 25 + tol for d in got),
                f"--max-distance 25 at t = {s}: {got} kept, hits within 25: {within}")
    t.check(worst <= tol, f"--nearest: kept points {worst:.3g} farther than the nearest hit")
    for b, (surface, pcurve, _) in zip(runs["max"][1]["branches"], capped):
        for kind, tt in ((b["start"], b["t_range"][0]), (b["end"], b["t_range"][1])):
            if kind == "max_distance":
                u, v, _ = pcurve.eval(tt)
                d = curve.eval(tt)[2] - surface.eval(u, v)[2]
                t.check(abs(d - 25) <= tol, f"--max-distance 25: a cut at distance {d}")
    t.check(any("max_distance" in (b["start"], b["end"]) for b in runs["max"][1]["branches"]),
            "--max-distance 25: no branch cut at the distance")
    for value in ("0", "-1", "x", "1e400"):
        proc = t.run(base + ["--max-distance", value], 2, f"--max-distance {value}")
        t.check("--max-distance wants a positive distance" in proc.stderr,
                f"--max-distance {value}: {proc.stderr!r}")
    t.run(base + ["--nearest", "--nearest"], 2, "--nearest twice")
    # the eye sees the same fold: nearest keeps one point per ray there too
    js = os.path.join(work, "hits_eye.json")
    if t.run([t.exe, "project", case, "--eye", "30,0,100", "--nearest", "--json", js], 0,
             "--eye --nearest").returncode == 0:
        data = load_json(js, t.check, "--eye --nearest")
        t.check(data and "occluded" in [b["end"] for b in data["branches"]],
                "--eye --nearest: no branch ends occluded")
