/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Deviation of a result from the exact projection (see deviation.h).
 */
#include "deviation.h"

#include <math.h>
#include <stdlib.h>

/* As in exact.c: 0.618^64 ~ 4e-14 of the bracket (two sample spacings). */
#define GOLDEN_ITER 64

typedef struct sample {
    size_t curve;
    double s;
    double p[3];
} sample;

typedef struct sampled_set {
    const pcb_curve_set *set;
    sample *pts;
    size_t n;
    size_t per_curve;
} sampled_set;

static double dist3(const double *a, const double *b)
{
    const double dx = a[0] - b[0], dy = a[1] - b[1], dz = a[2] - b[2];
    return sqrt(dx * dx + dy * dy + dz * dz);
}

static int sample_curves(const pcb_curve_set *set, size_t per_curve, sampled_set *out)
{
    out->set = set;
    out->per_curve = per_curve;
    out->n = 0;
    out->pts = set->n_curves ? malloc(set->n_curves * per_curve * sizeof *out->pts) : NULL;
    if (set->n_curves && !out->pts)
        return -1;
    for (size_t c = 0; c < set->n_curves; ++c) {
        double range[2];
        if (set->domain(set->user, c, range) != 0)
            return -1;
        for (size_t k = 0; k < per_curve; ++k) {
            sample *sm = &out->pts[out->n++];
            sm->curve = c;
            sm->s = k + 1 == per_curve
                        ? range[1]
                        : range[0] + (range[1] - range[0]) * (double)k / (double)(per_curve - 1);
            if (set->eval(set->user, c, sm->s, sm->p) != 0)
                return -1;
        }
    }
    return 0;
}

/* |x - R_c(s)|, infinity where the curve cannot be evaluated. */
static double curve_distance(const pcb_curve_set *set, size_t c, double s, const double x[3])
{
    double p[3];
    return set->eval(set->user, c, s, p) == 0 ? dist3(x, p) : INFINITY;
}

/* Distance from x to the sampled curves: nearest sample, then golden
 * section between its neighbours on the same curve. */
static double set_distance(const sampled_set *ss, const double x[3])
{
    if (ss->n == 0)
        return INFINITY;
    size_t best = 0;
    double best_d = INFINITY;
    for (size_t i = 0; i < ss->n; ++i) {
        const double d = dist3(x, ss->pts[i].p);
        if (d < best_d) {
            best_d = d;
            best = i;
        }
    }
    const size_t k = best % ss->per_curve;
    const sample *lo = k > 0 ? &ss->pts[best - 1] : &ss->pts[best];
    const sample *hi = k + 1 < ss->per_curve ? &ss->pts[best + 1] : &ss->pts[best];
    const size_t c = ss->pts[best].curve;
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    double a = lo->s, b = hi->s;
    double sc = b - g * (b - a), sd = a + g * (b - a);
    double fc = curve_distance(ss->set, c, sc, x), fd = curve_distance(ss->set, c, sd, x);
    for (int it = 0; it < GOLDEN_ITER; ++it) {
        if (fc < fd) {
            b = sd;
            sd = sc;
            fd = fc;
            sc = b - g * (b - a);
            fc = curve_distance(ss->set, c, sc, x);
        } else {
            a = sc;
            sc = sd;
            fc = fd;
            sd = a + g * (b - a);
            fd = curve_distance(ss->set, c, sd, x);
        }
    }
    return fmin(best_d, fmin(fc, fd));
}

int pcb_measure_deviation(const pcb_exact *ex, const pcb_curve_set *result,
                          size_t samples_per_curve, pcb_deviation *out)
{
    sampled_set ss;
    if (samples_per_curve < 2)
        samples_per_curve = 2;
    if (sample_curves(result, samples_per_curve, &ss) != 0) {
        free(ss.pts);
        return -1;
    }
    double r2e = 0.0, e2r = 0.0;
    for (size_t i = 0; i < ss.n; ++i)
        r2e = fmax(r2e, pcb_exact_distance(ex, ss.pts[i].p));
    for (size_t i = 0; i < ex->n; ++i)
        if (ex->pts[i].primary)
            e2r = fmax(e2r, set_distance(&ss, ex->pts[i].p));
    free(ss.pts);
    out->result_to_exact = r2e;
    out->exact_to_result = e2r;
    out->hausdorff = fmax(r2e, e2r);
    return 0;
}

projcurve_status pcb_result_curves_init(projcurve_context *ctx, const projcurve_result *result,
                                        pcb_result_curves *rc)
{
    rc->n = 0;
    const size_t n = projcurve_result_branch_count(result);
    rc->curves = n ? calloc(n, sizeof *rc->curves) : NULL;
    if (n && !rc->curves)
        return PROJCURVE_ERR_NO_MEMORY;
    for (size_t b = 0; b < n; ++b) {
        const projcurve_status st = projcurve_result_branch_curve(ctx, result, b, &rc->curves[b]);
        if (st != PROJCURVE_OK) {
            pcb_result_curves_free(rc);
            return st;
        }
        rc->n = b + 1;
    }
    return PROJCURVE_OK;
}

/* Adds c's pole count to *poles and raises *degree to its degree. */
static void count_poles(const projcurve_curve *c, double *poles, double *degree)
{
    int d = 0;
    size_t n = 0;
    if (projcurve_curve_nurbs_info(NULL, c, &d, &n, NULL, NULL) != PROJCURVE_OK)
        return;
    if (poles)
        *poles += (double)n;
    if (degree)
        *degree = fmax(*degree, (double)d);
}

projcurve_status pcb_result_compact_curves_init(projcurve_context *ctx,
                                                const projcurve_result *result,
                                                pcb_result_curves *rc, double *poles,
                                                double *degree, double *pcurve_poles,
                                                double *pcurve_degree)
{
    double *outs[4] = {poles, degree, pcurve_poles, pcurve_degree};
    for (int k = 0; k < 4; ++k)
        if (outs[k])
            *outs[k] = 0.0;
    rc->n = 0;
    const size_t n = projcurve_result_branch_count(result);
    rc->curves = n ? calloc(n, sizeof *rc->curves) : NULL;
    if (n && !rc->curves)
        return PROJCURVE_ERR_NO_MEMORY;
    for (size_t b = 0; b < n; ++b) {
        projcurve_status st = projcurve_result_branch_compact_curve(NULL, result, b,
                                                                    &rc->curves[b]);
        if (st != PROJCURVE_OK)
            st = projcurve_result_branch_curve(ctx, result, b, &rc->curves[b]);
        if (st != PROJCURVE_OK) {
            pcb_result_curves_free(rc);
            return st;
        }
        rc->n = b + 1;
        count_poles(rc->curves[b], poles, degree);
        projcurve_curve *q = NULL;
        if (projcurve_result_branch_compact_pcurve(NULL, result, b, &q) == PROJCURVE_OK)
            count_poles(q, pcurve_poles, pcurve_degree);
        projcurve_curve_destroy(q);
    }
    return PROJCURVE_OK;
}

void pcb_result_curves_free(pcb_result_curves *rc)
{
    for (size_t i = 0; i < rc->n; ++i)
        projcurve_curve_destroy(rc->curves[i]);
    free(rc->curves);
    rc->curves = NULL;
    rc->n = 0;
}

static int result_domain(void *user, size_t i, double range[2])
{
    const pcb_result_curves *rc = user;
    return projcurve_curve_domain(NULL, rc->curves[i], &range[0], &range[1]) == PROJCURVE_OK ? 0
                                                                                            : -1;
}

static int result_eval(void *user, size_t i, double s, double p[3])
{
    const pcb_result_curves *rc = user;
    return projcurve_curve_eval(NULL, rc->curves[i], s, 0, p) == PROJCURVE_OK ? 0 : -1;
}

pcb_curve_set pcb_result_curve_set(pcb_result_curves *rc)
{
    pcb_curve_set set = {rc->n, result_domain, result_eval, rc};
    return set;
}
