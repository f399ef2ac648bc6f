#include "ortho/ortho_centres.h"

#include <math.h>

#include "common/error.h"
#include "ortho/ortho_projector.h"

/* Bisection of a crossing stops when its t-interval is this fraction of the
 * curve domain (as the engine's smallest step), or after this many halvings. */
#define CENTRE_T_TOL_REL 1e-12
#define CENTRE_MAX_BISECTIONS 60

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

/* Narrows [a, b] (different indices) around the crossing with corrected
 * points; stops early where the corrector fails (the crossing is then
 * known only to the current interval). */
static projcurve_status bisect(projcurve_context *ctx, const pc_projector *proj, double t_tol,
                               vertex *a, vertex *b)
{
    for (int it = 0; it < CENTRE_MAX_BISECTIONS && b->t - a->t > t_tol; ++it) {
        vertex m = {0.5 * (a->t + b->t), 0.5 * (a->u + b->u), 0.5 * (a->v + b->v), 0};
        double uv[2] = {m.u, m.v};
        if (!proj->correct(proj, m.t, uv, NULL))
            return PROJCURVE_OK;
        m.u = uv[0];
        m.v = uv[1];
        const projcurve_status status = index_at(ctx, proj, &m);
        if (status != PROJCURVE_OK)
            return status;
        if (m.index == a->index)
            *a = m;
        else if (m.index == b->index)
            *b = m;
        else
            return PROJCURVE_OK;   /* a third index: two crossings, keep the interval */
    }
    return PROJCURVE_OK;
}

/* Splits branch k after vertex i (crossing between i and i + 1, located as
 * [a, b]): vertices up to i plus a stay, b plus the rest move to a new
 * branch appended to r. */
static projcurve_status split(projcurve_context *ctx, projcurve_result *r, size_t k, size_t i,
                              const vertex *a, const vertex *b)
{
    pc_branch *tail = NULL;
    projcurve_status status = pc_result_add_branch(ctx, r, &tail);
    if (status != PROJCURVE_OK)
        return status;
    pc_branch *head = &r->branches[k];   /* re-read: the array may have moved */
    const double first[3] = {b->t, b->u, b->v};
    status = pc_branch_add_point(ctx, tail, 3, first);
    for (size_t j = i + 1; status == PROJCURVE_OK && j < head->n_points; ++j)
        if (head->points[3 * j] > b->t)
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
                vertex a = prev, b = cur;
                status = bisect(ctx, proj, t_tol, &a, &b);
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
