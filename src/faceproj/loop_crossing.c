/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Loop crossings of a branch, guessed on polylines and refined on the exact
 * projection (faceproj/loop_crossing.h).
 */
#include "faceproj/loop_crossing.h"

#include <math.h>
#include <stdlib.h>

#include "common/array.h"
#include "common/error.h"
#include "geom/surface.h"

int pc_projection_at(const pc_projector *proj, double t, double uv[2])
{
    return proj->correct(proj, t, uv, NULL);
}

/* Distance in 3D of a (u, v) offset d at uv, to first order. */
static double offset_3d(const projcurve_surface *surface, const double uv[2], const double d[2])
{
    pc_vec3 e[3];
    pc_nurbs_surface_eval(&surface->nurbs, uv[0], uv[1], 1, NULL, NULL, e);
    return vec3_norm(vec3_add(vec3_scale(e[1], d[0]), vec3_scale(e[2], d[1])));
}

void pc_loop_hit_refine(const pc_loop_samples *s, const pc_projector *proj, double t_lo,
                        double t_hi, pc_loop_hit *h)
{
    const pc_piece_samples *ps = &s->pieces[h->which];
    const pc_curve2 *cv = &s->face->loops[ps->loop].pieces[ps->piece].curve;
    double tau0, tau1;
    pc_curve2_domain(cv, &tau0, &tau1);
    const double tol = PC_CROSSING_TOL * proj->model_size;
    double uv[2] = {h->uv[0], h->uv[1]};
    double t = h->t, tau = h->tau;
    h->refined = 0;
    for (int it = 0; it < PC_CROSSING_MAX_ITER; ++it) {
        if (!pc_projection_at(proj, t, uv))
            return;
        pc_proj_point pp;
        if (!proj->derivatives(proj, t, uv[0], uv[1], &pp))
            return;
        double c[2], dc[2];
        pc_loop_piece_eval(s, h->which, tau, c, dc);
        const double f[2] = {uv[0] - c[0], uv[1] - c[1]};
        h->t = t;
        h->tau = tau;
        h->uv[0] = uv[0];
        h->uv[1] = uv[1];
        if (offset_3d(proj->surface, uv, f) <= tol) {
            h->refined = 1;
            return;
        }
        /* [q'(t), -c'(tau)] (dt, dtau) = -F, its columns scaled to unit
         * length first: near a silhouette |q'| reaches 1e15 while the
         * directions still cross well */
        const double r[2] = {-f[0], -f[1]};
        const double sq = hypot(pp.du, pp.dv), sc = hypot(dc[0], dc[1]);
        double x[2];
        if (!(sq > 0.0 && sc > 0.0) ||
            !mat2_solve(pp.du / sq, -dc[0] / sc, pp.dv / sq, -dc[1] / sc, r, x))
            return; /* the branch runs along the loop here: keep the guess */
        x[0] /= sq;
        x[1] /= sc;
        const double tn = fmin(t_hi, fmax(t_lo, t + x[0]));
        uv[0] += pp.du * (tn - t);
        uv[1] += pp.dv * (tn - t);
        t = tn;
        tau = fmin(tau1, fmax(tau0, tau + x[1]));
    }
}

/* The intersection of segments a->b and c->d: 1 with the parameters along
 * each when they cross (alpha in [0, 1], beta in [0, 1]). */
static int segments_cross(const double a[2], const double b[2], const double c[2],
                          const double d[2], double *alpha, double *beta)
{
    const double r[2] = {b[0] - a[0], b[1] - a[1]};
    const double q[2] = {d[0] - c[0], d[1] - c[1]};
    const double den = r[0] * q[1] - r[1] * q[0];
    if (den == 0.0)
        return 0;
    const double w[2] = {c[0] - a[0], c[1] - a[1]};
    const double al = (w[0] * q[1] - w[1] * q[0]) / den;
    const double be = (w[0] * r[1] - w[1] * r[0]) / den;
    if (!(al >= 0.0 && al <= 1.0 && be >= 0.0 && be <= 1.0))
        return 0;
    *alpha = al;
    *beta = be;
    return 1;
}

static int boxes_meet(const double a[2], const double b[2], const double box[4], double grow)
{
    return fmax(a[0], b[0]) >= box[0] - grow && fmin(a[0], b[0]) <= box[1] + grow &&
           fmax(a[1], b[1]) >= box[2] - grow && fmin(a[1], b[1]) <= box[3] + grow;
}

static projcurve_status guess_segment(projcurve_context *ctx, const pc_loop_samples *s,
                                      const double *pa, const double *pb, pc_loop_hits *hits)
{
    const double a[2] = {pa[1], pa[2]}, b[2] = {pb[1], pb[2]};
    const double grow = s->face->tol_uv;
    for (size_t i = 0; i < s->n_pieces; ++i) {
        const pc_piece_samples *ps = &s->pieces[i];
        if (!boxes_meet(a, b, ps->box, grow))
            continue;
        for (size_t j = 0; j + 1 < ps->count; ++j) {
            const pc_loop_sample *c = &s->items[ps->first + j], *d = c + 1;
            double al, be;
            if (!segments_cross(a, b, c->uv, d->uv, &al, &be))
                continue;
            projcurve_status st;
            PC_ARRAY_RESERVE(st, ctx, hits, hits->count + 1, 8, "loop crossings");
            if (st != PROJCURVE_OK)
                return st;
            pc_loop_hit *h = &hits->items[hits->count++];
            h->t = pa[0] + al * (pb[0] - pa[0]);
            h->tau = c->tau + be * (d->tau - c->tau);
            h->uv[0] = a[0] + al * (b[0] - a[0]);
            h->uv[1] = a[1] + al * (b[1] - a[1]);
            h->which = i;
            h->refined = 0;
        }
    }
    return PROJCURVE_OK;
}

static int by_t(const void *x, const void *y)
{
    const pc_loop_hit *a = x, *b = y;
    return (a->t > b->t) - (a->t < b->t);
}

/* Drops hits that are the same crossing found twice (at a polyline vertex,
 * at the joint of two loop pieces): within the crossing tolerance in
 * (t, 3D). */
static void drop_duplicates(const pc_projector *proj, pc_loop_hits *hits, size_t from)
{
    size_t m = from;
    const double tol = 1e3 * PC_CROSSING_TOL * proj->model_size;
    for (size_t i = from; i < hits->count; ++i) {
        const pc_loop_hit *h = &hits->items[i];
        if (m > from) {
            const pc_loop_hit *g = &hits->items[m - 1];
            const double d[2] = {h->uv[0] - g->uv[0], h->uv[1] - g->uv[1]};
            if (offset_3d(proj->surface, g->uv, d) <= tol) {
                if (h->refined && !g->refined)
                    hits->items[m - 1] = *h;
                continue;
            }
        }
        hits->items[m++] = *h;
    }
    hits->count = m;
}

/* hits[from..] in increasing t, each crossing once. */
static void sort_hits(const pc_projector *proj, pc_loop_hits *hits, size_t from)
{
    if (hits->count == from)
        return; /* no crossing (items may be NULL) */
    qsort(hits->items + from, hits->count - from, sizeof *hits->items, by_t);
    drop_duplicates(proj, hits, from);
}

projcurve_status pc_loop_crossings(projcurve_context *ctx, const pc_loop_samples *s,
                                   const pc_projector *proj, const double *poly, size_t n,
                                   const pc_seam_record *seams, size_t n_seams,
                                   pc_loop_hits *hits)
{
    const size_t from = hits->count;
    for (size_t i = 0; i + 1 < n; ++i) {
        const projcurve_status st = guess_segment(ctx, s, poly + 3 * i, poly + 3 * i + 3, hits);
        if (st != PROJCURVE_OK)
            return st;
    }
    if (n == 0)
        return PROJCURVE_OK;
    const double t_lo = fmin(poly[0], poly[3 * (n - 1)]);
    const double t_hi = fmax(poly[0], poly[3 * (n - 1)]);
    for (size_t i = from; i < hits->count; ++i)
        pc_loop_hit_refine(s, proj, t_lo, t_hi, &hits->items[i]);
    sort_hits(proj, hits, from);
    /* then where the side of the loops changes between two crossings */
    const size_t found = hits->count;
    const projcurve_status st = pc_loop_crossings_by_side(ctx, s, proj, poly, n, seams, n_seams,
                                                         hits, from);
    if (st == PROJCURVE_OK && hits->count > found)
        sort_hits(proj, hits, from);
    return st;
}
