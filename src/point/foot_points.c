/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Every interior foot point of a point on a surface: the seeds of the
 * orthogonal projection ([PW96]), which must not miss a branch.
 *
 * Every patch is subdivided (those of BVH nodes where the tangent boxes
 * prove that (S - p).Su or (S - p).Sv keeps one sign are skipped whole,
 * bezier/tangent_boxes.h); a sub-patch is discarded when its control net
 * proves that (S - p).Su or (S - p).Sv keeps one sign over it (no foot
 * point inside). Around each foot point only the few sub-patches that
 * contain or touch it survive; once flat they start Newton from their
 * centre and, when that converges to a foot point outside the sub-patch,
 * from four more points (unless a foot point found before lies in the
 * sub-patch).
 * Newton's steps are limited to the sub-patch size so that each start
 * converges to the foot point of its own basin. Duplicates (a foot point on
 * a shared edge is found from both sides) are merged at the end.
 */
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"
#include "point/point.h"
#include "point/subdivide.h"

/* Smallest capacity of a foot list. */
#define PC_FOOT_LIST_MIN_CAPACITY 16

#define FEET_FLATNESS 0.15
/* Two foot points closer than this fraction of the domain in both
 * parameters are one. */
#define FEET_SAME_PARAM 1e-8
/* Newton starts per call; only a continuum of foot points (p at the centre
 * of a sphere) comes near it. */
#define FEET_MAX_STARTS 4096
/* Newton starts per Bezier patch, so that no patch can spend the call's
 * FEET_MAX_STARTS before the others are searched. A knot span of width
 * 1.8e-8 in v (linkrods.step surface 16, degree 6 x 10, rational, spans
 * 10 to 17 of 30) has a control net blown up by the rounding of its
 * extraction (box ~30 across, the span itself ~0.2): nothing in it is
 * culled, and its sub-patches took 618 starts each, all 4096 before the
 * search reached span 29, which held the only foot point. */
#define FEET_MAX_PATCH_STARTS 256
/* |Su x Sv| below this fraction of |Su|^2 + |Sv|^2: a singular point. */
#define FEET_SINGULAR 1e-8
/* A patch narrower than this fraction of the domain in u or v is a knot
 * span of rounding width (hammer.iges surface 9 has [-1.5e-14, 0] in u):
 * in space it is its edge curve, and its derivatives, divided by that
 * width, point anywhere. Its "foot points" satisfy G = 0 for those
 * derivatives, not for the surface: it is not searched (the foot points
 * on that edge are the neighbouring patch's). */
#define FEET_MIN_SPAN 1e-12

typedef struct feet_search {
    const projcurve_surface *s;
    pc_vec3 p;
    pc_subdiv_work *work; /* not inside: an initialiser of this struct would zero its scratch */
    pc_foot_list *list;
    size_t starts;
    size_t patch_starts; /* the starts of the patch being searched */
    projcurve_status status;
    projcurve_context *ctx;
    pc_budget *budget; /* NULL: none */
} feet_search;

void pc_foot_list_free(pc_foot_list *list)
{
    PC_ARRAY_FREE(list);
}

static int push_foot(feet_search *fs, double u, double v)
{
    pc_foot_list *l = fs->list;
    projcurve_status st;
    PC_ARRAY_RESERVE(st, fs->ctx, l, l->count + 1, PC_FOOT_LIST_MIN_CAPACITY, "the foot points");
    if (st != PROJCURVE_OK) {
        fs->status = st;
        return 0;
    }
    pc_surface_point *f = &l->items[l->count++];
    f->u = u;
    f->v = v;
    pc_nurbs_surface_eval(&fs->s->nurbs, u, v, 0, NULL, NULL, &f->q);
    f->dist = vec3_dist(f->q, fs->p);
    return 1;
}

/* Singular points of the parametrisation (the poles of a sphere, where
 * Su = 0) satisfy G = 0 whatever p is: their normal is undefined and they
 * are not reported. */
static int is_regular(const pc_nurbs_surface *s, double u, double v)
{
    pc_vec3 d[3];
    pc_nurbs_surface_eval(s, u, v, 1, NULL, NULL, d);
    const double area = vec3_norm(vec3_cross(d[1], d[2]));
    return area > FEET_SINGULAR * (vec3_dot(d[1], d[1]) + vec3_dot(d[2], d[2]));
}

/* 1 when x lies strictly inside a span of breaks narrower than
 * FEET_MIN_SPAN of the domain [breaks[0], breaks[n]]. */
static int in_thin_span(const double *breaks, size_t n, double x)
{
    const double thin = FEET_MIN_SPAN * (breaks[n] - breaks[0]);
    for (size_t k = 0; k < n; ++k)
        if (breaks[k + 1] - breaks[k] <= thin && x > breaks[k] && x < breaks[k + 1])
            return 1;
    return 0;
}

/* 1 when the foot point (u, v) is a local minimum of |S - p|: its Hessian
 * H = [g_ij + (S - p).S_ij] is positive definite ([PW96], the matrix K). */
static int is_minimum(const pc_nurbs_surface *s, pc_vec3 p, double u, double v)
{
    pc_vec3 d[6];
    pc_nurbs_surface_eval(s, u, v, 2, NULL, NULL, d);
    const pc_vec3 r = vec3_sub(d[0], p);
    const double h11 = vec3_dot(d[1], d[1]) + vec3_dot(r, d[3]);
    const double h12 = vec3_dot(d[1], d[2]) + vec3_dot(r, d[4]);
    const double h22 = vec3_dot(d[2], d[2]) + vec3_dot(r, d[5]);
    return h11 > 0.0 && h11 * h22 - h12 * h12 > 0.0;
}

/* 1 when the call or the current patch has no Newton start left. */
static int out_of_starts(const feet_search *fs)
{
    return fs->starts >= FEET_MAX_STARTS || fs->patch_starts >= FEET_MAX_PATCH_STARTS;
}

/* Newton from (u, v): 0 if it failed, 1 if it converged inside the
 * sub-patch (grown by half its size), 2 if it converged farther away,
 * 3 if it converged inside to a foot point that is no local minimum. */
static int start_newton(feet_search *fs, const pc_subpatch *sp, double u, double v)
{
    ++fs->starts;
    ++fs->patch_starts;
    const double hu = sp->u1 - sp->u0, hv = sp->v1 - sp->v0;
    double uv[2] = {u, v};
    const pc_patch_grid *g = &fs->s->grid;
    if (!pc_surface_foot_newton(&fs->s->nurbs, fs->p, fs->s->size, hu, hv, uv) ||
        !is_regular(&fs->s->nurbs, uv[0], uv[1]) ||
        in_thin_span(g->breaks_u, g->spans_u, uv[0]) || in_thin_span(g->breaks_v, g->spans_v, uv[1]))
        return 0; /* a thin span's "foot points" are its derivatives' (FEET_MIN_SPAN) */
    if (!push_foot(fs, uv[0], uv[1]))
        return 1;
    const int inside = uv[0] >= sp->u0 - 0.5 * hu && uv[0] <= sp->u1 + 0.5 * hu &&
                       uv[1] >= sp->v0 - 0.5 * hv && uv[1] <= sp->v1 + 0.5 * hv;
    if (!inside)
        return 2;
    return is_minimum(&fs->s->nurbs, fs->p, uv[0], uv[1]) ? 1 : 3;
}

/* A saddle or maximum found in a flat sub-patch means det H changes sign
 * nearby (critical points of different index are separated by a curve where
 * det H = 0, where p is a centre of curvature), so the sub-patch may hold a
 * minimum beside it that Newton from its centre does not reach: it lands on
 * the saddle (teapot body patch 0: a saddle and a minimum 0.29 apart in v in
 * one flat quarter). A descent cannot land on a saddle: from each quarter
 * point the distance is minimised (pc_surface_minimize, bounded) and Newton
 * started where it stopped; a minimum on the domain's edge is no foot point
 * and Newton drops it. */
static void descend_from_quarters(feet_search *fs, const pc_subpatch *sp)
{
    static const double quarter[4][2] = {{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}};
    const double hu = sp->u1 - sp->u0, hv = sp->v1 - sp->v0;
    for (int k = 0; k < 4 && !out_of_starts(fs); ++k) {
        double uv[2] = {sp->u0 + quarter[k][0] * hu, sp->v0 + quarter[k][1] * hv};
        pc_surface_minimize(&fs->s->nurbs, fs->p, fs->s->size, uv);
        start_newton(fs, sp, uv[0], uv[1]);
    }
}

static pc_subdiv_action decide_feet(void *user, const pc_subpatch *sp)
{
    feet_search *fs = user;
    const pc_nurbs_surface *n = &fs->s->nurbs;
    if (fs->status != PROJCURVE_OK)
        return PC_SUBDIV_DROP;
    /* a sub-patch is a unit of the call's budget (0: no news of progress) */
    if (pc_budget_check(fs->budget, 0.0) != PROJCURVE_OK)
        return PC_SUBDIV_DROP;
    if (!pc_subpatch_may_hold_foot(sp, n->deg_u, n->deg_v, n->rational, fs->p))
        return PC_SUBDIV_DROP;
    const int leaf = pc_subpatch_flatness(sp, n->deg_u, n->deg_v) <= FEET_FLATNESS ||
                     sp->depth >= PC_SUBDIV_MAX_DEPTH || out_of_starts(fs);
    if (!leaf)
        return PC_SUBDIV_SPLIT;
    if (out_of_starts(fs))
        return PC_SUBDIV_STOP;
    const double hu = sp->u1 - sp->u0, hv = sp->v1 - sp->v0;
    /* A flat sub-patch holding a foot point already found holds no other
     * (short of two foot points merging, where p is a centre of
     * curvature): skip its Newton, which would find the same one again.
     * Unless that one is no minimum (descend_from_quarters). */
    for (size_t k = 0; k < fs->list->count; ++k) {
        const pc_surface_point *f = &fs->list->items[k];
        if (f->u >= sp->u0 && f->u <= sp->u1 && f->v >= sp->v0 && f->v <= sp->v1) {
            if (!is_minimum(n, fs->p, f->u, f->v))
                descend_from_quarters(fs, sp);
            return PC_SUBDIV_STOP;
        }
    }
    const int found = start_newton(fs, sp, sp->u0 + 0.5 * hu, sp->v0 + 0.5 * hv);
    if (found == 2) {
        static const double quarter[4][2] = {{0.25, 0.25}, {0.75, 0.25}, {0.25, 0.75}, {0.75, 0.75}};
        for (int k = 0; k < 4; ++k)
            start_newton(fs, sp, sp->u0 + quarter[k][0] * hu, sp->v0 + quarter[k][1] * hv);
    }
    if (found == 3)
        descend_from_quarters(fs, sp);
    return PC_SUBDIV_STOP;
}

static int by_distance(const void *a, const void *b)
{
    const pc_surface_point *x = a, *y = b;
    if (x->dist != y->dist)
        return x->dist < y->dist ? -1 : 1;
    if (x->u != y->u)
        return x->u < y->u ? -1 : 1;
    return x->v < y->v ? -1 : (x->v > y->v ? 1 : 0);
}

static int by_u(const void *a, const void *b)
{
    const pc_surface_point *x = a, *y = b;
    if (x->u != y->u)
        return x->u < y->u ? -1 : 1;
    return x->v < y->v ? -1 : (x->v > y->v ? 1 : 0);
}

/* Keeps one of each cluster of equal foot points (a sweep in u: only kept
 * points within the u tolerance are compared), then sorts by distance. */
static void merge_duplicates(pc_foot_list *l, const double dom[4])
{
    if (l->count < 2)
        return;   /* nothing to merge; items may be NULL, which qsort must not get */
    qsort(l->items, l->count, sizeof *l->items, by_u);
    const double tol_u = FEET_SAME_PARAM * (dom[1] - dom[0]);
    const double tol_v = FEET_SAME_PARAM * (dom[3] - dom[2]);
    size_t kept = 0;
    for (size_t i = 0; i < l->count; ++i) {
        int dup = 0;
        for (size_t k = kept; k > 0 && !dup && l->items[k - 1].u >= l->items[i].u - tol_u; --k)
            dup = fabs(l->items[k - 1].v - l->items[i].v) <= tol_v;
        if (!dup)
            l->items[kept++] = l->items[i];
    }
    l->count = kept;
    qsort(l->items, l->count, sizeof *l->items, by_distance);
}

/* The BVH walk: nodes where (S - p).Su and (S - p).Sv may both vanish, and
 * in their leaves every patch, each subdivided as above. */
static int enter_node(void *user, size_t node_index)
{
    const feet_search *fs = user;
    return pc_tangent_boxes_may_hold_foot(&fs->s->tangents, &fs->s->bvh, node_index, fs->p);
}

/* 1 when the patch has the extent FEET_MIN_SPAN asks for. */
static int has_extent(const projcurve_surface *s, const pc_bezier_patch *patch)
{
    const double *dom = s->nurbs.domain;
    return patch->u1 - patch->u0 > FEET_MIN_SPAN * (dom[1] - dom[0]) &&
           patch->v1 - patch->v0 > FEET_MIN_SPAN * (dom[3] - dom[2]);
}

static int search_patch(void *user, size_t patch_index)
{
    feet_search *fs = user;
    const pc_bezier_patch *patch = &fs->s->grid.patches[patch_index];
    fs->patch_starts = 0;
    if (has_extent(fs->s, patch))
        pc_subdiv_walk(fs->work, patch, decide_feet, fs);
    return fs->status != PROJCURVE_OK;
}

/* The search over the patches the BVH walk keeps (use_tree) or over all. */
static projcurve_status foot_points(projcurve_context *ctx, const projcurve_surface *s, pc_vec3 p,
                                    int use_tree, pc_budget *budget, pc_foot_list *list)
{
    list->count = 0;
    pc_subdiv_work work;
    feet_search fs = {s, p, &work, list, 0, 0, PROJCURVE_OK, ctx, budget};
    projcurve_status st = pc_subdiv_work_init(ctx, fs.work, s->nurbs.deg_u, s->nurbs.deg_v);
    if (st != PROJCURVE_OK)
        return st;
    if (use_tree && s->tangents.node != NULL) {
        pc_bvh_query_nodes(&s->bvh, enter_node, search_patch, &fs);
    } else {
        const size_t n_patches = s->grid.spans_u * s->grid.spans_v;
        for (size_t k = 0; k < n_patches && fs.status == PROJCURVE_OK; ++k)
            search_patch(&fs, k);
    }
    pc_subdiv_work_free(fs.work);
    if (fs.status != PROJCURVE_OK)
        return fs.status;
    merge_duplicates(list, s->nurbs.domain);
    return PROJCURVE_OK;
}

projcurve_status pc_surface_foot_points(projcurve_context *ctx, const projcurve_surface *s,
                                        pc_vec3 p, pc_foot_list *list)
{
    return foot_points(ctx, s, p, 1, NULL, list);
}

projcurve_status pc_surface_foot_points_uv(projcurve_context *ctx, const projcurve_surface *s,
                                           pc_vec3 p, pc_budget *budget, size_t capacity,
                                           double *uv, size_t *count)
{
    pc_foot_list list = {NULL, 0, 0};
    const projcurve_status st = foot_points(ctx, s, p, 1, budget, &list);
    if (st == PROJCURVE_OK) {
        for (size_t k = 0; k < list.count && k < capacity; ++k) {
            uv[2 * k] = list.items[k].u;
            uv[2 * k + 1] = list.items[k].v;
        }
        *count = list.count;
    }
    pc_foot_list_free(&list);
    return st;
}

projcurve_status pc_surface_foot_points_exhaustive(projcurve_context *ctx,
                                                   const projcurve_surface *s, pc_vec3 p,
                                                   pc_foot_list *list)
{
    return foot_points(ctx, s, p, 0, NULL, list);
}
