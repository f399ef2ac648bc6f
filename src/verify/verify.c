/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The verification pass (verify.h): the driver. Each branch is checked item
 * by item — its pieces when it has them, else the segments of its polyline —
 * and where an item fails the branch is cut there: every run of verified
 * items becomes a branch, the ends at a cut saying END_FAILED and
 * START_FAILED. The checks themselves are in verify_piece.c.
 */
#include <math.h>
#include <stdlib.h>

#include "common/array.h"
#include "common/error.h"
#include "verify/verify.h"
#include "verify/verify_internal.h"

/* A branch whose image on S stays within this fraction of the model size of
 * its first point, over a curve-parameter range below this fraction of the
 * curve's domain, is below the precision the library places points to (the
 * knot-line crossings are put on their line to 1e-9 of the domain, and a
 * parameter step below 1e-12 of a range is not resolved): it is the trace
 * of a seed met twice by rounding at a boundary or fold, not a curve, and
 * is dropped. (A point curve, whose image is one point over its whole
 * domain, is not noise: its projection is a point branch.) */
#define PC_VERIFY_NOISE_REL 1e-9

static pc_vec3 surface_point(const pc_projector *proj, double u, double v)
{
    size_t hu = 0, hv = 0;
    pc_vec3 s;
    pc_nurbs_surface_eval(&proj->surface->nurbs, u, v, 0, &hu, &hv, &s);
    return s;
}

/* 1 when every point of b maps to within the noise length of the first. */
static int is_noise(const pc_projector *proj, const pc_branch *b)
{
    if (b->n_points == 0)
        return 1;
    const double domain = proj->curve->t1 - proj->curve->t0;
    if (!(fabs(b->points[3 * (b->n_points - 1)] - b->points[0]) <= PC_VERIFY_NOISE_REL * domain))
        return 0;
    const double noise = PC_VERIFY_NOISE_REL * proj->model_size;
    const pc_vec3 first = surface_point(proj, b->points[1], b->points[2]);
    for (size_t k = 1; k < b->n_points; ++k)
        if (!(vec3_dist(surface_point(proj, b->points[3 * k + 1], b->points[3 * k + 2]), first) <=
              noise))
            return 0;
    for (size_t k = 0; k < b->n_pieces; ++k) { /* a piece may bulge between its ends */
        const pc_piece *p = &b->pieces[k];
        for (int j = 0; j <= p->degree; ++j) {
            const double *c = p->ctrl + 3 * j;
            if (!(vec3_dist(vec3(c[0], c[1], c[2]), first) <= noise))
                return 0;
        }
    }
    return 1;
}

/* (a) for vertex k of b (of n items): the start of piece k (the end of
 * the last one for k = n), or polyline point k. */
static unsigned char vertex_ok(pc_verifier *v, const pc_branch *b, size_t k, size_t n)
{
    if (b->n_pieces == 0)
        return (unsigned char)pc_verify_vertex(v, b->points[3 * k], b->points[3 * k + 1],
                                               b->points[3 * k + 2]);
    /* the start of piece k and the end of piece k - 1, each checked on its
     * own side of a crease */
    const pc_piece *next = k < n ? &b->pieces[k] : NULL, *prev = k > 0 ? &b->pieces[k - 1] : NULL;
    const double *const toward[2] = {next ? next->uv + 2 : NULL, prev ? prev->uv : NULL};
    return (unsigned char)(next ? pc_verify_vertex_of_pieces(v, next->t0, next->uv[0], next->uv[1],
                                                             toward)
                                : pc_verify_vertex_of_pieces(v, prev->t1, prev->uv[2], prev->uv[3],
                                                             toward));
}

/* Marks in keep[k] whether item k of b passes: piece k, with both its end
 * vertices, or polyline segment k with both its vertices. *n_items gets the
 * item count, or the count checked when the budget stopped the check (a
 * unit per item); returns 1 when every item passes. ok is scratch for the
 * items + 1 vertices. */
static int check_branch(pc_verifier *v, const pc_branch *b, unsigned char *keep,
                        unsigned char *ok, size_t *n_items)
{
    const int pieces = b->n_pieces > 0;
    const size_t n = pieces ? b->n_pieces : b->n_points - 1;
    *n_items = n;
    ok[0] = vertex_ok(v, b, 0, n);
    int all = 1;
    for (size_t k = 0; k < n; ++k) {
        if (pc_budget_check(v->budget, 0.0) != PROJCURVE_OK) {
            *n_items = k;
            return 0;
        }
        ok[k + 1] = vertex_ok(v, b, k + 1, n);
        keep[k] = ok[k] && ok[k + 1] &&
                  (!pieces || pc_verify_piece(v, &b->pieces[k], k > 0 ? &b->pieces[k - 1] : NULL));
        all &= keep[k];
    }
    return all;
}

/* Appends to r a branch made of items [lo, hi] of branch i. */
static projcurve_status copy_run(projcurve_context *ctx, projcurve_result *r, size_t i,
                                 size_t lo, size_t hi, projcurve_branch_start start,
                                 projcurve_branch_end end)
{
    pc_branch *nb = NULL;
    projcurve_status st = pc_result_add_branch(ctx, r, &nb);
    if (st != PROJCURVE_OK)
        return st;
    const pc_branch *b = &r->branches[i]; /* after the append: it may have moved */
    nb->start = start;
    nb->end = end;
    if (b->n_pieces == 0) {
        for (size_t k = lo; k <= hi + 1 && st == PROJCURVE_OK; ++k)
            st = pc_branch_add_point(ctx, nb, 3, b->points + 3 * k);
        return st;
    }
    for (size_t k = lo; k <= hi && st == PROJCURVE_OK; ++k) {
        const pc_piece *p = &b->pieces[k];
        const double vertex[3] = {p->t0, p->uv[0], p->uv[1]};
        st = pc_branch_add_point(ctx, nb, 3, vertex);
        if (st == PROJCURVE_OK)
            st = pc_branch_add_piece(ctx, nb, p->degree, p->t0, p->t1, p->uv, p->ctrl,
                                     p->weights);
        if (st == PROJCURVE_OK)
            pc_branch_set_last_pcurve(nb, p->uv_degree, p->uv_ctrl);
    }
    const pc_piece *last = &b->pieces[hi];
    const double vertex[3] = {last->t1, last->uv[2], last->uv[3]};
    return st == PROJCURVE_OK ? pc_branch_add_point(ctx, nb, 3, vertex) : st;
}

/* 1 when items [lo, hi) of b (their vertices, and the control points of
 * their pieces) lie within `radius` of vertex `anchor` on S. */
static int items_near(const pc_projector *proj, const pc_branch *b, size_t lo, size_t hi,
                      size_t anchor, double radius)
{
    const int pieces = b->n_pieces > 0;
    const double *a = pieces ? NULL : b->points + 3 * anchor;
    const pc_vec3 x = pieces ? surface_point(proj, anchor < b->n_pieces ? b->pieces[anchor].uv[0]
                                                                          : b->pieces[anchor - 1].uv[2],
                                             anchor < b->n_pieces ? b->pieces[anchor].uv[1]
                                                                  : b->pieces[anchor - 1].uv[3])
                             : surface_point(proj, a[1], a[2]);
    for (size_t k = lo; k < hi; ++k) {
        if (!pieces) {
            const double *p = b->points + 3 * k, *q = p + 3;
            if (!(vec3_dist(surface_point(proj, p[1], p[2]), x) <= radius) ||
                !(vec3_dist(surface_point(proj, q[1], q[2]), x) <= radius))
                return 0;
            continue;
        }
        const pc_piece *pc = &b->pieces[k];
        for (int j = 0; j <= pc->degree; ++j) {
            const double *c = pc->ctrl + 3 * j;
            if (!(vec3_dist(vec3(c[0], c[1], c[2]), x) <= radius))
                return 0;
        }
    }
    return 1;
}

/* The items of b that start and end what is kept: first and last (past the
 * end) item of the kept runs, leaving out the runs and failing items at
 * either end that lie within eps_D / 2 of the first (or last) vertex of the
 * runs kept, as the refinement does with its gaps (refine.c,
 * gap_stretch_short). A branch born at a fold starts with pieces a few
 * 1e-12 apart in t, where the exact projection is two points that merge
 * and some fail the check: the runs between them came out as branches of
 * a piece or two, starting and ending FAILED (teapot surface 18, a lifted
 * diagonal, at t = 0.8475). They are the fold reached to the tolerance. */
static void kept_span(const pc_projector *proj, const pc_branch *b, const unsigned char *keep,
                      size_t n, double radius, size_t *first, size_t *last)
{
    *first = 0;
    *last = n;
    for (size_t lo = 1; lo < n; ++lo) /* the latest run start with a short prefix */
        if (keep[lo] && !keep[lo - 1] && items_near(proj, b, 0, lo, lo, radius))
            *first = lo;
    for (size_t hi = n - 1; hi > *first; --hi) /* the earliest run end with a short suffix */
        if (keep[hi - 1] && !keep[hi] && items_near(proj, b, hi, n, hi, radius))
            *last = hi;
}

/* Replaces branch i by its runs of kept items (appended to r), the cuts
 * ending FAILED and starting FAILED; a branch with no run is dropped and
 * counted as a failure. The original is removed. stopped: only the first
 * n items were checked (the budget stopped the check): the last run ends
 * with END_LIMIT, and a branch with no run is not a failure. */
static projcurve_status cut_branch(projcurve_context *ctx, const pc_projector *proj, double radius,
                                   projcurve_result *r, size_t i, const unsigned char *keep,
                                   size_t n, int stopped)
{
    projcurve_status st = PROJCURVE_OK;
    size_t runs = 0, first = 0, last = 0;
    if (n > 0) /* none when the budget stopped before the first item */
        kept_span(proj, &r->branches[i], keep, n, radius, &first, &last);
    for (size_t lo = first; lo < last && st == PROJCURVE_OK;) {
        if (!keep[lo]) {
            ++lo;
            continue;
        }
        size_t hi = lo;
        while (hi + 1 < last && keep[hi + 1])
            ++hi;
        const projcurve_branch_start start =
            lo == first ? r->branches[i].start : PROJCURVE_START_FAILED;
        const projcurve_branch_end last_end = stopped ? PROJCURVE_END_LIMIT : r->branches[i].end;
        const projcurve_branch_end end = hi + 1 == last ? last_end : PROJCURVE_END_FAILED;
        st = copy_run(ctx, r, i, lo, hi, start, end);
        ++runs;
        lo = hi + 1;
    }
    if (st == PROJCURVE_OK && runs == 0 && !stopped)
        ++r->failures_dropped;
    pc_result_remove_branch(r, i);
    return st;
}

projcurve_status pc_verify_result(projcurve_context *ctx, const pc_projector *proj,
                                  const pc_params *o, projcurve_result *r)
{
    PC_REQUIRE(ctx, proj, "projector");
    PC_REQUIRE(ctx, r, "result");
    if (r->point_dim != 3)
        return PROJCURVE_OK;
    const double *dom = proj->surface->nurbs.domain;
    const double diag = hypot(dom[1] - dom[0], dom[3] - dom[2]);
    /* the exact points measured against are placed to the corrector's
     * tolerance: the distance is known to that, and no better */
    /* polled only when the call still runs: after a stop the partial
     * result is verified whole, bounded by its size */
    pc_verifier v = {proj, o->tol_distance + proj->newton_tol, pc_verify_vertex_tolerance(proj),
                     1e-10 * diag, 1e-13 * diag, 0, 0.0, 0.0, pc_budget_if_running(o->budget)};
    pc_budget_step(v.budget, "verifying the result");
    unsigned char *keep = NULL, *ok = NULL;
    size_t cap_keep = 0, cap_ok = 0;
    projcurve_status st = PROJCURVE_OK;
    size_t n_checked = r->n_branches; /* runs of cut branches are appended, verified */
    for (size_t i = 0; i < n_checked && st == PROJCURVE_OK;) {
        const pc_branch *b = &r->branches[i];
        const int limited = b->end == PROJCURVE_END_LIMIT;
        const int noise = is_noise(proj, b);
        if (noise || b->n_points < 2 || (o->compose && b->n_pieces == 0 && !limited)) {
            if (!noise)
                ++r->failures_dropped; /* nothing verifiable: a failure */
            pc_result_remove_branch(r, i);
            --n_checked;
            continue;
        }
        const size_t need = (b->n_pieces > 0 ? b->n_pieces : b->n_points) + 1;
        void *k2 = keep, *o2 = ok;
        st = pc_array_reserve(ctx, &k2, &cap_keep, 0, need, 1, 64, NULL, "the verified pieces");
        keep = k2;
        if (st == PROJCURVE_OK)
            st = pc_array_reserve(ctx, &o2, &cap_ok, 0, need, 1, 64, NULL, "the verified points");
        ok = o2;
        if (st != PROJCURVE_OK)
            break;
        size_t n = 0;
        if (check_branch(&v, b, keep, ok, &n)) {
            ++i;
            continue;
        }
        const int stopped = pc_budget_status(v.budget) != PROJCURVE_OK;
        st = cut_branch(ctx, proj, 0.5 * o->tol_distance, r, i, keep, n, stopped);
        --n_checked;
        if (st == PROJCURVE_OK && stopped) {
            /* only verified branches are returned: those not yet checked go */
            while (n_checked > i)
                pc_result_remove_branch(r, --n_checked);
            st = pc_budget_fail(v.budget, ctx);
        }
    }
    pc_budget_step(v.budget, NULL);
    free(keep);
    free(ok);
    if (o->compose) {
        double pieces = 0.0;
        for (size_t i = 0; i < r->n_branches; ++i)
            pieces += (double)r->branches[i].n_pieces;
        r->stats.pieces = pieces;
    }
    return st;
}

projcurve_status pc_verify_kept(projcurve_context *ctx, const pc_projector *proj,
                                const pc_params *o, projcurve_result *r, projcurve_status st)
{
    if (!pc_status_keeps_result(st))
        return st;
    const projcurve_status vs = pc_verify_result(ctx, proj, o, r);
    return vs != PROJCURVE_OK ? vs : st;
}
