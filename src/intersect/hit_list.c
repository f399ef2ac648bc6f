/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The hit list: growth, and the final pass that sorts hits by lambda, merges
 * the copies of one hit and flags the ones on the domain's boundary.
 */
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"
#include "intersect/ray_patch.h"

/* Two hits are one when their lambda differ by at most this fraction of
 * the model's scale: the same point of the line, hence of space. Newton
 * gives lambda to ~1e-15 of it, so copies of a hit agree far closer, while
 * two distinct crossings this close along a line are sheets of the surface
 * within 1e-8 of each other, one crossing to the eye. Parameters closer
 * than this fraction of the domain count as equal when choosing the copy
 * kept. */
#define PC_DEDUP_REL 1e-8
/* The same for grazing hits: a double root is only determined to about
 * sqrt(rounding) ~ 1e-8 along the tangent, and two roots this close along a
 * grazing line are reported as the one tangent hit they nearly are. */
#define PC_DEDUP_TANGENT_REL 1e-5
/* A hit this close (fraction of the domain) to an edge of it is on the
 * boundary. */
#define PC_BOUNDARY_REL 1e-9
/* Initial capacities. */
#define PC_HIT_LIST_MIN_CAPACITY 8

projcurve_status pc_hit_list_push(projcurve_context *ctx, pc_hit_list *list, pc_hit hit)
{
    void *items = list->items;
    const projcurve_status st =
        pc_array_reserve(ctx, &items, &list->capacity, list->count, list->count + 1,
                         sizeof *list->items, PC_HIT_LIST_MIN_CAPACITY, &list->items_borrowed,
                         "the hit list");
    list->items = items;
    if (st != PROJCURVE_OK)
        return st;
    list->items[list->count++] = hit;
    return PROJCURVE_OK;
}

projcurve_status pc_hit_list_reserve_work(projcurve_context *ctx, pc_hit_list *list, size_t n)
{
    if (list->work_capacity >= n)
        return PROJCURVE_OK;
    if (n > SIZE_MAX / sizeof *list->work)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "clipping scratch of %zu doubles is too large",
                       n);
    double *work = malloc(n * sizeof *work);
    if (work == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY,
                       "cannot allocate %zu doubles of clipping scratch", n);
    if (!list->work_borrowed)
        free(list->work);
    list->work = work;
    list->work_capacity = n;
    list->work_borrowed = 0;
    return PROJCURVE_OK;
}

void pc_hit_list_borrow(pc_hit_list *list, pc_hit *items, size_t n_items, double *work,
                        size_t n_work)
{
    *list = (pc_hit_list){items, 0, n_items, work, n_work, 1, 1};
}

void pc_hit_list_free(pc_hit_list *list)
{
    if (list == NULL)
        return;
    if (!list->items_borrowed)
        free(list->items);
    if (!list->work_borrowed)
        free(list->work);
    list->items_borrowed = list->work_borrowed = 0;
    list->items = NULL;
    list->work = NULL;
    list->count = list->capacity = list->work_capacity = 0;
}

/* By lambda, then u, then v: a total order, so that results do not depend
 * on the order in which patches were visited. */
static int compare_hits(const void *a, const void *b)
{
    const pc_hit *x = a, *y = b;
    if (x->lambda != y->lambda)
        return x->lambda < y->lambda ? -1 : 1;
    if (x->u != y->u)
        return x->u < y->u ? -1 : 1;
    if (x->v != y->v)
        return x->v < y->v ? -1 : 1;
    return 0;
}

typedef struct dedup_tolerances {
    double du, dv, dlambda;                 /* transversal hits */
    double du_tangent, dv_tangent, dlambda_tangent; /* when either is grazing */
    double residual;                        /* the hit tolerance */
} dedup_tolerances;

/* Two hits are one point of the line, hence one point in space, when their
 * lambda agree: whatever their (u, v). That merges the copies from shared
 * patch edges and corners and from neighbouring boxes, the two sides of a
 * closed surface's seam, the patches around a pole, and the sheets of a
 * surface folded onto itself (a knot cluster whose spans retrace one
 * sheet), which a user sees as one crossing. Grazing hits are known only to
 * ~sqrt(tolerance) along the line: they merge within the wider tolerance
 * when their parameters are close too or the surface between them hugs the
 * line. */
static int same_hit(const pc_hit *a, const pc_hit *b, const dedup_tolerances *tol,
                    const pc_graze_test *graze)
{
    if (fabs(a->lambda - b->lambda) <= tol->dlambda)
        return 1;
    const int tangent = ((a->flags | b->flags) & PROJCURVE_HIT_TANGENT) != 0;
    if (!tangent || !(fabs(a->lambda - b->lambda) <= tol->dlambda_tangent))
        return 0;
    if (fabs(a->u - b->u) <= tol->du_tangent && fabs(a->v - b->v) <= tol->dv_tangent)
        return 1;
    return graze != NULL && graze->same(graze->user, a, b);
}

/* Whether copy a, a transversal Newton root, outranks copy b, the
 * least-squares point of an unresolved box or a pole record at the same
 * place (boxes and poles of a degenerate patch: a span of near zero width
 * makes a patch a curve or a point, whose normal means nothing): Newton's
 * root with |d . n| >= PC_HIT_TANGENT_COS shows the hit is simple, and b's
 * tangent flag only says that b could not tell. */
static int newton_outranks(const pc_hit *a, const pc_hit *b)
{
    return !(a->flags & (PROJCURVE_HIT_TANGENT | PC_HIT_STALLED | PC_HIT_POLE)) &&
           (b->flags & (PC_HIT_STALLED | PC_HIT_POLE));
}

/* Which of two copies of one hit is kept: h (1) or k (0). Transversal
 * copies on the line to the hit tolerance are equally exact, and the one
 * with the smaller u (then v, beyond the merging tolerance) is kept, so that
 * a seam crossing is reported at the domain's start (u0, or v0) whichever
 * patch was visited first. Otherwise (grazing copies, which lie up to
 * ~sqrt(tolerance) apart along the line, or copies whose parameters cannot
 * put S on the line to the tolerance) the one nearest the line. */
static int keep_new(const pc_hit *h, const pc_hit *k, const dedup_tolerances *tol)
{
    if (newton_outranks(h, k) || newton_outranks(k, h))
        return newton_outranks(h, k);
    const int tangent = ((h->flags | k->flags) & PROJCURVE_HIT_TANGENT) != 0;
    if (tangent || !(h->residual <= tol->residual && k->residual <= tol->residual))
        return h->residual < k->residual;
    if (fabs(h->u - k->u) > tol->du)
        return h->u < k->u;
    return h->v < k->v - tol->dv;
}

void pc_hit_list_finish(pc_hit_list *list, const double domain[4], double dir_norm,
                        double scale, double tol_residual, const pc_graze_test *graze)
{
    const double span_u = domain[1] - domain[0], span_v = domain[3] - domain[2];
    if (list->count > 1)
        qsort(list->items, list->count, sizeof *list->items, compare_hits);
    dedup_tolerances tol;
    tol.du = PC_DEDUP_REL * span_u;
    tol.dv = PC_DEDUP_REL * span_v;
    tol.dlambda = PC_DEDUP_REL * scale / dir_norm; /* both hits lie on the line */
    tol.du_tangent = PC_DEDUP_TANGENT_REL * span_u;
    tol.dv_tangent = PC_DEDUP_TANGENT_REL * span_v;
    tol.dlambda_tangent = PC_DEDUP_TANGENT_REL * scale / dir_norm;
    tol.residual = tol_residual;
    size_t kept = 0;
    /* The kept hit the previous one went into, and that one's lambda: hits
     * are chained, so that a run of copies each within dlambda of the next
     * (the sheets of a folded knot cluster, spread over a little more than
     * dlambda) is one hit whatever copy represents it. */
    size_t prev_into = SIZE_MAX;
    double prev_lambda = 0.0;
    for (size_t i = 0; i < list->count; ++i) {
        const pc_hit h = list->items[i];
        size_t into = SIZE_MAX;
        if (prev_into != SIZE_MAX && h.lambda - prev_lambda <= tol.dlambda)
            into = prev_into;
        /* Sorted by lambda: only the last few kept hits can match. */
        for (size_t j = kept; into == SIZE_MAX && j-- > 0;) {
            if (h.lambda - list->items[j].lambda > tol.dlambda_tangent)
                break;
            if (same_hit(&list->items[j], &h, &tol, graze))
                into = j;
        }
        if (into == SIZE_MAX) {
            into = kept;
            list->items[kept++] = h;
        } else {
            pc_hit *k = &list->items[into];
            unsigned flags = k->flags | h.flags;
            if (newton_outranks(&h, k) || newton_outranks(k, &h))
                flags = newton_outranks(&h, k) ? h.flags : k->flags;
            if (keep_new(&h, k, &tol))
                *k = h;
            k->flags = flags;
        }
        prev_into = into;
        prev_lambda = h.lambda;
    }
    list->count = kept;
    for (size_t i = 0; i < kept; ++i) {
        pc_hit *h = &list->items[i];
        const double bu = PC_BOUNDARY_REL * span_u, bv = PC_BOUNDARY_REL * span_v;
        if (h->u - domain[0] <= bu || domain[1] - h->u <= bu || h->v - domain[2] <= bv ||
            domain[3] - h->v <= bv)
            h->flags |= PROJCURVE_HIT_BOUNDARY;
    }
}
