/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Clipping a projection to a face's loops (faceproj/face_clip.h).
 */
#include "faceproj/face_clip.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"
#include "faceproj/loop_crossing.h"
#include "faceproj/piece_cut.h"
#include "seam/seam.h"

/* Samples of a cubic pcurve between its ends in the guess polyline. */
#define PC_CLIP_CUBIC_SAMPLES 4

typedef struct pc_poly3 {
    double *items; /* 3 per vertex: t, u, v */
    size_t count, capacity;
} pc_poly3;

static projcurve_status poly_push(projcurve_context *ctx, pc_poly3 *p, double t, double u,
                                  double v)
{
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, p, p->count + 3, 48, "clip polyline");
    if (st == PROJCURVE_OK) {
        p->items[p->count++] = t;
        p->items[p->count++] = u;
        p->items[p->count++] = v;
    }
    return st;
}

/* The guess polyline of a branch: its pieces' pcurves when composed (exact
 * points at the piece ends, within eps_D between), else its traced points. */
static projcurve_status guess_polyline(projcurve_context *ctx, const pc_branch *b, pc_poly3 *p)
{
    projcurve_status st = PROJCURVE_OK;
    if (b->n_pieces == 0) {
        for (size_t i = 0; st == PROJCURVE_OK && i < b->n_points; ++i)
            st = poly_push(ctx, p, b->points[3 * i], b->points[3 * i + 1], b->points[3 * i + 2]);
        return st;
    }
    for (size_t k = 0; st == PROJCURVE_OK && k < b->n_pieces; ++k) {
        const pc_piece *q = &b->pieces[k];
        const int n = q->uv_degree;
        const int m = n > 1 ? PC_CLIP_CUBIC_SAMPLES : 1;
        for (int j = 0; st == PROJCURVE_OK && j < m; ++j) {
            const double s = (double)j / m;
            double uv[2] = {0.0, 0.0};
            /* Bernstein sum: degree <= 3 */
            for (int i = 0; i <= n; ++i) {
                double c = 1.0;
                for (int r = 0; r < i; ++r)
                    c = c * (n - r) / (r + 1);
                const double w = c * pow(s, i) * pow(1.0 - s, n - i);
                uv[0] += w * q->uv_ctrl[2 * i];
                uv[1] += w * q->uv_ctrl[2 * i + 1];
            }
            st = poly_push(ctx, p, q->t0 + s * (q->t1 - q->t0), uv[0], uv[1]);
        }
    }
    const pc_piece *last = &b->pieces[b->n_pieces - 1];
    if (st == PROJCURVE_OK)
        st = poly_push(ctx, p, last->t1, last->uv[2], last->uv[3]);
    return st;
}

/* (u, v) of the branch at t by linear interpolation of its traced points
 * (t monotone along them). */
static void interpolate(const pc_branch *b, double t, double uv[2])
{
    const double *P = b->points;
    const size_t n = b->n_points;
    const int up = P[3 * (n - 1)] >= P[0];
    size_t i = 0;
    while (i + 2 < n && (up ? P[3 * (i + 1)] < t : P[3 * (i + 1)] > t))
        ++i;
    const double *a = P + 3 * i, *c = P + 3 * (i + 1 < n ? i + 1 : i);
    const double span = c[0] - a[0];
    const double f = span != 0.0 ? fmin(1.0, fmax(0.0, (t - a[0]) / span)) : 0.0;
    uv[0] = a[1] + f * (c[1] - a[1]);
    uv[1] = a[2] + f * (c[2] - a[2]);
}

/* The exact point at t (the interpolated guess where the corrector fails). */
static void point_at(const pc_projector *proj, const pc_branch *b, double t, double uv[2])
{
    interpolate(b, t, uv);
    double q[2] = {uv[0], uv[1]};
    if (pc_projection_at(proj, t, q)) {
        uv[0] = q[0];
        uv[1] = q[1];
    }
}

/* A stretch [ta, tb] of a branch and the crossings that bound it (NULL:
 * an end of the untrimmed branch). */
typedef struct stretch {
    double ta, tb;
    const pc_loop_hit *ha, *hb;
} stretch;

static pc_trim_end hit_end(const pc_loop_samples *s, const pc_loop_hit *h)
{
    const pc_piece_samples *ps = &s->pieces[h->which];
    return (pc_trim_end){.on_loop = 1, .loop = ps->loop, .piece = ps->piece, .tau = h->tau,
                         .edge = s->face->loops[ps->loop].pieces[ps->piece].edge, .t = h->t,
                         .uv = {h->uv[0], h->uv[1]}};
}

/* The end of the untrimmed branch at its vertex i: on a loop when it
 * classifies ON. */
static pc_trim_end branch_end(const pc_loop_samples *s, const pc_branch *b, size_t i)
{
    const double *P = b->points + 3 * i;
    pc_trim_end e = {.on_loop = 0, .edge = -1, .t = P[0], .uv = {P[1], P[2]}};
    if (pc_classify(&s->face->cls, P[1], P[2]) != PC_ON)
        return e;
    size_t which = 0;
    double tau = 0.0;
    if (isfinite(pc_loop_samples_nearest(s, e.uv, &which, &tau))) {
        const pc_piece_samples *ps = &s->pieces[which];
        e.on_loop = 1;
        e.loop = ps->loop;
        e.piece = ps->piece;
        e.tau = tau;
        e.edge = s->face->loops[ps->loop].pieces[ps->piece].edge;
    }
    return e;
}

static projcurve_status add_point(projcurve_context *ctx, pc_branch *b, double t, const double uv[2])
{
    const double p[3] = {t, uv[0], uv[1]};
    return pc_branch_add_point(ctx, b, 3, p);
}

/* The points of src inside the stretch, in src's order, with the exact
 * crossings at the ends that are crossings. */
static projcurve_status copy_points(projcurve_context *ctx, const pc_branch *src, const stretch *sr,
                                    int up, pc_branch *dst)
{
    const pc_loop_hit *first = up ? sr->ha : sr->hb, *last = up ? sr->hb : sr->ha;
    projcurve_status st = first ? add_point(ctx, dst, first->t, first->uv) : PROJCURVE_OK;
    for (size_t i = 0; st == PROJCURVE_OK && i < src->n_points; ++i) {
        const double t = src->points[3 * i];
        const int in_a = sr->ha ? t > sr->ta : t >= sr->ta;
        const int in_b = sr->hb ? t < sr->tb : t <= sr->tb;
        if (in_a && in_b)
            st = pc_branch_add_point(ctx, dst, 3, src->points + 3 * i);
    }
    if (st == PROJCURVE_OK && last)
        st = add_point(ctx, dst, last->t, last->uv);
    return st;
}

/* s on piece q of the stretch end at t (hit h, NULL: an untrimmed end). */
static double piece_s(const pc_loop_samples *s, const pc_piece *q, double t, const pc_loop_hit *h)
{
    const double lo = fmin(q->t0, q->t1), hi = fmax(q->t0, q->t1);
    if (h != NULL && t > lo && t < hi)
        return pc_piece_cut_parameter(q, s, h->which, t, h->tau);
    const double span = q->t1 - q->t0;
    return span != 0.0 ? fmin(1.0, fmax(0.0, (t - q->t0) / span)) : 0.0;
}

/* Smallest part of a piece kept, in s: below it the part is a point. */
#define PC_CLIP_MIN_PART 1e-12

static projcurve_status copy_pieces(projcurve_context *ctx, const pc_loop_samples *s,
                                    const pc_branch *src, const stretch *sr, pc_branch *dst)
{
    projcurve_status st = PROJCURVE_OK;
    for (size_t k = 0; st == PROJCURVE_OK && k < src->n_pieces; ++k) {
        const pc_piece *q = &src->pieces[k];
        const double lo = fmax(sr->ta, fmin(q->t0, q->t1));
        const double hi = fmin(sr->tb, fmax(q->t0, q->t1));
        if (!(lo < hi))
            continue;
        const double s_lo = piece_s(s, q, lo, sr->ha), s_hi = piece_s(s, q, hi, sr->hb);
        const double s0 = fmin(s_lo, s_hi), s1 = fmax(s_lo, s_hi);
        if (!(s1 - s0 > PC_CLIP_MIN_PART))
            continue;
        const int forward = q->t1 >= q->t0;
        st = pc_piece_append_part(ctx, dst, q, s0, s1, forward ? lo : hi, forward ? hi : lo);
    }
    return st;
}

static projcurve_status copy_compact(projcurve_context *ctx, const pc_branch *src,
                                     const stretch *sr, pc_branch *dst)
{
    if (src->compact == PC_COMPACT_NONE)
        return PROJCURVE_OK;
    projcurve_status st =
        pc_bspline_restrict(ctx, &src->compact_pcurve, sr->ta, sr->tb, &dst->compact_pcurve);
    if (st == PROJCURVE_OK)
        st = pc_bspline_restrict(ctx, &src->compact_curve, sr->ta, sr->tb, &dst->compact_curve);
    if (st != PROJCURVE_OK)
        return st;
    dst->compact = dst->compact_pcurve.n_poles > 0 ? src->compact : PC_COMPACT_NONE;
    dst->compact_pcurve_error = src->compact_pcurve_error;
    dst->compact_curve_error = src->compact_curve_error;
    return PROJCURVE_OK;
}

typedef struct trims {
    pc_branch_trim *items;
    size_t count, capacity;
} trims;

static projcurve_status keep_stretch(projcurve_context *ctx, const pc_loop_samples *s,
                                     const pc_branch *src, const stretch *sr, projcurve_result *r,
                                     trims *tr)
{
    const int up = src->points[3 * (src->n_points - 1)] >= src->points[0];
    pc_branch *dst = NULL;
    projcurve_status st = pc_result_add_branch(ctx, r, &dst);
    if (st == PROJCURVE_OK)
        PC_ARRAY_RESERVE(st, ctx, tr, tr->count + 1, 8, "branch trims");
    if (st != PROJCURVE_OK)
        return st;
    pc_branch_trim *bt = &tr->items[tr->count++];
    const pc_loop_hit *hs = up ? sr->ha : sr->hb, *he = up ? sr->hb : sr->ha;
    bt->start = hs ? hit_end(s, hs) : branch_end(s, src, 0);
    bt->end = he ? hit_end(s, he) : branch_end(s, src, src->n_points - 1);
    dst->start = bt->start.on_loop ? PROJCURVE_START_TRIM : src->start;
    dst->end = bt->end.on_loop ? PROJCURVE_END_TRIM : src->end;
    st = copy_points(ctx, src, sr, up, dst);
    if (st == PROJCURVE_OK)
        st = copy_pieces(ctx, s, src, sr, dst);
    if (st == PROJCURVE_OK)
        st = copy_compact(ctx, src, sr, dst);
    /* a stretch across the face's seam keeps its jumps (the writers split
     * its curve there, src/io/seam_split.c) */
    if (st == PROJCURVE_OK)
        st = pc_seam_restrict_records(ctx, src, sr->ta, sr->tb, dst);
    return st;
}

/* Points of a stretch classified when its midpoint lies in the loops' ON
 * band (below): at s = k / PC_CLIP_SIDE_SAMPLES. */
#define PC_CLIP_SIDE_SAMPLES 8

/* 1 when the stretch [ta, tb] of b (no crossing inside it) lies in the
 * face; at_a, at_b: that end is a crossing (on a loop), else an end of
 * the untrimmed branch. Its midpoint decides when it is IN or OUT. Within
 * the ON band (the model's precision in (u, v): 1 % of the domain on
 * bearing.iges face 169) it does not: the stretch from a crossing to a
 * branch end just beyond the loop (there 0.015 outside, its midpoint
 * 0.007) would be kept whole, its end outside the face. Then the stretch
 * is kept unless one of its points at the samples (its crossing ends
 * left out: they lie on the loop to the crossing's tolerance, or less
 * where refining them failed) lies OUT: a stretch that runs along the
 * loop within the band stays, as before. */
static int stretch_inside(const pc_loop_samples *s, const pc_projector *proj, const pc_branch *b,
                          double ta, double tb, int at_a, int at_b)
{
    double uv[2];
    point_at(proj, b, 0.5 * (ta + tb), uv);
    const pc_where mid = pc_classify(&s->face->cls, uv[0], uv[1]);
    if (mid != PC_ON)
        return mid == PC_IN;
    for (int k = at_a ? 1 : 0; k <= (at_b ? PC_CLIP_SIDE_SAMPLES - 1 : PC_CLIP_SIDE_SAMPLES); ++k) {
        point_at(proj, b, ta + (tb - ta) * k / PC_CLIP_SIDE_SAMPLES, uv);
        if (pc_classify(&s->face->cls, uv[0], uv[1]) == PC_OUT)
            return 0;
    }
    return 1;
}

static projcurve_status clip_branch(projcurve_context *ctx, const pc_loop_samples *s,
                                    const pc_projector *proj, const pc_branch *b,
                                    projcurve_result *r, trims *tr, size_t *unrefined)
{
    if (b->n_points == 0)
        return PROJCURVE_OK;
    pc_poly3 poly = {0};
    pc_loop_hits hits = {0};
    projcurve_status st = guess_polyline(ctx, b, &poly);
    if (st == PROJCURVE_OK)
        st = pc_loop_crossings(ctx, s, proj, poly.items, poly.count / 3, b->seams, b->n_seams,
                               &hits);
    const double T0 = fmin(b->points[0], b->points[3 * (b->n_points - 1)]);
    const double T1 = fmax(b->points[0], b->points[3 * (b->n_points - 1)]);
    /* stretches between consecutive bounds, the kept ones merged while
     * adjacent */
    stretch cur = {0};
    int open = 0;
    for (size_t i = 0; st == PROJCURVE_OK && i <= hits.count; ++i) {
        const pc_loop_hit *ha = i > 0 ? &hits.items[i - 1] : NULL;
        const pc_loop_hit *hb = i < hits.count ? &hits.items[i] : NULL;
        const double ta = ha ? ha->t : T0, tb = hb ? hb->t : T1;
        if (ha && !ha->refined)
            ++*unrefined;
        const int keep = tb > ta && stretch_inside(s, proj, b, ta, tb, ha != NULL, hb != NULL);
        if (keep) {
            if (!open)
                cur = (stretch){.ta = ta, .ha = ha};
            open = 1;
            cur.tb = tb;
            cur.hb = hb;
        } else if (open && tb > ta) {
            st = keep_stretch(ctx, s, b, &cur, r, tr);
            open = 0;
        }
    }
    if (st == PROJCURVE_OK && open)
        st = keep_stretch(ctx, s, b, &cur, r, tr);
    PC_ARRAY_FREE(&poly);
    PC_ARRAY_FREE(&hits);
    return st;
}

projcurve_status pc_face_clip(projcurve_context *ctx, const projcurve_face *face,
                              const pc_projector *proj, const projcurve_result *untrimmed,
                              projcurve_result **out, pc_branch_trim **trims_out,
                              size_t *unrefined)
{
    pc_loop_samples s;
    projcurve_status st = pc_loop_samples_build(ctx, face, &s);
    if (st != PROJCURVE_OK)
        return st;
    projcurve_result *r = NULL;
    trims tr = {0};
    size_t n_unrefined = 0;
    st = pc_result_create(ctx, 3, &r);
    for (size_t i = 0; st == PROJCURVE_OK && i < untrimmed->n_branches; ++i)
        st = clip_branch(ctx, &s, proj, &untrimmed->branches[i], r, &tr, &n_unrefined);
    pc_loop_samples_free(&s);
    if (st != PROJCURVE_OK) {
        projcurve_result_destroy(r);
        PC_ARRAY_FREE(&tr);
        return st;
    }
    r->stats = untrimmed->stats;
    r->failures_dropped = untrimmed->failures_dropped;
    double pieces = 0.0;
    for (size_t i = 0; i < r->n_branches; ++i)
        pieces += (double)r->branches[i].n_pieces;
    r->stats.pieces = pieces;
    *out = r;
    *trims_out = tr.items;
    *unrefined = n_unrefined;
    return PROJCURVE_OK;
}
