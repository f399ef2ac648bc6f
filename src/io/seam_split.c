/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Splitting a branch's curves at its seams (io/seam_split.h). A clamped
 * B-spline of degree p split at an interior t: insert t until it has
 * multiplicity p (Boehm, The NURBS Book eq. 5.15, on the homogeneous
 * poles, so exact for rational curves up to rounding); the pole before the
 * run of t is then the curve's point at t, the last pole of the part
 * before and the first of the part after, and each part is clamped by one
 * more t. Both parts evaluate as the curve did over their ranges.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "io/seam_split.h"

/* Where a seam is taken at a knot rather than beside it: a knot this close
 * (relative to the domain's length) is the seam's (the joined forms put a
 * knot at each jump's t; a second knot beside it would only add a sliver). */
#define PC_SEAM_SPLIT_SNAP 1e-12
/* How far the domains of a branch's two forms may differ (relative to the
 * length): the pieces' pcurves joined end where the last piece's range
 * does, which the joining rounds (1.1e-12 seen on a unit range). */
#define PC_SEAM_SPLIT_SAME_DOMAIN 1e-9

/* A working copy of a clamped curve: degree p, n poles of 4 doubles. */
typedef struct split_work {
    int p;
    size_t n;
    double *knots, *cw;
} split_work;

/* a + b, or 0 when it overflows (which every caller then reports). */
static size_t size_add(size_t a, size_t b) { return a > SIZE_MAX - b ? 0 : a + b; }

static void work_free(split_work *w)
{
    free(w->knots);
    free(w->cw);
    w->knots = w->cw = NULL;
}

static projcurve_status work_of(projcurve_context *ctx, const pc_nurbs_curve *c, size_t extra,
                                split_work *w)
{
    const size_t n_knots = c->n_ctrl + (size_t)c->degree + 1;
    const size_t cap_poles = size_add(c->n_ctrl, extra);
    const size_t cap_knots = size_add(n_knots, extra);
    if (cap_poles == 0 || cap_knots == 0 || pc_size_mul(cap_poles, 4 * sizeof(double)) == 0)
        return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW, "a curve too large to split at its seams");
    w->p = c->degree;
    w->n = c->n_ctrl;
    w->knots = malloc(cap_knots * sizeof(double));
    w->cw = malloc(cap_poles * 4 * sizeof(double));
    if (w->knots == NULL || w->cw == NULL) {
        work_free(w);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory splitting at a seam");
    }
    memcpy(w->knots, c->knots, n_knots * sizeof(double));
    memcpy(w->cw, c->cw, 4 * c->n_ctrl * sizeof(double));
    return PROJCURVE_OK;
}

static size_t work_multiplicity(const split_work *w, double t)
{
    size_t m = 0;
    for (size_t i = 0; i < w->n + (size_t)w->p + 1; ++i)
        m += w->knots[i] == t;
    return m;
}

/* t, or the knot within the snap distance of it. */
static double snapped(const split_work *w, double t, double len)
{
    for (size_t i = 0; i < w->n + (size_t)w->p + 1; ++i)
        if (fabs(w->knots[i] - t) <= PC_SEAM_SPLIT_SNAP * len)
            return w->knots[i];
    return t;
}

/* Inserts t once (U[p] < t < U[n]); the arrays have room for one more. */
static void insert_once(split_work *w, double t)
{
    const size_t p = (size_t)w->p, n = w->n, n_knots = n + p + 1;
    double *U = w->knots, *P = w->cw;
    size_t k = p; /* the last index with U[k] <= t */
    while (k + 1 < n_knots && U[k + 1] <= t)
        ++k;
    /* Q_i = P_{i-1} for i > k, from the end down; then the blended ones
     * from k down to k - p + 1 (each reads P_i and P_{i-1}, still old). */
    for (size_t i = n; i > k; --i)
        memcpy(P + 4 * i, P + 4 * (i - 1), 4 * sizeof(double));
    for (size_t i = k; i + p > k; --i) {
        const double a = (t - U[i]) / (U[i + p] - U[i]);
        for (int c = 0; c < 4; ++c)
            P[4 * i + c] = a * P[4 * i + c] + (1.0 - a) * P[4 * (i - 1) + c];
        if (i == 0)
            break;
    }
    memmove(U + k + 2, U + k + 1, (n_knots - k - 1) * sizeof(double));
    U[k + 1] = t;
    w->n = n + 1;
}

/* The first index of t's run of knots. */
static size_t run_start(const split_work *w, double t)
{
    size_t i = 0;
    while (w->knots[i] != t)
        ++i;
    return i;
}

/* Segment j of m splits at ts (each of multiplicity p in w) into out. */
static projcurve_status cut(projcurve_context *ctx, const split_work *w, const double *ts,
                            size_t m, size_t j, pc_nurbs_curve *out)
{
    const size_t p = (size_t)w->p;
    const size_t first = j > 0 ? run_start(w, ts[j - 1]) - 1 : 0;
    const size_t last = j < m ? run_start(w, ts[j]) - 1 : w->n - 1;
    const size_t n = last - first + 1;
    /* knots: [t_{j-1}] U[first + 1 .. last + p] [t_j] (U[0..] at the start,
     * U[..n + p] at the end) */
    const size_t lo = j > 0 ? first + 1 : 0, hi = j < m ? last + p : w->n + p;
    memset(out, 0, sizeof *out);
    out->knots = malloc((n + p + 1) * sizeof(double));
    out->cw = malloc(4 * n * sizeof(double));
    if (out->knots == NULL || out->cw == NULL) {
        free(out->knots);
        free(out->cw);
        memset(out, 0, sizeof *out);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory splitting at a seam");
    }
    size_t k = 0;
    if (j > 0)
        out->knots[k++] = ts[j - 1];
    memcpy(out->knots + k, w->knots + lo, (hi - lo + 1) * sizeof(double));
    k += hi - lo + 1;
    if (j < m)
        out->knots[k++] = ts[j];
    memcpy(out->cw, w->cw + 4 * first, 4 * n * sizeof(double));
    out->degree = w->p;
    out->n_ctrl = n;
    out->t0 = out->knots[p];
    out->t1 = out->knots[n];
    out->rational = 0;
    for (size_t i = 0; i < n; ++i)
        out->rational |= out->cw[4 * i + 3] != 1.0;
    return PROJCURVE_OK;
}

/* Splits c at the m values ts (strictly inside its domain, increasing)
 * into out[0..m] (the .pcurve or .curve member by `which`). */
static projcurve_status split_curve(projcurve_context *ctx, const pc_nurbs_curve *c,
                                    const double *ts_in, size_t m, int which,
                                    pc_seam_segment *out)
{
    split_work w = {0};
    const size_t extra = pc_size_mul(m, (size_t)c->degree);
    double *ts = malloc((m + 1) * sizeof *ts);
    projcurve_status st = ts == NULL ? pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY,
                                               "out of memory splitting at a seam")
                                     : work_of(ctx, c, extra, &w);
    if (st != PROJCURVE_OK) {
        free(ts);
        return st;
    }
    const double len = c->t1 - c->t0;
    for (size_t k = 0; k < m; ++k) {
        ts[k] = snapped(&w, ts_in[k], len);
        /* at most p insertions per seam: the room work_of made */
        for (size_t s = work_multiplicity(&w, ts[k]); s < (size_t)w.p; ++s)
            insert_once(&w, ts[k]);
    }
    for (size_t j = 0; st == PROJCURVE_OK && j <= m; ++j)
        st = cut(ctx, &w, ts, m, j, which ? &out[j].curve : &out[j].pcurve);
    work_free(&w);
    free(ts);
    return st;
}

/* Puts a coordinate outside [lo, hi] by rounding (within the snap share of
 * the width) on the edge. */
static double onto_edge(double x, double lo, double hi)
{
    const double slack = PC_SEAM_SPLIT_SNAP * (hi - lo);
    if (x < lo && x >= lo - slack)
        return lo;
    if (x > hi && x <= hi + slack)
        return hi;
    return x;
}

static void shift_into_domain(pc_nurbs_curve *q, const double shift[2], const double domain[4])
{
    for (size_t i = 0; i < q->n_ctrl; ++i) {
        double *P = q->cw + 4 * i;
        P[0] += shift[0] * P[3];
        P[1] += shift[1] * P[3];
        if (i == 0 || i + 1 == q->n_ctrl) { /* the ends, which the curve passes */
            P[0] = onto_edge(P[0] / P[3], domain[0], domain[1]) * P[3];
            P[1] = onto_edge(P[1] / P[3], domain[2], domain[3]) * P[3];
        }
    }
}

void pc_seam_segments_free(pc_seam_segment *segments, size_t n)
{
    if (segments == NULL)
        return;
    for (size_t i = 0; i < n; ++i) {
        free(segments[i].pcurve.knots);
        free(segments[i].pcurve.cw);
        free(segments[i].curve.knots);
        free(segments[i].curve.cw);
    }
    free(segments);
}

projcurve_status pc_seam_split(projcurve_context *ctx, const pc_nurbs_curve *pcurve,
                               const pc_nurbs_curve *curve, const pc_seam_record *seams,
                               size_t n_seams, const double domain[4], pc_seam_segment **out,
                               size_t *n_out)
{
    *out = NULL;
    *n_out = 0;
    const double t0 = pcurve->t0, t1 = pcurve->t1, margin = PC_SEAM_SPLIT_SNAP * (t1 - t0);
    const double same = PC_SEAM_SPLIT_SAME_DOMAIN * (t1 - t0);
    if (curve != NULL && !(fabs(curve->t0 - t0) <= same && fabs(curve->t1 - t1) <= same))
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "a pcurve over [%.17g, %.17g] and a 3D curve over [%.17g, %.17g] do "
                       "not split at the same seams",
                       t0, t1, curve->t0, curve->t1);
    if (size_add(n_seams, 1) == 0 || n_seams > SIZE_MAX / (2 * sizeof(double)) - 1)
        return pc_fail(ctx, PROJCURVE_ERR_OVERFLOW, "%zu seams overflow", n_seams);
    pc_seam_segment *seg = calloc(n_seams + 1, sizeof *seg);
    double *ts = malloc(size_add(n_seams, 1) * sizeof *ts);
    if (seg == NULL || ts == NULL) {
        free(seg);
        free(ts);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory splitting at seams");
    }
    /* the jumps inside the domain, with the shift of the segment after each */
    double (*shift)[2] = calloc(size_add(n_seams, 1), sizeof *shift);
    size_t m = 0;
    double sum[2] = {0.0, 0.0};
    for (size_t k = 0; shift != NULL && k < n_seams; ++k) {
        sum[0] += seams[k].du;
        sum[1] += seams[k].dv;
        if (seams[k].t > t0 + margin && seams[k].t < t1 - margin &&
            (m == 0 || seams[k].t > ts[m - 1] + margin)) {
            ts[m++] = seams[k].t;
        }
        /* a jump at the domain's ends or beside the last changes the shift
         * of the segment it begins (or, before t0, the first's) */
        shift[m][0] = sum[0];
        shift[m][1] = sum[1];
    }
    projcurve_status st = shift == NULL ? pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY,
                                                  "out of memory splitting at seams")
                                        : split_curve(ctx, pcurve, ts, m, 0, seg);
    if (st == PROJCURVE_OK && curve != NULL)
        st = split_curve(ctx, curve, ts, m, 1, seg);
    for (size_t j = 0; st == PROJCURVE_OK && j <= m; ++j)
        shift_into_domain(&seg[j].pcurve, shift[j], domain);
    free(ts);
    free(shift);
    if (st != PROJCURVE_OK) {
        pc_seam_segments_free(seg, n_seams + 1);
        return st;
    }
    *out = seg;
    *n_out = m + 1;
    return PROJCURVE_OK;
}
