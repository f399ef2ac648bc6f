/* SPDX-License-Identifier: BSD-3-Clause */
#include "ortho/ortho_centres.h"

#include <math.h>

#include "common/error.h"
#include "nurbs/nurbs.h"
#include "ortho/ortho_creases.h"
#include "ortho/ortho_projector.h"

/* Bisection of a crossing stops when its t-interval is this fraction of the
 * curve domain (as the engine's smallest step), or after this many halvings. */
#define CENTRE_T_TOL_REL 1e-12
#define CENTRE_MAX_BISECTIONS 60
/* Located points closer to the centre than |det K| / (|Su||Sv|)^2 = this
 * (the engine's fold threshold) are not kept as vertices: there K's
 * conditioning makes (u, v) and q' too noisy for the tolerance control of
 * refine/, so the branch ends at its last vertex farther away. */
#define CENTRE_MIN_DET 1e-6

typedef struct vertex {
    double t, u, v;
    int index;
} vertex;

/* A consecutive pair of vertices farther apart on S than this multiple of
 * (larger end speed x parameter gap) is not one continuous piece: the
 * tracer went from one foot point to another (seen where two foot points
 * annihilate at a fold and the step lands on a third one of the same
 * Morse index). Arc length is the integral of the speed, which near a fold
 * grows towards the fold, so a continuous segment stays well inside. */
#define GAP_FACTOR 10.0
/* |det| below this at the end of such a gap: the branch ended at a centre
 * of curvature (as the engine's PC_PROJECTOR_DET_NEAR_FOLD). */
#define GAP_NEAR_CENTRE 1e-2

/* What the gap test needs at a vertex. */
typedef struct probe {
    pc_vec3 x;
    double speed, det;
    int known;   /* derivatives() succeeded */
} probe;

static probe probe_at(const pc_projector *proj, const double *tuv)
{
    probe pb = {vec3(0, 0, 0), 0.0, 0.0, 0};
    pc_proj_point d;
    pb.known = proj->derivatives(proj, tuv[0], tuv[1], tuv[2], &d);
    pb.x = d.s;
    pb.speed = d.speed;
    pb.det = d.det;
    return pb;
}

static int is_gap(const pc_projector *proj, const probe *a, const probe *b, double dt)
{
    if (!a->known || !b->known)
        return 0;
    const double speed = a->speed > b->speed ? a->speed : b->speed;
    return vec3_dist(a->x, b->x) > GAP_FACTOR * speed * dt + proj->newton_tol;
}

static projcurve_status index_at(projcurve_context *ctx, const pc_projector *proj, vertex *x)
{
    if (!pc_ortho_morse_index(proj, x->t, x->u, x->v, &x->index))
        return pc_fail(ctx, PROJCURVE_ERR_CALLBACK, "curve callback failed at t = %.17g", x->t);
    return PROJCURVE_OK;
}

/* 1 when x is far enough from the centre to be a vertex. */
static int well_conditioned(const pc_projector *proj, const vertex *x)
{
    pc_proj_point d;
    return proj->derivatives(proj, x->t, x->u, x->v, &d) && fabs(d.det) >= CENTRE_MIN_DET;
}

/* A corrected point of the bisection is on the branch when it lies within
 * this multiple of the chord |S(a) - S(b)| (plus newton_tol) of its guess.
 * At an umbilic centre (P at a sphere's centre) every point of S is a foot
 * point and the corrector, from any guess, converges anywhere (to the pole,
 * on the NURBS sphere): such a point is no point of the branch. */
#define CENTRE_MOVE_FACTOR 2.0

static pc_vec3 point_on(const pc_projector *proj, double u, double v)
{
    size_t hu = 0, hv = 0;
    pc_vec3 x;
    pc_nurbs_surface_eval(&proj->surface->nurbs, u, v, 0, &hu, &hv, &x);
    return x;
}

/* The corrected point at the fraction w of [a, b], from the interpolated
 * guess; 0 where the corrector fails or leaves the branch (above). */
static int corrected_between(const pc_projector *proj, const vertex *a, const vertex *b, double w,
                             double chord, vertex *m)
{
    m->t = a->t + w * (b->t - a->t);
    m->u = a->u + w * (b->u - a->u);
    m->v = a->v + w * (b->v - a->v);
    double uv[2] = {m->u, m->v};
    if (!proj->correct(proj, m->t, uv, NULL))
        return 0;
    const double moved = vec3_dist(point_on(proj, uv[0], uv[1]), point_on(proj, m->u, m->v));
    m->u = uv[0];
    m->v = uv[1];
    return moved <= CENTRE_MOVE_FACTOR * chord + proj->newton_tol;
}

/* Narrows [a, b] (different indices) around the crossing with corrected
 * points; stops early where the corrector fails (the crossing is then
 * known only to the current interval). The bisection's midpoints are
 * dyadic, like the engine's steps, and so is the centre of a curve crossing
 * a centre at such a parameter (t = 0.5 on [0, 1]): where the midpoint
 * fails, the points at 3/8 and 5/8 are tried before giving up. keep_a /
 * keep_b get the points nearest the crossing on each side that are still
 * well conditioned (a and b themselves when none is). */
static projcurve_status bisect(projcurve_context *ctx, const pc_projector *proj, double t_tol,
                               vertex a, vertex b, vertex *keep_a, vertex *keep_b)
{
    static const double fractions[3] = {0.5, 0.375, 0.625};
    *keep_a = a;
    *keep_b = b;
    for (int it = 0; it < CENTRE_MAX_BISECTIONS && b.t - a.t > t_tol; ++it) {
        const double chord = vec3_dist(point_on(proj, a.u, a.v), point_on(proj, b.u, b.v));
        vertex m = {0, 0, 0, 0};
        int found = 0;
        for (int k = 0; k < 3 && !found; ++k)
            found = corrected_between(proj, &a, &b, fractions[k], chord, &m);
        if (!found)
            return PROJCURVE_OK;
        const projcurve_status status = index_at(ctx, proj, &m);
        if (status != PROJCURVE_OK)
            return status;
        if (m.index == a.index) {
            a = m;
            if (well_conditioned(proj, &m))
                *keep_a = m;
        } else if (m.index == b.index) {
            b = m;
            if (well_conditioned(proj, &m))
                *keep_b = m;
        } else {
            return PROJCURVE_OK;   /* a third index: two crossings, keep the interval */
        }
    }
    return PROJCURVE_OK;
}

/* Splits branch k between vertices i and i + 1 around a crossing: the head
 * keeps vertices 0..i and ends at a (if beyond vertex i), the new branch
 * appended to r starts at b (if before vertex i + 1) and takes the rest. */
static projcurve_status split(projcurve_context *ctx, projcurve_result *r, size_t k, size_t i,
                              const vertex *a, const vertex *b, projcurve_branch_end head_end,
                              projcurve_branch_start tail_start)
{
    pc_branch *tail = NULL;
    projcurve_status status = pc_result_add_branch(ctx, r, &tail);
    if (status != PROJCURVE_OK)
        return status;
    pc_branch *head = &r->branches[k];   /* re-read: the array may have moved */
    if (b->t < head->points[3 * (i + 1)]) {
        const double first[3] = {b->t, b->u, b->v};
        status = pc_branch_add_point(ctx, tail, 3, first);
    }
    for (size_t j = i + 1; status == PROJCURVE_OK && j < head->n_points; ++j)
        status = pc_branch_add_point(ctx, tail, 3, head->points + 3 * j);
    if (status != PROJCURVE_OK)
        return status;
    tail->start = tail_start;
    tail->end = head->end;
    head->n_points = i + 1;
    head->end = head_end;
    if (a->t > head->points[3 * i]) {
        const double last[3] = {a->t, a->u, a->v};
        status = pc_branch_add_point(ctx, head, 3, last);
    }
    return status;
}

/* Splits branch k where a crossing or a gap follows vertex i - 1 (cur is
 * vertex i); *split_done tells whether it did. */
static projcurve_status check_pair(projcurve_context *ctx, const pc_projector *proj,
                                   projcurve_result *r, size_t k, size_t i, const vertex *prev,
                                   const probe *prev_probe, const vertex *cur,
                                   const probe *cur_probe, int *split_done)
{
    const double t_tol = CENTRE_T_TOL_REL * (proj->curve->t1 - proj->curve->t0);
    *split_done = 0;
    if (cur->index != prev->index) {
        vertex a, b;
        projcurve_status status = bisect(ctx, proj, t_tol, *prev, *cur, &a, &b);
        if (status == PROJCURVE_OK)
            status = split(ctx, r, k, i - 1, &a, &b, PROJCURVE_END_CURVATURE_CENTRE,
                           PROJCURVE_START_SILHOUETTE);
        *split_done = 1;
        return status;
    }
    if (is_gap(proj, prev_probe, cur_probe, cur->t - prev->t)) {
        *split_done = 1;
        return split(ctx, r, k, i - 1, prev, cur,
                     fabs(prev_probe->det) < GAP_NEAR_CENTRE ? PROJCURVE_END_CURVATURE_CENTRE
                                                             : PROJCURVE_END_FAILED,
                     fabs(cur_probe->det) < GAP_NEAR_CENTRE ? PROJCURVE_START_SILHOUETTE
                                                            : PROJCURVE_START_JUMP);
    }
    return PROJCURVE_OK;
}

projcurve_status pc_ortho_split_at_centres(projcurve_context *ctx, const pc_projector *proj,
                                           projcurve_result *r)
{
    /* Branches appended by split() are scanned too (k runs to the end). */
    for (size_t k = 0; k < r->n_branches; ++k) {
        vertex prev = {0, 0, 0, 0};
        probe prev_probe = {vec3(0, 0, 0), 0.0, 0.0, 0};
        for (size_t i = 0; i < r->branches[k].n_points; ++i) {
            const double *pt = r->branches[k].points + 3 * i;
            vertex cur = {pt[0], pt[1], pt[2], 0};
            const probe cur_probe = probe_at(proj, pt);
            projcurve_status status = index_at(ctx, proj, &cur);
            int split_done = 0;
            if (status == PROJCURVE_OK && i > 0)
                status = check_pair(ctx, proj, r, k, i, &prev, &prev_probe, &cur, &cur_probe,
                                    &split_done);
            if (status != PROJCURVE_OK)
                return status;
            if (split_done)
                break;
            prev = cur;
            prev_probe = cur_probe;
        }
    }
    /* The other singular places where the tracer stops, creases (C0 knot
     * lines), get their names in the same pass over the traced branches. */
    pc_ortho_name_crease_ends(proj, r);
    return PROJCURVE_OK;
}
