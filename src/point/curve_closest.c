/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Closest point of a curve to a point ([Ook]).
 *
 * [Ook] finds the zero of d(t) = C'(t).(C(t) - p) by Newton from one
 * start. To get the global minimum, NURBS curves are cut into Bezier
 * segments visited nearest first; each is subdivided while a piece may
 * still beat the best distance (its control polygon's box is nearer) and
 * may hold a zero of d (C' lies in the cone of the polygon's edges — for
 * rational pieces too, by Floater's derivative formula — so if every edge
 * has a dot product of one sign with the whole box minus p, d has no zero).
 * Flat pieces start a clamped Newton from their control point nearest to p.
 * The two ends are candidates from the start.
 *
 * Callback curves have no control polygon: they are sampled densely and
 * Newton starts from the discrete local minima of the samples.
 */
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "point/point.h"
#include "point/subdivide.h"

#define CURVE_FLATNESS 0.02
#define CURVE_MAX_DEPTH 24
#define CURVE_MAX_ITER 60
#define CURVE_MAX_HALVINGS 40
#define CURVE_STEP_TOL 1e-13
/* Newton starts stay this fraction of a piece away from its ends. */
#define START_MARGIN 0.02
/* Samples of a callback curve, and Newton starts taken from them. */
#define CALLBACK_SAMPLES 512
#define CALLBACK_STARTS 16

typedef struct curve_search {
    const projcurve_curve *c;
    pc_vec3 p;
    double size;
    double best_t, best_d2;
    projcurve_status status;
} curve_search;

/* Clamped Newton on d(t) = 0 with d'(t) = C''.(C - p) + |C'|^2 replaced by
 * |C'|^2 where it is not positive, and backtracking on |C - p|^2. */
static void minimize_from(curve_search *cs, double t)
{
    const projcurve_curve *c = cs->c;
    pc_vec3 e[3];
    size_t hint = 0;
    if ((cs->status = pc_curve_eval(c, t, 2, &hint, e)) != PROJCURVE_OK)
        return;
    pc_vec3 r = vec3_sub(e[0], cs->p);
    double d2 = vec3_dot(r, r);
    for (int it = 0; it < CURVE_MAX_ITER; ++it) {
        const double g = vec3_dot(r, e[1]);
        if ((t <= c->t0 && g > 0.0) || (t >= c->t1 && g < 0.0))
            break; /* minimum at an end */
        double h = vec3_dot(r, e[2]) + vec3_dot(e[1], e[1]);
        if (!(h > 0.0))
            h = vec3_dot(e[1], e[1]);
        if (!(h > 0.0))
            break; /* C' = 0: a cusp, nothing to follow */
        const double delta = -g / h;
        const double predicted = fabs(delta) * vec3_norm(e[1]);
        double alpha = 1.0;
        int accepted = 0;
        pc_vec3 ne[3];
        double nt = t;
        for (int k = 0; k < CURVE_MAX_HALVINGS; ++k, alpha *= 0.5) {
            nt = fmin(fmax(t + alpha * delta, c->t0), c->t1);
            if ((cs->status = pc_curve_eval(c, nt, 2, &hint, ne)) != PROJCURVE_OK)
                return;
            const pc_vec3 nr = vec3_sub(ne[0], cs->p);
            if (vec3_dot(nr, nr) <= d2) {
                accepted = 1;
                break;
            }
        }
        if (!accepted)
            break;
        t = nt;
        memcpy(e, ne, sizeof e);
        r = vec3_sub(e[0], cs->p);
        d2 = vec3_dot(r, r);
        if (predicted <= CURVE_STEP_TOL * cs->size)
            break;
    }
    if (d2 < cs->best_d2) {
        cs->best_d2 = d2;
        cs->best_t = t;
    }
}

/* ---- NURBS curves: Bezier pieces ------------------------------------- */

typedef struct piece {
    double t0, t1;
    int depth;
} piece;

static void piece_box(const double *cw, size_t n, double *xyz, double box[6])
{
    box_empty(box);
    for (size_t i = 0; i < n; ++i) {
        for (size_t k = 0; k < 3; ++k)
            xyz[3 * i + k] = cw[4 * i + k] / cw[4 * i + 3];
        box_add_point(box, xyz + 3 * i);
    }
}

/* Can d(t) vanish on the piece? (see the file comment) */
static int may_hold_foot(const double *xyz, size_t n, const double box[6], pc_vec3 p)
{
    const double lo[3] = {box[0] - p.x, box[1] - p.y, box[2] - p.z};
    const double hi[3] = {box[3] - p.x, box[4] - p.y, box[5] - p.z};
    int sign = 2;
    for (size_t i = 0; i + 1 < n; ++i) {
        double mn = 0.0, mx = 0.0;
        for (size_t k = 0; k < 3; ++k) {
            const double d = xyz[3 * (i + 1) + k] - xyz[3 * i + k];
            mn += d >= 0.0 ? d * lo[k] : d * hi[k];
            mx += d >= 0.0 ? d * hi[k] : d * lo[k];
        }
        const int s = mn > 0.0 ? 1 : (mx < 0.0 ? -1 : 0);
        if (s == 0 || (sign != 2 && s != sign))
            return 1;
        sign = s;
    }
    return 0;
}

/* Largest distance of a control point from the chord, relative to the box. */
static double flatness(const double *xyz, size_t n, const double box[6])
{
    const pc_vec3 a = vec3_load(xyz), b = vec3_load(xyz + 3 * (n - 1));
    const pc_vec3 ab = vec3_sub(b, a);
    const double len2 = vec3_dot(ab, ab);
    double worst = 0.0;
    for (size_t i = 1; i + 1 < n; ++i) {
        const pc_vec3 ap = vec3_sub(vec3_load(xyz + 3 * i), a);
        const double s = len2 > 0.0 ? vec3_dot(ap, ab) / len2 : 0.0;
        worst = fmax(worst, vec3_norm(vec3_axpy(ap, -s, ab)));
    }
    const double diag = box_diagonal(box);
    return diag > 0.0 ? worst / diag : 0.0;
}

/* de Casteljau at 1/2 of n homogeneous points. */
static void split_half(const double *src, size_t n, double *lo, double *hi)
{
    double tmp[PC_MAX_ORDER][4];
    memcpy(tmp, src, n * 4 * sizeof(double));
    for (size_t r = 0; r < n; ++r) {
        memcpy(lo + 4 * r, tmp[0], 4 * sizeof(double));
        memcpy(hi + 4 * (n - 1 - r), tmp[n - 1 - r], 4 * sizeof(double));
        for (size_t i = 0; i + r + 1 < n; ++i)
            for (int m = 0; m < 4; ++m)
                tmp[i][m] = 0.5 * (tmp[i][m] + tmp[i + 1][m]);
    }
}

/* Walks one Bezier segment depth-first with an explicit stack (a split pops
 * one piece and pushes two: at most CURVE_MAX_DEPTH + 1 pending). */
static void walk_segment(curve_search *cs, const double *cw, size_t n, double t0, double t1,
                         double *nets)
{
    piece stack[CURVE_MAX_DEPTH + 1];
    double xyz[3 * PC_MAX_ORDER], box[6];
    const size_t len = 4 * n;
    size_t top = 0;
    memcpy(nets, cw, len * sizeof(double));
    stack[top++] = (piece){t0, t1, 0};
    /* The segment's end points are on the curve: candidates for minima at
     * kinks (knots of multiplicity >= degree), where d(t) jumps over 0. */
    for (size_t e = 0; e < 2; ++e) {
        const double *h = cw + 4 * (e ? n - 1 : 0);
        const pc_vec3 x = vec3(h[0] / h[3], h[1] / h[3], h[2] / h[3]);
        const double d2 = vec3_dot(vec3_sub(x, cs->p), vec3_sub(x, cs->p));
        if (d2 < cs->best_d2) {
            cs->best_d2 = d2;
            cs->best_t = e ? t1 : t0;
        }
    }
    while (top > 0 && cs->status == PROJCURVE_OK) {
        const piece pc = stack[--top];
        double *net = nets + top * len;
        piece_box(net, n, xyz, box);
        if (!(pc_box_distance_sq(box, cs->p) < cs->best_d2) || !may_hold_foot(xyz, n, box, cs->p))
            continue;
        const int flat = flatness(xyz, n, box) <= CURVE_FLATNESS;
        if (flat || pc.depth >= CURVE_MAX_DEPTH) {
            /* Start at p's projection on the chord, kept strictly inside
             * the piece: at a knot the derivatives are those of the next
             * span, which could lead Newton into the wrong basin. */
            const pc_vec3 a = vec3_load(xyz), b = vec3_load(xyz + 3 * (n - 1));
            const pc_vec3 ab = vec3_sub(b, a);
            const double len2 = vec3_dot(ab, ab);
            double s = len2 > 0.0 ? vec3_dot(vec3_sub(cs->p, a), ab) / len2 : 0.5;
            s = fmin(fmax(s, START_MARGIN), 1.0 - START_MARGIN);
            minimize_from(cs, pc.t0 + (pc.t1 - pc.t0) * s);
            continue;
        }
        double *scratch = nets + (CURVE_MAX_DEPTH + 2) * len;
        split_half(net, n, scratch, scratch + len);
        const double tm = 0.5 * (pc.t0 + pc.t1);
        memcpy(nets + top * len, scratch + len, len * sizeof(double));
        stack[top++] = (piece){tm, pc.t1, pc.depth + 1};
        memcpy(nets + top * len, scratch, len * sizeof(double));
        stack[top++] = (piece){pc.t0, tm, pc.depth + 1};
    }
}

typedef struct seg_order {
    double d2;
    size_t index;
} seg_order;

static int by_d2(const void *a, const void *b)
{
    const seg_order *x = a, *y = b;
    return x->d2 < y->d2 ? -1 : (x->d2 > y->d2 ? 1 : (x->index < y->index ? -1 : 1));
}

static projcurve_status closest_nurbs(projcurve_context *ctx, curve_search *cs)
{
    const pc_nurbs_curve *nc = &cs->c->nurbs;
    pc_bezier_curves segs;
    projcurve_status st = pc_bezier_curves_build(ctx, &segs, nc);
    if (st != PROJCURVE_OK)
        return st;
    const size_t n = (size_t)nc->degree + 1, len = 4 * n;
    seg_order *order = malloc(segs.n_segments * sizeof *order);
    double *nets = malloc((CURVE_MAX_DEPTH + 4) * len * sizeof(double));
    if (order == NULL || nets == NULL) {
        free(order);
        free(nets);
        pc_bezier_curves_free(&segs);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for curve projection");
    }
    double box[6];
    box_empty(box);
    for (size_t i = 0; i < nc->n_ctrl; ++i) {
        const double pt[3] = {nc->cw[4 * i] / nc->cw[4 * i + 3], nc->cw[4 * i + 1] / nc->cw[4 * i + 3],
                              nc->cw[4 * i + 2] / nc->cw[4 * i + 3]};
        box_add_point(box, pt);
    }
    cs->size = fmax(box_diagonal(box), 1e-300);
    for (size_t k = 0; k < segs.n_segments; ++k) {
        double xyz[3 * PC_MAX_ORDER], sbox[6];
        piece_box(segs.cw + k * len, n, xyz, sbox);
        order[k] = (seg_order){pc_box_distance_sq(sbox, cs->p), k};
    }
    qsort(order, segs.n_segments, sizeof *order, by_d2);
    for (size_t k = 0; k < segs.n_segments && order[k].d2 < cs->best_d2; ++k) {
        const size_t i = order[k].index;
        walk_segment(cs, segs.cw + i * len, n, segs.breaks[i], segs.breaks[i + 1], nets);
    }
    free(order);
    free(nets);
    pc_bezier_curves_free(&segs);
    return PROJCURVE_OK;
}

/* ---- Callback curves: dense samples ----------------------------------- */

static projcurve_status closest_callback(curve_search *cs)
{
    double d2s[CALLBACK_SAMPLES + 1];
    double box[6];
    box_empty(box);
    const projcurve_curve *c = cs->c;
    for (size_t k = 0; k <= CALLBACK_SAMPLES; ++k) {
        const double t = c->t0 + (c->t1 - c->t0) * (double)k / CALLBACK_SAMPLES;
        pc_vec3 e[3];
        const projcurve_status st = pc_curve_eval(c, t, 0, NULL, e);
        if (st != PROJCURVE_OK)
            return st;
        const double pt[3] = {e[0].x, e[0].y, e[0].z};
        box_add_point(box, pt);
        d2s[k] = vec3_dot(vec3_sub(e[0], cs->p), vec3_sub(e[0], cs->p));
    }
    cs->size = fmax(box_diagonal(box), 1e-300);
    /* Newton from the CALLBACK_STARTS smallest discrete local minima. */
    int started[CALLBACK_SAMPLES + 1] = {0};
    for (int s = 0; s < CALLBACK_STARTS; ++s) {
        size_t best = CALLBACK_SAMPLES + 1;
        for (size_t k = 0; k <= CALLBACK_SAMPLES; ++k) {
            const int local_min = (k == 0 || d2s[k] <= d2s[k - 1]) &&
                                  (k == CALLBACK_SAMPLES || d2s[k] <= d2s[k + 1]);
            if (local_min && !started[k] && (best > CALLBACK_SAMPLES || d2s[k] < d2s[best]))
                best = k;
        }
        if (best > CALLBACK_SAMPLES)
            break;
        started[best] = 1;
        minimize_from(cs, c->t0 + (c->t1 - c->t0) * (double)best / CALLBACK_SAMPLES);
        if (cs->status != PROJCURVE_OK)
            return cs->status;
    }
    return PROJCURVE_OK;
}

projcurve_status pc_curve_closest(projcurve_context *ctx, const projcurve_curve *c, pc_vec3 p,
                                  double *t, pc_vec3 *q, double *dist)
{
    curve_search cs = {c, p, 1.0, c->t0, INFINITY, PROJCURVE_OK};
    /* The ends are candidates whatever the interior does. */
    const double ends[2] = {c->t0, c->t1};
    for (int k = 0; k < 2; ++k) {
        pc_vec3 e[3];
        if (pc_curve_eval(c, ends[k], 0, NULL, e) != PROJCURVE_OK)
            return pc_fail(ctx, PROJCURVE_ERR_CALLBACK, "curve callback failed at t = %.17g",
                           ends[k]);
        const double d2 = vec3_dot(vec3_sub(e[0], p), vec3_sub(e[0], p));
        if (d2 < cs.best_d2) {
            cs.best_d2 = d2;
            cs.best_t = ends[k];
        }
    }
    projcurve_status st =
        c->kind == PC_CURVE_NURBS ? closest_nurbs(ctx, &cs) : closest_callback(&cs);
    if (st == PROJCURVE_OK)
        st = cs.status;
    if (st == PROJCURVE_ERR_CALLBACK)
        return pc_fail(ctx, st, "curve callback failed or returned a non-finite value");
    if (st != PROJCURVE_OK)
        return st;
    pc_vec3 e[3];
    if (pc_curve_eval(c, cs.best_t, 0, NULL, e) != PROJCURVE_OK)
        return pc_fail(ctx, PROJCURVE_ERR_CALLBACK, "curve callback failed at t = %.17g",
                       cs.best_t);
    *t = cs.best_t;
    *q = e[0];
    *dist = vec3_dist(e[0], p);
    return PROJCURVE_OK;
}
