/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Loop crossings the polyline test misses, found where the side of the
 * loops changes along the exact projection (faceproj/loop_crossing.h,
 * pc_loop_crossings_by_side).
 *
 * Between two consecutive crossings a branch stays on one side of the
 * loops: IN or OUT, ON within the face's tolerance band. The samples are
 * the exact projection (the corrector from the polyline's guess) at the t
 * of each polyline vertex and at the middle of each segment (where a chord
 * inside a loop hides a pcurve bulging past it). Not the vertices as they
 * are: those inside a cubic pcurve piece lie on it but at a t of their
 * own (the piece's parameter mapped linearly): on linkrods.step one lies
 * 0.07 in u past a crossing that the projection reaches 1.3e-5 later in
 * t, so its side does not belong to its t. Two samples of one stretch on
 * opposite sides (IN and OUT: ON decides nothing) have a crossing between
 * them that the polyline did not show: bisection on the side brings it
 * into the ON band, the loop piece nearest to that point and the Newton of
 * pc_loop_hit_refine place it. Only a
 * crossing Newton brings within PC_CROSSING_TOL is added: one it cannot
 * place (the corrector failing, a branch running along the loop) leaves
 * the stretch as it was.
 *
 * Across a seam jump of the branch the polyline runs from one side of the
 * domain to the other (its segment there is no part of the pcurve) and a
 * point on the seam may classify either way: the walk takes no sample
 * within PC_SIDE_JUMP_T of a jump nor on a segment across one, and starts
 * afresh after it.
 */
#include <math.h>

#include "common/array.h"
#include "common/error.h"
#include "faceproj/loop_crossing.h"

/* Bisection steps on the side: each halves the bracket in t; the band is
 * reached long before 2^-60 of it (else the last midpoint is the guess). */
#define PC_SIDE_BISECTIONS 60

/* How near a jump's t a sample is left out, relative to the polyline's t
 * range: the two sides of a jump place it to the tracers' resolution,
 * ~1e-10 of the curve's domain (docs/seams.md). */
#define PC_SIDE_JUMP_T 1e-8

/* 1 when a jump of seams lies in [a - eps, b + eps]. */
static int near_jump(const pc_seam_record *seams, size_t n_seams, double a, double b, double eps)
{
    for (size_t k = 0; k < n_seams; ++k)
        if (seams[k].t >= a - eps && seams[k].t <= b + eps)
            return 1;
    return 0;
}

/* (u, v) of the polyline at t by linear interpolation (t monotone along
 * it, increasing or decreasing; n >= 2): the corrector's guess. The
 * segment by bisection: the first i with t at or before vertex i + 1
 * (the last segment for t beyond the end), as a linear scan would pick. */
static void poly_guess(const double *poly, size_t n, double t, double uv[2])
{
    const int up = poly[3 * (n - 1)] >= poly[0];
    size_t lo = 0, hi = n - 2;
    while (lo < hi) {
        const size_t mid = lo + (hi - lo) / 2;
        if (up ? poly[3 * (mid + 1)] < t : poly[3 * (mid + 1)] > t)
            lo = mid + 1;
        else
            hi = mid;
    }
    const size_t i = lo;
    const double *a = poly + 3 * i, *c = poly + 3 * (i + 1 < n ? i + 1 : i);
    const double span = c[0] - a[0];
    const double f = span != 0.0 ? fmin(1.0, fmax(0.0, (t - a[0]) / span)) : 0.0;
    uv[0] = a[1] + f * (c[1] - a[1]);
    uv[1] = a[2] + f * (c[2] - a[2]);
}

/* The side of the projection's point at t (ON where the corrector fails:
 * undecided), its (u, v) in uv. */
static pc_where side_at(const pc_loop_samples *s, const pc_projector *proj, const double *poly,
                        size_t n, double t, double uv[2])
{
    poly_guess(poly, n, t, uv);
    if (!pc_projection_at(proj, t, uv))
        return PC_ON;
    return pc_classify(&s->face->cls, uv[0], uv[1]);
}

/* The crossing between t_a (side w_a) and t_b (the other side), t_a < t_b:
 * 1 with *h when Newton placed it. */
static int locate(const pc_loop_samples *s, const pc_projector *proj, const double *poly,
                  size_t n, double t_a, pc_where w_a, double t_b, pc_loop_hit *h)
{
    double lo = t_a, hi = t_b, m = 0.5 * (lo + hi), uv[2];
    for (int it = 0; it < PC_SIDE_BISECTIONS; ++it) {
        m = 0.5 * (lo + hi);
        const pc_where w = side_at(s, proj, poly, n, m, uv);
        if (w == PC_ON || m <= lo || m >= hi)
            break;
        if (w == w_a)
            lo = m;
        else
            hi = m;
    }
    size_t which = 0;
    double tau = 0.0;
    if (!isfinite(pc_loop_samples_nearest(s, uv, &which, &tau)))
        return 0;
    *h = (pc_loop_hit){.t = m, .tau = tau, .uv = {uv[0], uv[1]}, .which = which, .refined = 0};
    pc_loop_hit_refine(s, proj, t_a, t_b, h);
    return h->refined && h->t > t_a && h->t < t_b;
}

/* The walk over the samples in increasing t: the last sample on a side
 * (IN or OUT) since the last crossing passed. */
typedef struct side_walk {
    const pc_loop_hits *hits;
    size_t next; /* first crossing not yet passed */
    int have;    /* 1: t, w hold a sample of the current stretch */
    double t;
    pc_where w;
} side_walk;

static projcurve_status visit(projcurve_context *ctx, const pc_loop_samples *s,
                              const pc_projector *proj, const double *poly, size_t n,
                              side_walk *sw, size_t end, pc_loop_hits *hits, double t,
                              pc_where w)
{
    while (sw->next < end && sw->hits->items[sw->next].t <= t) {
        ++sw->next; /* a crossing passed: a new stretch */
        sw->have = 0;
    }
    if (w == PC_ON)
        return PROJCURVE_OK;
    if (sw->have && w != sw->w && t > sw->t) {
        pc_loop_hit h;
        if (locate(s, proj, poly, n, sw->t, sw->w, t, &h)) {
            projcurve_status st;
            PC_ARRAY_RESERVE(st, ctx, hits, hits->count + 1, 8, "loop crossings");
            if (st != PROJCURVE_OK)
                return st;
            hits->items[hits->count++] = h;
        }
    }
    sw->have = 1;
    sw->t = t;
    sw->w = w;
    return PROJCURVE_OK;
}

projcurve_status pc_loop_crossings_by_side(projcurve_context *ctx, const pc_loop_samples *s,
                                           const pc_projector *proj, const double *poly, size_t n,
                                           const pc_seam_record *seams, size_t n_seams,
                                           pc_loop_hits *hits, size_t from)
{
    if (n < 2)
        return PROJCURVE_OK;
    /* the crossings found so far bound the stretches; those added here
     * come after them and are not bounds */
    const size_t end = hits->count;
    side_walk sw = {.hits = hits, .next = from};
    const int up = poly[3 * (n - 1)] >= poly[0];
    const double eps = PC_SIDE_JUMP_T * fabs(poly[3 * (n - 1)] - poly[0]);
    projcurve_status st = PROJCURVE_OK;
    for (size_t k = 0; st == PROJCURVE_OK && k < n; ++k) {
        /* vertex i, then the middle of its segment to the next (in t) */
        const size_t i = up ? k : n - 1 - k;
        const double *p = poly + 3 * i;
        double uv[2];
        if (near_jump(seams, n_seams, p[0], p[0], eps))
            sw.have = 0;
        else
            st = visit(ctx, s, proj, poly, n, &sw, end, hits, p[0],
                       side_at(s, proj, poly, n, p[0], uv));
        if (st != PROJCURVE_OK || k + 1 == n)
            break;
        const double *q = poly + 3 * (up ? i + 1 : i - 1);
        if (!(q[0] > p[0]))
            continue;
        if (near_jump(seams, n_seams, p[0], q[0], eps)) {
            sw.have = 0;
            continue;
        }
        const double t = 0.5 * (p[0] + q[0]);
        const pc_where w = side_at(s, proj, poly, n, t, uv);
        st = visit(ctx, s, proj, poly, n, &sw, end, hits, t, w);
    }
    return st;
}
