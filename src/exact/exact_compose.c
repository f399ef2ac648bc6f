/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The driver of the exact composition (exact.h): q's Bezier segments by
 * blossoming, each cut at the seam jumps inside it and moved into the
 * domain, then cut where it crosses a knot line of S (sign_changes.c),
 * each part composed with the patch it lies in, the parts joined and
 * their join knots reduced (join_removal.c) where the two sides are not
 * C0 by construction.
 */
#include "exact/exact.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"
#include "compose/compose.h"
#include "seam/seam.h"

#define PC_EXACT_ORDER (PC_COMPOSE_POLY_MAX_DEGREE + 1)
/* Sign changes of one cubic against one knot line: three roots, and
 * room for a root the halving reports twice (two neighbours at 2^-52). */
#define PC_EXACT_ROOTS_PER_LINE 8

/* One part of q to compose: over [t0, t1], in patch `patch`, with its
 * (u, v) Bezier control points in the domain and their weights (1 for a
 * polynomial q). smooth: 0 where the part
 * meets the one before only C0 by construction (at a seam or pole jump,
 * where the two sides are different curves of S's homogeneous space, or
 * at a crease of q: a knot of multiplicity its degree); 1 where it
 * starts at a knot of q of lower multiplicity, or at a knot line of S
 * (whether S is C0 there is told by the patches, patches_smooth). */
typedef struct exact_part {
    double t0, t1;
    size_t patch;
    unsigned char smooth;
    double uv[2 * PC_EXACT_ORDER];
    double w[PC_EXACT_ORDER];
} exact_part;

typedef struct exact_parts {
    exact_part *items;
    size_t count, capacity;
} exact_parts;

typedef struct exact_cuts {
    double *items;
    size_t count, capacity;
} exact_cuts;

/* q's Bezier pieces are kept homogeneous, (u w, v w, w) per control
 * point (PC_EXACT_DIM doubles), so that a rational q is cut as a
 * polynomial one is; for a polynomial q, w = 1 is never combined (hd = 2
 * below: only the first two coordinates are), which keeps its pieces
 * bit for bit those of the Cartesian code. */
#define PC_EXACT_DIM 3

/* The coordinates of q's homogeneous points that vary: 3, or 2 when q
 * is polynomial. */
static int homogeneous_dims(const pc_bspline *q) { return q->weights != NULL ? 3 : 2; }

/* The blossom of q at args (d values) on knot span `span` (de Boor with
 * one argument per level: each step a convex combination while the
 * arguments lie in the span), homogeneous. */
static void blossom(const pc_bspline *q, size_t span, const double *args,
                    double out[PC_EXACT_DIM])
{
    const int d = q->degree, hd = homogeneous_dims(q);
    double w[PC_EXACT_DIM * PC_EXACT_ORDER];
    for (int i = 0; i <= d; ++i) {
        const size_t at = span - (size_t)d + (size_t)i;
        const double wt = q->weights != NULL ? q->weights[at] : 1.0;
        w[3 * i] = q->poles[2 * at] * wt;
        w[3 * i + 1] = q->poles[2 * at + 1] * wt;
        w[3 * i + 2] = wt;
    }
    for (int r = 1; r <= d; ++r)
        for (int i = d; i >= r; --i) {
            const size_t idx = span - (size_t)d + (size_t)i;
            const double kl = q->knots[idx], kr = q->knots[idx + (size_t)(d + 1 - r)];
            const double a = (args[r - 1] - kl) / (kr - kl);
            for (int c = 0; c < hd; ++c)
                w[3 * i + c] = (1.0 - a) * w[3 * (i - 1) + c] + a * w[3 * i + c];
        }
    for (int c = 0; c < PC_EXACT_DIM; ++c)
        out[c] = w[3 * d + c];
}

/* The Bezier control points of q on span [knots[span], knots[span + 1]]:
 * b_m = blossom(t0^(d - m), t1^m). */
static void span_bezier(const pc_bspline *q, size_t span, double *uvw)
{
    const int d = q->degree;
    for (int m = 0; m <= d; ++m) {
        double args[PC_EXACT_ORDER];
        for (int r = 0; r < d; ++r)
            args[r] = r < d - m ? q->knots[span] : q->knots[span + 1];
        blossom(q, span, args, uvw + PC_EXACT_DIM * m);
    }
}

/* de Casteljau at s: the part on [0, s] (keep_right 0) or [s, 1] of the
 * homogeneous Bezier curve uvw (d + 1 points), in place; the first hd
 * coordinates combined. */
static void bezier_split(int d, int hd, double *uvw, double s, int keep_right)
{
    double w[PC_EXACT_DIM * PC_EXACT_ORDER], out[PC_EXACT_DIM * PC_EXACT_ORDER];
    const size_t n = PC_EXACT_DIM * (size_t)(d + 1);
    memcpy(w, uvw, n * sizeof *w);
    for (int k = 0; k <= d; ++k) {
        const int at = keep_right ? d - k : k, from = keep_right ? d - k : 0;
        for (int c = 0; c < PC_EXACT_DIM; ++c)
            out[3 * at + c] = w[3 * from + c];
        for (int i = 0; i < d - k; ++i)
            for (int c = 0; c < hd; ++c)
                w[3 * i + c] = (1.0 - s) * w[3 * i + c] + s * w[3 * (i + 1) + c];
    }
    memcpy(uvw, out, n * sizeof *uvw);
}

/* The part of uvw on [a, b] (0 <= a < b <= 1) into out. */
static void bezier_part(int d, int hd, const double *uvw, double a, double b, double *out)
{
    memcpy(out, uvw, PC_EXACT_DIM * (size_t)(d + 1) * sizeof *out);
    if (b < 1.0)
        bezier_split(d, hd, out, b, 0);
    if (a > 0.0)
        bezier_split(d, hd, out, a / b, 1);
}

static int cmp_double(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return (x > y) - (x < y);
}

/* Sorts the cuts, keeps those in (gap, 1 - gap) at least gap apart, and
 * closes them with 0 and 1. Statuses: OK, NO_MEMORY. */
static projcurve_status close_cuts(projcurve_context *ctx, exact_cuts *c)
{
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, c, c->count + 2, 8, "the cuts of an exact composition");
    if (st != PROJCURVE_OK)
        return st;
    qsort(c->items, c->count, sizeof *c->items, cmp_double);
    size_t n = 0;
    double last = 0.0;
    for (size_t i = 0; i < c->count; ++i) {
        const double s = c->items[i];
        if (s - last > PC_EXACT_MIN_GAP && s < 1.0 - PC_EXACT_MIN_GAP)
            c->items[n++] = last = s;
    }
    memmove(c->items + 1, c->items, n * sizeof *c->items);
    c->items[0] = 0.0;
    c->items[n + 1] = 1.0;
    c->count = n + 2;
    return PROJCURVE_OK;
}

static projcurve_status add_cut(projcurve_context *ctx, exact_cuts *c, double s)
{
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, c, c->count + 1, 8, "the cuts of an exact composition");
    if (st == PROJCURVE_OK)
        c->items[c->count++] = s;
    return st;
}

/* The crossings of the homogeneous Bezier uvw with the interior knot
 * lines of one direction (coordinate c, breaks[1 .. spans - 1]): the sign
 * changes of U - u_k W (W > 0), whose coefficients are w_i (u_i - u_k).
 * Only lines strictly between the extreme control coordinates can be
 * crossed (the curve lies in their hull). */
static projcurve_status line_cuts(projcurve_context *ctx, int d, const double *uvw, int c,
                                  const double *breaks, size_t spans, exact_cuts *cuts)
{
    double lo = uvw[c] / uvw[2], hi = lo;
    for (int i = 1; i <= d; ++i) {
        const double x = uvw[3 * i + c] / uvw[3 * i + 2];
        lo = x < lo ? x : lo;
        hi = x > hi ? x : hi;
    }
    size_t k = 1, top = spans; /* first interior break above lo: binary search */
    while (k < top) {
        const size_t m = k + (top - k) / 2;
        if (breaks[m] <= lo)
            k = m + 1;
        else
            top = m;
    }
    projcurve_status st = PROJCURVE_OK;
    for (; st == PROJCURVE_OK && k < spans && breaks[k] < hi; ++k) {
        double f[PC_EXACT_ORDER], roots[PC_EXACT_ROOTS_PER_LINE];
        for (int i = 0; i <= d; ++i)
            f[i] = uvw[3 * i + c] - breaks[k] * uvw[3 * i + 2];
        const size_t n = pc_exact_sign_changes(d, f, roots, PC_EXACT_ROOTS_PER_LINE);
        if (n == (size_t)-1)
            return pc_fail(ctx, PROJCURVE_ERR_NOT_CONVERGED,
                           "a pcurve piece crosses the knot line %s = %.17g more than %d "
                           "times", c == 0 ? "u" : "v", breaks[k], PC_EXACT_ROOTS_PER_LINE);
        for (size_t j = 0; st == PROJCURVE_OK && j < n; ++j)
            st = add_cut(ctx, cuts, roots[j]);
    }
    return st;
}

/* Moves the homogeneous uvw by shift (its Cartesian points, the weights
 * kept: the same curve moved) and clamps it to the domain: after the
 * shift a pole lies outside only by rounding (the fit keeps its poles in
 * the domain, docs/fit.md; the seam joins keep them there,
 * docs/seams.md). */
static void into_domain(int d, double *uvw, const double shift[2], const double dom[4])
{
    for (int i = 0; i <= d; ++i)
        for (int c = 0; c < 2; ++c) {
            const double w = uvw[3 * i + 2], x = uvw[3 * i + c] / w + shift[c];
            const double lo = dom[2 * c], hi = dom[2 * c + 1];
            uvw[3 * i + c] = (x < lo ? lo : (x > hi ? hi : x)) * w;
        }
}

/* The parts of one domain-side stretch uvw (homogeneous, hd coordinates
 * varying) over [t0, t1]: cut at the knot lines it crosses, each in the
 * patch holding its middle; the first starts smooth or not as the caller
 * says, the others at knot lines. */
static projcurve_status side_parts(projcurve_context *ctx, const pc_patch_grid *g, int d,
                                   int hd, const double *uvw, double t0, double t1, int smooth,
                                   exact_parts *parts)
{
    exact_cuts cuts = {NULL, 0, 0};
    projcurve_status st = line_cuts(ctx, d, uvw, 0, g->breaks_u, g->spans_u, &cuts);
    if (st == PROJCURVE_OK)
        st = line_cuts(ctx, d, uvw, 1, g->breaks_v, g->spans_v, &cuts);
    if (st == PROJCURVE_OK)
        st = close_cuts(ctx, &cuts);
    if (st == PROJCURVE_OK)
        PC_ARRAY_RESERVE(st, ctx, parts, parts->count + cuts.count, 16,
                         "the parts of an exact composition");
    for (size_t i = 0; st == PROJCURVE_OK && i + 1 < cuts.count; ++i) {
        const double a = cuts.items[i], b = cuts.items[i + 1];
        exact_part *p = &parts->items[parts->count++];
        double part[PC_EXACT_DIM * PC_EXACT_ORDER];
        bezier_part(d, hd, uvw, a, b, part);
        for (int k = 0; k <= d; ++k) {
            p->w[k] = part[3 * k + 2];
            p->uv[2 * k] = part[3 * k] / p->w[k];
            p->uv[2 * k + 1] = part[3 * k + 1] / p->w[k];
        }
        p->t0 = a == 0.0 ? t0 : t0 + a * (t1 - t0);
        p->t1 = b == 1.0 ? t1 : t0 + b * (t1 - t0);
        p->smooth = (unsigned char)(i > 0 || smooth);
        bezier_split(d, hd, part, 0.5, 0);
        p->patch = pc_patch_grid_locate(g, part[3 * d] / part[3 * d + 2],
                                        part[3 * d + 1] / part[3 * d + 2]);
    }
    PC_ARRAY_FREE(&cuts);
    return st;
}

/* The parts of q's span `span`: cut at the jumps inside it, each side
 * moved into the domain by the jumps before it. */
static projcurve_status span_parts(projcurve_context *ctx, const projcurve_surface *s,
                                   const pc_branch *b, size_t span, exact_parts *parts)
{
    const pc_bspline *q = &b->compact_pcurve;
    const int d = q->degree, hd = homogeneous_dims(q);
    const double t0 = q->knots[span], t1 = q->knots[span + 1];
    double uvw[PC_EXACT_DIM * PC_EXACT_ORDER];
    span_bezier(q, span, uvw);
    exact_cuts cuts = {NULL, 0, 0};
    projcurve_status st = PROJCURVE_OK;
    for (size_t k = 0; st == PROJCURVE_OK && k < b->n_seams; ++k)
        if (b->seams[k].t > t0 && b->seams[k].t < t1)
            st = add_cut(ctx, &cuts, (b->seams[k].t - t0) / (t1 - t0));
    if (st == PROJCURVE_OK)
        st = close_cuts(ctx, &cuts);
    /* q is C^(d - m) at its knot of multiplicity m where the span starts;
     * a jump there (or merged into it by close_cuts) makes it C0 */
    size_t m = 1;
    while (m < span && q->knots[span - m] == t0)
        ++m;
    const double near = PC_EXACT_MIN_GAP * (q->knots[q->n_poles] - q->knots[(size_t)d]);
    for (size_t k = 0; k < b->n_seams; ++k)
        if (fabs(b->seams[k].t - t0) <= near)
            m = (size_t)d;
    for (size_t i = 0; st == PROJCURVE_OK && i + 1 < cuts.count; ++i) {
        const double a = cuts.items[i], c = cuts.items[i + 1];
        const double ta = a == 0.0 ? t0 : t0 + a * (t1 - t0);
        const double tc = c == 1.0 ? t1 : t0 + c * (t1 - t0);
        double side[PC_EXACT_DIM * PC_EXACT_ORDER], shift[2];
        bezier_part(d, hd, uvw, a, c, side);
        pc_seam_unwrap_shift(b, 0.5 * (ta + tc), shift);
        into_domain(d, side, shift, s->nurbs.domain);
        st = side_parts(ctx, &s->grid, d, hd, side, ta, tc, i == 0 && m < (size_t)d, parts);
    }
    PC_ARRAY_FREE(&cuts);
    return st;
}

/* Whether two parts' patches meet smoother than C0: not across a knot
 * line where S may be only C0 (the grid's creases: a knot of S of
 * multiplicity its degree). */
static int patches_smooth(const pc_patch_grid *g, size_t a, size_t b)
{
    const size_t ua = a % g->spans_u, va = a / g->spans_u;
    const size_t ub = b % g->spans_u, vb = b / g->spans_u;
    for (size_t k = (ua < ub ? ua : ub) + 1; k <= (ua < ub ? ub : ua); ++k)
        if (g->crease_u[k])
            return 0;
    for (size_t k = (va < vb ? va : vb) + 1; k <= (va < vb ? vb : va); ++k)
        if (g->crease_v[k])
            return 0;
    return 1;
}

/* The parts composed and joined into c (poles of dim 4, homogeneous,
 * when S is rational, else 3), knots of multiplicity the degree at the
 * joins, and smooth[k] for join k: a piece's homogeneous points are
 * scaled (which leaves a rational Bezier curve unchanged) so that its
 * first weight is the previous piece's last, whose pole it shares. cw:
 * scratch for one composed part. */
static void compose_parts(const projcurve_surface *s, int d, const exact_parts *parts,
                          pc_knot_curve *c, unsigned char *smooth, double *cw)
{
    const size_t nd = (size_t)c->degree, np = parts->count, dim = (size_t)c->dim;
    double w_join = 1.0;
    for (size_t i = 0; i < np; ++i) {
        const exact_part *p = &parts->items[i];
        pc_compose_poly_weighted(&s->grid.patches[p->patch], d, p->uv, p->w, cw);
        const double scale = w_join / cw[3];
        for (size_t j = i == 0 ? 0 : 1; j <= nd; ++j) {
            double *at = c->poles + dim * (i * nd + j);
            for (size_t k = 0; k < 3; ++k)
                at[k] = dim == 4 ? cw[4 * j + k] * scale : cw[4 * j + k] / cw[4 * j + 3];
            if (dim == 4)
                at[3] = cw[4 * j + 3] * scale;
        }
        w_join = cw[4 * nd + 3] * scale;
        for (size_t j = 0; j < nd; ++j)
            c->knots[1 + i * nd + j] = p->t0;
        if (i > 0)
            smooth[i - 1] = (unsigned char)(p->smooth &&
                                            patches_smooth(&s->grid, parts->items[i - 1].patch,
                                                           p->patch));
    }
    c->knots[0] = parts->items[0].t0;
    for (size_t j = 0; j <= nd; ++j)
        c->knots[np * nd + 1 + j] = parts->items[np - 1].t1;
}

/* The bound of the join removal in c's space: PC_EXACT_REMOVAL_ULPS of
 * the largest Cartesian pole, tol. Homogeneous poles X, w moved by at most
 * delta (each of |dX|, |dw| <= delta) move C = X / w by at most
 * delta (1 + |C|) / (w - delta), w >= the smallest weight: delta =
 * tol w_min / (1 + |C|_max + tol) keeps C within tol. 0 (no removal)
 * where a weight is not positive. */
static double removal_tol(const pc_knot_curve *c)
{
    const size_t dim = (size_t)c->dim;
    double c_max = 0.0, w_min = INFINITY;
    for (size_t i = 0; i < c->n_poles; ++i) {
        const double *x = c->poles + dim * i, w = dim == 4 ? x[3] : 1.0;
        c_max = fmax(c_max, sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]) / w);
        w_min = fmin(w_min, w);
    }
    const double tol = PC_EXACT_REMOVAL_ULPS * DBL_EPSILON * c_max;
    if (!(w_min > 0.0 && tol < INFINITY))
        return 0.0;
    return dim == 4 ? tol * w_min / (1.0 + c_max + tol) : tol;
}

/* c's homogeneous poles as out's Cartesian poles and weights. */
static void to_cartesian(const pc_knot_curve *c, pc_bspline *out)
{
    for (size_t i = 0; i < c->n_poles; ++i) {
        const double *x = c->poles + 4 * i;
        for (size_t k = 0; k < 3; ++k)
            out->poles[3 * i + k] = x[k] / x[3];
        out->weights[i] = x[3];
    }
}

/* The parts composed, joined and reduced into out, rational when S or q
 * is. */
static projcurve_status join_parts(projcurve_context *ctx, const projcurve_surface *s, int d,
                                   int rational, const exact_parts *parts, pc_bspline *out)
{
    const int n = d * (s->nurbs.deg_u + s->nurbs.deg_v);
    const size_t nd = (size_t)n, np = parts->count, dim = rational ? 4 : 3;
    if (np > (SIZE_MAX / (4 * sizeof(double)) - 2 * nd - 2) / nd)
        return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW, "%zu parts of degree %d overflow", np, n);
    pc_knot_curve c = {n, (int)dim, np * nd + 1, NULL, NULL};
    c.knots = malloc((c.n_poles + nd + 1) * sizeof *c.knots);
    c.poles = malloc(dim * c.n_poles * sizeof *c.poles);
    double *work = malloc((4 * (nd + 1) + 2 * np + 1) * sizeof *work);
    unsigned char *smooth = malloc(np);
    projcurve_status st = PROJCURVE_OK;
    if (!c.knots || !c.poles || !work || !smooth)
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for an exact composition");
    if (st == PROJCURVE_OK) {
        compose_parts(s, d, parts, &c, smooth, work);
        pc_exact_reduce_joins(&c, smooth, np, removal_tol(&c), work);
        out->degree = n;
        out->dim = 3;
        out->n_poles = c.n_poles;
        out->knots = c.knots;
        c.knots = NULL;
        out->weights = NULL;
        if (dim == 3) {
            out->poles = c.poles;
            c.poles = NULL;
        } else {
            out->poles = malloc(3 * c.n_poles * sizeof *out->poles);
            out->weights = malloc(c.n_poles * sizeof *out->weights);
            if (out->poles && out->weights)
                to_cartesian(&c, out);
            else
                st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY,
                             "out of memory for an exact composition");
        }
    }
    if (st != PROJCURVE_OK)
        pc_bspline_free(out);
    free(c.knots);
    free(c.poles);
    free(work);
    free(smooth);
    return st;
}

projcurve_status pc_exact_compose(projcurve_context *ctx, const projcurve_surface *s,
                                  const pc_branch *b, pc_bspline *out)
{
    const pc_bspline *q = &b->compact_pcurve;
    const int d = q->degree;
    if (d < 1 || d > PC_COMPOSE_POLY_MAX_DEGREE)
        return pc_fail(ctx, PROJCURVE_ERR_UNSUPPORTED,
                       "the compact pcurve is in the curve's own space (degree %d, above %d): "
                       "its exact composition is not offered; the pieces joined "
                       "(projcurve_result_branch_curve) are exact",
                       d, PC_COMPOSE_POLY_MAX_DEGREE);
    for (size_t i = 0; q->weights != NULL && i < q->n_poles; ++i)
        if (!(q->weights[i] > 0.0)) /* the composer's convex combinations need w > 0 */
            return pc_fail(ctx, PROJCURVE_ERR_UNSUPPORTED,
                           "the compact pcurve has weight %g at pole %zu: its exact "
                           "composition is not offered; the pieces joined "
                           "(projcurve_result_branch_curve) are exact",
                           q->weights[i], i);
    const int n = d * (s->nurbs.deg_u + s->nurbs.deg_v);
    if (n > PROJCURVE_MAX_DEGREE)
        return pc_fail(ctx, PROJCURVE_ERR_UNSUPPORTED,
                       "the exact composition has degree %d (%d (%d + %d)), above the %d of "
                       "a NURBS curve; read the pieces with projcurve_result_piece",
                       n, d, s->nurbs.deg_u, s->nurbs.deg_v, PROJCURVE_MAX_DEGREE);
    exact_parts parts = {NULL, 0, 0};
    projcurve_status st = PROJCURVE_OK;
    for (size_t span = (size_t)d; st == PROJCURVE_OK && span < q->n_poles; ++span)
        if (q->knots[span] < q->knots[span + 1])
            st = span_parts(ctx, s, b, span, &parts);
    if (st == PROJCURVE_OK && parts.count == 0)
        st = pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT, "the compact pcurve has no span");
    if (st == PROJCURVE_OK)
        st = join_parts(ctx, s, d, s->nurbs.rational || q->weights != NULL, &parts, out);
    PC_ARRAY_FREE(&parts);
    return st;
}
