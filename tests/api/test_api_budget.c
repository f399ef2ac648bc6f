/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The work budget of a projection call (common/budget.h, projcurve.h):
 * TIME_LIMIT, MAX_WORK and the progress / cancel callback.
 *
 * Nothing here depends on the machine's speed: the budget module is tested
 * with a clock the test drives; through the public API the time limit is
 * tested with a limit far below the time of the first unit of work (its
 * outcome is certain), the callback by counting its calls, which depend
 * only on the work done.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "api/project.h"
#include "brep/face.h"
#include "brep/shape.h"
#include "check.h"
#include "common/budget.h"
#include "directional/directional_project.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "point/point.h"
#include "shapes.h"

/* ---- the module, with a clock the test advances ------------------------ */

typedef struct fake_clock {
    double now, tick; /* each reading advances the clock by tick */
    int reads;
} fake_clock;

static double fake_now(void *user)
{
    fake_clock *c = user;
    const double t = c->now;
    c->now += c->tick;
    ++c->reads;
    return t;
}

typedef struct progress_log {
    double fractions[4096];
    int calls;
    int cancel_at; /* the call (1-based) that returns nonzero; 0 = never */
} progress_log;

static int log_progress(void *user, double f)
{
    progress_log *log = user;
    if (log->calls < (int)(sizeof log->fractions / sizeof log->fractions[0]))
        log->fractions[log->calls] = f;
    ++log->calls;
    return log->cancel_at > 0 && log->calls == log->cancel_at;
}

/* The time limit is seen at the first full poll after it passed: with a
 * clock that moves 1 s per reading and a 5 s limit, the init reads 0 and
 * the polls read 1, 2, ...: the 5th poll (unit 1 + 4 * POLL_EVERY) stops. */
static void test_module_time_limit(void)
{
    fake_clock clock = {0.0, 1.0, 0};
    pc_budget b;
    pc_budget_init_clock(&b, 5.0, 0, NULL, NULL, fake_now, &clock);
    unsigned long long units = 0;
    while (pc_budget_check(&b, 0.5) == PROJCURVE_OK && units < 100000)
        ++units;
    CHECK(units == 4ull * PC_BUDGET_POLL_EVERY); /* units 1 .. 4 POLL_EVERY passed */
    CHECK(clock.reads == 6);                     /* init + 5 polls */
    CHECK_STATUS(pc_budget_status(&b), PROJCURVE_ERR_LIMIT_REACHED);
    /* sticky, without reading the clock again */
    CHECK_STATUS(pc_budget_check(&b, 0.9), PROJCURVE_ERR_LIMIT_REACHED);
    CHECK(clock.reads == 6);
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK_STATUS(pc_budget_fail(&b, ctx), PROJCURVE_ERR_LIMIT_REACHED);
    CHECK(strstr(projcurve_context_message(ctx), "time limit of 5 s") != NULL);
    projcurve_context_destroy(ctx);
    /* no limit: the clock is never read */
    fake_clock idle = {0.0, 1.0, 0};
    pc_budget_init_clock(&b, 0.0, 0, NULL, NULL, fake_now, &idle);
    for (int i = 0; i < 10000; ++i)
        CHECK(pc_budget_check(&b, 0.0) == PROJCURVE_OK);
    CHECK(idle.reads == 0);
}

/* MAX_WORK n allows exactly n units, whatever the poll interval. */
static void test_module_work_limit(void)
{
    const unsigned long long limits[] = {1, 2, 255, 256, 257, 1000};
    for (size_t i = 0; i < sizeof limits / sizeof limits[0]; ++i) {
        pc_budget b;
        pc_budget_init(&b, 0.0, limits[i], NULL, NULL);
        unsigned long long units = 0;
        while (pc_budget_check(&b, 0.0) == PROJCURVE_OK && units < 100000)
            ++units;
        CHECK(units == limits[i]);
        CHECK_STATUS(pc_budget_status(&b), PROJCURVE_ERR_LIMIT_REACHED);
        CHECK(b.stopped_by == PC_BUDGET_STOP_WORK);
    }
    CHECK(pc_budget_check(NULL, 0.5) == PROJCURVE_OK); /* no budget */
}

/* The callback: first at unit 1, then every POLL_EVERY units; the fraction
 * maps the stage's share, never decreases (nor takes a NaN) and is 1 at
 * finish; a nonzero return cancels for good. */
static void test_module_progress(void)
{
    progress_log log = {{0}, 0, 0};
    pc_budget b;
    pc_budget_init(&b, 0.0, 0, log_progress, &log);
    pc_budget_stage(&b, 0.0, 0.5);
    const double stage_fraction[] = {0.2, 0.1, NAN, 0.8, 2.0};
    for (size_t k = 0; k < 5; ++k)
        for (unsigned i = 0; i < PC_BUDGET_POLL_EVERY; ++i)
            CHECK(pc_budget_check(&b, stage_fraction[k]) == PROJCURVE_OK);
    CHECK(log.calls == 5);
    const double expected[] = {0.1, 0.1, 0.1, 0.4, 0.5};
    for (int k = 0; k < 5 && k < log.calls; ++k)
        CHECK_NEAR(log.fractions[k], expected[k], 1e-15);
    pc_budget_stage(&b, 0.5, 1.0);
    pc_budget_finish(&b);
    CHECK(log.calls == 6 && log.fractions[5] == 1.0);

    progress_log stop = {{0}, 0, 2};
    pc_budget_init(&b, 0.0, 0, log_progress, &stop);
    unsigned long long units = 0;
    while (pc_budget_check(&b, 0.0) == PROJCURVE_OK && units < 100000)
        ++units;
    CHECK(units == PC_BUDGET_POLL_EVERY); /* unit 1 + POLL_EVERY is cancelled */
    CHECK_STATUS(pc_budget_status(&b), PROJCURVE_ERR_CANCELLED);
    pc_budget_finish(&b); /* a stopped call does not report 1 */
    CHECK(stop.calls == 2);
}

/* ---- through the public API ------------------------------------------- */

/* A wave above the unit square, z = 1: projected along -z onto a bumpy
 * graph over the square it gives one long branch with many traced steps
 * and (at eps_D 1e-6) many pieces. */
static int wave_fn(void *user, double t, double out[9])
{
    (void)user;
    const double w = 6.0 * 3.14159265358979323846;
    out[0] = 0.1 + 0.8 * t;
    out[1] = 0.5 + 0.3 * sin(w * t);
    out[2] = 1.0;
    out[3] = 0.8;
    out[4] = 0.3 * w * cos(w * t);
    out[5] = 0.0;
    out[6] = 0.0;
    out[7] = -0.3 * w * w * sin(w * t);
    out[8] = 0.0;
    return 0;
}

/* The unit sphere as f(x) = |x|^2 - 1. */
static int sphere_fn(void *user, const double x[3], double *value, double grad[3],
                     double hess[9])
{
    (void)user;
    *value = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - 1.0;
    for (int i = 0; i < 3; ++i)
        grad[i] = 2.0 * x[i];
    for (int i = 0; i < 9; ++i)
        hess[i] = i % 4 == 0 ? 2.0 : 0.0;
    return 0;
}

typedef enum call_kind { CALL_DIRECTIONAL, CALL_ORTHOGONAL, CALL_IMPLICIT } call_kind;

typedef struct fixture {
    projcurve_surface *surface;
    projcurve_curve *wave, *low_wave;
} fixture;

static const char *const kind_names[] = {"directional", "orthogonal", "implicit"};

static projcurve_options *base_options(call_kind kind)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_ARC_STEP_FRACTION, 1e-3));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE,
                                          kind == CALL_DIRECTIONAL ? 1e-6 : 1e-5));
    return o;
}

static projcurve_status run(const fixture *f, call_kind kind, const projcurve_options *o,
                            projcurve_context *ctx, projcurve_result **r)
{
    static const double down[3] = {0.0, 0.0, -1.0};
    switch (kind) {
    case CALL_DIRECTIONAL:
        return projcurve_project_directional(ctx, f->surface, f->wave, down, o, r);
    case CALL_ORTHOGONAL:
        return projcurve_project_orthogonal(ctx, f->surface, f->low_wave, o, r);
    default:
        return projcurve_project_orthogonal_implicit(ctx, sphere_fn, NULL, 2.0, f->wave, o, r);
    }
}

/* Everything a caller can read of a result, checked for consistency: the
 * branch and piece counts agree with the statistics, points are finite and
 * run one way in t inside the curve's domain, pieces tile their branch's
 * range in order. Returns the number of branches ending with END_LIMIT. */
static size_t check_readable(const projcurve_result *r, double t0, double t1)
{
    const size_t n = projcurve_result_branch_count(r);
    const int dim = projcurve_result_point_dim(r);
    CHECK(dim == 3 || dim == 4);
    size_t limited = 0, pieces_total = 0;
    for (size_t i = 0; i < n; ++i) {
        double range[2];
        projcurve_branch_start start;
        projcurve_branch_end end;
        size_t n_points = 0, n_pieces = 0;
        CHECK_OK(projcurve_result_branch_info(NULL, r, i, range, &start, &end, &n_points,
                                              &n_pieces));
        limited += end == PROJCURVE_END_LIMIT;
        pieces_total += n_pieces;
        double *p = malloc((n_points + 1) * 4 * sizeof *p);
        size_t count = 0;
        CHECK_OK(projcurve_result_branch_points(NULL, r, i, n_points, p, &count));
        CHECK(count == n_points);
        for (size_t k = 0; k < count; ++k) {
            for (int c = 0; c < dim; ++c)
                CHECK(isfinite(p[dim * k + c]));
            CHECK(p[dim * k] >= t0 - 1e-12 && p[dim * k] <= t1 + 1e-12);
            if (k >= 2) /* one way in t */
                CHECK((p[dim * k] - p[dim * (k - 1)]) * (p[dim * 1] - p[0]) >= 0.0);
        }
        free(p);
        double prev_end = NAN;
        for (size_t k = 0; k < n_pieces; ++k) {
            int degree = 0;
            double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS];
            double pr[2], uv[4];
            CHECK_OK(projcurve_result_piece(NULL, r, i, k, &degree, ctrl, w, pr, uv));
            CHECK(degree >= 1 && degree < PROJCURVE_MAX_PIECE_POINTS);
            if (k > 0) /* pieces follow each other */
                CHECK_NEAR(pr[0], prev_end, 1e-12);
            prev_end = pr[1];
        }
    }
    double stat = 0.0;
    CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_PIECES, &stat));
    CHECK(stat == (double)pieces_total);
    return limited;
}

/* 1 when two results have the same branches, points and pieces, bit for bit. */
static int same_result(const projcurve_result *a, const projcurve_result *b)
{
    const size_t n = projcurve_result_branch_count(a);
    if (n != projcurve_result_branch_count(b))
        return 0;
    const int dim = projcurve_result_point_dim(a);
    for (size_t i = 0; i < n; ++i) {
        size_t na = 0, nb = 0, pa = 0, pb = 0;
        projcurve_branch_end ea, eb;
        projcurve_result_branch_info(NULL, a, i, NULL, NULL, &ea, &na, &pa);
        projcurve_result_branch_info(NULL, b, i, NULL, NULL, &eb, &nb, &pb);
        if (na != nb || pa != pb || ea != eb)
            return 0;
        double *x = malloc((na + 1) * 4 * sizeof *x), *y = malloc((nb + 1) * 4 * sizeof *y);
        size_t count = 0;
        projcurve_result_branch_points(NULL, a, i, na, x, &count);
        projcurve_result_branch_points(NULL, b, i, nb, y, &count);
        const int same = memcmp(x, y, na * (size_t)dim * sizeof *x) == 0;
        free(x);
        free(y);
        if (!same)
            return 0;
    }
    return 1;
}

/* A complete call: progress is monotone in [0, 1], ends at 1, and the
 * callback changes nothing in the result. Returns the number of calls. */
static int check_complete_call(const fixture *f, call_kind kind)
{
    projcurve_options *o = base_options(kind);
    projcurve_result *plain = NULL, *watched = NULL;
    CHECK_OK(run(f, kind, o, NULL, &plain));
    progress_log *log = calloc(1, sizeof *log);
    CHECK_OK(projcurve_options_set_progress(NULL, o, log_progress, log));
    CHECK_OK(run(f, kind, o, NULL, &watched));
    CHECK(log->calls >= 3);
    const int n = log->calls < 4096 ? log->calls : 4096;
    for (int k = 0; k < n; ++k) {
        CHECK(log->fractions[k] >= 0.0 && log->fractions[k] <= 1.0);
        if (k > 0)
            CHECK(log->fractions[k] >= log->fractions[k - 1]);
    }
    CHECK(log->fractions[n - 1] == 1.0);
    CHECK(n < 2 || log->fractions[n - 2] < 1.0); /* 1 comes at the end */
    CHECK(same_result(plain, watched));
    CHECK(projcurve_result_branch_count(plain) >= 1);
    check_readable(watched, 0.0, 1.0);
    printf("%s: %d progress calls, %zu branches\n", kind_names[kind], log->calls,
           projcurve_result_branch_count(plain));
    const int calls = log->calls;
    free(log);
    projcurve_result_destroy(plain);
    projcurve_result_destroy(watched);
    projcurve_options_destroy(o);
    return calls;
}

/* Cancelling at the k-th call: CANCELLED, a readable partial result, no
 * call after the one that cancelled. With in_composition, the call came
 * in the composition stage (past 1/2): some pieces are made, and kept. */
static void check_cancel_at(const fixture *f, call_kind kind, int k, int in_composition)
{
    projcurve_options *o = base_options(kind);
    progress_log *log = calloc(1, sizeof *log);
    log->cancel_at = k;
    CHECK_OK(projcurve_options_set_progress(NULL, o, log_progress, log));
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_result *r = NULL;
    CHECK_STATUS(run(f, kind, o, ctx, &r), PROJCURVE_ERR_CANCELLED);
    CHECK(log->calls == k);
    CHECK(strstr(projcurve_context_message(ctx), "progress callback") != NULL);
    CHECK(r != NULL);
    if (r != NULL) {
        /* (a branch cut at its first vertex is dropped, and a cut in the
         * jump sweep falls between branches: no END_LIMIT need remain) */
        check_readable(r, 0.0, 1.0);
        double pieces = 0.0;
        CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_PIECES, &pieces));
        if (in_composition)
            CHECK(log->fractions[k - 1] > 0.5 && pieces > 0.0);
    }
    projcurve_result_destroy(r);
    projcurve_context_destroy(ctx);
    free(log);
    projcurve_options_destroy(o);
}

/* MAX_WORK cuts at the same place every time (the count depends on the
 * work only); enough of it changes nothing. */
static void check_work_limit(const fixture *f, call_kind kind)
{
    projcurve_options *o = base_options(kind);
    projcurve_result *full = NULL, *a = NULL, *b = NULL, *big = NULL;
    CHECK_OK(run(f, kind, o, NULL, &full));
    const long long limits[] = {1, 200, 1000};
    for (size_t i = 0; i < 3; ++i) {
        CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_MAX_WORK, limits[i]));
        projcurve_context *ctx = NULL;
        CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
        CHECK_STATUS(run(f, kind, o, ctx, &a), PROJCURVE_ERR_LIMIT_REACHED);
        CHECK(strstr(projcurve_context_message(ctx), "work limit") != NULL);
        CHECK_STATUS(run(f, kind, o, NULL, &b), PROJCURVE_ERR_LIMIT_REACHED);
        CHECK(a != NULL && b != NULL);
        if (a != NULL && b != NULL) {
            CHECK(same_result(a, b));
            check_readable(a, 0.0, 1.0);
        }
        projcurve_result_destroy(a);
        projcurve_result_destroy(b);
        a = b = NULL;
        projcurve_context_destroy(ctx);
    }
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_MAX_WORK, 1099511627776LL));
    CHECK_OK(run(f, kind, o, NULL, &big));
    CHECK(same_result(full, big));
    projcurve_result_destroy(full);
    projcurve_result_destroy(big);
    projcurve_options_destroy(o);
}

/* A time limit of 1 ns has passed by the first full poll (after the seed
 * search and a traced step, microseconds at least): LIMIT_REACHED with a
 * readable result; a limit of 1e9 s changes nothing. */
static void check_time_limit(const fixture *f, call_kind kind)
{
    projcurve_options *o = base_options(kind);
    projcurve_result *full = NULL, *cut = NULL, *relaxed = NULL;
    CHECK_OK(run(f, kind, o, NULL, &full));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TIME_LIMIT, 1e-9));
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK_STATUS(run(f, kind, o, ctx, &cut), PROJCURVE_ERR_LIMIT_REACHED);
    CHECK(strstr(projcurve_context_message(ctx), "time limit") != NULL);
    CHECK(cut != NULL);
    if (cut != NULL)
        check_readable(cut, 0.0, 1.0);
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TIME_LIMIT, 1e9));
    CHECK_OK(run(f, kind, o, NULL, &relaxed));
    CHECK(same_result(full, relaxed));
    projcurve_result_destroy(full);
    projcurve_result_destroy(cut);
    projcurve_result_destroy(relaxed);
    projcurve_context_destroy(ctx);
    projcurve_options_destroy(o);
}

static void test_options(void)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    projcurve_progress_fn fn = log_progress;
    void *user = &fn;
    CHECK_OK(projcurve_options_get_progress(NULL, o, &fn, &user));
    CHECK(fn == NULL && user == NULL);
    int token = 0;
    CHECK_OK(projcurve_options_set_progress(NULL, o, log_progress, &token));
    CHECK_OK(projcurve_options_get_progress(NULL, o, &fn, NULL));
    CHECK_OK(projcurve_options_get_progress(NULL, o, NULL, &user));
    CHECK(fn == log_progress && user == &token);
    CHECK_OK(projcurve_options_set_progress(NULL, o, NULL, &token));
    CHECK_OK(projcurve_options_get_progress(NULL, o, &fn, &user));
    CHECK(fn == NULL && user == NULL);
    CHECK_STATUS(projcurve_options_set_progress(NULL, NULL, log_progress, NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_options_get_progress(NULL, NULL, &fn, &user),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TIME_LIMIT, -1.0),
                 PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_STATUS(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_MAX_WORK, -1),
                 PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK(strcmp(projcurve_status_string(PROJCURVE_ERR_CANCELLED), "unknown status") != 0);
    projcurve_options_destroy(o);
}

/* ---- memory bounded by the limits ---------------------------------------- */

/* A line across a plane of 64 x 64 spans crosses ~100 knot lines, each a
 * vertex of the refined polyline. With MAX_PIECES 5 the list of crossings
 * stops after the pieces left (refine.c) instead of holding all of them:
 * the pieces kept are still the first ones of the unlimited projection,
 * bit for bit, and the polyline is their pcurve. */
static void test_crossings_bounded_by_pieces(void)
{
    pc_shape_surface ps = pc_shape_plane(1, 1, 64, 64);
    projcurve_surface *plane = pc_shape_surface_create(&ps);
    pc_shape_surface_free(&ps);
    pc_shape_line line = {{-0.9, -0.9, 1.0}, {1.8, 2.8, 0.0}};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, pc_shape_line_fn, &line, 0.0, 1.0, &c));
    static const double down[3] = {0.0, 0.0, -1.0};
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    projcurve_result *full = NULL, *cut = NULL;
    CHECK_OK(projcurve_project_directional(NULL, plane, c, down, o, &full));
    size_t n_full = 0;
    CHECK_OK(projcurve_result_branch_info(NULL, full, 0, NULL, NULL, NULL, NULL, &n_full));
    CHECK(projcurve_result_branch_count(full) == 1 && n_full >= 100);
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_MAX_PIECES, 5));
    CHECK_STATUS(projcurve_project_directional(NULL, plane, c, down, o, &cut),
                 PROJCURVE_ERR_LIMIT_REACHED);
    size_t n_points = 0, n_pieces = 0;
    projcurve_branch_end end;
    CHECK_OK(projcurve_result_branch_info(NULL, cut, 0, NULL, NULL, &end, &n_points, &n_pieces));
    CHECK(n_pieces == 5 && n_points == 6 && end == PROJCURVE_END_LIMIT);
    for (size_t k = 0; k < n_pieces && k < n_full; ++k) {
        int da = 0, db = 0;
        double ca[3 * PROJCURVE_MAX_PIECE_POINTS], cb[3 * PROJCURVE_MAX_PIECE_POINTS];
        double ra[2], rb[2];
        CHECK_OK(projcurve_result_piece(NULL, full, 0, k, &da, ca, NULL, ra, NULL));
        CHECK_OK(projcurve_result_piece(NULL, cut, 0, k, &db, cb, NULL, rb, NULL));
        CHECK(da == db && ra[0] == rb[0] && ra[1] == rb[1] &&
              memcmp(ca, cb, 3 * (size_t)(da + 1) * sizeof *ca) == 0);
    }
    check_readable(cut, 0.0, 1.0);
    projcurve_result_destroy(full);
    projcurve_result_destroy(cut);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(plane);
}

/* The implicit fit allocated pieces past MAX_PIECES (it checked only the
 * point limit): now it stops at the limit like the parametric projections,
 * with the pieces made kept and the branch ending with END_LIMIT. */
static void test_implicit_piece_limit(const fixture *f)
{
    projcurve_options *o = base_options(CALL_IMPLICIT);
    projcurve_result *full = NULL, *cut = NULL;
    CHECK_OK(run(f, CALL_IMPLICIT, o, NULL, &full));
    double pieces = 0.0;
    CHECK_OK(projcurve_result_stat(NULL, full, PROJCURVE_STAT_PIECES, &pieces));
    CHECK(pieces > 3.0);
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_MAX_PIECES, 3));
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK_STATUS(run(f, CALL_IMPLICIT, o, ctx, &cut), PROJCURVE_ERR_LIMIT_REACHED);
    CHECK(strstr(projcurve_context_message(ctx), "piece limit 3") != NULL);
    CHECK(cut != NULL);
    if (cut != NULL) {
        size_t n_pieces = 0;
        projcurve_branch_end end;
        CHECK_OK(projcurve_result_branch_info(NULL, cut, 0, NULL, NULL, &end, NULL, &n_pieces));
        CHECK(n_pieces == 3 && end == PROJCURVE_END_LIMIT);
        check_readable(cut, 0.0, 1.0);
    }
    projcurve_result_destroy(full);
    projcurve_result_destroy(cut);
    projcurve_context_destroy(ctx);
    projcurve_options_destroy(o);
}

/* ---- real data: calls that ran for seconds to minutes ----------------- */

/* linkrods.step, curve 7: onto surface 1 along -z the jump sweep's step
 * collapsed and the call took ~550 s; onto surface 16 orthogonally one
 * foot-point search took ~0.7 s, with no poll inside. A time limit bounds
 * both (the limit itself is met or the call completes: nothing here
 * depends on the machine's speed but the generous hang guard). */
static void test_real_calls(void)
{
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_file(NULL, pc_test_data_path("real/linkrods.step"), &m));
    if (m == NULL)
        return;
    const projcurve_curve *c = projcurve_model_curve(m, 7);
    const projcurve_surface *s1 = projcurve_model_surface(m, 1), *s16 = projcurve_model_surface(m, 16);
    CHECK(c != NULL && s1 != NULL && s16 != NULL);
    if (c == NULL || s1 == NULL || s16 == NULL) {
        projcurve_model_destroy(m);
        return;
    }
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TIME_LIMIT, 0.25));
    double t0 = 0.0, t1 = 0.0;
    CHECK_OK(projcurve_curve_domain(NULL, c, &t0, &t1));
    for (int orthogonal = 0; orthogonal <= 1; ++orthogonal) {
        static const double down[3] = {0.0, 0.0, -1.0};
        projcurve_context *ctx = NULL;
        CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
        projcurve_result *r = NULL;
        const projcurve_status st = orthogonal
                                        ? projcurve_project_orthogonal(ctx, s16, c, o, &r)
                                        : projcurve_project_directional(ctx, s1, c, down, o, &r);
        CHECK(st == PROJCURVE_OK || st == PROJCURVE_ERR_LIMIT_REACHED);
        if (st == PROJCURVE_ERR_LIMIT_REACHED)
            CHECK(strstr(projcurve_context_message(ctx), "time limit") != NULL);
        CHECK(r != NULL);
        if (r != NULL)
            check_readable(r, t0, t1);
        printf("linkrods curve 7 onto surface %d (%s), 0.25 s limit: %s\n", orthogonal ? 16 : 1,
               orthogonal ? "orthogonal" : "along -z", projcurve_status_string(st));
        projcurve_result_destroy(r);
        projcurve_context_destroy(ctx);
    }

    /* the foot-point search polls the budget once per sub-patch: it stops
     * at exactly MAX_WORK units, with the feet found so far, and says OK
     * (the caller's next poll sees the budget's status) */
    pc_vec3 p;
    CHECK_OK(pc_curve_eval(c, t0, 0, NULL, &p));
    double uv[2 * 64];
    size_t count = 0;
    pc_budget b;
    pc_budget_init(&b, 0.0, 0, NULL, NULL);
    CHECK_OK(pc_surface_foot_points_uv(NULL, s16, p, &b, 64, uv, &count));
    printf("a foot-point search on linkrods surface 16: %llu sub-patches\n", b.work);
    CHECK(b.work >= 100);
    pc_budget_init(&b, 0.0, 50, NULL, NULL);
    CHECK_OK(pc_surface_foot_points_uv(NULL, s16, p, &b, 64, uv, &count));
    CHECK(b.work == 51);
    CHECK_STATUS(pc_budget_status(&b), PROJCURVE_ERR_LIMIT_REACHED);
    projcurve_options_destroy(o);
    projcurve_model_destroy(m);
}

/* ---- a cut inside the fitting stage ------------------------------------ */

/* A wave whose crests leave the unit square (y > 1): over the bumpy graph
 * four branches, each composed and fitted. */
static int tall_wave_fn(void *user, double t, double out[9])
{
    (void)user;
    const double w = 3.0 * 3.14159265358979323846;
    out[0] = 0.1 + 0.8 * t;
    out[1] = 0.4 + 0.7 * sin(w * t);
    out[2] = 1.0;
    out[3] = 0.8;
    out[4] = 0.7 * w * cos(w * t);
    out[5] = 0.0;
    out[6] = 0.0;
    out[7] = -0.7 * w * w * sin(w * t);
    out[8] = 0.0;
    return 0;
}

/* The work units of the directional call with opts, the compact fits on
 * or off (white box: pc_params.compact, the benchmark's switch). The
 * public call runs exactly this (api/project.c). */
static unsigned long long work_units(const projcurve_surface *s, const projcurve_curve *c,
                                     const projcurve_options *o, int compact)
{
    pc_params p;
    pc_budget b;
    CHECK_OK(pc_projection_params(NULL, o, s->size, &b, &p));
    p.compact = compact;
    const pc_vec3 down = {0.0, 0.0, -1.0};
    projcurve_result *r = NULL;
    CHECK_OK(pc_directional_project(NULL, s, c, down, &p, &r));
    projcurve_result_destroy(r);
    return b.work;
}

/* MAX_WORK halfway through the fitting stage (after the W0 units of
 * tracing, composing and verifying, before the W1 of the whole call):
 * LIMIT_REACHED with the message of the work limit; every branch with
 * all its pieces (the same as the complete call's); the branches fitted
 * before the cut come first, with the complete call's compact forms, and
 * from the one being fitted on none has a compact 3D curve
 * (LIMIT_REACHED) and each whose pcurve fit was cut has the pieces'
 * pcurves joined (compact_info fitted 0, error -1); the exact
 * composition of that joined pcurve is the pieces (to rounding). The
 * result is destroyed like any other (ASan checks for leaks). */
static void test_cut_in_fit(const projcurve_surface *s)
{
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, tall_wave_fn, NULL, 0.0, 1.0, &c));
    projcurve_options *o = base_options(CALL_DIRECTIONAL);
    const unsigned long long w0 = work_units(s, c, o, 0), w1 = work_units(s, c, o, 1);
    printf("cut in the fit: %llu units without the fits, %llu with\n", w0, w1);
    CHECK(w1 > w0 + 10);
    projcurve_result *full = NULL, *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, (const double[3]){0, 0, -1}, o, &full));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_MAX_WORK,
                                       (long long)(w0 + (w1 - w0) / 2)));
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK_STATUS(projcurve_project_directional(ctx, s, c, (const double[3]){0, 0, -1}, o, &r),
                 PROJCURVE_ERR_LIMIT_REACHED);
    printf("  %s\n", projcurve_context_message(ctx));
    CHECK(strstr(projcurve_context_message(ctx), "work limit") != NULL);
    CHECK(r != NULL);
    if (r == NULL || full == NULL)
        goto done;
    const size_t n = projcurve_result_branch_count(r);
    CHECK(n >= 2 && n == projcurve_result_branch_count(full));
    CHECK(same_result(r, full));
    int fitted_before = 1, cut_seen = 0;
    size_t unfitted = 0;
    for (size_t b = 0; b < n; ++b) {
        int fitted = -1;
        double qe = 0, ce = 0;
        CHECK_OK(projcurve_result_branch_compact_info(NULL, r, b, &fitted, &qe, &ce));
        int full_fitted = -1;
        double fqe = 0, fce = 0;
        CHECK_OK(projcurve_result_branch_compact_info(NULL, full, b, &full_fitted, &fqe, &fce));
        printf("  branch %zu: fitted %d, errors %.3g %.3g (complete call: %d, %.3g %.3g)\n", b,
               fitted, qe, ce, full_fitted, fqe, fce);
        CHECK(fitted <= fitted_before); /* fitted ones first, in branch order */
        fitted_before = fitted;
        projcurve_curve *q = NULL, *k = NULL, *e = NULL, *pieces = NULL;
        CHECK_OK(projcurve_result_branch_compact_pcurve(NULL, r, b, &q));
        /* the fitted forms are the complete call's; from the one cut on
         * no branch has a 3D curve (each round of a fit polls the budget,
         * also one that needs no new exact point); a cut in the 3D fit of
         * a branch whose pcurve was fitted leaves it that pcurve alone */
        if (fitted)
            CHECK(qe == fqe && full_fitted == 1);
        if (ce >= 0.0) {
            CHECK(fitted && ce == fce && !cut_seen);
            CHECK_OK(projcurve_result_branch_compact_curve(NULL, r, b, &k));
        } else {
            cut_seen = 1;
            CHECK_STATUS(projcurve_result_branch_compact_curve(NULL, r, b, &k),
                         PROJCURVE_ERR_LIMIT_REACHED);
            CHECK(k == NULL);
        }
        if (!fitted) {
            ++unfitted;
            CHECK(qe == -1.0);
            /* S o (the pieces' pcurves joined) is the pieces: both exact on S */
            CHECK_OK(projcurve_result_branch_compact_exact(NULL, r, s, b, &e));
            CHECK_OK(projcurve_result_branch_curve(NULL, r, b, &pieces));
            double dom[2] = {0, 0}, worst = 0;
            if (e)
                CHECK_OK(projcurve_curve_domain(NULL, e, &dom[0], &dom[1]));
            for (int i = 0; e && pieces && i <= 200; ++i) {
                double x[9], y[9];
                const double t = i == 200 ? dom[1] : dom[0] + (dom[1] - dom[0]) * i / 200.0;
                CHECK_OK(projcurve_curve_eval(NULL, e, t, 0, x));
                CHECK_OK(projcurve_curve_eval(NULL, pieces, t, 0, y));
                worst = fmax(worst, sqrt((x[0] - y[0]) * (x[0] - y[0]) +
                                         (x[1] - y[1]) * (x[1] - y[1]) +
                                         (x[2] - y[2]) * (x[2] - y[2])));
            }
            /* two compositions of one pcurve: rounding, 1e-12 of the size */
            CHECK(worst <= 1e-12 * s->size);
        }
        projcurve_curve_destroy(q);
        projcurve_curve_destroy(k);
        projcurve_curve_destroy(e);
        projcurve_curve_destroy(pieces);
    }
    CHECK(unfitted >= 1);
    printf("  %zu of %zu branches left with the joined pcurve\n", unfitted, n);
done:
    projcurve_context_destroy(ctx);
    projcurve_result_destroy(r);
    projcurve_result_destroy(full);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
}

/* ---- stops inside the hits selection and the verification ------------- */

/* Where a call stopped, read from its status and message (the steps after
 * tracing name themselves there): a stop further into the call for a
 * larger work limit or a later cancelling callback. */
typedef enum stop_place { STOP_TRACING, STOP_HITS, STOP_VERIFYING, STOP_NONE } stop_place;

/* The options of the stage tests: polylines only (COMPOSE 0), so that the
 * cut result compares to the full one branch by branch; MAX_DISTANCE 1
 * cuts the wave's projection (at distance 1 +- 0.05 from the bumpy graph)
 * into parts, so the selection has work to do. */
static projcurve_options *stage_options(void)
{
    projcurve_options *o = base_options(CALL_DIRECTIONAL);
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_MAX_DISTANCE, 1.0));
    return o;
}

/* Runs the stage call with MAX_WORK limit (when cancel_at is 0) or with a
 * callback cancelling at its cancel_at-th call; *r gets the result. */
static stop_place run_cut(const fixture *f, long long limit, int cancel_at, projcurve_result **r)
{
    projcurve_options *o = stage_options();
    progress_log *log = calloc(1, sizeof *log);
    log->cancel_at = cancel_at;
    if (cancel_at > 0)
        CHECK_OK(projcurve_options_set_progress(NULL, o, log_progress, log));
    else
        CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_MAX_WORK, limit));
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    const projcurve_status st = run(f, CALL_DIRECTIONAL, o, ctx, r);
    const char *msg = projcurve_context_message(ctx);
    stop_place place = STOP_TRACING;
    if (st == PROJCURVE_OK)
        place = STOP_NONE;
    else if (strstr(msg, "while selecting the hits") != NULL)
        place = STOP_HITS;
    else if (strstr(msg, "while verifying the result") != NULL)
        place = STOP_VERIFYING;
    if (st != PROJCURVE_OK) {
        CHECK_STATUS(st, cancel_at > 0 ? PROJCURVE_ERR_CANCELLED : PROJCURVE_ERR_LIMIT_REACHED);
        CHECK(strstr(msg, cancel_at > 0 ? "progress callback" : "work limit") != NULL);
        CHECK(strstr(msg, "partial result is kept") != NULL);
    }
    if (cancel_at > 0)
        CHECK(log->calls == cancel_at || st == PROJCURVE_OK);
    projcurve_context_destroy(ctx);
    free(log);
    projcurve_options_destroy(o);
    return place;
}

static stop_place place_at(const fixture *f, long long limit, int cancel_at)
{
    projcurve_result *r = NULL;
    const stop_place place = run_cut(f, limit, cancel_at, &r);
    projcurve_result_destroy(r);
    return place;
}

/* The smallest limit (or cancelling call) in [1, hi] whose stop is at or
 * after `place` (hi when none): the stop moves forward with the limit. */
static long long first_at(const fixture *f, stop_place place, int by_cancel, long long hi)
{
    long long lo = 1;
    while (lo < hi) {
        const long long mid = lo + (hi - lo) / 2;
        const stop_place at = by_cancel ? place_at(f, 0, (int)mid) : place_at(f, mid, 0);
        if (at >= place)
            hi = mid;
        else
            lo = mid + 1;
    }
    return lo;
}

/* The points (t, u, v) of branch i. */
static double *points_of(const projcurve_result *r, size_t i, size_t *n, projcurve_branch_end *end)
{
    size_t n_pieces = 0;
    CHECK_OK(projcurve_result_branch_info(NULL, r, i, NULL, NULL, end, n, &n_pieces));
    double *p = malloc((*n + 1) * 3 * sizeof *p);
    size_t count = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, i, *n, p, &count));
    CHECK(count == *n);
    return p;
}

/* The documented partial result of a stop in the hits selection or the
 * verification: the branches of the full result before the stop, bit for
 * bit; then the one it stopped in, its points a prefix of the full one's
 * (all of them when the stop came after it), ending with END_LIMIT; no
 * later branch. Returns the number of branches. */
static size_t check_prefix(const projcurve_result *cut, const projcurve_result *full)
{
    CHECK(projcurve_result_point_dim(cut) == 3);
    const size_t n = projcurve_result_branch_count(cut);
    CHECK(n <= projcurve_result_branch_count(full));
    check_readable(cut, 0.0, 1.0);
    for (size_t i = 0; i < n && i < projcurve_result_branch_count(full); ++i) {
        size_t nc = 0, nf = 0;
        projcurve_branch_end ec, ef;
        double *pc = points_of(cut, i, &nc, &ec), *pf = points_of(full, i, &nf, &ef);
        if (i + 1 < n) {
            CHECK(nc == nf && ec == ef);
        } else {
            CHECK(ec == PROJCURVE_END_LIMIT);
            CHECK(nc >= 2 && nc <= nf);
        }
        CHECK(memcmp(pc, pf, (nc < nf ? nc : nf) * 3 * sizeof *pc) == 0);
        free(pc);
        free(pf);
    }
    return n;
}

/* A stop inside the hits selection and inside the verification, by
 * MAX_WORK and by the callback, each found by bisection on the limit /
 * the cancelling call (the place of the stop is in the message), each
 * checked against the full result. */
static void test_stops_after_tracing(const fixture *f)
{
    projcurve_options *o = stage_options();
    projcurve_result *full = NULL;
    progress_log *log = calloc(1, sizeof *log);
    CHECK_OK(projcurve_options_set_progress(NULL, o, log_progress, log));
    CHECK_OK(run(f, CALL_DIRECTIONAL, o, NULL, &full));
    const int calls = log->calls; /* the last (1) cannot cancel */
    free(log);
    projcurve_options_destroy(o);
    const size_t n_full = projcurve_result_branch_count(full);
    printf("stage cuts: %zu parts within distance 1, %d progress calls\n", n_full, calls);
    CHECK(n_full >= 2);
    for (int by_cancel = 0; by_cancel <= 1; ++by_cancel) {
        const long long most = by_cancel ? calls : 1LL << 40;
        const long long done_from = first_at(f, STOP_NONE, by_cancel, most);
        const long long hits_from = first_at(f, STOP_HITS, by_cancel, done_from);
        const long long verify_from = first_at(f, STOP_VERIFYING, by_cancel, done_from);
        printf("  %s: hits from %lld, verification from %lld, complete from %lld\n",
               by_cancel ? "cancelling call" : "work limit", hits_from, verify_from, done_from);
        CHECK(hits_from < verify_from && verify_from < done_from);
        /* the first and the last stop in each stage */
        const long long at[4] = {hits_from, verify_from - 1, verify_from, done_from - 1};
        for (int k = 0; k < 4; ++k) {
            projcurve_result *cut = NULL;
            const stop_place place = by_cancel ? run_cut(f, 0, (int)at[k], &cut)
                                               : run_cut(f, at[k], 0, &cut);
            CHECK(place == (k < 2 ? STOP_HITS : STOP_VERIFYING));
            CHECK(cut != NULL);
            if (cut != NULL) {
                const size_t n = check_prefix(cut, full);
                /* a stop at a stage's last unit keeps every part but the
                 * last one's end (the selection closes a part after its
                 * last unit; the last verified branch may be one item);
                 * a stop at its first unit keeps nothing: the selection
                 * has made no part, the verification has verified none.
                 * (The callback comes every 256 units: it lands anywhere
                 * in them, and only the prefix holds.) */
                if (!by_cancel)
                    CHECK(k % 2 == 1 ? n + 1 >= n_full : n == 0);
            }
            projcurve_result_destroy(cut);
        }
    }
    projcurve_result_destroy(full);
}

/* ---- a stop inside the nearest selection across faces ----------------- */

/* The plane O + u A + v B over [0, 1]^2 (bilinear: exact). */
static projcurve_surface *plane(const double o[3], const double a[3], const double b[3])
{
    double net[12];
    for (int i = 0; i < 3; ++i) {
        net[i] = o[i];
        net[3 + i] = o[i] + a[i];
        net[6 + i] = o[i] + b[i];
        net[9 + i] = o[i] + a[i] + b[i];
    }
    static const double knots[] = {0, 0, 1, 1};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 1, 1, 2, 2, net, NULL, knots, knots, &s));
    return s;
}

/* The whole of s as a face, its sides' edge ids first_id.. */
static projcurve_face *square_face(const projcurve_surface *s, long first_id)
{
    const double c[5][2] = {{0, 0}, {1, 0}, {1, 1}, {0, 1}, {0, 0}};
    double ctrl[4][4];
    static const double knots[] = {0, 0, 1, 1};
    pc_piece_input pieces[4];
    for (int k = 0; k < 4; ++k) {
        ctrl[k][0] = c[k][0];
        ctrl[k][1] = c[k][1];
        ctrl[k][2] = c[k + 1][0];
        ctrl[k][3] = c[k + 1][1];
        pieces[k] = (pc_piece_input){.degree = 1, .n_ctrl = 2, .ctrl = ctrl[k], .knots = knots,
                                     .edge = first_id + k, .sense = 1, .edge_sense = 1};
    }
    const pc_loop_input loop = {.pieces = pieces, .n_pieces = 4, .outer = 1};
    const pc_face_params params = {.tol_uv = 1e-9, .tol_model = 0.0, .close_tol = 1e-9,
                                   .same_sense = 1, .id = -1, .kind = "plane", .what = "square"};
    projcurve_face *f = NULL;
    CHECK_OK(pc_face_build(NULL, s, &loop, 1, &params, &f));
    return f;
}

/* Two walls seen along +x, a front one (x = 1, |y| <= 1/2) and a back one
 * (x = 3, |y| <= 1), from the line (-1, -0.8 + 1.6 t, 0.1 + 0.2 t): the
 * nearest hits are the front piece and the back one where the front is
 * missing (test_shapeproj_nearest checks them). MAX_WORK cuts found by
 * bisection on the message: at the selection's first unit nothing is
 * kept; at its last, the front piece (selected first) is whole. */
static void test_stop_in_shape_nearest(void)
{
    const double of[3] = {1, -0.5, -1}, ob[3] = {3, -1, -1};
    const double y1[3] = {0, 1, 0}, y2[3] = {0, 2, 0}, z2[3] = {0, 0, 2};
    projcurve_surface *sf = plane(of, y1, z2), *sb = plane(ob, y2, z2);
    projcurve_face *faces[2] = {square_face(sf, 1), square_face(sb, 5)};
    const size_t index[2] = {0, 1};
    projcurve_shape *shape = NULL;
    CHECK_OK(pc_shape_build(NULL, PROJCURVE_SHAPE_OPEN_SHELL, -1,
                            (const projcurve_face *const *)faces, index, 2, &shape));
    const double ctrl[6] = {-1, -0.8, 0.1, -1, 0.8, 0.3}, knots[4] = {0, 0, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &c));
    const double dir[3] = {1, 0, 0};
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_HITS, PROJCURVE_HITS_NEAREST));
    projcurve_shape_result *full = NULL;
    CHECK_OK(projcurve_project_shape(NULL, shape, c, PROJCURVE_PROJECT_DIRECTIONAL, dir, o, &full));
    /* where the stop lands for a limit: 0 before the selection, 1 in it, 2 complete */
    long long lo_sel = 1, lo_done = 1;
    for (int pass = 0; pass < 2; ++pass) {
        long long lo = 1, hi = 1LL << 40;
        while (lo < hi) {
            const long long mid = lo + (hi - lo) / 2;
            CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_MAX_WORK, mid));
            projcurve_context *ctx = NULL;
            CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
            projcurve_shape_result *sr = NULL;
            const projcurve_status st =
                projcurve_project_shape(ctx, shape, c, PROJCURVE_PROJECT_DIRECTIONAL, dir, o, &sr);
            const int at = st == PROJCURVE_OK ? 2
                           : strstr(projcurve_context_message(ctx), "nearest hits") != NULL ? 1
                                                                                            : 0;
            if (at >= pass + 1)
                hi = mid;
            else
                lo = mid + 1;
            projcurve_shape_result_destroy(sr);
            projcurve_context_destroy(ctx);
        }
        *(pass == 0 ? &lo_sel : &lo_done) = lo;
    }
    printf("shape nearest: selection from %lld units, complete from %lld\n", lo_sel, lo_done);
    CHECK(lo_sel < lo_done);
    const long long at[2] = {lo_sel, lo_done - 1};
    for (int k = 0; k < 2; ++k) {
        CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_MAX_WORK, at[k]));
        projcurve_context *ctx = NULL;
        CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
        projcurve_shape_result *sr = NULL;
        CHECK_STATUS(projcurve_project_shape(ctx, shape, c, PROJCURVE_PROJECT_DIRECTIONAL, dir, o,
                                             &sr),
                     PROJCURVE_ERR_LIMIT_REACHED);
        CHECK(strstr(projcurve_context_message(ctx),
                     "work limit of") != NULL &&
              strstr(projcurve_context_message(ctx),
                     "while selecting the nearest hits across faces") != NULL);
        CHECK(sr != NULL);
        if (sr != NULL) {
            const projcurve_result *cut_front = NULL, *full_front = NULL, *cut_back = NULL;
            CHECK_OK(projcurve_shape_result_face(NULL, sr, 0, NULL, &cut_front, NULL, NULL));
            CHECK_OK(projcurve_shape_result_face(NULL, sr, 1, NULL, &cut_back, NULL, NULL));
            CHECK_OK(projcurve_shape_result_face(NULL, full, 0, NULL, &full_front, NULL, NULL));
            const size_t n_front = projcurve_result_branch_count(cut_front);
            const size_t n_back = projcurve_result_branch_count(cut_back);
            /* a face not selected in full says so; one selected whole does not */
            projcurve_status st_front = PROJCURVE_OK, st_back = PROJCURVE_OK;
            const char *m_back = NULL;
            CHECK_OK(projcurve_shape_result_face(NULL, sr, 0, NULL, NULL, &st_front, NULL));
            CHECK_OK(projcurve_shape_result_face(NULL, sr, 1, NULL, NULL, &st_back, &m_back));
            CHECK(st_back == PROJCURVE_ERR_LIMIT_REACHED);
            CHECK(m_back != NULL && strstr(m_back, "not yet selected") != NULL);
            if (k == 0) {
                CHECK(n_front == 0 && n_back == 0);
                CHECK(st_front == PROJCURVE_ERR_LIMIT_REACHED);
            } else {
                CHECK(n_front == 1 && same_result(cut_front, full_front));
                CHECK(n_back <= 2);
                CHECK(st_front == PROJCURVE_OK);
            }
        }
        projcurve_shape_result_destroy(sr);
        projcurve_context_destroy(ctx);
    }
    projcurve_shape_result_destroy(full);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    pc_shape_free(shape);
    pc_face_free(faces[0]);
    pc_face_free(faces[1]);
    projcurve_surface_destroy(sf);
    projcurve_surface_destroy(sb);
}

int main(void)
{
    test_module_time_limit();
    test_module_work_limit();
    test_module_progress();
    test_options();
    test_real_calls();
    test_crossings_bounded_by_pieces();

    pc_shape_surface s = pc_shape_bumpy(7, 6, 6, 0.05, 0);
    fixture f = {pc_shape_surface_create(&s), NULL, NULL};
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, NULL, 0.0, 1.0, &f.wave));
    f.low_wave = f.wave; /* z = 1: far from the graph's centres of curvature */
    pc_shape_surface_free(&s);
    CHECK(f.surface != NULL);
    if (f.surface == NULL)
        return pc_test_finish("test_api_budget");

    for (int kind = CALL_DIRECTIONAL; kind <= CALL_IMPLICIT; ++kind) {
        const int calls = check_complete_call(&f, (call_kind)kind);
        /* cancel at the first call, at a few k, and at the last call
         * before the final 1 (the composition stage) */
        const int ks[] = {1, 2, 3, calls / 2, calls - 1};
        for (size_t i = 0; i < sizeof ks / sizeof ks[0]; ++i)
            if (ks[i] >= 1 && ks[i] < calls)
                check_cancel_at(&f, (call_kind)kind, ks[i], ks[i] == calls - 1);
        check_work_limit(&f, (call_kind)kind);
        check_time_limit(&f, (call_kind)kind);
    }
    test_implicit_piece_limit(&f);
    test_cut_in_fit(f.surface);
    test_stops_after_tracing(&f);
    test_stop_in_shape_nearest();
    projcurve_curve_destroy(f.wave);
    projcurve_surface_destroy(f.surface);
    return pc_test_finish("test_api_budget");
}
