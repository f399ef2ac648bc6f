/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The piece limit (PROJCURVE_OPT_MAX_PIECES) through the public API, with
 * straight pcurves (the default): a tolerance that needs more pieces than
 * the limit returns PROJCURVE_ERR_LIMIT_REACHED with the partial result set
 * and readable, never a silent truncation. On a single-branch projection
 * (the paper's Example 1) and on one with two branches (the sphere whose
 * branches are born and end on the silhouette), for limits cutting the first
 * branch, the second one, and at a single piece, the facts checked against
 * the unlimited projection of the same call:
 *  - at most MAX_PIECES pieces, PROJCURVE_STAT_PIECES counting them;
 *  - the branches before the cut are those of the unlimited result (same
 *    pieces, bit for bit, same ends); the branch that is cut keeps a prefix
 *    of it (the pieces from its start, joined) and ends with END_LIMIT; its
 *    polyline is the pcurve of the kept pieces (vertex count pieces + 1, t
 *    range that of the pieces): the traced polyline beyond the cut is
 *    dropped; every later branch has no pieces, ends with END_LIMIT and
 *    keeps its traced polyline (that of the trace-only projection, bit for
 *    bit), also when the limit is reached right at the end of a branch;
 *  - every piece reads back (projcurve_result_piece, _piece_pcurve) and
 *    equals S at its pcurve (tests/support/on_surface), every branch with
 *    pieces joins into one NURBS curve (projcurve_result_branch_curve),
 *    those without give INVALID_ARGUMENT;
 *  - the kept pieces are within eps_D of the exact projection and meet
 *    within eps_T (tests/support/piece_oracle, measured over their range).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "on_surface.h"
#include "piece_oracle.h"
#include "trace_shapes.h"

#define EPS_T_DEG 1.0

typedef struct limit_case {
    const char *name;
    projcurve_surface *surface;
    projcurve_curve *curve;
    double dir[3];
    double rel_eps;
} limit_case;

/* max_pieces 0: the default limit; -1: trace only (PROJCURVE_OPT_COMPOSE 0). */
static projcurve_status project(const limit_case *c, long long max_pieces,
                                projcurve_context *ctx, projcurve_result **r)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE,
                                          c->rel_eps * c->surface->size));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_ANGLE_DEG, EPS_T_DEG));
    if (max_pieces < 0)
        CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0));
    else if (max_pieces > 0)
        CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_MAX_PIECES, max_pieces));
    const projcurve_status st =
        projcurve_project_directional(ctx, c->surface, c->curve, c->dir, o, r);
    projcurve_options_destroy(o);
    return st;
}

typedef struct branch_view {
    double t_range[2];
    projcurve_branch_start start;
    projcurve_branch_end end;
    size_t n_points, n_pieces;
} branch_view;

static branch_view view(const projcurve_result *r, size_t i)
{
    branch_view v;
    memset(&v, 0, sizeof v);
    CHECK_OK(projcurve_result_branch_info(NULL, r, i, v.t_range, &v.start, &v.end, &v.n_points,
                                          &v.n_pieces));
    return v;
}

/* 1 when piece k of branch i is the same, bit for bit, in a and b. */
static int same_piece(const projcurve_result *a, const projcurve_result *b, size_t i, size_t k)
{
    int da = 0, db = 0;
    double ca[3 * PROJCURVE_MAX_PIECE_POINTS], cb[3 * PROJCURVE_MAX_PIECE_POINTS];
    double wa[PROJCURVE_MAX_PIECE_POINTS], wb[PROJCURVE_MAX_PIECE_POINTS];
    double ra[2], rb[2], ua[4], ub[4];
    if (projcurve_result_piece(NULL, a, i, k, &da, ca, wa, ra, ua) != PROJCURVE_OK ||
        projcurve_result_piece(NULL, b, i, k, &db, cb, wb, rb, ub) != PROJCURVE_OK || da != db)
        return 0;
    const size_t n = (size_t)da + 1;
    return memcmp(ca, cb, 3 * n * sizeof *ca) == 0 && memcmp(wa, wb, n * sizeof *wa) == 0 &&
           memcmp(ra, rb, sizeof ra) == 0 && memcmp(ua, ub, sizeof ua) == 0;
}

/* 1 when branch i has the same polyline, bit for bit, in a and b. */
static int same_points(const projcurve_result *a, const projcurve_result *b, size_t i)
{
    size_t na = 0, nb = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, a, i, 0, NULL, &na));
    CHECK_OK(projcurve_result_branch_points(NULL, b, i, 0, NULL, &nb));
    if (na != nb || na == 0)
        return 0;
    double *pa = malloc(3 * na * sizeof *pa), *pb = malloc(3 * nb * sizeof *pb);
    int same = pa != NULL && pb != NULL;
    if (same) {
        CHECK_OK(projcurve_result_branch_points(NULL, a, i, na, pa, &na));
        CHECK_OK(projcurve_result_branch_points(NULL, b, i, nb, pb, &nb));
        same = memcmp(pa, pb, 3 * na * sizeof *pa) == 0;
    }
    free(pa);
    free(pb);
    return same;
}

/* The partial result r (limit max_pieces) against the unlimited one and the
 * traced polylines (trace only). */
static void check_partial(const limit_case *c, const projcurve_result *full,
                          const projcurve_result *traced, const projcurve_result *r,
                          size_t max_pieces)
{
    const size_t nb = projcurve_result_branch_count(r);
    CHECK(nb == projcurve_result_branch_count(full));
    double stat = NAN;
    CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_PIECES, &stat));
    size_t total = 0, cut = nb;
    for (size_t i = 0; i < nb && i < projcurve_result_branch_count(full); ++i) {
        const branch_view p = view(r, i), f = view(full, i);
        total += p.n_pieces;
        CHECK(p.start == f.start);
        if (cut == nb && p.end == PROJCURVE_END_LIMIT)
            cut = i;
        if (i < cut) { /* complete, as without the limit */
            CHECK(p.end == f.end && p.n_pieces == f.n_pieces && p.n_points == f.n_points);
        } else if (i == cut && p.n_pieces > 0) { /* cut: a prefix of the branch */
            CHECK(p.n_pieces < f.n_pieces);
            CHECK(p.n_points == p.n_pieces + 1);
            double first[2], last[2];
            CHECK_OK(projcurve_result_piece(NULL, r, i, 0, NULL, NULL, NULL, first, NULL));
            CHECK_OK(projcurve_result_piece(NULL, r, i, p.n_pieces - 1, NULL, NULL, NULL, last,
                                            NULL));
            CHECK(p.t_range[0] == f.t_range[0] && first[0] == f.t_range[0]);
            CHECK(p.t_range[1] == last[1]);
            CHECK(p.t_range[1] < f.t_range[1]);
        } else { /* after the cut: traced, not composed */
            CHECK(p.end == PROJCURVE_END_LIMIT);
            CHECK(p.n_pieces == 0);
            CHECK(same_points(r, traced, i));
        }
        /* the pieces kept are those of the unlimited projection */
        int differ = 0;
        for (size_t k = 0; k < p.n_pieces && k < f.n_pieces; ++k)
            differ += !same_piece(r, full, i, k);
        CHECK(differ == 0);
        projcurve_curve *joined = NULL;
        CHECK_STATUS(projcurve_result_branch_curve(NULL, r, i, &joined),
                     p.n_pieces > 0 ? PROJCURVE_OK : PROJCURVE_ERR_INVALID_ARGUMENT);
        projcurve_curve_destroy(joined);
    }
    CHECK(cut < nb); /* some branch says where the limit stopped it */
    CHECK(total <= max_pieces && total > 0);
    CHECK(stat == (double)total);
    pc_on_surface_check(c->name, r, c->surface, 3); /* the default degree: 3 */

    pc_oracle_dir d;
    pc_projector proj;
    pc_oracle_projector(c->surface, c->curve, c->dir, &d, &proj);
    pc_oracle_summary sum;
    pc_oracle_measure_result(r, &proj, &c->surface->grid, &sum);
    const double eps = c->rel_eps * c->surface->size;
    printf("%-20s limit %5zu: %zu pieces, first END_LIMIT branch %zu, Hausdorff %.2f eps_D, joints <= "
           "%.3f deg\n",
           c->name, max_pieces, total, cut, sum.worst.hausdorff / eps, sum.worst.max_angle);
    CHECK(sum.failures == 0 && sum.loose_points == 0);
    CHECK(sum.worst.hausdorff <= eps);
    CHECK(sum.worst.max_angle <= EPS_T_DEG * (1.0 + 1e-9));
    CHECK(sum.worst.max_gap <= 1e-12 * c->surface->size);
    CHECK(sum.worst.max_end_err <= 1e-9 * c->surface->size);
    CHECK(sum.worst.off_patch == 0);
}

static void run(const limit_case *c)
{
    projcurve_result *full = NULL;
    CHECK_OK(project(c, 0, NULL, &full));
    if (full == NULL)
        return;
    double full_pieces = 0.0;
    CHECK_OK(projcurve_result_stat(NULL, full, PROJCURVE_STAT_PIECES, &full_pieces));
    projcurve_result *traced = NULL;
    CHECK_OK(project(c, -1, NULL, &traced));
    CHECK(projcurve_result_branch_count(traced) == projcurve_result_branch_count(full));
    size_t first = 0;
    CHECK_OK(projcurve_result_branch_info(NULL, full, 0, NULL, NULL, NULL, NULL, &first));
    /* cut the first branch at a third and at one piece; with two branches,
     * also right after the first one and the second one half-way through */
    size_t limits[4] = {first / 3, 1, 0, 0};
    if (projcurve_result_branch_count(full) > 1) {
        limits[2] = first;
        limits[3] = first + (size_t)(full_pieces - (double)first) / 2;
    }
    for (size_t k = 0; k < 4 && traced != NULL; ++k) {
        if (limits[k] == 0)
            continue;
        projcurve_context *ctx = NULL;
        CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
        projcurve_result *r = NULL;
        CHECK_STATUS(project(c, (long long)limits[k], ctx, &r), PROJCURVE_ERR_LIMIT_REACHED);
        CHECK(strstr(projcurve_context_message(ctx), "limit") != NULL);
        CHECK(r != NULL);
        if (r != NULL)
            check_partial(c, full, traced, r, limits[k]);
        projcurve_result_destroy(r);
        projcurve_context_destroy(ctx);
    }
    /* exactly enough is no limit */
    projcurve_result *r = NULL;
    CHECK_OK(project(c, (long long)full_pieces, NULL, &r));
    projcurve_result_destroy(r);
    projcurve_result_destroy(traced);
    projcurve_result_destroy(full);
}

int main(void)
{
    const double sphere_line[6] = {-15, 3, 20, 15, 3, 20};
    limit_case cases[] = {
        {"example 1", shape_example1_surface(), shape_example1_curve(), {-1, 0, 0}, 1e-5},
        {"sphere silhouettes", shape_sphere(10.0), shape_bspline_curve(1, 2, sphere_line),
         {0, 0, -1}, 1e-4},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        CHECK(cases[k].surface != NULL && cases[k].curve != NULL);
        if (cases[k].surface != NULL && cases[k].curve != NULL)
            run(&cases[k]);
        projcurve_surface_destroy(cases[k].surface);
        projcurve_curve_destroy(cases[k].curve);
    }
    return pc_test_finish("test_refine_limit");
}
