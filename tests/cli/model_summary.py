# SPDX-License-Identifier: BSD-3-Clause
"""What `projcurve info` should print about a file's surfaces, found here
without the library: for each surface, in the order the readers keep
(IGES directory order, STEP instance order, G+Smo document order, teapot
patch order), its degrees and its numbers of non-empty knot spans.

Each format is read only as far as these numbers need:
  IGES    entity 128: K1, K2, M1, M2, the two knot vectors and the
          parameter range (U(0), U(1), V(0), V(1)) the surface is cut to;
  STEP    B_SPLINE_SURFACE_WITH_KNOTS (simple or inside a complex
          entity): the degrees, the knot multiplicities and the knots;
          then the analytic surfaces, which the reader turns into exact
          NURBS after the B-splines: a plane is bilinear (1 x 1 span), a
          full turn is four rational quadratic arcs, the sphere's
          latitude two, a height one linear span; unbounded ones (plane,
          cylinder, cone) only when a face uses them;
  G+Smo   <Geometry type="TensorBSpline2|TensorNurbs2">: the two
          <KnotVector degree="p"> elements;
  teapot  Newell's text: the patch count (each patch is a bicubic Bezier).
"""
import re
import xml.etree.ElementTree as ET


def spans(knots, degree):
    """Non-empty spans of a clamped knot vector inside its domain."""
    n = len(knots) - degree - 1
    inner = knots[degree:n + 1]
    return sum(1 for a, b in zip(inner, inner[1:]) if b > a)


def spans_within(knots, degree, a, b):
    """Non-empty spans of a clamped knot vector that overlap (a, b)."""
    n = len(knots) - degree - 1
    inner = knots[degree:n + 1]
    return sum(1 for k0, k1 in zip(inner, inner[1:]) if k1 > k0 and max(a, k0) < min(b, k1))


def _real(text):
    return float(text.strip().replace("D", "E").replace("d", "e"))


def iges_surfaces(path):
    with open(path, errors="replace") as f:
        records = [line.rstrip("\r\n") for line in f]
    records = [r.ljust(80) for r in records if len(r) >= 73]
    globals_text = "".join(r[:72] for r in records if r[72] == "G")
    delim = globals_text[2] if globals_text.startswith("1H") else ","
    d_lines = [r for r in records if r[72] == "D"]
    params = {}
    for r in records:
        if r[72] == "P":
            params.setdefault(int(r[64:72]), []).append(r[:64])
    out = []
    for i in range(0, len(d_lines), 2):
        if int(d_lines[i][0:8]) != 128:
            continue
        fields = "".join(params[i + 1]).split(delim)
        k1, k2, m1, m2 = (int(x) for x in fields[1:5])
        at = 10
        ku = [_real(x) for x in fields[at:at + k1 + m1 + 2]]
        at += k1 + m1 + 2
        kv = [_real(x) for x in fields[at:at + k2 + m2 + 2]]
        at += k2 + m2 + 2 + 4 * (k1 + 1) * (k2 + 1)  # past the weights and points
        # the surface is restricted to its parameter range U(0), U(1), V(0), V(1)
        u0, u1, v0, v1 = (_real(x.rstrip(";").split(";")[0]) for x in fields[at:at + 4])
        out.append((m1, m2, spans_within(ku, m1, u0, u1), spans_within(kv, m2, v0, v1)))
    return out


def _step_instances(text):
    """[(id, body)] of the DATA section, comments and strings kept intact."""
    text = re.sub(r"/\*.*?\*/", " ", text, flags=re.S)
    data = text[text.index("DATA;") + 5:]
    out, start, quoted = [], 0, False
    for i, ch in enumerate(data):
        if ch == "'":
            quoted = not quoted
        elif ch == ";" and not quoted:
            m = re.match(r"\s*#(\d+)\s*=\s*(.*)", data[start:i], re.S)
            if m:
                out.append((int(m.group(1)), m.group(2)))
            start = i + 1
    return out


def _arguments(body, name):
    """The top-level arguments (as text) of the part `name(...)` of body."""
    m = re.search(r"(?<![A-Z_])" + name + r"\s*\(", body)
    if not m:
        return None
    depth, args, cur, quoted = 0, [], "", False
    for ch in body[m.end():]:
        if ch == "'":
            quoted = not quoted
        if not quoted:
            if ch == "(":
                depth += 1
            elif ch == ")":
                if depth == 0:
                    args.append(cur.strip())
                    return args
                depth -= 1
            elif ch == "," and depth == 0:
                args.append(cur.strip())
                cur = ""
                continue
        cur += ch
    return None


def _numbers(text):
    return [float(x) for x in text.strip("() ").split(",") if x.strip()]


def _expand(mults, knots):
    out = []
    for m, k in zip(mults, knots):
        out += [k] * int(m)
    return out


def step_surfaces(path):
    with open(path, errors="replace") as f:
        text = f.read()
    out = []
    for _, body in _step_instances(text):
        simple = _arguments(body, "B_SPLINE_SURFACE_WITH_KNOTS")
        if simple is None:
            continue
        if body.lstrip().startswith("B_SPLINE_SURFACE_WITH_KNOTS"):
            du, dv = int(simple[1]), int(simple[2])
            mu, mv, ku, kv = simple[8:12]
        else:  # complex: the degrees are in the B_SPLINE_SURFACE part
            base = _arguments(body, "B_SPLINE_SURFACE")
            du, dv = int(base[0]), int(base[1])
            mu, mv, ku, kv = simple[0:4]
        ku, kv = _expand(_numbers(mu), _numbers(ku)), _expand(_numbers(mv), _numbers(kv))
        out.append((du, dv, spans(ku, du), spans(kv, dv)))
    used = set()
    for _, body in _step_instances(text):
        face = _arguments(body, "ADVANCED_FACE")
        if face is not None and body.lstrip().startswith("ADVANCED_FACE"):
            used.add(face[2].strip())
    for ident, body in _step_instances(text):
        name = body.lstrip().split("(")[0].strip()
        if name in ANALYTIC_SHAPES and (name in BOUNDED_ANALYTIC or f"#{ident}" in used):
            out.append(ANALYTIC_SHAPES[name])
    return out


# (degree u, degree v, spans u, spans v) of each analytic surface's NURBS.
ANALYTIC_SHAPES = {"PLANE": (1, 1, 1, 1), "CYLINDRICAL_SURFACE": (2, 1, 4, 1),
                   "CONICAL_SURFACE": (2, 1, 4, 1), "SPHERICAL_SURFACE": (2, 2, 4, 2),
                   "TOROIDAL_SURFACE": (2, 2, 4, 4)}
BOUNDED_ANALYTIC = {"SPHERICAL_SURFACE", "TOROIDAL_SURFACE"}


def gismo_surfaces(path):
    out = []
    for g in ET.parse(path).getroot().iter("Geometry"):
        if g.get("type") not in ("TensorBSpline2", "TensorNurbs2"):
            continue
        kvs = list(g.iter("KnotVector"))[:2]
        degrees = [int(k.get("degree")) for k in kvs]
        knots = [[float(x) for x in k.text.split()] for k in kvs]
        out.append((degrees[0], degrees[1], spans(knots[0], degrees[0]),
                    spans(knots[1], degrees[1])))
    return out


def teapot_surfaces(path):
    with open(path) as f:
        patches = int(f.readline())
    return [(3, 3, 1, 1)] * patches


def surfaces(path):
    """[(degree_u, degree_v, spans_u, spans_v)] by the file's content."""
    with open(path, errors="replace") as f:
        head = f.read(4096)
    if head.startswith("ISO-10303-21"):
        return step_surfaces(path)
    if head.lstrip().startswith("<?xml") or head.lstrip().startswith("<xml"):
        return gismo_surfaces(path)
    if re.match(r"\s*\d+\s*\n", head):
        return teapot_surfaces(path)
    return iges_surfaces(path)


INFO_SURFACE = re.compile(r"^  surface (\d+): degree (\d+)x(\d+), \d+x\d+ control points, "
                          r"(\d+)x(\d+) spans,", re.M)


def printed_surfaces(info_output):
    """[(degree_u, degree_v, spans_u, spans_v)] from `projcurve info`'s lines."""
    return [tuple(int(g) for g in m.groups()[1:]) for m in INFO_SURFACE.finditer(info_output)]
