/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Closest point of a surface to a point.
 *
 * The minimum of |S - p| over the domain is either an interior foot point
 * or a minimum on the boundary (an edge or a corner). Patches are visited
 * nearest first through the BVH; each is subdivided while a sub-patch may
 * still beat the best distance found so far:
 *   - its control-net box (which contains it) is nearer than the best, and
 *   - it touches the domain boundary or a crease, or it may hold a foot
 *     point.
 * A surviving sub-patch that is flat (or at the depth limit) starts the
 * bound-constrained minimiser at its control point nearest to p. The first
 * patch visited gives a good bound at once, after which most patches are
 * discarded by their box alone.
 */
#include <stdlib.h>

#include "common/error.h"
#include "point/point.h"
#include "point/subdivide.h"

/* Sub-patches whose control net deviates from a bilinear patch by less
 * than this fraction of their size are not split further: the distance has
 * a single basin there for all but pathological points. */
#define CLOSEST_FLATNESS 0.15
/* Newton starts stay this fraction of a sub-patch away from its edges. */
#define START_MARGIN 0.02
/* A minimiser result this close (relative to the domain) to a crease is
 * finished on it. */
#define CREASE_SNAP 1e-6

typedef struct closest_search {
    const projcurve_surface *s;
    pc_vec3 p;
    pc_subdiv_work *work; /* not inside: an initialiser of this struct would zero its scratch */
    double best_d2;
    pc_surface_point best;
    const pc_bezier_patch *patch; /* the patch being walked */
    const unsigned char *crease_u; /* the grid's crease flags */
    const unsigned char *crease_v;
} closest_search;

/* Parameters of the control point of the sub-patch nearest to p (control
 * point (i, j) sits near parameter (i / deg_u, j / deg_v) of the box). */
static void nearest_control_param(const pc_subpatch *sp, int p_deg, int q_deg, pc_vec3 p,
                                  double uv[2])
{
    size_t best = 0;
    double best_d2 = INFINITY;
    const size_t n = ((size_t)p_deg + 1) * ((size_t)q_deg + 1);
    for (size_t k = 0; k < n; ++k) {
        const double d2 = vec3_dot(vec3_sub(vec3_load(sp->xyz + 3 * k), p),
                                   vec3_sub(vec3_load(sp->xyz + 3 * k), p));
        if (d2 < best_d2) {
            best_d2 = d2;
            best = k;
        }
    }
    const size_t i = best % ((size_t)p_deg + 1), j = best / ((size_t)p_deg + 1);
    /* Kept strictly inside: on a patch edge the derivatives would be those
     * of the neighbouring patch. */
    const double s = fmin(fmax((double)i / p_deg, START_MARGIN), 1.0 - START_MARGIN);
    const double t = fmin(fmax((double)j / q_deg, START_MARGIN), 1.0 - START_MARGIN);
    uv[0] = sp->u0 + (sp->u1 - sp->u0) * s;
    uv[1] = sp->v0 + (sp->v1 - sp->v0) * t;
}

/* Index of the crease break nearest to x within tol, or -1. */
static long crease_near(const double *breaks, const unsigned char *crease, size_t spans, double x,
                        double tol)
{
    for (size_t k = 0; k <= spans; ++k)
        if (crease[k] && fabs(breaks[k] - x) <= tol)
            return (long)k;
    return -1;
}

/* The minimiser stalls on a crease (the kink stops Newton): finish the
 * minimum along the crease line, with the crossing parameter held on it. */
static double finish_on_crease(closest_search *cs, double uv[2], double d2)
{
    const pc_patch_grid *g = &cs->s->grid;
    const double *dom = cs->s->nurbs.domain;
    for (int dir = 0; dir < 2; ++dir) {
        const double *breaks = dir == 0 ? g->breaks_u : g->breaks_v;
        const unsigned char *crease = dir == 0 ? cs->crease_u : cs->crease_v;
        const size_t spans = dir == 0 ? g->spans_u : g->spans_v;
        const double tol = CREASE_SNAP * (dom[2 * dir + 1] - dom[2 * dir]);
        const long k = crease_near(breaks, crease, spans, uv[dir], tol);
        if (k < 0)
            continue;
        double on[2] = {uv[0], uv[1]};
        on[dir] = breaks[k];
        const double e2 = pc_surface_minimize_along(&cs->s->nurbs, cs->p, cs->s->size, on, 1 - dir);
        if (e2 <= d2) {
            uv[0] = on[0];
            uv[1] = on[1];
            d2 = e2;
        }
    }
    return d2;
}

static void try_start(closest_search *cs, const double start[2])
{
    double uv[2] = {start[0], start[1]};
    double d2 = pc_surface_minimize(&cs->s->nurbs, cs->p, cs->s->size, uv);
    d2 = finish_on_crease(cs, uv, d2);
    if (d2 < cs->best_d2) {
        cs->best_d2 = d2;
        cs->best.u = uv[0];
        cs->best.v = uv[1];
    }
}

/* Minima that are not foot points lie on the domain boundary or on creases
 * (where S is only C^0 and G may jump over 0): a sub-patch touching one of
 * those must not be discarded by the foot point test. */
static int touches_crease(const closest_search *cs, const pc_subpatch *sp)
{
    const pc_bezier_patch *pt = cs->patch;
    return (sp->u0 <= pt->u0 && cs->crease_u[pt->iu]) ||
           (sp->u1 >= pt->u1 && cs->crease_u[pt->iu + 1]) ||
           (sp->v0 <= pt->v0 && cs->crease_v[pt->iv]) ||
           (sp->v1 >= pt->v1 && cs->crease_v[pt->iv + 1]);
}

static pc_subdiv_action decide_closest(void *user, const pc_subpatch *sp)
{
    closest_search *cs = user;
    const pc_nurbs_surface *n = &cs->s->nurbs;
    if (!(pc_box_distance_sq(sp->box, cs->p) < cs->best_d2))
        return PC_SUBDIV_DROP;
    if (!touches_crease(cs, sp) &&
        !pc_subpatch_may_hold_foot(sp, n->deg_u, n->deg_v, n->rational, cs->p))
        return PC_SUBDIV_DROP;
    const int flat = pc_subpatch_flatness(sp, n->deg_u, n->deg_v) <= CLOSEST_FLATNESS;
    /* Start the minimiser on flat sub-patches, and on the very first patch
     * (nearest to p) at once to get a bound that discards most others;
     * not where the best point found so far already lies inside (its basin
     * is this sub-patch's). A best point on the sub-patch's edge does not
     * count: it may be a minimum on a crease or in the neighbour, with the
     * sub-patch's own minimum elsewhere. */
    const int holds_best = cs->best.u > sp->u0 && cs->best.u < sp->u1 &&
                           cs->best.v > sp->v0 && cs->best.v < sp->v1;
    if ((cs->best_d2 == INFINITY || flat || sp->depth >= PC_SUBDIV_MAX_DEPTH) && !holds_best) {
        double uv[2];
        nearest_control_param(sp, n->deg_u, n->deg_v, cs->p, uv);
        try_start(cs, uv);
    }
    return flat ? PC_SUBDIV_STOP : PC_SUBDIV_SPLIT;
}

static double visit_patch(void *user, size_t patch_index, double box_distance_sq)
{
    closest_search *cs = user;
    (void)box_distance_sq;
    cs->patch = &cs->s->grid.patches[patch_index];
    pc_subdiv_walk(cs->work, &cs->s->grid.patches[patch_index], decide_closest, cs);
    return cs->best_d2;
}

projcurve_status pc_surface_closest(projcurve_context *ctx, const projcurve_surface *s,
                                    pc_vec3 p, pc_surface_point *out)
{
    pc_subdiv_work work;
    closest_search cs = {.s = s,
                         .p = p,
                         .work = &work,
                         .best_d2 = INFINITY,
                         .crease_u = s->grid.crease_u,
                         .crease_v = s->grid.crease_v};
    const pc_nurbs_surface *n = &s->nurbs;
    const projcurve_status st = pc_subdiv_work_init(ctx, cs.work, n->deg_u, n->deg_v);
    if (st != PROJCURVE_OK)
        return st;
    cs.best.u = cs.best.v = NAN; /* nothing found yet */
    pc_bvh_query_nearest(&s->bvh, p, visit_patch, &cs);
    pc_subdiv_work_free(cs.work);
    if (isnan(cs.best.u)) { /* cannot happen: some patch holds the minimum */
        cs.best.u = s->nurbs.domain[0];
        cs.best.v = s->nurbs.domain[2];
    }
    pc_nurbs_surface_eval(&s->nurbs, cs.best.u, cs.best.v, 0, NULL, NULL, &cs.best.q);
    cs.best.dist = vec3_dist(cs.best.q, p);
    *out = cs.best;
    return PROJCURVE_OK;
}
