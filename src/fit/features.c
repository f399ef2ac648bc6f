/* SPDX-License-Identifier: BSD-3-Clause */
#include "fit/features.h"

#include <math.h>
#include <stdlib.h>

#include "common/array.h"
#include "common/error.h"

/* A joint this close to a knot line (relative to the knot vector's range)
 * lies on it: the refinement puts its knot-line crossings exactly there. */
#define PC_FIT_ON_KNOT_REL 1e-12
/* Features closer in t than this fraction of the branch are one. */
#define PC_FIT_FEATURE_MERGE_REL 1e-12
#define PC_RADIANS_PER_DEGREE 0.017453292519943295769
/* Continuity that no fit degree needs to mark. */
#define PC_FIT_SMOOTH 1000

/* Continuity of a spline of `degree` at the value x (an interior knot
 * within tol of x: degree - multiplicity), PC_FIT_SMOOTH elsewhere. */
static int knot_continuity(const double *knots, size_t n_ctrl, int degree, double x, double tol)
{
    const double lo = knots[degree], hi = knots[n_ctrl];
    if (!(x > lo + tol && x < hi - tol))
        return PC_FIT_SMOOTH;
    size_t mult = 0;
    for (size_t k = (size_t)degree + 1; k < n_ctrl; ++k)
        mult += fabs(knots[k] - x) <= tol;
    return mult ? degree - (int)mult : PC_FIT_SMOOTH;
}

/* Direction of piece p's 3D tangent at its low (hi = 0) or high end, as t
 * increases, from its end control points; 0 when degenerate. */
static int end_tangent(const pc_piece *p, int hi, double d[3])
{
    const int forward = p->t1 > p->t0, n = p->degree;
    const int at_last = forward == (hi != 0); /* the end is the piece's s = 1 */
    const double *a = p->ctrl + 3 * (at_last ? n - 1 : 0), *b = p->ctrl + 3 * (at_last ? n : 1);
    double len = 0.0;
    for (int c = 0; c < 3; ++c) {
        d[c] = (b[c] - a[c]) * (forward ? 1.0 : -1.0);
        len += d[c] * d[c];
    }
    len = sqrt(len);
    if (!(len > 0.0))
        return 0;
    for (int c = 0; c < 3; ++c)
        d[c] /= len;
    return 1;
}

static int joint_is_crease(const pc_piece *a, const pc_piece *b, double cos_limit)
{
    double da[3], db[3];
    if (!end_tangent(a, 1, da) || !end_tangent(b, 0, db))
        return 0;
    return da[0] * db[0] + da[1] * db[1] + da[2] * db[2] < cos_limit;
}

static projcurve_status push(projcurve_context *ctx, pc_fit_features *f, double t, int continuity)
{
    if (continuity >= PC_FIT_SMOOTH)
        return PROJCURVE_OK;
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, f, f->count + 1, 16, "fit features");
    if (st != PROJCURVE_OK)
        return st;
    f->items[f->count].t = t;
    f->items[f->count].continuity = continuity;
    f->count++;
    return PROJCURVE_OK;
}

static int by_t(const void *a, const void *b)
{
    const double x = ((const pc_fit_feature *)a)->t, y = ((const pc_fit_feature *)b)->t;
    return (x > y) - (x < y);
}

/* Sorts and merges features closer than merge (keeping the lower
 * continuity) and drops those at the branch's ends. */
static void tidy(pc_fit_features *f, double t_lo, double t_hi, double merge)
{
    if (f->count > 1) /* items is NULL while there are none */
        qsort(f->items, f->count, sizeof *f->items, by_t);
    size_t m = 0;
    for (size_t i = 0; i < f->count; ++i) {
        const pc_fit_feature x = f->items[i];
        if (!(x.t > t_lo + merge && x.t < t_hi - merge))
            continue;
        if (m > 0 && x.t - f->items[m - 1].t <= merge) {
            if (x.continuity < f->items[m - 1].continuity)
                f->items[m - 1].continuity = x.continuity;
            continue;
        }
        f->items[m++] = x;
    }
    f->count = m;
}

projcurve_status pc_fit_features_find(projcurve_context *ctx, pc_fit_branch *fb,
                                      double crease_deg, pc_fit_features *out)
{
    out->items = NULL;
    out->count = out->capacity = 0;
    const pc_nurbs_surface *s = fb->surface;
    const double tol_u = PC_FIT_ON_KNOT_REL * (s->domain[1] - s->domain[0]);
    const double tol_v = PC_FIT_ON_KNOT_REL * (s->domain[3] - s->domain[2]);
    const double cos_limit = cos(crease_deg * PC_RADIANS_PER_DEGREE);
    projcurve_status st = PROJCURVE_OK;
    for (size_t k = 0; st == PROJCURVE_OK && k + 1 < fb->b->n_pieces; ++k) {
        pc_fit_sample j;
        pc_fit_piece_end(fb, k, 1, &j);
        const int cu = knot_continuity(s->knots_u, s->n_u, s->deg_u, j.uv[0], tol_u);
        const int cv = knot_continuity(s->knots_v, s->n_v, s->deg_v, j.uv[1], tol_v);
        int c = cu < cv ? cu : cv;
        if (joint_is_crease(pc_fit_piece(fb, k), pc_fit_piece(fb, k + 1), cos_limit))
            c = 0;
        st = push(ctx, out, j.t, c);
    }
    const projcurve_curve *curve = fb->proj->curve;
    if (curve != NULL && curve->kind == PC_CURVE_NURBS) {
        const pc_nurbs_curve *c = &curve->nurbs;
        for (size_t k = (size_t)c->degree + 1; st == PROJCURVE_OK && k < c->n_ctrl; ++k)
            if (k == (size_t)c->degree + 1 || c->knots[k] != c->knots[k - 1])
                st = push(ctx, out, c->knots[k],
                          knot_continuity(c->knots, c->n_ctrl, c->degree, c->knots[k], 0.0));
    }
    if (st != PROJCURVE_OK) {
        pc_fit_features_free(out);
        return st;
    }
    tidy(out, fb->t_lo, fb->t_hi, PC_FIT_FEATURE_MERGE_REL * (fb->t_hi - fb->t_lo));
    return PROJCURVE_OK;
}

void pc_fit_features_free(pc_fit_features *f)
{
    PC_ARRAY_FREE(f);
}
