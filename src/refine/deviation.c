/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Hausdorff control ([SY13] s2 step 3, s4; the method of its ref. [13]):
 * the distance between the composed piece C(s) = S(uv(s)) of a segment and
 * the exact projection Q(t) = S(q(t)) over the same parameter range.
 *
 * Both curves share their end points, so the distance profile
 * d(t) = dist(Q(t), C) vanishes at both ends and, for a short segment, is a
 * smooth bump. It is sampled at PC_DEVIATION_SAMPLES (straight pcurves) or
 * PC_DEVIATION_SAMPLES_CUBIC (cubic ones: b->in_cubic) interior values of t
 * (each: the exact point by the corrector, then its foot on C by Newton),
 * and the largest sample is refined by one parabolic step. The traced
 * vertices inside the segment are exact points too and are measured as well:
 * they catch features narrower than the sample spacing. The farthest point
 * is where the segment is split when the bound is not met.
 */
#include <math.h>

#include "common/compiler.h"
#include "compose/compose.h"
#include "refine/refine_internal.h"

/* Interior samples: 3 for a straight pcurve (its error is a quadratic
 * bump), 7 for a cubic one (a quartic bump, skewed by the next term), as
 * the verification pass takes them (verify_piece.c, 2 d + 1): with 3, a
 * cubic piece whose profile peaked between them was accepted at 0.9 eps_D
 * and failed verification at 1.03 eps_D, and its branch was lost
 * (bearing.iges surface 196, the sweep's lifted orthogonal curve). */
#define PC_DEVIATION_SAMPLES 3
#define PC_DEVIATION_SAMPLES_CUBIC 7
#define PC_DEVIATION_GUIDE_MAX 4
/* A traced vertex whose distance to the chord-parameter point is below this
 * fraction of the bound needs no foot search. */
#define PC_DEVIATION_BOUND_FIRST 0.5
/* The parabolic refinement only matters near the bound: a largest sample
 * below this fraction of it cannot hide a peak above it. */
#define PC_DEVIATION_REFINE_FROM 0.5
/* Newton on the foot parameter: bound, and when a step counts as converged.
 * The distance is stationary at the foot: an error e in s changes it by
 * about |C'|^2 e^2 / (2 d). A step whose image |C'| e is below
 * PC_FOOT_MOVE_REL d therefore leaves the distance within
 * PC_FOOT_MOVE_REL^2 / 2 = 5e-9 of itself (relative), and the absolute
 * PC_FOOT_STEP_TOL covers d = 0. */
#define PC_FOOT_MAX_ITER 12
#define PC_FOOT_STEP_TOL 1e-10
#define PC_FOOT_MOVE_REL 1e-4

int pc_refine_compose(const pc_bezier_patch *patch, const pc_rvertex *a, const pc_rvertex *b,
                      double *cw)
{
    const double uv0[2] = {a->u, a->v}, uv1[2] = {b->u, b->v};
    pc_compose_segment(patch, uv0, uv1, cw);
    return patch->deg_u + patch->deg_v;
}

/* C(s) alone, by de Casteljau. */
static pc_vec3 piece_point(int n, const double *cw, double s)
{
    double work[PC_PIECE_MAX_DEGREE + 1][4];
    const double r = 1.0 - s;
    for (int i = 0; i < n; ++i)
        for (int c = 0; c < 4; ++c)
            work[i][c] = r * cw[4 * i + c] + s * cw[4 * (i + 1) + c];
    for (int level = n - 1; level > 0; --level)
        for (int i = 0; i < level; ++i)
            for (int c = 0; c < 4; ++c)
                work[i][c] = r * work[i][c] + s * work[i + 1][c];
    return vec3(work[0][0] / work[0][3], work[0][1] / work[0][3], work[0][2] / work[0][3]);
}

/* C, C', C'' at s for the degree n (a constant in the specialised callers):
 * de Casteljau down to the last three points, then their quadratic. */
static PC_ALWAYS_INLINE void piece_eval(const int n, const double *cw, double s, pc_vec3 out[3])
{
    double work[PC_PIECE_MAX_DEGREE + 1][4];
    for (int i = 0; i <= n; ++i)
        for (int c = 0; c < 4; ++c)
            work[i][c] = cw[4 * i + c];
    const double r = 1.0 - s;
    /* de Casteljau down to the last three points (degree 2 in s) */
    for (int level = n; level > 2; --level)
        for (int i = 0; i < level; ++i)
            for (int c = 0; c < 4; ++c)
                work[i][c] = r * work[i][c] + s * work[i + 1][c];
    double h[4], d1[4], d2[4];
    const double nn = (double)n;
    for (int c = 0; c < 4; ++c) {
        const double l0 = r * work[0][c] + s * work[1][c];
        const double l1 = r * work[1][c] + s * work[2][c];
        h[c] = r * l0 + s * l1;
        d1[c] = nn * (l1 - l0);
        d2[c] = nn * (nn - 1.0) * (work[2][c] - 2.0 * work[1][c] + work[0][c]);
    }
    /* quotient rule: C = A / w */
    const double w = h[3];
    const pc_vec3 p = vec3(h[0] / w, h[1] / w, h[2] / w);
    const pc_vec3 dp = vec3_scale(vec3_axpy(vec3(d1[0], d1[1], d1[2]), -d1[3], p), 1.0 / w);
    const pc_vec3 a2 = vec3(d2[0], d2[1], d2[2]);
    const pc_vec3 ddp =
        vec3_scale(vec3_axpy(vec3_axpy(a2, -2.0 * d1[3], dp), -d2[3], p), 1.0 / w);
    out[0] = p;
    out[1] = dp;
    out[2] = ddp;
}

/* The usual degrees, for constant-degree loops: straight pieces (p + q) on
 * bicubic and biquintic patches, and cubic pcurves on them, 3 (p + q). */
#define PC_PIECE_EVAL_FIXED(N)                                                               \
    static PC_HOT_CLONES void piece_eval_##N(const double *cw, double s, pc_vec3 out[3])     \
    {                                                                                        \
        piece_eval(N, cw, s, out);                                                           \
    }
PC_PIECE_EVAL_FIXED(6)
PC_PIECE_EVAL_FIXED(10)
PC_PIECE_EVAL_FIXED(18)
PC_PIECE_EVAL_FIXED(30)

void pc_piece_eval(int n, const double *cw, double s, pc_vec3 out[3])
{
    switch (n) {
    case 6: piece_eval_6(cw, s, out); break;
    case 10: piece_eval_10(cw, s, out); break;
    case 18: piece_eval_18(cw, s, out); break;
    case 30: piece_eval_30(cw, s, out); break;
    default: piece_eval(n, cw, s, out); break;
    }
}

double pc_piece_distance(int n, const double *cw, pc_vec3 x, double s0, double *s_foot)
{
    double s = s0 < 0.0 ? 0.0 : (s0 > 1.0 ? 1.0 : s0);
    double best = INFINITY, best_s = s;
    for (int iter = 0; iter < PC_FOOT_MAX_ITER; ++iter) {
        pc_vec3 c[3];
        pc_piece_eval(n, cw, s, c);
        const pc_vec3 diff = vec3_sub(c[0], x);
        const double d = vec3_norm(diff);
        if (d < best)
            best = d, best_s = s;
        /* f(s) = (C - x).C' = 0; f' = C'.C' + (C - x).C'' */
        const double f = vec3_dot(diff, c[1]);
        double fp = vec3_dot(c[1], c[1]) + vec3_dot(diff, c[2]);
        if (!(fp > 0.0)) /* not convex here: a gradient step instead */
            fp = vec3_dot(c[1], c[1]);
        if (!(fp > 0.0))
            break;
        double next = s - f / fp;
        next = next < 0.0 ? 0.0 : (next > 1.0 ? 1.0 : next);
        const double step = fabs(next - s);
        s = next;
        if (step <= PC_FOOT_STEP_TOL || step * vec3_norm(c[1]) <= PC_FOOT_MOVE_REL * d)
            break;
    }
    pc_vec3 c[3];
    pc_piece_eval(n, cw, s, c);
    const double d = vec3_dist(c[0], x);
    if (d < best)
        best = d, best_s = s;
    if (s_foot != NULL)
        *s_foot = best_s;
    return best;
}

/* dist(Q(t), C) at the fraction tau of the segment; -1 when the exact point
 * is not available. */
static double profile(pc_refiner *r, int n, const double *cw, const pc_rvertex *a,
                      const pc_rvertex *b, double tau)
{
    pc_rvertex q;
    if (!pc_refine_exact_point(r, a, b, a->t + tau * (b->t - a->t), &q))
        return -1.0;
    const pc_vec3 x = pc_refine_surface_point(r, q.u, q.v);
    /* foot guess: projection of q on the chord in (u, v) */
    const double du = b->u - a->u, dv = b->v - a->v, len2 = du * du + dv * dv;
    const double s0 = len2 > 0.0 ? ((q.u - a->u) * du + (q.v - a->v) * dv) / len2 : tau;
    return pc_piece_distance(n, cw, x, s0, NULL);
}

/* Largest distance of the traced vertices strictly inside (a.t, b.t) from C:
 * exact points already, they catch features between the samples. A dense
 * trace (constant small parameter steps) would make this the cost of the
 * whole refinement, so at most PC_DEVIATION_GUIDE_MAX of them, evenly spread,
 * are measured. */
/* First guide index >= from whose t is >= t. */
static size_t first_at_or_after(const pc_refiner *r, size_t from, double t)
{
    size_t lo = from, hi = r->n_guide;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (r->guide[mid].t < t)
            lo = mid + 1;
        else
            hi = mid;
    }
    return lo;
}

static double guide_deviation(pc_refiner *r, int n, const double *cw, const pc_rvertex *a,
                              const pc_rvertex *b, double limit, double *t_far)
{
    const double lo = a->t < b->t ? a->t : b->t, hi = a->t < b->t ? b->t : a->t;
    const double du = b->u - a->u, dv = b->v - a->v, len2 = du * du + dv * dv;
    double worst = 0.0;
    size_t first = pc_refine_guide_index(r, lo);
    while (first < r->n_guide && !(r->guide[first].t > lo))
        ++first;
    const size_t end = first_at_or_after(r, first, hi); /* inside: [first, end) */
    const size_t count = end - first;
    const size_t stride = count > PC_DEVIATION_GUIDE_MAX ? count / PC_DEVIATION_GUIDE_MAX : 1;
    for (size_t k = first; k < end; k += stride) {
        const pc_rvertex *g = &r->guide[k];
        const pc_vec3 x = pc_refine_surface_point(r, g->u, g->v);
        const double s0 = len2 > 0.0 ? ((g->u - a->u) * du + (g->v - a->v) * dv) / len2
                                     : (g->t - a->t) / (b->t - a->t);
        /* the point at the chord's parameter bounds the distance from above;
         * the foot is searched only when that bound is not small */
        double d = vec3_dist(piece_point(n, cw, s0 < 0.0 ? 0.0 : (s0 > 1.0 ? 1.0 : s0)), x);
        if (d > PC_DEVIATION_BOUND_FIRST * limit)
            d = pc_piece_distance(n, cw, x, s0, NULL);
        if (d > worst)
            worst = d, *t_far = g->t;
    }
    return worst;
}

double pc_refine_deviation(pc_refiner *r, int n, const double *cw, const pc_rvertex *a,
                           const pc_rvertex *b, double limit, double *t_far)
{
    const int m = b->in_cubic ? PC_DEVIATION_SAMPLES_CUBIC : PC_DEVIATION_SAMPLES;
    const double h = 1.0 / (m + 1);
    double d[PC_DEVIATION_SAMPLES_CUBIC + 2];
    d[0] = d[m + 1] = 0.0;
    int k_max = 1;
    *t_far = 0.5 * (a->t + b->t);
    for (int k = 1; k <= m; ++k) {
        d[k] = profile(r, n, cw, a, b, k * h);
        if (d[k] < 0.0)
            return INFINITY;
        if (d[k] > limit) { /* the verdict is known: stop here */
            *t_far = a->t + k * h * (b->t - a->t);
            return d[k];
        }
        if (d[k] > d[k_max])
            k_max = k;
    }
    /* One parabolic step through the largest sample and its neighbours. */
    double tau_far = k_max * h, d_far = d[k_max];
    const double curv = d[k_max - 1] - 2.0 * d[k_max] + d[k_max + 1];
    if (curv < 0.0 && d_far > PC_DEVIATION_REFINE_FROM * limit) {
        double delta = 0.5 * h * (d[k_max - 1] - d[k_max + 1]) / curv;
        delta = delta < -h ? -h : (delta > h ? h : delta);
        const double tau = k_max * h + delta;
        const double dv = profile(r, n, cw, a, b, tau);
        if (dv < 0.0)
            return INFINITY;
        if (dv > d_far)
            d_far = dv, tau_far = tau;
    }
    *t_far = a->t + tau_far * (b->t - a->t);
    double t_guide = *t_far;
    const double d_guide = guide_deviation(r, n, cw, a, b, limit, &t_guide);
    if (d_guide > d_far)
        d_far = d_guide, *t_far = t_guide;
    return d_far;
}
