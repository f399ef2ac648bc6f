/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Boundaries of faces on analytic surfaces (IGES 144 over 108, 118, 120,
 * 122): the 142's parameter-space curve (BPTR) is in the analytic entity's
 * own parametrisation, which IGES leaves to each entity (and for the plane
 * 108 to the writer), not in that of the exact NURBS the reader builds. The
 * boundary is instead taken from the 142's model-space curve (CPTR) by
 * point inversion onto the NURBS: a degree-1 pcurve through the (u, v) of
 * the curve's points at parameters spread over each knot span, doubled
 * until every chord's middle is within PC_IGES_MAP_TOL_FRACTION of the
 * face's (u, v) tolerance of the inverted point half way, and every point
 * within PC_IGES_MAP_OFF_FACTOR model tolerances of the surface (a curve
 * farther off does not bound this surface: the face is not built); then
 * refitted as a cubic within the same tolerance of the samples and of the
 * inverted curve between them, the curve's knots as breaks, when one is
 * (fit/resampled.h; else the polyline stays).
 *
 * Where the NURBS is an affine map of (u, v) (a bilinear patch over a
 * parallelogram: the plane 108), the inverse is affine too, and the
 * boundary is mapped exactly instead: its control points carried by the
 * inverse (affine maps commute with the rational basis), the same degree,
 * weights and knots, once every control point lies on the plane within
 * the model tolerance (the curve lies in their convex hull).
 *
 * On a closed direction (a full turn of revolution) a point on the seam
 * has two (u, v): each takes the one nearest its neighbour along the
 * curve, the first from the end of the loop's previous piece where it has
 * no neighbour off the seam. A curve that still jumps by half the period
 * crosses the seam; one NURBS domain cannot hold its loop, and the face is
 * not built (as before).
 */
#include <math.h>
#include <string.h>

#include "common/error.h"
#include "fit/resampled.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "io/iges.h"
#include "point/point.h"
#include "seam/seam.h"

#define PC_IGES_MAP_SPAN_SAMPLES 4
#define PC_IGES_MAP_MAX_SAMPLES 4096
#define PC_IGES_MAP_TOL_FRACTION 0.25
#define PC_IGES_MAP_OFF_FACTOR 10.0
/* A point this close to a closed direction's edge (relative to the width)
 * is on the seam. */
#define PC_IGES_MAP_SEAM_SLACK 1e-9

typedef struct inversion {
    const projcurve_surface *s;
    pc_closure closure;
    double dom[4];
    double worst; /* the largest distance of a curve point from its foot */
} inversion;

/* The affine map of a bilinear parallelogram patch: S(u, v) = o + a u + b v. */
typedef struct affine_patch {
    double o[3], a[3], b[3];
} affine_patch;

static int affine_of(const pc_nurbs_surface *n, affine_patch *m)
{
    if (n->deg_u != 1 || n->deg_v != 1 || n->n_u != 2 || n->n_v != 2)
        return 0;
    double P[4][3];
    for (int i = 0; i < 4; ++i) {
        const double w = n->cw[4 * i + 3];
        if (w != n->cw[3])
            return 0; /* not the same weight everywhere: not affine */
        for (int k = 0; k < 3; ++k)
            P[i][k] = n->cw[4 * i + k] / w;
    }
    const double du = n->domain[1] - n->domain[0], dv = n->domain[3] - n->domain[2];
    double twist = 0.0, scale = 0.0;
    for (int k = 0; k < 3; ++k) {
        twist = fmax(twist, fabs(P[3][k] - P[2][k] - P[1][k] + P[0][k]));
        scale = fmax(scale, fmax(fabs(P[1][k] - P[0][k]), fabs(P[2][k] - P[0][k])));
        m->a[k] = (P[1][k] - P[0][k]) / du;
        m->b[k] = (P[2][k] - P[0][k]) / dv;
        m->o[k] = P[0][k] - m->a[k] * n->domain[0] - m->b[k] * n->domain[2];
    }
    return twist <= 1e-14 * scale; /* a parallelogram to rounding */
}

/* (u, v) of the point x by the inverse of the patch (least squares in the
 * plane) and its distance from the plane. */
static double affine_inverse(const affine_patch *m, const double x[3], double uv[2])
{
    double d[3], aa = 0.0, ab = 0.0, bb = 0.0, ad = 0.0, bd = 0.0;
    for (int k = 0; k < 3; ++k) {
        d[k] = x[k] - m->o[k];
        aa += m->a[k] * m->a[k], ab += m->a[k] * m->b[k], bb += m->b[k] * m->b[k];
        ad += m->a[k] * d[k], bd += m->b[k] * d[k];
    }
    const double det = aa * bb - ab * ab;
    uv[0] = (bb * ad - ab * bd) / det;
    uv[1] = (aa * bd - ab * ad) / det;
    double off = 0.0;
    for (int k = 0; k < 3; ++k)
        off = fmax(off, fabs(d[k] - m->a[k] * uv[0] - m->b[k] * uv[1]));
    return off;
}

/* c mapped exactly by the inverse of an affine patch into out (arena);
 * *reason when a control point is off the plane. */
static projcurve_status affine_boundary(const pc_iges_file *f, const affine_patch *m,
                                        const pc_io_curve *c, double off_tol, pc_io_curve *out,
                                        const char **reason)
{
    double *ctrl = pc_arena_calloc(f->arena, 3 * c->n_ctrl, sizeof *ctrl);
    if (ctrl == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES");
    for (size_t i = 0; i < c->n_ctrl; ++i) {
        double uv[2];
        if (!(affine_inverse(m, c->ctrl + 3 * i, uv) <= off_tol)) {
            *reason = "its model-space curve lies off the plane";
            return PROJCURVE_OK;
        }
        ctrl[3 * i] = uv[0], ctrl[3 * i + 1] = uv[1], ctrl[3 * i + 2] = 0.0;
    }
    *out = *c;
    out->ctrl = ctrl;
    return PROJCURVE_OK;
}

/* (u, v) of the point of s nearest p, from uv when seeded (a local
 * minimum that is close enough stands), else from the whole surface. */
static projcurve_status invert(inversion *in, pc_vec3 p, int seeded, double tol, double uv[2])
{
    if (seeded) {
        const double d2 = pc_surface_minimize(&in->s->nurbs, p, in->s->size, uv);
        if (d2 <= tol * tol) {
            in->worst = fmax(in->worst, sqrt(d2));
            return PROJCURVE_OK;
        }
    }
    pc_surface_point q;
    const projcurve_status st = pc_surface_closest(NULL, in->s, p, &q);
    if (st != PROJCURVE_OK)
        return st;
    uv[0] = q.u, uv[1] = q.v;
    in->worst = fmax(in->worst, q.dist);
    return PROJCURVE_OK;
}

static int on_edge(const inversion *in, int k, double x)
{
    const double lo = in->dom[2 * k], hi = in->dom[2 * k + 1];
    const double slack = PC_IGES_MAP_SEAM_SLACK * (hi - lo);
    return fabs(x - lo) <= slack || fabs(x - hi) <= slack;
}

/* The representative of uv[k] on the seam nearest ref. */
static void nearest_side(const inversion *in, int k, double ref, double *x)
{
    const double lo = in->dom[2 * k], hi = in->dom[2 * k + 1];
    if (on_edge(in, k, *x))
        *x = fabs(ref - lo) <= fabs(ref - hi) ? lo : hi;
}

/* Seam sides along the n samples uv (2 per sample); 0 when they still
 * jump by half a period (the curve crosses the seam). */
static int choose_seam_sides(const inversion *in, double *uv, size_t n, const double *anchor)
{
    for (int k = 0; k < 2; ++k) {
        const int closed = k == 0 ? in->closure.closed_u : in->closure.closed_v;
        if (!closed)
            continue;
        size_t a = 0; /* the first sample off the seam */
        while (a < n && on_edge(in, k, uv[2 * a + k]))
            ++a;
        if (a == n) { /* along the seam: the side of the loop's last point */
            if (anchor != NULL)
                nearest_side(in, k, anchor[k], &uv[k]);
            a = 0;
        }
        for (size_t i = a; i-- > 0;)
            nearest_side(in, k, uv[2 * (i + 1) + k], &uv[2 * i + k]);
        for (size_t i = a + 1; i < n; ++i)
            nearest_side(in, k, uv[2 * (i - 1) + k], &uv[2 * i + k]);
        const double half = 0.5 * (in->dom[2 * k + 1] - in->dom[2 * k]);
        for (size_t i = 1; i < n; ++i)
            if (fabs(uv[2 * i + k] - uv[2 * (i - 1) + k]) > half)
                return 0;
    }
    return 1;
}

/* The distinct knots of c over its domain into brk (n_ctrl - degree + 1 at
 * most); their count. */
static size_t breaks_of(const pc_io_curve *c, double *brk)
{
    size_t n = 0;
    for (size_t i = (size_t)c->degree; i <= c->n_ctrl; ++i)
        if (n == 0 || c->knots[i] > brk[n - 1])
            brk[n++] = c->knots[i];
    return n;
}

/* The parameters of 2 m + 1 samples per span (odd ones: chord middles). */
static void sample_params(const double *brk, size_t n_brk, size_t m, double *t)
{
    size_t k = 0;
    for (size_t j = 0; j + 1 < n_brk; ++j)
        for (size_t i = 0; i < 2 * m; ++i)
            t[k++] = brk[j] + (brk[j + 1] - brk[j]) * (double)i / (double)(2 * m);
    t[k] = brk[n_brk - 1];
}

/* The largest distance of a chord's middle sample from the chord's middle. */
static double chord_error(const double *uv, size_t n)
{
    double err = 0.0;
    for (size_t i = 1; i + 1 < n; i += 2)
        err = fmax(err, hypot(uv[2 * i] - 0.5 * (uv[2 * i - 2] + uv[2 * i + 2]),
                              uv[2 * i + 1] - 0.5 * (uv[2 * i - 1] + uv[2 * i + 3])));
    return err;
}

static projcurve_status invert_samples(inversion *in, const projcurve_curve *c, const double *t,
                                       size_t n, double tol, double *uv)
{
    for (size_t i = 0; i < n; ++i) {
        double x[3];
        projcurve_status st = projcurve_curve_eval(NULL, c, t[i], 0, x);
        if (st != PROJCURVE_OK)
            return st;
        if (i > 0)
            uv[2 * i] = uv[2 * i - 2], uv[2 * i + 1] = uv[2 * i - 1];
        if ((st = invert(in, (pc_vec3){x[0], x[1], x[2]}, i > 0, tol, uv + 2 * i)) != PROJCURVE_OK)
            return st;
    }
    return PROJCURVE_OK;
}

/* The polyline through the even samples into out (arena). */
static projcurve_status polyline(const pc_iges_file *f, const double *t, const double *uv,
                                 size_t n, pc_io_curve *out)
{
    const size_t m = n / 2 + 1;
    double *ctrl = pc_arena_calloc(f->arena, 3 * m, sizeof *ctrl);
    double *knots = pc_arena_calloc(f->arena, m + 2, sizeof *knots);
    if (ctrl == NULL || knots == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES");
    for (size_t i = 0; i < m; ++i) {
        ctrl[3 * i] = uv[4 * i];
        ctrl[3 * i + 1] = uv[4 * i + 1];
        knots[i + 1] = t[2 * i];
    }
    knots[0] = t[0];
    knots[m + 1] = t[n - 1];
    *out = (pc_io_curve){.degree = 1, .n_ctrl = m, .ctrl = ctrl, .weights = NULL, .knots = knots};
    return PROJCURVE_OK;
}

/* The boundary inverted at t, from the (u, v) of the nearest sample (its
 * seam side): the exact curve the polyline is refitted to. */
typedef struct inverted_boundary {
    const projcurve_surface *s;
    const projcurve_curve *h;
    const double *t, *uv; /* the n samples */
    size_t n;
    double off; /* the farthest a point may lie from the surface */
} inverted_boundary;

static void inverted_at(const void *user, double t, double *out)
{
    const inverted_boundary *b = user;
    size_t lo = 0, hi = b->n - 1; /* b->t[lo] <= t <= b->t[hi] */
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (b->t[mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    const size_t k = t - b->t[lo] <= b->t[hi] - t ? lo : hi;
    out[0] = b->uv[2 * k], out[1] = b->uv[2 * k + 1];
    double x[3];
    if (projcurve_curve_eval(NULL, b->h, t, 0, x) != PROJCURVE_OK ||
        !(pc_surface_minimize(&b->s->nurbs, (pc_vec3){x[0], x[1], x[2]}, b->s->size, out) <=
          b->off * b->off))
        out[0] = out[1] = NAN; /* fails the fit's check: the polyline stays */
}

/* The polyline through the even samples, out, as a cubic when one is
 * within tol of every even sample and of the inverted boundary between
 * them (fit/resampled.h), the curve's knots as breaks. */
static projcurve_status compact(const pc_iges_file *f, const inverted_boundary *b,
                                const double *brk, size_t n_brk, double tol, pc_io_curve *out)
{
    const size_t m = b->n / 2 + 1;
    double *t = pc_arena_calloc(f->arena, m, sizeof *t);
    double *uv = pc_arena_calloc(f->arena, 2 * m, sizeof *uv);
    double *poles = pc_arena_calloc(f->arena, 2 * PC_FIT_RESAMPLED_POLES, sizeof *poles);
    double *ctrl = pc_arena_calloc(f->arena, 3 * PC_FIT_RESAMPLED_POLES, sizeof *ctrl);
    double *knots = pc_arena_calloc(f->arena, PC_FIT_RESAMPLED_POLES + 4, sizeof *knots);
    if (t == NULL || uv == NULL || poles == NULL || ctrl == NULL || knots == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES");
    for (size_t i = 0; i < m; ++i)
        t[i] = b->t[2 * i], uv[2 * i] = b->uv[4 * i], uv[2 * i + 1] = b->uv[4 * i + 1];
    const size_t n_breaks = n_brk > 2 ? n_brk - 2 : 0;
    const pc_fit_resampled_input in = {.dim = 2, .samples = uv, .n = m - 1, .t0 = t[0],
                                       .t1 = t[m - 1], .t = t, .breaks = brk + 1,
                                       .n_breaks = n_breaks, .exact = inverted_at, .user = b,
                                       .tol = tol};
    size_t n_poles = 0;
    const projcurve_status st = pc_fit_resampled_cubic(f->ctx, &in, poles, knots, &n_poles);
    if (st != PROJCURVE_OK || n_poles == 0 || n_poles >= m)
        return st;
    for (size_t i = 0; i < n_poles; ++i)
        ctrl[3 * i] = poles[2 * i], ctrl[3 * i + 1] = poles[2 * i + 1], ctrl[3 * i + 2] = 0.0;
    *out = (pc_io_curve){.degree = 3, .n_ctrl = n_poles, .ctrl = ctrl, .weights = NULL,
                         .knots = knots};
    return PROJCURVE_OK;
}

projcurve_status pc_iges_boundary_by_inversion(const pc_iges_file *f, const projcurve_surface *s,
                                               const pc_io_curve *c, double tol_model,
                                               double tol_uv, const double *anchor,
                                               pc_io_curve *out, const char **reason)
{
    *reason = NULL;
    affine_patch plane;
    if (affine_of(&s->nurbs, &plane))
        return affine_boundary(f, &plane, c, PC_IGES_MAP_OFF_FACTOR * tol_model, out, reason);
    projcurve_curve *h = NULL;
    projcurve_status st =
        projcurve_curve_create_nurbs(NULL, c->degree, c->n_ctrl, c->ctrl, c->weights, c->knots, &h);
    if (st == PROJCURVE_ERR_NO_MEMORY)
        return pc_fail(f->ctx, st, "out of memory reading IGES");
    if (st != PROJCURVE_OK) {
        *reason = "its model-space curve is not a valid curve";
        return PROJCURVE_OK;
    }
    inversion in = {.s = s};
    pc_surface_closure(&s->nurbs, tol_model, &in.closure);
    projcurve_surface_domain(NULL, s, in.dom);
    const size_t spans = c->n_ctrl - (size_t)c->degree;
    double *brk = pc_arena_calloc(f->arena, spans + 1, sizeof *brk);
    const size_t n_brk = brk ? breaks_of(c, brk) : 0;
    const double off = PC_IGES_MAP_OFF_FACTOR * tol_model;
    double *t = NULL, *uv = NULL;
    size_t n = 0;
    double err = INFINITY;
    /* doubling the samples per span: at most log2 of the bound rounds */
    for (size_t m = PC_IGES_MAP_SPAN_SAMPLES; st == PROJCURVE_OK && brk != NULL && n_brk >= 2;
         m *= 2) {
        n = 2 * m * (n_brk - 1) + 1;
        t = pc_arena_calloc(f->arena, n, sizeof *t);
        uv = pc_arena_calloc(f->arena, 2 * n, sizeof *uv);
        if (t == NULL || uv == NULL)
            break;
        sample_params(brk, n_brk, m, t);
        in.worst = 0.0;
        if ((st = invert_samples(&in, h, t, n, off, uv)) != PROJCURVE_OK)
            break;
        if (in.worst > off) {
            *reason = "its model-space curve lies off the surface's exact NURBS";
            break;
        }
        if (!choose_seam_sides(&in, uv, n, anchor)) {
            *reason = "its boundary crosses the seam of its closed surface";
            break;
        }
        err = chord_error(uv, n);
        if (err <= PC_IGES_MAP_TOL_FRACTION * tol_uv || n >= PC_IGES_MAP_MAX_SAMPLES)
            break;
    }
    const inverted_boundary b = {s, h, t, uv, n, off};
    if (st == PROJCURVE_OK && *reason == NULL && t != NULL && uv != NULL &&
        err <= PC_IGES_MAP_TOL_FRACTION * tol_uv && (st = polyline(f, t, uv, n, out)) == PROJCURVE_OK)
        st = compact(f, &b, brk, n_brk, PC_IGES_MAP_TOL_FRACTION * tol_uv, out);
    projcurve_curve_destroy(h);
    if (brk != NULL && n_brk < 2) {
        *reason = "its model-space curve has an empty domain";
        return PROJCURVE_OK;
    }
    if (st != PROJCURVE_OK)
        return st == PROJCURVE_ERR_NO_MEMORY ? pc_fail(f->ctx, st, "out of memory reading IGES")
                                             : st;
    if (brk == NULL || t == NULL || uv == NULL)
        return pc_fail(f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading IGES");
    if (*reason != NULL)
        return PROJCURVE_OK;
    if (err > PC_IGES_MAP_TOL_FRACTION * tol_uv) {
        *reason = "its model-space curve inverted onto the surface at the most samples is "
                  "not within the face's (u, v) tolerance";
        return PROJCURVE_OK;
    }
    return PROJCURVE_OK; /* the polyline or its cubic, made above */
}
