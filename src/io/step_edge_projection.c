/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The pcurve of a STEP edge that has none on its face: the 3D curve
 * projected onto the face's surface point by point with the library's
 * closest-point projection ([Ook]), a degree-1 polyline whose error in 3D
 * is measured at every chord's middle.
 */
#include <math.h>
#include <string.h>

#include "common/error.h"
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
    projcurve_curve_destroy(c);
    double *knots = uv ? pc_arena_calloc(t->arena, n + 3, sizeof *knots) : NULL;
    if (knots == NULL)
        return pc_fail(t->f->ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading STEP");
    knots[0] = t0;
    for (size_t i = 0; i <= n; ++i)
        knots[i + 1] = t0 + (t1 - t0) * (double)i / (double)n;
    knots[n + 2] = t1;
    *out = (pc_piece_input){.degree = 1, .n_ctrl = n + 1, .ctrl = uv, .knots = knots};
    if (err > prec || off > PC_STEP_PCURVE_CHECK_FACTOR * prec)
        return pc_model_add_skipped(t->f->ctx, t->model,
                                    "STEP #%ld: the edge projected onto its face at %zu samples "
                                    "is within %.3g (precision %.3g); the edge is up to %.3g "
                                    "from the surface", curve->inst->id, n + 1, err, prec, off);
    return PROJCURVE_OK;
}
