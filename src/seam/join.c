/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The seam stage (seam.h): boundary-end / boundary-start pairs of branches
 * at the same t and the same point of an identified edge, joined.
 */
#include "seam/seam.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"
#include "geom/curve.h"

/* A point counts as on an edge within this fraction of the domain's width:
 * ten times the snap of trace/boundary_exit.c (PC_EXIT_LOOSE_TOL). */
#define PC_SEAM_ON_EDGE 1e-8

double pc_seam_join_tolerance(const pc_params *p, double size)
{
    return 1e3 * pc_params_precision(p) * size;
}

/* The PC_SIDE_* edges that (u, v) lies on. */
static unsigned sides_of(const double dom[4], double u, double v)
{
    const double eu = PC_SEAM_ON_EDGE * (dom[1] - dom[0]);
    const double ev = PC_SEAM_ON_EDGE * (dom[3] - dom[2]);
    unsigned s = 0;
    if (fabs(u - dom[0]) <= eu)
        s |= PC_SIDE_U0;
    if (fabs(u - dom[1]) <= eu)
        s |= PC_SIDE_U1;
    if (fabs(v - dom[2]) <= ev)
        s |= PC_SIDE_V0;
    if (fabs(v - dom[3]) <= ev)
        s |= PC_SIDE_V1;
    return s;
}

/* Whether one coordinate may differ between the edge points a and b (side
 * masks sa, sb): it agrees, or the direction is closed and they lie on its
 * opposite edges, or both lie on one collapsed edge along which it runs
 * (mask `along`: the edges on which this coordinate is free). */
static int coordinate_identified(double d, double width, int closed, unsigned lo, unsigned hi,
                                 unsigned sa, unsigned sb, unsigned along, unsigned collapsed)
{
    if (fabs(d) <= PC_SEAM_ON_EDGE * width)
        return 1;
    if (closed && (((sa & lo) && (sb & hi)) || ((sa & hi) && (sb & lo))))
        return 1;
    return (sa & sb & along & collapsed) != 0;
}

/* The last vertex of a and the first of b are the two sides of one jump:
 * same P(t), same S(u, v), identified edges, (u, v) different. */
static int is_jump(const projcurve_surface *surface, const projcurve_curve *curve,
                   const pc_closure *cl, double tol, const double *a, const double *b)
{
    const double *dom = surface->nurbs.domain;
    const double du = b[1] - a[1], dv = b[2] - a[2];
    const double wu = dom[1] - dom[0], wv = dom[3] - dom[2];
    if (fabs(du) <= PC_SEAM_ON_EDGE * wu && fabs(dv) <= PC_SEAM_ON_EDGE * wv)
        return 0;
    const unsigned sa = sides_of(dom, a[1], a[2]), sb = sides_of(dom, b[1], b[2]);
    if (!coordinate_identified(du, wu, cl->closed_u, PC_SIDE_U0, PC_SIDE_U1, sa, sb,
                               PC_SIDE_V0 | PC_SIDE_V1, cl->collapsed) ||
        !coordinate_identified(dv, wv, cl->closed_v, PC_SIDE_V0, PC_SIDE_V1, sa, sb,
                               PC_SIDE_U0 | PC_SIDE_U1, cl->collapsed))
        return 0;
    pc_vec3 pa, pb, sa3, sb3;
    if (pc_curve_eval(curve, a[0], 0, NULL, &pa) != PROJCURVE_OK ||
        pc_curve_eval(curve, b[0], 0, NULL, &pb) != PROJCURVE_OK)
        return 0; /* a failing callback: no join, the branches stay as traced */
    pc_nurbs_surface_eval(&surface->nurbs, a[1], a[2], 0, NULL, NULL, &sa3);
    pc_nurbs_surface_eval(&surface->nurbs, b[1], b[2], 0, NULL, NULL, &sb3);
    return vec3_norm(vec3_sub(pa, pb)) <= tol && vec3_norm(vec3_sub(sa3, sb3)) <= tol;
}

/* Index of the branch that starts where branch i ends across a seam, or
 * r->n_branches. */
static size_t find_continuation(const projcurve_surface *surface, const projcurve_curve *curve,
                                const pc_closure *cl, double tol, const projcurve_result *r,
                                size_t i)
{
    const pc_branch *a = &r->branches[i];
    if (a->end != PROJCURVE_END_BOUNDARY || a->n_points == 0)
        return r->n_branches;
    const double *last = a->points + 3 * (a->n_points - 1);
    for (size_t j = 0; j < r->n_branches; ++j) {
        const pc_branch *b = &r->branches[j];
        if (j != i && b->start == PROJCURVE_START_BOUNDARY && b->n_points > 0 &&
            is_jump(surface, curve, cl, tol, last, b->points))
            return j;
    }
    return r->n_branches;
}

/* Reverses a piece in place: its Bezier points, weights, pcurve and ends. */
static void flip_piece(pc_piece *p)
{
    const size_t n = (size_t)p->degree + 1, m = (size_t)p->uv_degree + 1;
    for (size_t i = 0, k = n - 1; i < k; ++i, --k) {
        for (size_t d = 0; d < 3; ++d) {
            const double c = p->ctrl[3 * i + d];
            p->ctrl[3 * i + d] = p->ctrl[3 * k + d];
            p->ctrl[3 * k + d] = c;
        }
        const double w = p->weights[i];
        p->weights[i] = p->weights[k];
        p->weights[k] = w;
    }
    for (size_t i = 0, k = m - 1; i < k; ++i, --k)
        for (size_t d = 0; d < 2; ++d) {
            const double c = p->uv_ctrl[2 * i + d];
            p->uv_ctrl[2 * i + d] = p->uv_ctrl[2 * k + d];
            p->uv_ctrl[2 * k + d] = c;
        }
    const double t = p->t0, u = p->uv[0], v = p->uv[1];
    p->t0 = p->t1;
    p->t1 = t;
    p->uv[0] = p->uv[2];
    p->uv[1] = p->uv[3];
    p->uv[2] = u;
    p->uv[3] = v;
}

/* Puts b's pieces in increasing t (a branch composed from its far end
 * holds them the other way). */
static void pieces_increasing(pc_branch *b)
{
    if (b->n_pieces == 0 || !(b->pieces[0].t0 > b->pieces[0].t1))
        return;
    for (size_t i = 0, k = b->n_pieces - 1; i < k; ++i, --k) {
        const pc_piece p = b->pieces[i];
        b->pieces[i] = b->pieces[k];
        b->pieces[k] = p;
    }
    for (size_t i = 0; i < b->n_pieces; ++i)
        flip_piece(&b->pieces[i]);
}

/* Appends branch j to branch i across the jump between them, then removes
 * j. Everything is allocated before anything changes, so that NO_MEMORY
 * leaves both branches as they were. */
static projcurve_status join_pair(projcurve_context *ctx, projcurve_result *r, size_t i,
                                  size_t j)
{
    pc_branch *a = &r->branches[i], *b = &r->branches[j];
    const double *last = a->points + 3 * (a->n_points - 1);
    const pc_seam_record jump = {b->points[0], b->points[1] - last[1], b->points[2] - last[2]};
    double shift[2] = {jump.du, jump.dv};
    for (size_t k = 0; k < a->n_seams; ++k) {
        shift[0] += a->seams[k].du;
        shift[1] += a->seams[k].dv;
    }
    void *pts = a->points, *pcs = a->pieces;
    projcurve_status st = pc_array_reserve(ctx, &pts, &a->cap_points, a->n_points,
                                           a->n_points + b->n_points, 3 * sizeof *a->points,
                                           16, NULL, "a branch's points");
    a->points = pts;
    if (st == PROJCURVE_OK) {
        st = pc_array_reserve(ctx, &pcs, &a->cap_pieces, a->n_pieces, a->n_pieces + b->n_pieces,
                              sizeof *a->pieces, 16, NULL, "a branch's pieces");
        a->pieces = pcs;
    }
    const size_t n_seams = a->n_seams + 1 + b->n_seams;
    pc_seam_record *seams = st == PROJCURVE_OK ? malloc(n_seams * sizeof *seams) : NULL;
    if (st == PROJCURVE_OK && seams == NULL)
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the seams of a branch");
    pieces_increasing(a);
    pieces_increasing(b);
    if (st == PROJCURVE_OK && a->compact != PC_COMPACT_NONE && b->compact != PC_COMPACT_NONE)
        st = pc_seam_join_compact(ctx, a, b, shift);
    if (st != PROJCURVE_OK) {
        free(seams);
        return st;
    }
    if (a->compact == PC_COMPACT_NONE || b->compact == PC_COMPACT_NONE) {
        pc_bspline_free(&a->compact_pcurve);
        pc_bspline_free(&a->compact_curve);
        a->compact = PC_COMPACT_NONE;
    }
    if (a->n_seams > 0)
        memcpy(seams, a->seams, a->n_seams * sizeof *seams);
    seams[a->n_seams] = jump;
    if (b->n_seams > 0)
        memcpy(seams + a->n_seams + 1, b->seams, b->n_seams * sizeof *seams);
    free(a->seams);
    a->seams = seams;
    a->n_seams = n_seams;
    memcpy(a->points + 3 * a->n_points, b->points, 3 * b->n_points * sizeof *a->points);
    a->n_points += b->n_points;
    if (b->n_pieces > 0)
        memcpy(a->pieces + a->n_pieces, b->pieces, b->n_pieces * sizeof *a->pieces);
    a->n_pieces += b->n_pieces;
    b->n_pieces = 0; /* a owns them now */
    a->end = b->end;
    pc_result_remove_branch(r, j);
    return PROJCURVE_OK;
}

projcurve_status pc_seam_join(projcurve_context *ctx, const projcurve_surface *surface,
                              const projcurve_curve *curve, const pc_params *p,
                              projcurve_result *r)
{
    if (r->point_dim != 3)
        return PROJCURVE_OK;
    const double tol = pc_seam_join_tolerance(p, surface->size);
    pc_closure cl;
    pc_surface_closure(&surface->nurbs, tol, &cl);
    if (!cl.closed_u && !cl.closed_v && cl.collapsed == 0)
        return PROJCURVE_OK;
    /* each join removes a branch: at most n_branches joins in all */
    for (size_t i = 0; i < r->n_branches; ++i) {
        for (;;) {
            const size_t j = find_continuation(surface, curve, &cl, tol, r, i);
            if (j == r->n_branches)
                break;
            const projcurve_status st = join_pair(ctx, r, i, j);
            if (st != PROJCURVE_OK)
                return st;
            if (j < i)
                --i;
        }
    }
    return PROJCURVE_OK;
}

projcurve_status pc_seam_stage(projcurve_context *ctx, const projcurve_surface *surface,
                               const projcurve_curve *curve, const pc_params *p,
                               projcurve_result *r, projcurve_status st)
{
    if (!p->join_seams || !pc_status_keeps_result(st))
        return st;
    const projcurve_status js = pc_seam_join(ctx, surface, curve, p, r);
    return js != PROJCURVE_OK ? js : st;
}

void pc_seam_unwrap_shift(const pc_branch *b, double t, double shift[2])
{
    shift[0] = shift[1] = 0.0;
    for (size_t k = 0; k < b->n_seams && b->seams[k].t <= t; ++k) {
        shift[0] += b->seams[k].du;
        shift[1] += b->seams[k].dv;
    }
}
