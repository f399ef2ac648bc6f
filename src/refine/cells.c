/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Knot lines of S ([SY13] s4): a composed piece is exact only inside one
 * Bezier patch, so every segment is split where its chord meets a knot line.
 * The split vertex is put on the projection curve and exactly on the knot
 * line, so the two sub-chords lie in closed patch boxes. When the corrector
 * cannot give it, there is no such vertex: never the chord's own crossing,
 * which is off the projection (the caller makes the segment a gap).
 */
#include <math.h>

#include "refine/refine_internal.h"

/* Bound of the bracketed root search for a knot-line crossing; the Illinois
 * variant of regula falsi converges superlinearly, so it is never reached in
 * practice (when it is, there is no crossing: a gap, see refine.c); room is
 * left for the bisection towards a failure of the corrector (from a
 * segment of the whole branch down to min_dt, 1e-12 of it: ~40 halvings,
 * each maybe followed by a few regula falsi steps). */
#define PC_CROSSING_MAX_ITER 160

/* Cells [lo, hi] of the breaks holding x: x in cell i iff
 * breaks[i] <= x <= breaks[i + 1]; a value on an inner break is in two. */
static void cell_range(const double *breaks, size_t n_cells, double x, size_t *lo, size_t *hi)
{
    size_t a = 0, b = n_cells; /* largest i < n_cells with breaks[i] <= x */
    while (b - a > 1) {
        const size_t mid = a + (b - a) / 2;
        if (breaks[mid] <= x)
            a = mid;
        else
            b = mid;
    }
    *hi = a;
    *lo = (a > 0 && x == breaks[a]) ? a - 1 : a;
}

/* Overlap of the cell ranges of x0 and x1 (1 and its lowest cell), or 0 and
 * the knot line first crossed when going from x0 to x1. */
static int common_cell(const double *breaks, size_t n_cells, double x0, double x1, size_t *cell,
                       double *line)
{
    size_t lo0, hi0, lo1, hi1;
    cell_range(breaks, n_cells, x0, &lo0, &hi0);
    cell_range(breaks, n_cells, x1, &lo1, &hi1);
    const size_t lo = lo0 > lo1 ? lo0 : lo1, hi = hi0 < hi1 ? hi0 : hi1;
    if (lo <= hi) {
        *cell = lo;
        return 1;
    }
    *line = x0 < x1 ? breaks[hi0 + 1] : breaks[lo0];
    return 0;
}

/* x moved onto the nearest inner break if within tol. */
static double snap_to_break(const double *breaks, size_t n_cells, double x, double tol)
{
    size_t lo, hi;
    cell_range(breaks, n_cells, x, &lo, &hi);
    if (hi > 0 && fabs(x - breaks[hi]) <= tol)
        return breaks[hi];
    if (hi + 1 < n_cells && fabs(breaks[hi + 1] - x) <= tol)
        return breaks[hi + 1];
    return x;
}

const pc_bezier_patch *pc_refine_common_patch(const pc_refiner *r, const pc_rvertex *a,
                                              const pc_rvertex *b)
{
    const pc_patch_grid *g = r->grid;
    size_t iu, iv;
    double line;
    if (!common_cell(g->breaks_u, g->spans_u, a->u, b->u, &iu, &line) ||
        !common_cell(g->breaks_v, g->spans_v, a->v, b->v, &iv, &line))
        return NULL;
    return pc_patch_grid_at(g, iu, iv);
}

void pc_refine_snap_to_knot_lines(const pc_refiner *r, pc_rvertex *v)
{
    const pc_patch_grid *g = r->grid;
    v->u = snap_to_break(g->breaks_u, g->spans_u, v->u, r->snap);
    v->v = snap_to_break(g->breaks_v, g->spans_v, v->v, r->snap);
}

int pc_refine_on_knot_line(const pc_refiner *r, const pc_rvertex *v)
{
    const pc_patch_grid *g = r->grid;
    size_t lo, hi;
    cell_range(g->breaks_u, g->spans_u, v->u, &lo, &hi);
    if (lo != hi)
        return 1;
    cell_range(g->breaks_v, g->spans_v, v->v, &lo, &hi);
    return lo != hi;
}

/* Where the corrector fails inside the bracket of a crossing, the exact
 * curve runs into the knot line there (a C0 knot line of a surface that is
 * not G1 across it: the foot point sits on the crease for a stretch of t,
 * no critical point of either side, and Newton oscillates across it;
 * linkrods.step surface 1, whose every knot in v has multiplicity = degree,
 * at t = 0.0915 of curve 3). An end of the bracket within snap_far of the
 * line is then the crossing, as when the bracket closes (the caller puts it
 * on the line); without one there is no crossing. (Making the whole traced
 * segment a gap instead dropped 0.03 of t, where the other side's foot
 * point exists.) */
static int bracket_end_on_line(const pc_refiner *r, const pc_rvertex *lo, const pc_rvertex *hi,
                               int coord, double line, pc_rvertex *out)
{
    const double d_lo = fabs((coord == 0 ? lo->u : lo->v) - line);
    const double d_hi = fabs((coord == 0 ? hi->u : hi->v) - line);
    const pc_rvertex *best = d_lo <= d_hi ? lo : hi;
    if (!(fmin(d_lo, d_hi) <= r->snap_far))
        return 0;
    *out = *best;
    return 1;
}

/* Root of coord(t) = line on the projection between a and b (coordinate 0 =
 * u, 1 = v), which bracket it; regula falsi, Illinois variant. Where the
 * corrector fails at an iterate, the projection is out of reach there (a
 * C0 knot line the foot point runs into, or, beyond the line, spans whose
 * net rounding blew up: linkrods.step surface 16 has 26 spans of width
 * ~1e-8 in v ~ -3.6128 whose image loops 0.2 away from its neighbours):
 * the search then bisects between the reachable end on a's side and the
 * failure, so that the crossing reached from a is found (or, within
 * snap_far of the line, the last point reached). Only then the caller
 * gives up: the segment that cannot be split there becomes a gap. */
static int exact_crossing(pc_refiner *r, const pc_rvertex *a, const pc_rvertex *b, int coord,
                          double line, pc_rvertex *out)
{
    pc_rvertex lo = *a, hi = *b;
    double g_lo = (coord == 0 ? lo.u : lo.v) - line, g_hi = (coord == 0 ? hi.u : hi.v) - line;
    int side = 0;         /* which end stayed last time, for the Illinois halving */
    double t_bad = NAN;   /* a failing t between lo and hi (NaN: none known) */
    for (int iter = 0; iter < PC_CROSSING_MAX_ITER; ++iter) {
        const double t = isnan(t_bad) ? (g_hi * lo.t - g_lo * hi.t) / (g_hi - g_lo)
                                      : 0.5 * (lo.t + t_bad);
        pc_rvertex c;
        if (!pc_refine_exact_point(r, &lo, &hi, t, &c)) {
            t_bad = t;
            side = 0;
            if (fabs(t_bad - lo.t) > r->min_dt)
                continue;
            /* lo is the last point reached from a's side; else an end
             * of the bracket on the line, as when the bracket closes */
            if (!(fabs(g_lo) <= r->snap_far))
                return bracket_end_on_line(r, &lo, &hi, coord, line, out);
            *out = lo;
            return 1;
        }
        const double g = (coord == 0 ? c.u : c.v) - line;
        if (fabs(g) <= r->min_move) {
            *out = c;
            return 1;
        }
        /* The bracket has closed in t: a crossing within snap_far of the
         * line is put on it; farther, the curve jumps across the line
         * (the traced polyline stepped over a gap) and there is none. */
        if (fabs(hi.t - lo.t) <= r->min_dt) {
            *out = c;
            return fabs(g) <= r->snap_far;
        }
        if ((g < 0.0) == (g_lo < 0.0)) {
            lo = c, g_lo = g;
            if (side == -1)
                g_hi *= 0.5;
            side = isnan(t_bad) ? -1 : 0;
        } else {
            hi = c, g_hi = g;
            if (side == 1)
                g_lo *= 0.5;
            side = isnan(t_bad) ? 1 : 0;
            t_bad = NAN; /* the bracket now ends before the failure */
        }
    }
    return 0;
}

int pc_refine_knot_crossing(pc_refiner *r, const pc_rvertex *a, const pc_rvertex *b,
                            pc_rvertex *out)
{
    const pc_patch_grid *g = r->grid;
    size_t cell;
    double line_u = 0.0, line_v = 0.0;
    const int in_u = common_cell(g->breaks_u, g->spans_u, a->u, b->u, &cell, &line_u);
    const int in_v = common_cell(g->breaks_v, g->spans_v, a->v, b->v, &cell, &line_v);
    /* The line met first along the chord. */
    const double alpha_u = in_u ? INFINITY : (line_u - a->u) / (b->u - a->u);
    const double alpha_v = in_v ? INFINITY : (line_v - a->v) / (b->v - a->v);
    const int coord = alpha_u <= alpha_v ? 0 : 1;
    const double line = coord == 0 ? line_u : line_v;

    pc_rvertex c;
    if (!(fabs(b->t - a->t) > r->min_dt) || !exact_crossing(r, a, b, coord, line, &c))
        return 0;
    /* The crossing must fall strictly between a and b in t, or the split
     * would not shorten anything. */
    if (!((c.t - a->t) * (b->t - c.t) > 0.0))
        return 0;
    /* Exactly on the knot line (the move is below min_move); and at a patch
     * corner when it passes within rounding of one, or the next segment
     * would be a sliver across the other line whose chord direction is
     * noise. */
    if (coord == 0) {
        c.u = line;
        c.v = snap_to_break(g->breaks_v, g->spans_v, c.v, r->snap);
    } else {
        c.v = line;
        c.u = snap_to_break(g->breaks_u, g->spans_u, c.u, r->snap);
    }
    c.fixed = 1;
    *out = c;
    return 1;
}
