/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The verification pass (src/verify/) on results it must keep and on
 * results corrupted on purpose, white-box: a projection is made through the
 * public API, then a piece or a vertex of it is moved off the projection
 * and pc_verify_result, run again with the projector of the same call, must
 * cut exactly the corrupted part:
 *  - an uncorrupted result is kept bit for bit (every projection already
 *    went through the pass once; a second pass changes nothing);
 *  - a piece whose interior control points are lifted by 5 eps_D off S is
 *    cut: the branch before it ends END_FAILED, the rest becomes a branch
 *    starting START_FAILED, every other piece kept bit for bit, and
 *    projcurve_result_failure_count says 2;
 *  - a vertex moved along S by 1e-6 of the domain (far above the vertex
 *    tolerance, 1e-8 of the model size, and far below eps_D in 3D for the
 *    move 1e-6 of a domain of size ~1 on a model of size ~100: the pieces
 *    alone would not see it) cuts both pieces meeting there;
 *  - a corrupted last piece ends the branch FAILED (one branch, count 1);
 *    every piece corrupted drops the branch and still counts 1;
 *  - a pcurve control point outside the domain, a piece moved as a whole
 *    (its join with the previous piece broken), a trace-only polyline with a
 *    vertex moved: cut likewise.
 * Directional (the paper's Example 1) and orthogonal (a bumpy bicubic).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "common/params.h"
#include "directional/directional.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "ortho/ortho_projector.h"
#include "trace/result.h"
#include "trace_shapes.h"
#include "verify/verify.h"

typedef struct fixture {
    projcurve_surface *s;
    projcurve_curve *c;
    int orthogonal;
    double dir[3];
    int compose;
    /* the projector of the call, as the entry points make it */
    pc_projector proj;
    pc_directional_data ddata;
    pc_directional_cache dcache;
    pc_ortho_cache ocache;
    pc_params o;
} fixture;

static projcurve_result *project(fixture *f)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, f->compose));
    projcurve_result *r = NULL;
    CHECK_OK(f->orthogonal ? projcurve_project_orthogonal(NULL, f->s, f->c, o, &r)
                           : projcurve_project_directional(NULL, f->s, f->c, f->dir, o, &r));
    projcurve_options_destroy(o);
    pc_params_defaults(&f->o);
    f->o.compose = f->compose;
    f->o.tol_distance = r->stats.tol_distance;
    if (f->orthogonal) {
        pc_ortho_projector_init(&f->proj, &f->ocache, f->s, f->c, f->o.newton_tol,
                                (int)f->o.newton_max_iter);
    } else {
        const double n = sqrt(f->dir[0] * f->dir[0] + f->dir[1] * f->dir[1] + f->dir[2] * f->dir[2]);
        pc_directional_init(&f->proj, &f->ddata, &f->dcache, f->s, f->c,
                            vec3(f->dir[0] / n, f->dir[1] / n, f->dir[2] / n), f->o.newton_tol,
                            (int)f->o.newton_max_iter);
        pc_directional_use_bound_table(&f->dcache, NULL, 0);
    }
    return r;
}

static int same_piece(const pc_piece *a, const pc_piece *b)
{
    return a->degree == b->degree && a->t0 == b->t0 && a->t1 == b->t1 &&
           memcmp(a->uv, b->uv, sizeof a->uv) == 0 &&
           memcmp(a->ctrl, b->ctrl, 3 * (size_t)(a->degree + 1) * sizeof *a->ctrl) == 0 &&
           memcmp(a->weights, b->weights, (size_t)(a->degree + 1) * sizeof *a->weights) == 0;
}

/* Index of the longest branch (most pieces, or points). */
static size_t longest(const projcurve_result *r)
{
    size_t best = 0;
    for (size_t i = 1; i < r->n_branches; ++i)
        if (r->branches[i].n_pieces + r->branches[i].n_points >
            r->branches[best].n_pieces + r->branches[best].n_points)
            best = i;
    return best;
}

/* Lifts the interior control points of piece k of branch b by `by` along z
 * (off S: every test surface here is a graph over z or x; the lift is
 * checked to move the piece's midpoint by at least `by` / 2 below). */
static void lift_piece(pc_branch *b, size_t k, double by, int axis)
{
    pc_piece *p = &b->pieces[k];
    for (int j = 1; j < p->degree; ++j)
        p->ctrl[3 * j + axis] += by;
}

static void test_uncorrupted(fixture *f)
{
    projcurve_result *r = project(f);
    const size_t nb = r->n_branches;
    CHECK(nb >= 1);
    CHECK(projcurve_result_failure_count(r) == 0);
    size_t pieces = 0;
    for (size_t i = 0; i < nb; ++i)
        pieces += r->branches[i].n_pieces;
    CHECK_OK(pc_verify_result(NULL, &f->proj, &f->o, r));
    CHECK(r->n_branches == nb);
    size_t after = 0;
    for (size_t i = 0; i < r->n_branches; ++i)
        after += r->branches[i].n_pieces;
    CHECK(after == pieces);
    CHECK(projcurve_result_failure_count(r) == 0);
    projcurve_result_destroy(r);
}

/* Corrupts piece k of the longest branch with `corrupt`, verifies, and
 * checks the cut: the pieces before k and after k + extra stay, bit for
 * bit, in two branches (or one when nothing is left on a side). */
typedef void (*corruption)(fixture *f, pc_branch *b, size_t k);

static void check_cut(fixture *f, corruption corrupt, size_t k_from_end, size_t extra,
                      const char *what)
{
    projcurve_result *r = project(f);
    projcurve_result *ref = project(f); /* the same result, untouched */
    const size_t i = longest(r);
    pc_branch *b = &r->branches[i];
    const size_t np = b->n_pieces;
    CHECK(np > 4 + extra);
    if (np <= 4 + extra) {
        projcurve_result_destroy(r);
        projcurve_result_destroy(ref);
        return;
    }
    const size_t k = k_from_end == 0 ? np / 2 : np - k_from_end;
    const projcurve_branch_start start = b->start;
    const projcurve_branch_end end = b->end;
    corrupt(f, b, k);
    const size_t nb = r->n_branches;
    CHECK_OK(pc_verify_result(NULL, &f->proj, &f->o, r));
    /* the branch was replaced by its verified runs, appended at the end */
    const size_t first_cut = k - (extra > 0 && k > 0 ? 1 : 0) * 0; /* pieces kept before */
    const size_t before = first_cut, after_from = k + 1 + extra;
    const size_t n_runs = (before > 0) + (after_from < np);
    printf("%s: piece %zu of %zu cut, %zu -> %zu branches, failures %zu\n", what, k, np, nb,
           r->n_branches, projcurve_result_failure_count(r));
    CHECK(r->n_branches == nb - 1 + n_runs);
    CHECK(projcurve_result_failure_count(r) == (n_runs == 2 ? 2 : 1));
    const pc_branch *ob = &ref->branches[i];
    size_t at = nb - 1; /* first run */
    if (before > 0) {
        const pc_branch *run = &r->branches[at++];
        CHECK(run->start == start && run->end == PROJCURVE_END_FAILED);
        CHECK(run->n_pieces == before && run->n_points == before + 1);
        for (size_t j = 0; j < before && j < run->n_pieces; ++j)
            CHECK(same_piece(&run->pieces[j], &ob->pieces[j]));
    }
    if (after_from < np) {
        const pc_branch *run = &r->branches[at];
        CHECK(run->start == PROJCURVE_START_FAILED && run->end == end);
        CHECK(run->n_pieces == np - after_from);
        for (size_t j = 0; j < run->n_pieces; ++j)
            CHECK(same_piece(&run->pieces[j], &ob->pieces[after_from + j]));
    }
    projcurve_result_destroy(r);
    projcurve_result_destroy(ref);
}

static int lift_axis(const fixture *f)
{
    return f->orthogonal ? 2 : 0; /* Example 1 is seen along -x */
}

static void corrupt_lift(fixture *f, pc_branch *b, size_t k)
{
    lift_piece(b, k, 5.0 * f->o.tol_distance, lift_axis(f));
}

/* The vertex between pieces k and k + 1 moved along S (both pieces keep
 * their own control points: only the vertex check can see it). */
static void corrupt_vertex(fixture *f, pc_branch *b, size_t k)
{
    const double *dom = f->s->nurbs.domain;
    const double move = 1e-6 * (dom[1] - dom[0]);
    b->pieces[k].uv[2] += move;
    b->pieces[k + 1].uv[0] += move;
}

static void corrupt_domain(fixture *f, pc_branch *b, size_t k)
{
    const double *dom = f->s->nurbs.domain;
    pc_piece *p = &b->pieces[k];
    p->uv_ctrl[2] = dom[1] + 1e-3 * (dom[1] - dom[0]);
}

/* The whole piece moved by 2 eps_D: its join with the previous one breaks
 * (and its samples are off). */
static void corrupt_join(fixture *f, pc_branch *b, size_t k)
{
    pc_piece *p = &b->pieces[k];
    for (int j = 0; j <= p->degree; ++j)
        p->ctrl[3 * j + lift_axis(f)] += 2.0 * f->o.tol_distance;
}

static void test_all_corrupted(fixture *f)
{
    projcurve_result *r = project(f);
    const size_t i = longest(r), nb = r->n_branches;
    for (size_t k = 0; k < r->branches[i].n_pieces; ++k)
        lift_piece(&r->branches[i], k, 5.0 * f->o.tol_distance, lift_axis(f));
    CHECK_OK(pc_verify_result(NULL, &f->proj, &f->o, r));
    CHECK(r->n_branches == nb - 1);
    CHECK(projcurve_result_failure_count(r) == 1);
    projcurve_result_destroy(r);
}

/* Trace only: a traced vertex moved along S cuts the two segments at it. */
static void test_polyline(fixture *f)
{
    f->compose = 0;
    projcurve_result *r = project(f);
    const size_t i = longest(r), nb = r->n_branches;
    pc_branch *b = &r->branches[i];
    const size_t n = b->n_points, k = n / 2;
    CHECK(n > 8);
    const double *dom = f->s->nurbs.domain;
    b->points[3 * k + 1] += 1e-6 * (dom[1] - dom[0]);
    CHECK_OK(pc_verify_result(NULL, &f->proj, &f->o, r));
    CHECK(r->n_branches == nb + 1);
    CHECK(projcurve_result_failure_count(r) == 2);
    CHECK(r->branches[nb - 1].n_points == k && r->branches[nb - 1].end == PROJCURVE_END_FAILED);
    CHECK(r->branches[nb].n_points == n - k - 1 &&
          r->branches[nb].start == PROJCURVE_START_FAILED);
    projcurve_result_destroy(r);
    f->compose = 1;
}

static void run_all(fixture *f, const char *name)
{
    printf("%s\n", name);
    test_uncorrupted(f);
    check_cut(f, corrupt_lift, 0, 0, "lifted piece");
    check_cut(f, corrupt_lift, 1, 0, "lifted last piece");
    check_cut(f, corrupt_domain, 0, 0, "pcurve outside the domain");
    check_cut(f, corrupt_join, 0, 1, "broken join");
    check_cut(f, corrupt_vertex, 0, 1, "moved vertex");
    test_all_corrupted(f);
    test_polyline(f);
}

/* projcurve_result_failure_count through the public API. */
static void test_failure_count_api(void)
{
    CHECK(projcurve_result_failure_count(NULL) == 0);
}

int main(void)
{
    fixture d = {0};
    d.s = shape_example1_surface();
    d.c = shape_example1_curve();
    d.dir[0] = -1.0;
    d.compose = 1;
    run_all(&d, "directional, Example 1");
    projcurve_surface_destroy(d.s);
    projcurve_curve_destroy(d.c);

    fixture o = {0};
    o.s = shape_bumpy(8.0, 3);
    const double pts[12] = {10, 20, 30, 40, 70, 25, 70, 30, 35, 90, 80, 30};
    o.c = shape_bspline_curve(3, 4, pts);
    o.orthogonal = 1;
    o.compose = 1;
    run_all(&o, "orthogonal, bumpy bicubic");
    projcurve_surface_destroy(o.s);
    projcurve_curve_destroy(o.c);
    test_failure_count_api();
    return pc_test_finish("test_verify");
}
