/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The pcurve of a STEP edge that has none on its face: the 3D curve
 * projected onto the face's surface point by point with the library's
 * closest-point projection ([Ook]), a degree-1 polyline whose error in 3D
 * is measured at every chord's middle, then refitted as a cubic within a
 * quarter of the face's (u, v) tolerance of the samples and of the
 * projection half way between them (fit/resampled.h) when one is.
 */
#include <math.h>
#include <string.h>

#include "brep/face.h"
#include "common/error.h"
#include "fit/resampled.h"
#include "geom/curve.h"
#include "io/step_topology.h"

/* Samples to start with and the most; the chord midpoints must be within
 * the precision. */
#define PC_STEP_PROJECT_SAMPLES 16
#define PC_STEP_PROJECT_MAX_SAMPLES 4096

/* The 3D curve of an edge without pcurve, from v0 to v1 along its
 * parameter, as a curve handle over [*t0, *t1]. */
static projcurve_status edge_curve3(const stopo *t, const pc_step_located *curve,
                                    const projcurve_surface *s, const double v0[3],
                                    const double v1[3], projcurve_curve **out, double *t0,
                                    double *t1, int *closed)
{
    pc_io_curve c;
    double ends[6];
    const char *skip = NULL;
    projcurve_status st;
    if (pc_step_is(curve->node, "LINE")) {
        memcpy(ends, v0, 3 * sizeof *ends);
        memcpy(ends + 3, v1, 3 * sizeof *ends);
        st = pc_io_line_curve(t->f->ctx, t->arena, ends, ends + 3, &c);
    } else {
        st = pc_step_curve(t->f, t->arena, curve, &c, NULL, &skip);
    }
    if (st != PROJCURVE_OK)
        return st;
    if (skip != NULL)
        return pc_step_give_up(t, "edge curve #%ld: %s, and no pcurve", curve->inst->id, skip);
    if (projcurve_curve_create_nurbs(NULL, c.degree, c.n_ctrl, c.ctrl, c.weights, c.knots, out) != PROJCURVE_OK)
        return pc_step_give_up(t, "edge curve #%ld: %s", curve->inst->id, "not a valid curve");
    projcurve_curve_domain(NULL, *out, t0, t1);
    /* a closed curve whose vertices meet within the check's tolerance is
     * a closed edge (files keep vertices to their edge tolerance) */
    double c0[3], c1[3];
    projcurve_curve_eval(NULL, *out, *t0, 0, c0);
    projcurve_curve_eval(NULL, *out, *t1, 0, c1);
    const double near = PC_STEP_PCURVE_CHECK_FACTOR * pc_step_precision(t, s);
    *closed = pc_step_dist3(v0, v1) <= near && pc_step_dist3(c0, c1) <= near;
    if (!*closed) { /* an open edge: between its vertices */
        double a = *t0, b = *t1;
        projcurve_curve_closest_point(NULL, *out, v0, &a, NULL, NULL);
        projcurve_curve_closest_point(NULL, *out, v1, &b, NULL, NULL);
        *t0 = a, *t1 = b;
    }
    if (!(*t1 > *t0)) {
        projcurve_curve_destroy(*out);
        *out = NULL;
        return pc_step_give_up(t, "edge curve #%ld: its vertices do not bound a %s", curve->inst->id,
                       "range of it");
    }
    return PROJCURVE_OK;
}

/* Projects samples C(t_i) onto s ([Ook] closest points) and returns the
 * largest distance, over the chords, of S at a chord's midpoint from the
 * curve's point half way (the polyline's error in 3D). */
static double project_samples(const projcurve_surface *s, const projcurve_curve *c, double t0,
                              double t1, size_t n, double *uv, double *off)
{
    double err = 0.0;
    *off = 0.0;
    for (size_t i = 0; i <= n; ++i) {
        double p[3], q[3], d = 0.0;
        projcurve_curve_eval(NULL, c, t0 + (t1 - t0) * (double)i / (double)n, 0, p);
        projcurve_surface_closest_point(NULL, s, p, uv + 2 * i, q, &d);
        *off = fmax(*off, d);
        if (i == 0)
            continue;
        double m[3], sm[3];
        const double mid[2] = {0.5 * (uv[2 * i - 2] + uv[2 * i]), 0.5 * (uv[2 * i - 1] + uv[2 * i + 1])};
        projcurve_curve_eval(NULL, c, t0 + (t1 - t0) * ((double)i - 0.5) / (double)n, 0, m);
        if (pc_step_surface_point(s, mid, sm))
            err = fmax(err, pc_step_dist3(m, sm));
    }
    return err;
}

/* The edge projected at t: the exact curve the polyline is refitted to. */
typedef struct projected_edge {
    const projcurve_surface *s;
    const projcurve_curve *c;
} projected_edge;

static void projected_at(const void *user, double t, double *uv)
{
    const projected_edge *e = user;
    double p[3];
    projcurve_curve_eval(NULL, e->c, t, 0, p);
    if (projcurve_surface_closest_point(NULL, e->s, p, uv, NULL, NULL) != PROJCURVE_OK)
        uv[0] = uv[1] = NAN; /* fails the fit's check: the polyline stays */
}

/* The breaks of the projection: the 3D curve's distinct knots inside
 * (t0, t1), where its parametrisation (a rational circle's arcs) has a
 * second derivative that jumps; PC_FIT_RESAMPLED_MAX_BREAKS + 1 when there
 * are more (no fit then). */
static size_t knot_breaks(const projcurve_curve *c, double t0, double t1, double *breaks)
{
    const pc_nurbs_curve *nc = &c->nurbs;
    size_t nb = 0;
    for (size_t i = (size_t)nc->degree + 1; i < nc->n_ctrl; ++i) {
        const double k = nc->knots[i];
        if (!(k > t0 && k < t1) || (nb > 0 && k <= breaks[nb - 1]))
            continue;
        if (nb == PC_FIT_RESAMPLED_MAX_BREAKS)
            return nb + 1;
        breaks[nb++] = k;
    }
    return nb;
}

/* The polyline uv (n + 1 samples over [t0, t1]) as a cubic in *out when one
 * is within a quarter of the face's (u, v) tolerance. */
static projcurve_status compact(const stopo *t, const projcurve_surface *s,
                                const projcurve_curve *c, double t0, double t1, const double *uv,
                                size_t n, pc_piece_input *out)
{
    double *poles = pc_arena_calloc(t->arena, 2 * PC_FIT_RESAMPLED_POLES, sizeof *poles);
    double *knots = pc_arena_calloc(t->arena, PC_FIT_RESAMPLED_POLES + 4, sizeof *knots);
    if (poles == NULL || knots == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    const projected_edge e = {s, c};
    const double tol = 0.25 * pc_face_uv_tolerance(s, pc_step_precision(t, s));
    double breaks[PC_FIT_RESAMPLED_MAX_BREAKS];
    const pc_fit_resampled_input in = {.dim = 2, .samples = uv, .n = n, .t0 = t0, .t1 = t1,
                                       .breaks = breaks, .n_breaks = knot_breaks(c, t0, t1, breaks),
                                       .exact = projected_at, .user = &e, .tol = tol};
    size_t n_poles = 0;
    const projcurve_status st = pc_fit_resampled_cubic(t->f->ctx, &in, poles, knots, &n_poles);
    if (st == PROJCURVE_OK && n_poles > 0 && n_poles < n + 1)
        *out = (pc_piece_input){.degree = 3, .n_ctrl = n_poles, .ctrl = poles, .knots = knots};
    return st;
}

/* The pcurve of an edge that has none: its 3D curve projected onto the
 * surface at n + 1 samples, n doubling from PC_STEP_PROJECT_SAMPLES until
 * the chords are within the precision or n reaches
 * PC_STEP_PROJECT_MAX_SAMPLES, or the error no longer halves (the edge
 * lies off the surface); the error reached is then reported. A degree-1
 * piece over the edge's parameters. */
projcurve_status pc_step_edge_projection(const stopo *t, const pc_step_located *curve,
                                        const projcurve_surface *s, const double v0[3],
                                        const double v1[3], pc_piece_input *out)
{
    projcurve_curve *c = NULL;
    double t0 = 0.0, t1 = 1.0;
    int closed = 0;
    projcurve_status st = edge_curve3(t, curve, s, v0, v1, &c, &t0, &t1, &closed);
    if (st != PROJCURVE_OK || c == NULL)
        return st;
    const double prec = pc_step_precision(t, s);
    double *uv = NULL, err = INFINITY, off = 0.0;
    size_t n = PC_STEP_PROJECT_SAMPLES;
    for (;; n *= 2) {
        uv = pc_arena_calloc(t->arena, 2 * (n + 1), sizeof *uv);
        if (uv == NULL)
            break;
        const double before = err;
        err = project_samples(s, c, t0, t1, n, uv, &off);
        if (closed) /* a closed edge: one point, one (u, v) */
            uv[2 * n] = uv[0], uv[2 * n + 1] = uv[1];
        /* chords shrink the error 4 times a doubling; when it stops
         * halving, the edge's own distance from the surface dominates */
        if (err <= prec || n >= PC_STEP_PROJECT_MAX_SAMPLES || err > 0.5 * before)
            break;
    }
    double *knots = uv ? pc_arena_calloc(t->arena, n + 3, sizeof *knots) : NULL;
    if (knots == NULL) {
        projcurve_curve_destroy(c);
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    }
    knots[0] = t0;
    for (size_t i = 0; i <= n; ++i)
        knots[i + 1] = t0 + (t1 - t0) * (double)i / (double)n;
    knots[n + 2] = t1;
    *out = (pc_piece_input){.degree = 1, .n_ctrl = n + 1, .ctrl = uv, .knots = knots};
    /* a cubic may meet the precision where 4097 chords cannot (a small
     * circle): it is checked against the projection itself */
    st = off <= PC_STEP_PCURVE_CHECK_FACTOR * prec ? compact(t, s, c, t0, t1, uv, n, out)
                                                   : PROJCURVE_OK;
    projcurve_curve_destroy(c);
    if (st != PROJCURVE_OK || out->degree == 3)
        return st;
    if (err > prec || off > PC_STEP_PCURVE_CHECK_FACTOR * prec)
        return pc_model_add_skipped(t->f->ctx, t->model,
                                    "STEP #%ld: the edge projected onto its face at %zu samples "
                                    "is within %.3g (precision %.3g); the edge is up to %.3g "
                                    "from the surface", curve->inst->id, n + 1, err, prec, off);
    return PROJCURVE_OK;
}
