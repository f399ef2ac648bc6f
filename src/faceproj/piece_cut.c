/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Exact cuts of composed pieces and compact B-splines
 * (faceproj/piece_cut.h).
 */
#include "faceproj/piece_cut.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "common/vec.h"

/* Largest homogeneous dimension handled: 3D + weight. */
#define PC_CUT_MAX_DIM 4

/* De Casteljau in place on n + 1 points of dim doubles: afterwards left
 * holds the part [0, s], right the part [s, 1] (either may be NULL). */
static void de_casteljau(const double *pts, int n, int dim, double s, double *left,
                         double *right)
{
    double w[PC_CUT_MAX_DIM * PROJCURVE_MAX_PIECE_POINTS];
    memcpy(w, pts, (size_t)((n + 1) * dim) * sizeof *w);
    for (int d = 0; d < dim; ++d) {
        if (left)
            left[d] = w[d];
        if (right)
            right[n * dim + d] = w[n * dim + d];
    }
    for (int r = 1; r <= n; ++r) {
        for (int i = 0; i <= n - r; ++i)
            for (int d = 0; d < dim; ++d)
                w[i * dim + d] = (1.0 - s) * w[i * dim + d] + s * w[(i + 1) * dim + d];
        for (int d = 0; d < dim; ++d) {
            if (left)
                left[r * dim + d] = w[d];
            if (right)
                right[(n - r) * dim + d] = w[(n - r) * dim + d];
        }
    }
}

/* The part [s0, s1] of a Bezier curve: [0, s1] first, then of it [s0/s1, 1]. */
static void bezier_part(const double *pts, int n, int dim, double s0, double s1, double *out)
{
    double tmp[PC_CUT_MAX_DIM * PROJCURVE_MAX_PIECE_POINTS];
    if (s1 < 1.0)
        de_casteljau(pts, n, dim, s1, tmp, NULL);
    else
        memcpy(tmp, pts, (size_t)((n + 1) * dim) * sizeof *tmp);
    if (s0 > 0.0)
        de_casteljau(tmp, n, dim, s0 / s1, NULL, out);
    else
        memcpy(out, tmp, (size_t)((n + 1) * dim) * sizeof *out);
}

static void pcurve_eval(const pc_piece *p, double s, double uv[2], double duv[2])
{
    double l[2 * PROJCURVE_MAX_PCURVE_POINTS];
    de_casteljau(p->uv_ctrl, p->uv_degree, 2, s, l, NULL);
    uv[0] = l[2 * p->uv_degree];
    uv[1] = l[2 * p->uv_degree + 1];
    /* the derivative: degree times the last difference of the left part's
     * next-to-last level (the hodograph at s) */
    const int n = p->uv_degree;
    double w[2 * PROJCURVE_MAX_PCURVE_POINTS];
    memcpy(w, p->uv_ctrl, (size_t)(2 * (n + 1)) * sizeof *w);
    for (int r = 1; r < n; ++r)
        for (int i = 0; i <= n - r; ++i)
            for (int d = 0; d < 2; ++d)
                w[2 * i + d] = (1.0 - s) * w[2 * i + d] + s * w[2 * (i + 1) + d];
    duv[0] = n * (w[2] - w[0]);
    duv[1] = n * (w[3] - w[1]);
}

double pc_piece_cut_parameter(const pc_piece *piece, const pc_loop_samples *s, size_t which,
                              double t_cut, double tau)
{
    const double span = piece->t1 - piece->t0;
    const double guess = span != 0.0 ? fmin(1.0, fmax(0.0, (t_cut - piece->t0) / span)) : 0.5;
    const pc_piece_samples *ps = &s->pieces[which];
    double tau0, tau1;
    pc_curve2_domain(&s->face->loops[ps->loop].pieces[ps->piece].curve, &tau0, &tau1);
    double x = guess;
    for (int it = 0; it < PC_CUT_MAX_ITER; ++it) {
        double uv[2], duv[2], c[2], dc[2];
        pcurve_eval(piece, x, uv, duv);
        pc_loop_piece_eval(s, which, tau, c, dc);
        const double r[2] = {c[0] - uv[0], c[1] - uv[1]};
        if (hypot(r[0], r[1]) <= 1e-3 * s->face->tol_uv)
            return x;
        double d[2];
        if (!mat2_solve(duv[0], -dc[0], duv[1], -dc[1], r, d))
            return guess;
        x = fmin(1.0, fmax(0.0, x + d[0]));
        tau = fmin(tau1, fmax(tau0, tau + d[1]));
    }
    return guess;
}

double pc_piece_point_parameter(const pc_piece *piece, double t_cut, const double target[2])
{
    const double span = piece->t1 - piece->t0;
    double x = span != 0.0 ? fmin(1.0, fmax(0.0, (t_cut - piece->t0) / span)) : 0.5;
    for (int it = 0; it < PC_CUT_MAX_ITER; ++it) {
        double uv[2], duv[2];
        pcurve_eval(piece, x, uv, duv);
        const double n2 = duv[0] * duv[0] + duv[1] * duv[1];
        if (!(n2 > 0.0))
            break;
        const double dx = ((target[0] - uv[0]) * duv[0] + (target[1] - uv[1]) * duv[1]) / n2;
        const double nx = fmin(1.0, fmax(0.0, x + dx));
        if (fabs(nx - x) <= 1e-15)
            return nx;
        x = nx;
    }
    return x;
}

projcurve_status pc_piece_append_part(projcurve_context *ctx, pc_branch *b, const pc_piece *piece,
                                      double s0, double s1, double t0, double t1)
{
    const int n = piece->degree;
    /* zeroed: gcc -O1 cannot see that n >= 0 fills what bezier_part reads */
    double hw[4 * PROJCURVE_MAX_PIECE_POINTS] = {0}, part[4 * PROJCURVE_MAX_PIECE_POINTS];
    for (int i = 0; i <= n; ++i) {
        const double w = piece->weights[i];
        for (int d = 0; d < 3; ++d)
            hw[4 * i + d] = w * piece->ctrl[3 * i + d];
        hw[4 * i + 3] = w;
    }
    bezier_part(hw, n, 4, s0, s1, part);
    double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], weights[PROJCURVE_MAX_PIECE_POINTS];
    for (int i = 0; i <= n; ++i) {
        weights[i] = part[4 * i + 3];
        for (int d = 0; d < 3; ++d)
            ctrl[3 * i + d] = part[4 * i + d] / weights[i];
    }
    double uvc[2 * PROJCURVE_MAX_PCURVE_POINTS];
    bezier_part(piece->uv_ctrl, piece->uv_degree, 2, s0, s1, uvc);
    const int m = piece->uv_degree;
    const double uv[4] = {uvc[0], uvc[1], uvc[2 * m], uvc[2 * m + 1]};
    const projcurve_status st = pc_branch_add_piece(ctx, b, n, t0, t1, uv, ctrl, weights);
    if (st == PROJCURVE_OK)
        pc_branch_set_last_pcurve(b, m, uvc);
    return st;
}

/* ---- B-spline restriction ------------------------------------------------ */

typedef struct hspline {
    int p;
    size_t dim, n;   /* homogeneous dim per pole, poles */
    double *knots;   /* n + p + 1 */
    double *h;       /* n * dim */
} hspline;

static size_t multiplicity(const hspline *s, double t)
{
    size_t m = 0;
    for (size_t k = 0; k < s->n + (size_t)s->p + 1; ++k)
        m += s->knots[k] == t;
    return m;
}

/* Inserts t once (The NURBS Book A5.1, r = 1); t inside the domain and
 * of multiplicity below p. */
static projcurve_status insert_once(projcurve_context *ctx, hspline *s, double t)
{
    const size_t p = (size_t)s->p, n = s->n, nk = n + p + 1, dim = s->dim;
    size_t k = p;
    while (k + 1 < n && s->knots[k + 1] <= t)
        ++k;
    double *knots = malloc((nk + 1) * sizeof *knots);
    double *h = malloc((n + 1) * dim * sizeof *h);
    if (knots == NULL || h == NULL) {
        free(knots);
        free(h);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory cutting a compact curve");
    }
    memcpy(knots, s->knots, (k + 1) * sizeof *knots);
    knots[k + 1] = t;
    memcpy(knots + k + 2, s->knots + k + 1, (nk - k - 1) * sizeof *knots);
    for (size_t i = 0; i <= n; ++i) {
        double *q = h + i * dim;
        if (i + p <= k) {
            memcpy(q, s->h + i * dim, dim * sizeof *q);
        } else if (i > k) {
            memcpy(q, s->h + (i - 1) * dim, dim * sizeof *q);
        } else {
            const double den = s->knots[i + p] - s->knots[i];
            const double a = den > 0.0 ? (t - s->knots[i]) / den : 0.0;
            for (size_t d = 0; d < dim; ++d)
                q[d] = a * s->h[i * dim + d] + (1.0 - a) * s->h[(i - 1) * dim + d];
        }
    }
    free(s->knots);
    free(s->h);
    s->knots = knots;
    s->h = h;
    s->n = n + 1;
    return PROJCURVE_OK;
}

static projcurve_status raise_to_degree(projcurve_context *ctx, hspline *s, double t)
{
    const double lo = s->knots[s->p], hi = s->knots[s->n];
    if (!(t > lo && t < hi))
        return PROJCURVE_OK;
    projcurve_status st = PROJCURVE_OK;
    /* bounded: each pass adds one to the multiplicity, at most p passes */
    for (size_t m = multiplicity(s, t); st == PROJCURVE_OK && m < (size_t)s->p; ++m)
        st = insert_once(ctx, s, t);
    return st;
}

static projcurve_status to_hspline(projcurve_context *ctx, const pc_bspline *in, hspline *s)
{
    s->p = in->degree;
    s->n = in->n_poles;
    s->dim = (size_t)in->dim + 1;
    const size_t nk = s->n + (size_t)s->p + 1;
    s->knots = malloc(nk * sizeof *s->knots);
    s->h = malloc(s->n * s->dim * sizeof *s->h);
    if (s->knots == NULL || s->h == NULL) {
        free(s->knots);
        free(s->h);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory cutting a compact curve");
    }
    memcpy(s->knots, in->knots, nk * sizeof *s->knots);
    for (size_t i = 0; i < s->n; ++i) {
        const double w = in->weights ? in->weights[i] : 1.0;
        for (size_t d = 0; d + 1 < s->dim; ++d)
            s->h[i * s->dim + d] = w * in->poles[i * (size_t)in->dim + d];
        s->h[i * s->dim + s->dim - 1] = w;
    }
    return PROJCURVE_OK;
}

projcurve_status pc_bspline_restrict(projcurve_context *ctx, const pc_bspline *in, double a,
                                     double b, pc_bspline *out)
{
    memset(out, 0, sizeof *out);
    out->degree = in->degree;
    out->dim = in->dim;
    if (in->n_poles == 0)
        return PROJCURVE_OK;
    hspline s;
    projcurve_status st = to_hspline(ctx, in, &s);
    if (st != PROJCURVE_OK)
        return st;
    const size_t p = (size_t)s.p;
    a = fmax(a, s.knots[p]);
    b = fmin(b, s.knots[s.n]);
    st = raise_to_degree(ctx, &s, a);
    if (st == PROJCURVE_OK)
        st = raise_to_degree(ctx, &s, b);
    if (st != PROJCURVE_OK || !(a < b)) {
        free(s.knots);
        free(s.h);
        return st;
    }
    size_t r = p; /* last index with knots[r] == a (a >= knots[p]) */
    while (r + 1 < s.n && s.knots[r + 1] <= a)
        ++r;
    size_t f = s.n; /* first index > p with knots[f] == b */
    while (f > r + 1 && s.knots[f - 1] >= b)
        --f;
    const size_t first = r - p, n_out = f - r + p;
    out->n_poles = n_out;
    out->knots = malloc((n_out + p + 1) * sizeof *out->knots);
    out->poles = malloc(n_out * (size_t)in->dim * sizeof *out->poles);
    out->weights = in->weights ? malloc(n_out * sizeof *out->weights) : NULL;
    if (out->knots == NULL || out->poles == NULL || (in->weights && out->weights == NULL)) {
        pc_bspline_free(out);
        free(s.knots);
        free(s.h);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory cutting a compact curve");
    }
    out->knots[0] = a;
    memcpy(out->knots + 1, s.knots + r - p + 1, (n_out + p - 1) * sizeof *out->knots);
    out->knots[n_out + p] = b;
    for (size_t i = 0; i < n_out; ++i) {
        const double *h = s.h + (first + i) * s.dim;
        const double w = h[s.dim - 1];
        for (size_t d = 0; d + 1 < s.dim; ++d)
            out->poles[i * (size_t)in->dim + d] = h[d] / w;
        if (out->weights)
            out->weights[i] = w;
    }
    free(s.knots);
    free(s.h);
    return PROJCURVE_OK;
}
