#include "ortho/ortho_centres.h"

#include <math.h>

#include "common/error.h"
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

/* Narrows [a, b] (different indices) around the crossing with corrected
 * points; stops early where the corrector fails (the crossing is then
 * known only to the current interval). keep_a / keep_b get the points
 * nearest the crossing on each side that are still well conditioned
 * (a and b themselves when none is). */
static projcurve_status bisect(projcurve_context *ctx, const pc_projector *proj, double t_tol,
                               vertex a, vertex b, vertex *keep_a, vertex *keep_b)
{
    *keep_a = a;
    *keep_b = b;
    for (int it = 0; it < CENTRE_MAX_BISECTIONS && b.t - a.t > t_tol; ++it) {
        vertex m = {0.5 * (a.t + b.t), 0.5 * (a.u + b.u), 0.5 * (a.v + b.v), 0};
        double uv[2] = {m.u, m.v};
        if (!proj->correct(proj, m.t, uv, NULL))
            return PROJCURVE_OK;
        m.u = uv[0];
        m.v = uv[1];
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
                              const vertex *a, const vertex *b)
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
    tail->start = PROJCURVE_START_SILHOUETTE;
    tail->end = head->end;
    head->n_points = i + 1;
    head->end = PROJCURVE_END_CURVATURE_CENTRE;
    if (a->t > head->points[3 * i]) {
        const double last[3] = {a->t, a->u, a->v};
        status = pc_branch_add_point(ctx, head, 3, last);
    }
    return status;
}

projcurve_status pc_ortho_split_at_centres(projcurve_context *ctx, const pc_projector *proj,
                                           projcurve_result *r)
{
    const double t_tol = CENTRE_T_TOL_REL * (proj->curve->t1 - proj->curve->t0);
    /* Branches appended by split() are scanned too (k runs to the end). */
    for (size_t k = 0; k < r->n_branches; ++k) {
        vertex prev = {0, 0, 0, 0};
        for (size_t i = 0; i < r->branches[k].n_points; ++i) {
            const double *pt = r->branches[k].points + 3 * i;
            vertex cur = {pt[0], pt[1], pt[2], 0};
            projcurve_status status = index_at(ctx, proj, &cur);
            if (status != PROJCURVE_OK)
                return status;
            if (i > 0 && cur.index != prev.index) {
                vertex a, b;
                status = bisect(ctx, proj, t_tol, prev, cur, &a, &b);
                if (status == PROJCURVE_OK)
                    status = split(ctx, r, k, i - 1, &a, &b);
                if (status != PROJCURVE_OK)
                    return status;
                break;
            }
            prev = cur;
        }
    }
    return PROJCURVE_OK;
}
