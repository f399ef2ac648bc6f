/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Case measurement (see measure.h).
 */
#include "measure.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "api/options.h" /* the internal switch of the compact fits */

#define PI 3.14159265358979323846
/* Oracle samples and result samples: 2001 curve parameters resolve every
 * case's features; 16 samples per composed piece catch a piece that bulges
 * between its ends. Quick runs only prove the code path. */
static const pcb_sampling dense_sampling = {2001, 512, 16};
static const pcb_sampling quick_sampling = {101, 64, 2};
/* The uniform split search stops here. */
#define MAX_UNIFORM_PIECES 65536
/* Chord points checked per uniform piece. */
#define UNIFORM_CHECKS 3

pcb_sampling pcb_sampling_for(int quick) { return quick ? quick_sampling : dense_sampling; }

void pcb_measurement_clear(pcb_measurement *m)
{
    m->ms = m->branches = m->pieces = m->control_points = m->points = m->max_joint_deg = NAN;
    m->deviation.result_to_exact = m->deviation.exact_to_result = m->deviation.hausdorff = NAN;
    m->uniform_pieces = NAN;
    m->compact_poles = m->compact_degree = m->pcurve_poles = m->pcurve_degree = NAN;
    m->compact_deviation = m->deviation;
    m->fit_ms = NAN;
}

typedef struct project_work {
    const pcb_case *c;
    const projcurve_options *opts;
} project_work;

static int work_project(void *user, size_t n)
{
    const project_work *w = user;
    for (size_t i = 0; i < n; ++i) {
        projcurve_result *r = NULL;
        const projcurve_status st = pcb_case_project(NULL, w->c, w->opts, &r);
        projcurve_result_destroy(r);
        if (st != PROJCURVE_OK)
            return 1;
    }
    return 0;
}

/* Angle in degrees between two vectors (0 when either vanishes). */
static double angle_between(const double a[3], const double b[3])
{
    const double na = sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
    const double nb = sqrt(b[0] * b[0] + b[1] * b[1] + b[2] * b[2]);
    if (!(na > 0.0 && nb > 0.0))
        return 0.0;
    const double c = (a[0] * b[0] + a[1] * b[1] + a[2] * b[2]) / (na * nb);
    return acos(fmax(-1.0, fmin(1.0, c))) * 180.0 / PI;
}

/* Angle in degrees between a piece's end tangent and the next one's start
 * tangent (for rational pieces the end tangents still point along the
 * first and last legs of the control polygon). */
static double joint_angle(const double *a, int deg_a, const double *b)
{
    double ta[3], tb[3];
    for (int k = 0; k < 3; ++k) {
        ta[k] = a[3 * deg_a + k] - a[3 * (deg_a - 1) + k];
        tb[k] = b[3 + k] - b[k];
    }
    return angle_between(ta, tb);
}

projcurve_status pcb_result_shape(projcurve_context *ctx, const projcurve_result *r,
                                  pcb_measurement *m)
{
    const size_t nb = projcurve_result_branch_count(r);
    m->branches = (double)nb;
    projcurve_status st = projcurve_result_stat(ctx, r, PROJCURVE_STAT_POINTS, &m->points);
    if (st == PROJCURVE_OK)
        st = projcurve_result_stat(ctx, r, PROJCURVE_STAT_PIECES, &m->pieces);
    double ctrl_total = 0.0, worst = 0.0;
    double prev[3 * PROJCURVE_MAX_PIECE_POINTS], cur[3 * PROJCURVE_MAX_PIECE_POINTS];
    for (size_t b = 0; b < nb && st == PROJCURVE_OK; ++b) {
        size_t n_pieces = 0;
        st = projcurve_result_branch_info(ctx, r, b, NULL, NULL, NULL, NULL, &n_pieces);
        int prev_deg = 0;
        for (size_t p = 0; p < n_pieces && st == PROJCURVE_OK; ++p) {
            int deg = 0;
            st = projcurve_result_piece(ctx, r, b, p, &deg, cur, NULL, NULL, NULL);
            if (st != PROJCURVE_OK)
                break;
            if (p > 0 && prev_deg > 0 && deg > 0)
                worst = fmax(worst, joint_angle(prev, prev_deg, cur));
            ctrl_total += (double)deg + (p == 0 ? 1.0 : 0.0);
            prev_deg = deg;
            for (int k = 0; k < 3 * (deg + 1); ++k)
                prev[k] = cur[k];
        }
    }
    m->control_points = ctrl_total;
    m->max_joint_deg = worst;
    return st;
}

int pcb_measure_case(const pcb_case *c, const pcb_timing *timing, const pcb_sampling *sampling,
                     int with_uniform, pcb_measurement *m, char *status, size_t status_size)
{
    pcb_measurement_clear(m);
    status[0] = '\0';
    projcurve_context *ctx = NULL;
    projcurve_options *opts = NULL;
    projcurve_result *r = NULL;
    projcurve_options *no_fit = NULL;
    pcb_result_curves rc = {NULL, 0}, compact = {NULL, 0};
    pcb_exact ex = {0};
    int ok = 0;
    projcurve_status st = projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx);
    if (st == PROJCURVE_OK)
        st = pcb_case_options(ctx, c, &opts);
    if (st == PROJCURVE_OK)
        st = pcb_case_project(ctx, c, opts, &r);
    if (st == PROJCURVE_OK)
        st = pcb_result_shape(ctx, r, m);
    if (st == PROJCURVE_OK)
        st = pcb_result_curves_init(ctx, r, &rc);
    if (st == PROJCURVE_OK)
        st = pcb_result_compact_curves_init(ctx, r, &compact, &m->compact_poles,
                                            &m->compact_degree, &m->pcurve_poles,
                                            &m->pcurve_degree);
    if (st == PROJCURVE_OK)
        st = pcb_case_options(ctx, c, &no_fit);
    if (st == PROJCURVE_OK)
        no_fit->compact = 0;
    if (st == PROJCURVE_OK)
        st = pcb_exact_sample(ctx, &ex, c->surface, c->curve, c->orthogonal, c->dir,
                              sampling->exact_samples);
    if (st != PROJCURVE_OK) {
        snprintf(status, status_size, "%s: %s", projcurve_status_string(st),
                 projcurve_context_message(ctx));
        goto cleanup;
    }
    size_t per_curve = sampling->min_per_curve;
    if (m->pieces * (double)sampling->per_piece > (double)per_curve)
        per_curve = (size_t)(m->pieces * (double)sampling->per_piece);
    const pcb_curve_set set = pcb_result_curve_set(&rc);
    if (pcb_measure_deviation(&ex, &set, per_curve, &m->deviation) != 0) {
        snprintf(status, status_size, "deviation: evaluation failed");
        goto cleanup;
    }
    /* the compact curves have a few dozen spans: the minimum per curve
     * samples them more densely than the pieces are */
    const pcb_curve_set compact_set = pcb_result_curve_set(&compact);
    if (pcb_measure_deviation(&ex, &compact_set, sampling->min_per_curve,
                              &m->compact_deviation) != 0) {
        snprintf(status, status_size, "deviation of the compact curves: evaluation failed");
        goto cleanup;
    }
    if (with_uniform)
        m->uniform_pieces = pcb_uniform_pieces(&ex, r, c->tol_dist, c->tol_angle_deg);
    project_work w = {c, opts}, w_no_fit = {c, no_fit};
    pcb_pair pair;
    if (pcb_time_pair(timing, work_project, &w, work_project, &w_no_fit, &pair) != 0) {
        snprintf(status, status_size, "a timed projection failed");
        goto cleanup;
    }
    m->ms = 1e3 * pair.a_s;
    m->fit_ms = 1e3 * (pair.a_s - pair.b_s);
    ok = 1;
cleanup:
    pcb_exact_free(&ex);
    pcb_result_curves_free(&rc);
    pcb_result_curves_free(&compact);
    projcurve_options_destroy(no_fit);
    projcurve_result_destroy(r);
    projcurve_options_destroy(opts);
    projcurve_context_destroy(ctx);
    return ok ? 0 : -1;
}

/* Points traced by one projection with opts. */
static projcurve_status traced_points(projcurve_context *ctx, const pcb_case *c,
                                      const projcurve_options *opts, double *points)
{
    projcurve_result *r = NULL;
    projcurve_status st = pcb_case_project(ctx, c, opts, &r);
    if (st == PROJCURVE_OK)
        st = projcurve_result_stat(ctx, r, PROJCURVE_STAT_POINTS, points);
    projcurve_result_destroy(r);
    return st;
}

int pcb_compare_methods(const pcb_case *c, const pcb_timing *timing, pcb_method_pair *out,
                        char *status, size_t status_size)
{
    out->second_ms = out->rk4_ms = out->rk4_over_second = NAN;
    out->second_points = out->rk4_points = NAN;
    status[0] = '\0';
    projcurve_context *ctx = NULL;
    projcurve_options *second = NULL, *rk4 = NULL;
    projcurve_status st = projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx);
    if (st == PROJCURVE_OK)
        st = pcb_case_options(ctx, c, &second);
    if (st == PROJCURVE_OK)
        st = pcb_case_options(ctx, c, &rk4);
    if (st == PROJCURVE_OK)
        st = projcurve_options_set_int(ctx, rk4, PROJCURVE_OPT_METHOD, PROJCURVE_METHOD_RK4);
    if (st == PROJCURVE_OK)
        st = traced_points(ctx, c, second, &out->second_points);
    if (st == PROJCURVE_OK)
        st = traced_points(ctx, c, rk4, &out->rk4_points);
    int ok = st == PROJCURVE_OK;
    if (!ok) {
        snprintf(status, status_size, "%s: %s", projcurve_status_string(st),
                 projcurve_context_message(ctx));
    } else {
        project_work w_second = {c, second}, w_rk4 = {c, rk4};
        pcb_pair pair;
        ok = pcb_time_pair(timing, work_project, &w_rk4, work_project, &w_second, &pair) == 0;
        if (ok) {
            out->rk4_ms = 1e3 * pair.a_s;
            out->second_ms = 1e3 * pair.b_s;
            out->rk4_over_second = pair.ratio;
        } else {
            snprintf(status, status_size, "a timed projection failed");
        }
    }
    projcurve_options_destroy(second);
    projcurve_options_destroy(rk4);
    projcurve_context_destroy(ctx);
    return ok ? 0 : -1;
}

/* ---- uniform split ------------------------------------------------------ */

typedef struct branch_guess {
    double *tuv;  /* traced polyline (t, u, v) */
    size_t n;
    double t0, t1;
} branch_guess;

/* (u, v) at t by linear interpolation of the traced polyline: only a
 * starting guess, the corrector makes it exact. */
static void guess_uv(const branch_guess *g, double t, double uv[2])
{
    size_t lo = 0, hi = g->n - 1;
    while (hi - lo > 1) {
        const size_t mid = (lo + hi) / 2;
        if (g->tuv[3 * mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    const double ta = g->tuv[3 * lo], tb = g->tuv[3 * hi];
    const double s = tb > ta ? (t - ta) / (tb - ta) : 0.0;
    uv[0] = g->tuv[3 * lo + 1] + s * (g->tuv[3 * hi + 1] - g->tuv[3 * lo + 1]);
    uv[1] = g->tuv[3 * lo + 2] + s * (g->tuv[3 * hi + 2] - g->tuv[3 * lo + 2]);
}

/* The exact point at t from the polyline guess; the guess itself where the
 * corrector gives up (a branch end exactly on the domain boundary). */
static void exact_uv(const pcb_exact *ex, const branch_guess *g, double t, double uv[2])
{
    guess_uv(g, t, uv);
    double q[2] = {uv[0], uv[1]};
    if (pcb_exact_correct(ex, t, q, NULL)) {
        uv[0] = q[0];
        uv[1] = q[1];
    }
}

/* Angle in degrees between the surface tangents J a and J b at uv, where J
 * = [Su Sv]: the joint angle of two chord compositions meeting there. */
static double chord_joint_angle(const projcurve_surface *s, const double uv[2], const double a[2],
                                const double b[2])
{
    double d[9];
    if (projcurve_surface_eval(NULL, s, uv[0], uv[1], 1, d) != PROJCURVE_OK)
        return INFINITY;
    double ta[3], tb[3];
    for (int k = 0; k < 3; ++k) {
        ta[k] = d[3 + k] * a[0] + d[6 + k] * a[1];
        tb[k] = d[3 + k] * b[0] + d[6 + k] * b[1];
    }
    return angle_between(ta, tb);
}

/* 1 when n equal-t chords of the branch all stay within eps_d of the exact
 * projection and meet at angles within eps_t_deg. */
static int uniform_ok(const pcb_exact *ex, const branch_guess *g, size_t n, double eps_d,
                      double eps_t_deg)
{
    const double h = (g->t1 - g->t0) / (double)n;
    double uv_a[2], prev[2] = {0.0, 0.0};
    exact_uv(ex, g, g->t0, uv_a);
    for (size_t i = 0; i < n; ++i) {
        const double ta = g->t0 + h * (double)i, tb = i + 1 == n ? g->t1 : ta + h;
        double uv_b[2];
        exact_uv(ex, g, tb, uv_b);
        const double chord[2] = {uv_b[0] - uv_a[0], uv_b[1] - uv_a[1]};
        if (i > 0 && chord_joint_angle(ex->surface, uv_a, prev, chord) > eps_t_deg)
            return 0;
        for (int k = 1; k <= UNIFORM_CHECKS; ++k) {
            const double s = (double)k / (UNIFORM_CHECKS + 1);
            const double uv_mid[2] = {uv_a[0] + s * chord[0], uv_a[1] + s * chord[1]};
            double x[3];
            if (projcurve_surface_eval(NULL, ex->surface, uv_mid[0], uv_mid[1], 0, x) !=
                PROJCURVE_OK)
                return 0;
            if (pcb_exact_distance_window(ex, x, ta, tb, uv_mid) > eps_d)
                return 0;
        }
        uv_a[0] = uv_b[0];
        uv_a[1] = uv_b[1];
        prev[0] = chord[0];
        prev[1] = chord[1];
    }
    return 1;
}

static size_t uniform_count(const pcb_exact *ex, const branch_guess *g, double eps_d,
                            double eps_t_deg)
{
    size_t hi = 1;
    while (hi < MAX_UNIFORM_PIECES && !uniform_ok(ex, g, hi, eps_d, eps_t_deg))
        hi *= 2;
    if (hi >= MAX_UNIFORM_PIECES)
        return MAX_UNIFORM_PIECES;
    size_t lo = hi / 2;  /* lo fails (or is 0), hi passes */
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (uniform_ok(ex, g, mid, eps_d, eps_t_deg))
            hi = mid;
        else
            lo = mid;
    }
    return hi;
}

double pcb_uniform_pieces(const pcb_exact *ex, const projcurve_result *r, double eps_d,
                          double eps_t_deg)
{
    const size_t nb = projcurve_result_branch_count(r);
    double total = 0.0;
    for (size_t b = 0; b < nb; ++b) {
        branch_guess g = {NULL, 0, 0.0, 0.0};
        double t_range[2];
        size_t n_points = 0;
        if (projcurve_result_branch_info(NULL, r, b, t_range, NULL, NULL, &n_points, NULL) !=
                PROJCURVE_OK ||
            n_points < 2)
            return NAN;
        g.tuv = malloc(3 * n_points * sizeof *g.tuv);
        if (!g.tuv ||
            projcurve_result_branch_points(NULL, r, b, n_points, g.tuv, &g.n) != PROJCURVE_OK ||
            g.n < 2) {
            free(g.tuv);
            return NAN;
        }
        g.t0 = t_range[0];
        g.t1 = t_range[1];
        total += (double)uniform_count(ex, &g, eps_d, eps_t_deg);
        free(g.tuv);
    }
    return total;
}
