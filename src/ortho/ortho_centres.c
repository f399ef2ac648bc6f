#include "ortho/ortho_centres.h"

#include <math.h>

#include "common/error.h"
#include "ortho/ortho_projector.h"

/* Bisection of a crossing stops when its t-interval is this fraction of the
 * curve domain (as the engine's smallest step), or after this many halvings. */
#define CENTRE_T_TOL_REL 1e-12
#define CENTRE_MAX_BISECTIONS 60
/* Attempts when pushing an end towards a centre (each success advances,
 * each failure halves the step: 60 halvings reach the tolerance). */
#define CENTRE_MAX_PUSHES 200
/* A corrected point farther from the end than this multiple of the
 * predicted motion went to another foot point. */
#define CENTRE_MAX_MOTION 4.0

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

/* Pushes the end vertex e of a branch in direction dir (+1 forward, -1
 * backward in t) while the corrector converges with the same Morse index;
 * *moved is set when *e changed. */
static projcurve_status push_end(projcurve_context *ctx, const pc_projector *proj,
                                 double t_tol, double h, vertex *e, int *moved)
{
    const pc_nurbs_surface *s = &proj->surface->nurbs;
    *moved = 0;
    for (int it = 0; it < CENTRE_MAX_PUSHES && fabs(h) > t_tol; ++it) {
        const double t_new = e->t + h;
        pc_proj_point d;
        if (t_new < proj->curve->t0 || t_new > proj->curve->t1 ||
            !proj->derivatives(proj, e->t, e->u, e->v, &d)) {
            h *= 0.5;
            continue;
        }
        double uv[2] = {e->u + h * d.du, e->v + h * d.dv};
        vertex n = {t_new, 0, 0, 0};
        if (proj->correct(proj, t_new, uv, NULL)) {
            n.u = uv[0];
            n.v = uv[1];
            const projcurve_status status = index_at(ctx, proj, &n);
            if (status != PROJCURVE_OK)
                return status;
            pc_vec3 a, b;
            pc_nurbs_surface_eval(s, e->u, e->v, 0, NULL, NULL, &a);
            pc_nurbs_surface_eval(s, n.u, n.v, 0, NULL, NULL, &b);
            const double allowed = CENTRE_MAX_MOTION * fabs(h) * d.speed + proj->newton_tol;
            if (n.index == e->index && vec3_dist(a, b) <= allowed) {
                *e = n;
                *moved = 1;
                continue;
            }
        }
        h *= 0.5;
    }
    return PROJCURVE_OK;
}

static int at_centre_end(projcurve_branch_end end)
{
    return end == PROJCURVE_END_SILHOUETTE || end == PROJCURVE_END_CURVATURE_CENTRE;
}

/* Pushes one end of branch k (last vertex when dir > 0, first otherwise). */
static projcurve_status extend_end(projcurve_context *ctx, const pc_projector *proj,
                                   double t_tol, pc_branch *b, int dir)
{
    if (b->n_points < 2)
        return PROJCURVE_OK;
    const size_t i_end = dir > 0 ? b->n_points - 1 : 0, i_next = dir > 0 ? i_end - 1 : 1;
    const double *p = b->points + 3 * i_end;
    vertex e = {p[0], p[1], p[2], 0};
    projcurve_status status = index_at(ctx, proj, &e);
    const double h = fabs(p[0] - b->points[3 * i_next]) * (dir > 0 ? 1.0 : -1.0);
    int moved = 0;
    if (status == PROJCURVE_OK)
        status = push_end(ctx, proj, t_tol, h, &e, &moved);
    if (status != PROJCURVE_OK || !moved)
        return status;
    const double v[3] = {e.t, e.u, e.v};
    return dir > 0 ? pc_branch_add_point(ctx, b, 3, v) : pc_branch_insert_point(ctx, b, 3, 0, v);
}

projcurve_status pc_ortho_extend_to_centres(projcurve_context *ctx, const pc_projector *proj,
                                            projcurve_result *r)
{
    const double t_tol = CENTRE_T_TOL_REL * (proj->curve->t1 - proj->curve->t0);
    projcurve_status status = PROJCURVE_OK;
    for (size_t k = 0; k < r->n_branches && status == PROJCURVE_OK; ++k) {
        pc_branch *b = &r->branches[k];
        if (at_centre_end(b->end))
            status = extend_end(ctx, proj, t_tol, b, 1);
        if (status == PROJCURVE_OK && b->start == PROJCURVE_START_SILHOUETTE)
            status = extend_end(ctx, proj, t_tol, b, -1);
    }
    return status;
}
