/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The selection of hits (hits.h). For each branch b, candidate cut points
 * are gathered: its ends, the ends of every branch overlapping it in t,
 * the crossings of its distance with theirs and with D (sign changes at
 * the vertices of either branch, each located by the Illinois variant of
 * regula falsi on exact distances). Between consecutive candidates
 * whether b is kept is constant; it is decided at the midpoint, and the
 * kept runs become the new branches.
 */
#include "hits/hits.h"

#include <math.h>
#include <stdlib.h>

#include "common/array.h"
#include "common/error.h"

/* Bound of the root iteration: Illinois converges superlinearly, and the
 * bracket is also halved whenever the secant leaves it, so 100 steps
 * reach any tolerance on a bracket of the branch's width; at the bound
 * the last iterate is taken (its |g| is then above the tolerance only by
 * the rounding of the distances). */
#define PC_HITS_ROOT_MAX_ITER 100

/* The shortest part kept, and the shortest interval between candidate
 * cuts or overlap of two branches considered, as a fraction of the
 * curve's domain: shorter ones are the rounding of a tie where two
 * branches meet (born at one point of a fold, or the two sides of a seam,
 * whose exits are located to ~1e-12). */
#define PC_HITS_MIN_PART 1e-9

int pc_hits_active(const pc_params *p)
{
    return p->hits == PROJCURVE_HITS_NEAREST || p->max_distance > 0.0;
}

typedef struct pc_cut {
    double t;
    int by_distance; /* a crossing of D, not of another branch */
} pc_cut;

typedef struct pc_cut_list {
    pc_cut *items;
    size_t count, capacity;
} pc_cut_list;

static projcurve_status push_cut(projcurve_context *ctx, pc_cut_list *l, double t, int by_d)
{
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, l, l->count + 1, 16, "the cuts of a branch");
    if (st == PROJCURVE_OK)
        l->items[l->count++] = (pc_cut){t, by_d};
    return st;
}

static double t_first(const pc_branch *b) { return b->points[0]; }
static double t_last(const pc_branch *b) { return b->points[3 * (b->n_points - 1)]; }

/* pc_hits_distance as one unit of the call's budget (NULL: none): an
 * exact point (a corrector call) and two evaluations, the cost of a
 * traced step. Returns the budget's status once it has stopped. */
static projcurve_status polled_distance(pc_budget *budget, const pc_projector *proj,
                                        const pc_branch *b, double t, double uv[2], double *out)
{
    const projcurve_status st = pc_budget_check(budget, 0.0);
    return st != PROJCURVE_OK ? st : pc_hits_distance(proj, b, t, uv, out);
}

/* g(t) = d_b(t) - d_j(t), or d_b(t) - D without j. */
typedef struct pc_gap_fn {
    const pc_projector *proj;
    const pc_branch *b, *j;
    double max_distance;
    pc_budget *budget; /* polled per distance; NULL: none */
} pc_gap_fn;

static projcurve_status gap_at(const pc_gap_fn *f, double t, double *g)
{
    double uv[2], db, dj;
    projcurve_status st = polled_distance(f->budget, f->proj, f->b, t, uv, &db);
    if (st == PROJCURVE_OK && f->j != NULL)
        st = polled_distance(f->budget, f->proj, f->j, t, uv, &dj);
    if (st == PROJCURVE_OK)
        *g = db - (f->j != NULL ? dj : f->max_distance);
    return st;
}

/* A root of g in [a, c] where g(a) = ga and g(c) = gc have opposite signs. */
static projcurve_status locate(const pc_gap_fn *f, double a, double ga, double c, double gc,
                               double tol, double *out)
{
    double x = 0.5 * (a + c);
    for (int it = 0; it < PC_HITS_ROOT_MAX_ITER; ++it) {
        x = c - gc * (c - a) / (gc - ga);
        if (!(x > fmin(a, c) && x < fmax(a, c)))
            x = 0.5 * (a + c);
        double gx;
        const projcurve_status st = gap_at(f, x, &gx);
        if (st != PROJCURVE_OK)
            return st;
        if (fabs(gx) <= tol || fabs(c - a) <= 1e-15 * (fabs(a) + fabs(c) + 1e-300))
            break;
        if ((gx < 0.0) != (gc < 0.0)) {
            a = c;
            ga = gc;
        } else {
            ga *= 0.5; /* Illinois: the end kept twice counts half */
        }
        c = x;
        gc = gx;
    }
    *out = x;
    return PROJCURVE_OK;
}

/* The next sample time after index *ib of b / *ij of j (both vertex
 * lists merged), within [lo, hi]; 0 when none is left. */
static int next_sample(const pc_branch *b, size_t *ib, const pc_branch *j, size_t *ij, double hi,
                       double *t)
{
    const double tb = *ib < b->n_points ? b->points[3 * *ib] : INFINITY;
    const double tj = j != NULL && *ij < j->n_points ? j->points[3 * *ij] : INFINITY;
    if (tb <= tj)
        ++*ib;
    else
        ++*ij;
    *t = fmin(tb, tj);
    return *t <= hi;
}

/* The crossings of g over [lo, hi] (sampled at the vertices of b and j
 * there, and at lo and hi) pushed as cuts. */
static projcurve_status push_crossings(projcurve_context *ctx, const pc_gap_fn *f, double lo,
                                       double hi, double tol, pc_cut_list *cuts)
{
    size_t ib = 0, ij = 0;
    while (ib < f->b->n_points && f->b->points[3 * ib] <= lo)
        ++ib;
    while (f->j != NULL && ij < f->j->n_points && f->j->points[3 * ij] <= lo)
        ++ij;
    double t_prev = lo, g_prev, t;
    projcurve_status st = gap_at(f, lo, &g_prev);
    int more = 1;
    while (st == PROJCURVE_OK && more) {
        more = next_sample(f->b, &ib, f->j, &ij, hi, &t);
        if (!more)
            t = hi;
        if (!(t > t_prev))
            continue;
        double g;
        st = gap_at(f, t, &g);
        if (st == PROJCURVE_OK && (g < 0.0) != (g_prev < 0.0)) {
            double root;
            st = locate(f, t_prev, g_prev, t, g, tol, &root);
            if (st == PROJCURVE_OK)
                st = push_cut(ctx, cuts, root, f->j == NULL);
        }
        t_prev = t;
        g_prev = g;
    }
    return st;
}

/* Whether b (index bi) is kept at t against the original branches (the
 * first n0; the parts appended after them copy those). Ties within tol go
 * to the lower index. */
static projcurve_status kept_at(const pc_projector *proj, const pc_params *p,
                                pc_budget *budget, const projcurve_result *r, size_t n0,
                                size_t bi, double t, double tol, int *keep)
{
    double uv[2], db;
    projcurve_status st = polled_distance(budget, proj, &r->branches[bi], t, uv, &db);
    *keep = st == PROJCURVE_OK && (p->max_distance <= 0.0 || db <= p->max_distance);
    if (p->hits != PROJCURVE_HITS_NEAREST)
        return st;
    for (size_t j = 0; st == PROJCURVE_OK && *keep && j < n0; ++j) {
        const pc_branch *o = &r->branches[j];
        if (j == bi || o->n_points < 2 || t < t_first(o) || t > t_last(o))
            continue;
        double dj;
        st = polled_distance(budget, proj, o, t, uv, &dj);
        if (st == PROJCURVE_OK && (dj < db - tol || (fabs(dj - db) <= tol && j < bi)))
            *keep = 0;
    }
    return st;
}

static int cut_order(const void *x, const void *y)
{
    const double a = ((const pc_cut *)x)->t, b = ((const pc_cut *)y)->t;
    return (a > b) - (a < b);
}

/* The candidate cuts of branch bi against the first n0 branches, sorted. */
static projcurve_status gather_cuts(projcurve_context *ctx, const pc_projector *proj,
                                    const pc_params *p, pc_budget *budget,
                                    const projcurve_result *r, size_t n0, size_t bi, double tol,
                                    pc_cut_list *cuts)
{
    const pc_branch *b = &r->branches[bi];
    const double lo = t_first(b), hi = t_last(b);
    const double min_len = PC_HITS_MIN_PART * (proj->curve->t1 - proj->curve->t0);
    projcurve_status st = push_cut(ctx, cuts, lo, 0);
    if (st == PROJCURVE_OK)
        st = push_cut(ctx, cuts, hi, 0);
    if (st == PROJCURVE_OK && p->max_distance > 0.0) {
        const pc_gap_fn f = {proj, b, NULL, p->max_distance, budget};
        st = push_crossings(ctx, &f, lo, hi, tol, cuts);
    }
    for (size_t j = 0; p->hits == PROJCURVE_HITS_NEAREST && j < n0; ++j) {
        const pc_branch *o = &r->branches[j];
        if (st != PROJCURVE_OK || j == bi || o->n_points < 2)
            continue;
        const double a = fmax(lo, t_first(o)), c = fmin(hi, t_last(o));
        if (!(c - a > min_len))
            continue; /* touching (a seam: one ends where the other starts) */
        st = push_cut(ctx, cuts, a, 0);
        if (st == PROJCURVE_OK)
            st = push_cut(ctx, cuts, c, 0);
        const pc_gap_fn f = {proj, b, o, 0.0, budget};
        if (st == PROJCURVE_OK)
            st = push_crossings(ctx, &f, a, c, tol, cuts);
    }
    if (st == PROJCURVE_OK)
        qsort(cuts->items, cuts->count, sizeof *cuts->items, cut_order);
    return st;
}

/* Appends to r the part of branch bi over [s, e] (cuts cs, ce), with the
 * exact points at its cut ends. */
static projcurve_status add_part(projcurve_context *ctx, const pc_projector *proj,
                                 projcurve_result *r, size_t bi, const pc_cut *cs,
                                 const pc_cut *ce)
{
    /* a part this short (of the curve's domain) is the rounding of a tie
     * at a fold, where two branches are born at one point with the same
     * distance: no curve */
    if (!(ce->t - cs->t > PC_HITS_MIN_PART * (proj->curve->t1 - proj->curve->t0)))
        return PROJCURVE_OK;
    pc_branch *nb = NULL;
    projcurve_status st = pc_result_add_branch(ctx, r, &nb);
    if (st != PROJCURVE_OK)
        return st;
    const pc_branch *b = &r->branches[bi]; /* after the array may have moved */
    const double lo = t_first(b), hi = t_last(b), s = cs->t, e = ce->t;
    const double eps = 1e-13 * (hi - lo);
    nb->start = s <= lo ? b->start
                : cs->by_distance ? PROJCURVE_START_MAX_DISTANCE
                                  : PROJCURVE_START_VISIBLE;
    nb->end = e >= hi ? b->end : ce->by_distance ? PROJCURVE_END_MAX_DISTANCE
                                                 : PROJCURVE_END_OCCLUDED;
    double pt[3], d;
    if (s > lo) {
        pt[0] = s;
        st = pc_hits_distance(proj, b, s, pt + 1, &d);
        if (st == PROJCURVE_OK)
            st = pc_branch_add_point(ctx, nb, 3, pt);
    }
    for (size_t k = 0; st == PROJCURVE_OK && k < b->n_points; ++k) {
        const double t = b->points[3 * k];
        const int inside = (s <= lo && t == lo) || (e >= hi && t == hi) ||
                           (t > s + eps && t < e - eps);
        if (inside)
            st = pc_branch_add_point(ctx, nb, 3, b->points + 3 * k);
    }
    if (st == PROJCURVE_OK && e < hi) {
        pt[0] = e;
        st = pc_hits_distance(proj, b, e, pt + 1, &d);
        if (st == PROJCURVE_OK)
            st = pc_branch_add_point(ctx, nb, 3, pt);
    }
    return st;
}

/* The kept parts of branch bi (one of the first n0) appended to r. When
 * the budget stops it, the parts appended so far are whole kept parts. */
static projcurve_status split_branch(projcurve_context *ctx, const pc_projector *proj,
                                     const pc_params *p, pc_budget *budget, projcurve_result *r,
                                     size_t n0, size_t bi, double tol)
{
    pc_cut_list cuts = {0};
    projcurve_status st = gather_cuts(ctx, proj, p, budget, r, n0, bi, tol, &cuts);
    const double min_len = PC_HITS_MIN_PART * (proj->curve->t1 - proj->curve->t0);
    size_t run_start = cuts.count; /* index of the cut opening the current kept run */
    for (size_t k = 0; st == PROJCURVE_OK && k + 1 < cuts.count; ++k) {
        const double a = cuts.items[k].t, c = cuts.items[k + 1].t;
        if (!(c - a > min_len))
            continue; /* coincident candidates: no interval between */
        int keep = 0;
        st = kept_at(proj, p, budget, r, n0, bi, 0.5 * (a + c), tol, &keep);
        if (st != PROJCURVE_OK)
            break;
        if (keep && run_start == cuts.count)
            run_start = k;
        if (!keep && run_start != cuts.count) {
            st = add_part(ctx, proj, r, bi, &cuts.items[run_start], &cuts.items[k]);
            run_start = cuts.count;
        }
    }
    if (st == PROJCURVE_OK && run_start != cuts.count)
        st = add_part(ctx, proj, r, bi, &cuts.items[run_start], &cuts.items[cuts.count - 1]);
    free(cuts.items);
    return st;
}

projcurve_status pc_hits_select(projcurve_context *ctx, const pc_projector *proj,
                                const pc_params *p, projcurve_result *r)
{
    if (!pc_hits_active(p) || r->point_dim != 3)
        return PROJCURVE_OK;
    const double tol = PC_HITS_ROOT_TOL * proj->model_size;
    const size_t n0 = r->n_branches;
    /* polled only when the call still runs: after a stop in tracing the
     * selection is made on the partial result, bounded by its size */
    pc_budget *const budget = pc_budget_if_running(p->budget);
    pc_budget_step(budget, "selecting the hits");
    projcurve_status st = PROJCURVE_OK;
    for (size_t i = 0; st == PROJCURVE_OK && i < n0; ++i)
        if (r->branches[i].n_points >= 2)
            st = split_branch(ctx, proj, p, budget, r, n0, i, tol);
    pc_budget_step(budget, NULL);
    const int stopped = st != PROJCURVE_OK && pc_budget_status(budget) == st;
    if (stopped) {
        /* the parts kept so far stay, the last ending where the budget
         * stopped (END_LIMIT); the branches not yet selected go */
        if (r->n_branches > n0)
            r->branches[r->n_branches - 1].end = PROJCURVE_END_LIMIT;
        st = pc_budget_fail(budget, ctx);
    } else if (st == PROJCURVE_ERR_CALLBACK) {
        st = pc_fail(ctx, st, "the curve callback failed while selecting the hits");
    }
    /* on another failure the parts made so far go, the originals stay */
    const size_t drop_from = st == PROJCURVE_OK || stopped ? 0 : n0;
    const size_t drop_to = st == PROJCURVE_OK || stopped ? n0 : r->n_branches;
    for (size_t i = drop_to; i-- > drop_from;)
        pc_result_remove_branch(r, i);
    return st;
}
