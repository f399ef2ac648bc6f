# SPDX-License-Identifier: BSD-3-Clause
"""projcurve project --faces on the B-rep cases (tests/data/cases-brep):
the JSON's connected curves (and, where the notes say, face pieces) against
the MANIFEST's EXPECT, its fields, the SVG's paths (one per connected
curve), and the IGES and STEP files written:
the IGES holds one composite curve (102) per connected curve of the JSON,
with as many members as the curve has face pieces (read from the file's
records, iges_geometry.py), and `projcurve info` reads it as one curve per
input curve plus one per connected curve (its members joined); the STEP
holds one COMPOSITE_CURVE per connected curve of the JSON, with as many
segments (COMPOSITE_CURVE_SEGMENT) as the curve has face pieces (read from
the file's text), and no SURFACE_CURVE, and `projcurve info` reads it as
one curve per input curve plus one per face piece (the segments'
B-splines; the composites listed as skipped). Where the Open CASCADE
checkers were built (PC_OCCT_IGES_CHECK, PC_OCCT_STEP_CHECK name them),
Open CASCADE reads them too: the 102s and the COMPOSITE_CURVEs with their
member counts."""
import json
import os
import re
import subprocess

from iges_geometry import read_entities

START_KINDS = {"curve_start", "jump", "boundary", "silhouette", "curve_crossing", "trim",
               "visible", "max_distance"}
END_KINDS = {"curve_end", "boundary", "silhouette", "curvature_centre", "limit", "failed",
             "curve_crossing", "trim", "occluded", "max_distance"}
PIECE_FIELDS = {"face": int, "shape_face": int, "t_range": list, "start": str, "end": str,
                "degree": int, "control_points": int, "pcurve_degree": int,
                "pcurve_control_points": int, "seams": int}


def manifest(data):
    rows = []
    with open(os.path.join(data, "cases-brep", "MANIFEST.tsv")) as f:
        header = None
        for line in f:
            fields = line.rstrip("\n").split("\t")
            if line.startswith("#"):
                header = [h.strip().lstrip("#").strip().split(" ")[0] for h in fields]
                continue
            if header and len(fields) >= len(header):
                rows.append(dict(zip(header, fields)))
    return rows


def expected(notes):
    """(connected curves, face pieces or None) from 'EXPECT n ... [made of m face pieces]'."""
    m = re.search(r"EXPECT (\d+) (?:connected )?curves?", notes)
    pieces = re.search(r"made of (\d+) face pieces", notes)
    return int(m.group(1)), int(pieces.group(1)) if pieces else None


def check_schema(data, name, check):
    check(isinstance(data.get("time_ms"), (int, float)) and data["time_ms"] >= 0,
          f"{name}: time_ms is a number >= 0")
    for run in data.get("runs", []):
        check(run.get("status") == "ok", f"{name}: run status {run.get('status')!r}")
        for c in run.get("curves", []):
            check(isinstance(c.get("closed"), bool), f"{name}: closed is a bool")
            check(len(c.get("pieces", [])) > 0, f"{name}: a connected curve has pieces")
            t_prev = None
            for p in c["pieces"]:
                for key, kind in PIECE_FIELDS.items():
                    check(isinstance(p.get(key), kind) and not isinstance(p.get(key), bool),
                          f"{name}: piece field {key} is a {kind.__name__}: {p.get(key)!r}")
                check(p.get("start") in START_KINDS, f"{name}: start {p.get('start')!r}")
                check(p.get("end") in END_KINDS, f"{name}: end {p.get('end')!r}")
                check(p["degree"] > 0 and p["control_points"] > p["degree"],
                      f"{name}: piece has a compact curve ({p['degree']}, {p['control_points']})")
                # pieces of a connected curve follow each other along the
                # curve (within the chaining tolerance)
                if t_prev is not None:
                    check(abs(p["t_range"][0] - t_prev) <= 1e-6 * max(1.0, abs(t_prev)),
                          f"{name}: piece starts at t {p['t_range'][0]}, last ended at {t_prev}")
                t_prev = p["t_range"][1]


def info_counts(exe, path):
    proc = subprocess.run([exe, "info", "--json", path], capture_output=True, text=True,
                          timeout=120)
    if proc.returncode != 0:
        return None
    data = json.loads(proc.stdout)
    return data["surfaces"], data["curves"]


# Cases whose written STEP Open CASCADE is known to reject, with why; the
# check must keep failing on them (so that a fix shows here).
OPEN_OCCT_STEP = {}


def composite_members(path):
    """The member count of each composite curve (102) of an IGES file, in
    directory order."""
    return [int(fields[0]) for _, (etype, _, fields) in sorted(read_entities(path).items())
            if etype == 102]


STEP_INSTANCE = re.compile(r"#(\d+)\s*=\s*([A-Z_0-9]*)\s*\((.*)\)\s*$", re.S)


def step_instances(path):
    """{id: (entity name, parameter text)} of a STEP file's DATA section
    (a complex instance has the name '')."""
    with open(path) as f:
        text = f.read()
    data = text[text.find("DATA;") + 5:text.rfind("ENDSEC;")]
    out = {}
    for record in data.split(";"):
        m = STEP_INSTANCE.match(record.strip())
        if m:
            out[int(m.group(1))] = (m.group(2), m.group(3))
    return out


def step_composites(path):
    """The segment count of each COMPOSITE_CURVE of a STEP file, in
    instance order, and the number of SURFACE_CURVEs; a segment reference
    that is no COMPOSITE_CURVE_SEGMENT counts as -1."""
    inst = step_instances(path)
    counts = []
    for _, (name, params) in sorted(inst.items()):
        if name != "COMPOSITE_CURVE":
            continue
        refs = [int(r) for r in re.findall(r"#(\d+)", params.split(")")[0])]
        good = all(inst.get(r, ("",))[0] == "COMPOSITE_CURVE_SEGMENT" for r in refs)
        counts.append(len(refs) if good else -1)
    return counts, sum(1 for name, _ in inst.values() if name == "SURFACE_CURVE")


def occt_check(out, members, name, check):
    """Open CASCADE reads the written files (skipped where not built)."""
    counts = ",".join(str(m) for m in members)
    for ext, env, args in (("igs", "PC_OCCT_IGES_CHECK", ["--composites", out["igs"], counts]),
                           ("step", "PC_OCCT_STEP_CHECK", ["--composites", out["step"], counts])):
        exe = os.environ.get(env)
        if not exe:
            print(f"SKIP {name}: {env} not set (Open CASCADE checker not built)")
            continue
        proc = subprocess.run([exe] + args,
                              capture_output=True, text=True, timeout=120,
                              env=dict(os.environ, ASAN_OPTIONS="detect_leaks=0"))
        if ext == "step" and name in OPEN_OCCT_STEP:
            print(f"OPEN {name}: {OPEN_OCCT_STEP[name]}")
            check(proc.returncode != 0, f"{name}: Open CASCADE accepts the STEP now: "
                                        f"remove it from OPEN_OCCT_STEP")
            continue
        check(proc.returncode == 0, f"{name}: Open CASCADE on the {ext} written: "
                                    f"{proc.stdout.strip()[-600:]}")


def part_faces(exe, data, work, run, check):
    os.makedirs(work, exist_ok=True)
    base = os.path.join(data, "cases-brep")
    for case in manifest(data):
        name = case["name"]
        curves = os.path.join(base, name + ".curves.igs")
        args = [exe, "project", os.path.join(base, case["model_file"]), "--faces", "--curves",
                curves, "--tol", case["tol_dist"], "--angle", case["tol_angle_deg"]]
        if case["mode"] == "directional":
            args += ["--dir", f"{case['ax']},{case['ay']},{case['az']}"]
        elif case["mode"] == "conical":
            args += ["--eye", f"{case['ax']},{case['ay']},{case['az']}"]
        else:
            args.append("--orthogonal")
        out = {ext: os.path.join(work, f"{name}.{ext}") for ext in ("json", "igs", "step", "svg")}
        if run(args + ["--json", out["json"], "-o", out["igs"], "--svg", out["svg"]], 0,
               name).returncode != 0:
            continue
        run(args + ["-o", out["step"], "--quiet"], 0, name + " (STEP)")
        with open(out["json"]) as f:
            result = json.load(f)
        check_schema(result, name, check)
        want_curves, want_pieces = expected(case["notes"])
        got_curves = sum(len(r["curves"]) for r in result["runs"])
        got_pieces = sum(len(c["pieces"]) for r in result["runs"] for c in r["curves"])
        check(got_curves == want_curves == result["connected_curves"],
              f"{name}: {got_curves} connected curves ({result['connected_curves']} counted), "
              f"MANIFEST expects {want_curves}")
        if want_pieces is not None:
            check(got_pieces == want_pieces, f"{name}: {got_pieces} face pieces, "
                                             f"MANIFEST expects {want_pieces}")
        n_input = info_counts(exe, curves)[1]
        faces = {(r["shape"], p["shape_face"]) for r in result["runs"] for c in r["curves"]
                 for p in c["pieces"]}
        # the SVG draws each connected curve as one path
        with open(out["svg"]) as f:
            paths = f.read().count('class="connected"')
        check(paths == got_curves,
              f"{name}: the SVG has {paths} connected-curve paths for {got_curves} curves")
        # one composite curve per connected curve, a member per face piece
        members = [len(c["pieces"]) for r in result["runs"] for c in r["curves"]]
        written = composite_members(out["igs"])
        check(written == members,
              f"{name}: the IGES's composite curves (102) have {written} members, the JSON's "
              f"connected curves {members} face pieces")
        # and in the STEP one COMPOSITE_CURVE per connected curve, a segment
        # per face piece, no piece on its own
        segments, surface_curves = step_composites(out["step"])
        check(segments == members and surface_curves == 0,
              f"{name}: the STEP's COMPOSITE_CURVEs have {segments} segments (and it holds "
              f"{surface_curves} SURFACE_CURVEs), the JSON's connected curves {members} face "
              f"pieces")
        for ext in ("igs", "step"):
            counts = info_counts(exe, out[ext])
            check(counts is not None, f"{name}: info reads the {ext} written")
            if counts is None:
                continue
            # IGES: each composite read as one curve (its members joined);
            # STEP: the composites' segments, each a face piece's B-spline
            want = n_input + (got_curves if ext == "igs" else got_pieces)
            check(counts[1] == want,
                  f"{name}: {ext} holds {counts[1]} curves, expected {want}: {n_input} input + "
                  + (f"{got_curves} connected curves" if ext == "igs" else
                     f"{got_pieces} face pieces"))
            # and the surfaces of the faces it lies on (faces may share one)
            check(counts[0] >= 1, f"{name}: {ext} holds no surface for {len(faces)} faces")
        occt_check(out, members, name, check)
    # --faces picks shapes; --surface one surface: not both
    run([exe, "project", os.path.join(base, "shell_2x2.step"), "--faces", "--surface", "0",
         "--dir", "0,0,-1"], 2, "--faces with --surface")
    run([exe, "project", os.path.join(base, "shell_2x2_bspline_oblique.curves.igs"), "--faces",
         "--dir", "0,0,-1"], 2, "--faces onto a file of curves only")
