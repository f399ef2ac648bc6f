# SPDX-License-Identifier: BSD-3-Clause
"""An independent reader and evaluator of the IGES entities projcurve writes.

The end-to-end checks use it to judge the written branches without the
library: parameter data of entities 126 (rational B-spline curve), 128
(rational B-spline surface) and 142 (curve on surface) is parsed from the
fixed-column records, and curves and surfaces are evaluated by the
Cox-de Boor recursion on homogeneous points.
"""


def read_entities(path):
    """{DE pointer: (type, status, [fields])} from the D and P sections."""
    directory, params = {}, {}
    with open(path) as f:
        records = [line.rstrip("\r\n") for line in f if line.strip()]
    d_lines = [r for r in records if len(r) >= 73 and r[72] == "D"]
    for i in range(0, len(d_lines), 2):
        first = d_lines[i]
        directory[i + 1] = (int(first[0:8]), first[64:72])
    for r in records:
        if len(r) >= 73 and r[72] == "P":
            params.setdefault(int(r[64:72]), []).append(r[:64])
    entities = {}
    for de, (etype, status) in directory.items():
        text = "".join(params[de]).strip()
        text = text[: text.index(";")]
        fields = [x.strip() for x in text.split(",")]
        if int(fields[0]) != etype:
            raise ValueError(f"{path}: DE {de} is a {etype} but its parameters say {fields[0]}")
        entities[de] = (etype, status, fields[1:])
    return entities


def _reals(fields, start, n):
    return [float(x.replace("D", "E")) if x else 0.0 for x in fields[start:start + n]]


class Curve:
    """Entity 126: degree, knots, homogeneous points (w x, w y, w z, w)."""

    def __init__(self, fields):
        k, self.degree = int(fields[0]), int(fields[1])
        n = k + 1
        at = 6
        self.knots = _reals(fields, at, n + self.degree + 1)
        at += n + self.degree + 1
        weights = _reals(fields, at, n)
        at += n
        xyz = _reals(fields, at, 3 * n)
        self.points = [[w * c for c in xyz[3 * i:3 * i + 3]] + [w] for i, w in enumerate(weights)]
        self.t0, self.t1 = self.knots[self.degree], self.knots[n]

    def eval(self, t):
        return _project(_de_boor(self.knots, self.degree, self.points, t))

    def distinct_spans(self):
        inner = self.knots[self.degree:len(self.knots) - self.degree]
        return sum(1 for a, b in zip(inner, inner[1:]) if b > a)


class Surface:
    """Entity 128: degrees, knots and the net, u index fastest."""

    def __init__(self, fields):
        k1, k2, self.pu, self.pv = (int(x) for x in fields[0:4])
        nu, nv = k1 + 1, k2 + 1
        at = 9
        self.ku = _reals(fields, at, nu + self.pu + 1)
        at += nu + self.pu + 1
        self.kv = _reals(fields, at, nv + self.pv + 1)
        at += nv + self.pv + 1
        weights = _reals(fields, at, nu * nv)
        at += nu * nv
        xyz = _reals(fields, at, 3 * nu * nv)
        pts = [[w * c for c in xyz[3 * i:3 * i + 3]] + [w] for i, w in enumerate(weights)]
        self.rows = [pts[j * nu:(j + 1) * nu] for j in range(nv)]  # rows of constant v
        self.domain = (self.ku[self.pu], self.ku[nu], self.kv[self.pv], self.kv[nv])

    def eval(self, u, v):
        # only the pv + 1 rows that act on the span of v
        span = _span(self.kv, self.pv, len(self.rows), v)
        column = [None] * len(self.rows)
        for j in range(span - self.pv, span + 1):
            column[j] = _de_boor(self.ku, self.pu, self.rows[j], u)
        return _project(_de_boor(self.kv, self.pv, column, v))


def _span(knots, p, n, t):
    """The knot span [knots[s], knots[s + 1]) holding t, in p..n-1 (t clamped)."""
    t = min(max(t, knots[p]), knots[n])
    lo, hi = p, n - 1
    while lo < hi:  # the last s with knots[s] <= t
        mid = (lo + hi + 1) // 2
        if knots[mid] <= t:
            lo = mid
        else:
            hi = mid - 1
    return lo


def _de_boor(knots, p, points, t):
    """Point of the B-spline of homogeneous points at t (clamped to the domain)."""
    n = len(points)
    t = min(max(t, knots[p]), knots[n])
    span = _span(knots, p, n, t)
    d = [list(points[j + span - p]) for j in range(p + 1)]
    for r in range(1, p + 1):
        for j in range(p, r - 1, -1):
            i = j + span - p
            denom = knots[i + p - r + 1] - knots[i]
            a = 0.0 if denom == 0.0 else (t - knots[i]) / denom
            d[j] = [(1.0 - a) * x + a * y for x, y in zip(d[j - 1], d[j])]
    return d[p]


def _project(h):
    return [h[0] / h[3], h[1] / h[3], h[2] / h[3]]


def branches(path):
    """The curves on surface of a written file: [(surface, pcurve, curve3d or None)]
    with the surface and curves parsed, in the order of the 142 entities."""
    ents = read_entities(path)
    out = []
    for de in sorted(ents):
        etype, _, fields = ents[de]
        if etype != 142:
            continue
        sptr, bptr, cptr = int(fields[1]), int(fields[2]), int(fields[3])
        surface = Surface(ents[sptr][2])
        pcurve = Curve(ents[bptr][2])
        curve = Curve(ents[cptr][2]) if cptr else None
        out.append((surface, pcurve, curve))
    return out


def input_curves(path):
    """The stand-alone 3D curves (126 with status 00000000) of a case file."""
    return [Curve(f) for de, (t, status, f) in sorted(read_entities(path).items())
            if t == 126 and status.strip() in ("", "00000000", "0")]
