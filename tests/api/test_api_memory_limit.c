/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The default size limits bound the memory of a call (projcurve.h,
 * PROJCURVE_OPT_MAX_POINTS and PROJCURVE_OPT_MAX_PIECES): a projection that
 * needs more pieces, or more traced points, than the defaults allow returns
 * PROJCURVE_ERR_LIMIT_REACHED with a readable partial result, and the call
 * grows the process by less than 256 MiB.
 *
 * The piece limit: a zig-zag curve over the unit square z = 0, projected
 * along -z with default options. Over a flat patch a piece with a straight
 * pcurve is a straight segment, and each of its end tangents must be within
 * eps_T / 2 of the exact one, so the projection needs about one piece per
 * eps_T = 1 degree that the curve turns: 200 U-turns, ~36,000 degrees of
 * turning, far more than the 50,000 pieces allowed... at 2 x 180 degrees per
 * zig-zag, 200 zig-zags turn 72,000 degrees. The facts: the status, the
 * piece count at the limit, every branch and piece readable, the pieces on
 * S (z = 0) and within eps_D of the exact projection (the curve's (x, y) at
 * z = 0) on a sample of them, the last branch ending END_LIMIT.
 *
 * The point limit: the orthogonal projection of the same curve with a
 * constant parameter step that needs more traced points than the 100,000
 * allowed (PROJCURVE_OPT_PARAM_STEP), uncomposed: LIMIT_REACHED, the
 * traced points readable and on the exact projection.
 *
 * Memory: the growth of the peak resident set over the call (getrusage),
 * against the 256 MiB the defaults are chosen for; under AddressSanitizer
 * (shadow memory, a quarantine of freed blocks) four times that, as the
 * real-data sweep allows.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <sys/resource.h>

#include "check.h"

#define DEFAULT_MAX_POINTS 100000
#define DEFAULT_MAX_PIECES 50000
#define ZIGZAGS 200
#define N_POLES (2 * ZIGZAGS + 1)
#define MEMORY_LIMIT_MIB 256.0
/* pieces checked against the exact projection: every this many */
#define PIECE_SAMPLE_EVERY 997
/* t samples of the exact projection per piece range, for its distance */
#define EXACT_SAMPLES 64

#if defined(__SANITIZE_ADDRESS__)
#define MEMORY_FACTOR 4.0
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
#define MEMORY_FACTOR 4.0
#endif
#endif
#ifndef MEMORY_FACTOR
#define MEMORY_FACTOR 1.0
#endif

static double peak_rss_mib(void)
{
    struct rusage ru;
    getrusage(RUSAGE_SELF, &ru);
    return (double)ru.ru_maxrss / 1024.0; /* KiB on Linux */
}

/* The unit square z = 0, one bilinear patch. */
static projcurve_surface *unit_square(void)
{
    static const double net[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0};
    static const double knots[] = {0, 0, 1, 1};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 1, 1, 2, 2, net, NULL, knots, knots, &s));
    return s;
}

/* A cubic B-spline at z = 1 whose poles alternate between y = 0.1 and
 * y = 0.9 as x goes from 0.05 to 0.95: ZIGZAGS rounded zig-zags. */
static projcurve_curve *zigzag(void)
{
    static double poles[3 * N_POLES], knots[N_POLES + 4];
    for (int k = 0; k < N_POLES; ++k) {
        poles[3 * k] = 0.05 + 0.9 * k / (N_POLES - 1);
        poles[3 * k + 1] = k % 2 ? 0.9 : 0.1;
        poles[3 * k + 2] = 1.0;
    }
    for (int k = 0; k < N_POLES + 4; ++k) {
        const int inner = k - 3;
        knots[k] = inner <= 0 ? 0.0 : inner >= N_POLES - 3 ? 1.0 : (double)inner / (N_POLES - 3);
    }
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 3, N_POLES, poles, NULL, knots, &c));
    return c;
}

/* Distance from x to the exact projection (P(t)'s x, y at z = 0) over
 * [t0, t1], by dense samples refined around the nearest. */
static double exact_distance(const projcurve_curve *c, const double x[3], double t0, double t1)
{
    double best = HUGE_VAL, best_t = t0;
    for (int k = 0; k <= EXACT_SAMPLES; ++k) {
        const double t = t0 + (t1 - t0) * k / EXACT_SAMPLES;
        double p[3];
        CHECK_OK(projcurve_curve_eval(NULL, c, t, 0, p));
        const double d = hypot(hypot(p[0] - x[0], p[1] - x[1]), x[2]);
        if (d < best)
            best = d, best_t = t;
    }
    double a = fmax(t0, best_t - (t1 - t0) / EXACT_SAMPLES);
    double b = fmin(t1, best_t + (t1 - t0) / EXACT_SAMPLES);
    for (int k = 0; k < 100; ++k) { /* golden section: the distance is unimodal this close */
        const double g = 0.5 * (sqrt(5.0) - 1.0), m1 = b - g * (b - a), m2 = a + g * (b - a);
        double p1[3], p2[3];
        CHECK_OK(projcurve_curve_eval(NULL, c, m1, 0, p1));
        CHECK_OK(projcurve_curve_eval(NULL, c, m2, 0, p2));
        if (hypot(p1[0] - x[0], p1[1] - x[1]) <= hypot(p2[0] - x[0], p2[1] - x[1]))
            b = m2;
        else
            a = m1;
    }
    double p[3];
    CHECK_OK(projcurve_curve_eval(NULL, c, 0.5 * (a + b), 0, p));
    return fmin(best, hypot(hypot(p[0] - x[0], p[1] - x[1]), x[2]));
}

/* Bezier point of a piece at s (de Casteljau, rational). */
static void piece_point(int degree, const double *ctrl, const double *w, double s, double out[3])
{
    double h[4 * PROJCURVE_MAX_PIECE_POINTS];
    for (int i = 0; i <= degree; ++i) {
        for (int k = 0; k < 3; ++k)
            h[4 * i + k] = ctrl[3 * i + k] * w[i];
        h[4 * i + 3] = w[i];
    }
    for (int r = 1; r <= degree; ++r)
        for (int i = 0; i <= degree - r; ++i)
            for (int k = 0; k < 4; ++k)
                h[4 * i + k] = (1.0 - s) * h[4 * i + k] + s * h[4 * (i + 1) + k];
    for (int k = 0; k < 3; ++k)
        out[k] = h[k] / h[3];
}

static void test_default_limits(void)
{
    long long v = 0;
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_get_int(NULL, o, PROJCURVE_OPT_MAX_POINTS, &v));
    CHECK(v == DEFAULT_MAX_POINTS);
    CHECK_OK(projcurve_options_get_int(NULL, o, PROJCURVE_OPT_MAX_PIECES, &v));
    CHECK(v == DEFAULT_MAX_PIECES);
    projcurve_options_destroy(o);
}

static void test_piece_limit(const projcurve_surface *s, const projcurve_curve *c)
{
    static const double down[3] = {0.0, 0.0, -1.0};
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    /* straight pieces: the curve needs more than the default piece limit
     * of them (of cubic ones, the default, it needs 37,615) */
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(ctx, &o));
    CHECK_OK(projcurve_options_set_int(ctx, o, PROJCURVE_OPT_PCURVE_DEGREE, 1));
    projcurve_result *r = NULL;
    const double before = peak_rss_mib();
    CHECK_STATUS(projcurve_project_directional(ctx, s, c, down, o, &r),
                 PROJCURVE_ERR_LIMIT_REACHED);
    projcurve_options_destroy(o);
    const double growth = peak_rss_mib() - before;
    printf("piece limit: %s; peak RSS grew by %.1f MiB\n", projcurve_context_message(ctx), growth);
    CHECK(growth < MEMORY_FACTOR * MEMORY_LIMIT_MIB);
    CHECK(r != NULL);
    double pieces = 0.0, eps_d = 0.0;
    CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_PIECES, &pieces));
    CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &eps_d));
    CHECK(pieces > 0.9 * DEFAULT_MAX_PIECES && pieces <= DEFAULT_MAX_PIECES);
    const size_t nb = projcurve_result_branch_count(r);
    CHECK(nb >= 1);
    size_t total = 0, checked = 0;
    double worst = 0.0;
    projcurve_branch_end last_end = PROJCURVE_END_CURVE_END;
    for (size_t b = 0; b < nb; ++b) {
        size_t n_pieces = 0;
        CHECK_OK(projcurve_result_branch_info(NULL, r, b, NULL, NULL, &last_end, NULL, &n_pieces));
        for (size_t k = 0; k < n_pieces; ++k, ++total) {
            int degree = 0;
            double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS], range[2];
            CHECK_OK(projcurve_result_piece(NULL, r, b, k, &degree, ctrl, w, range, NULL));
            if (total % PIECE_SAMPLE_EVERY != 0)
                continue;
            ++checked;
            for (int i = 0; i <= 4; ++i) {
                double x[3];
                piece_point(degree, ctrl, w, i / 4.0, x);
                CHECK(fabs(x[2]) <= 1e-12);
                worst = fmax(worst, exact_distance(c, x, range[0], range[1]));
            }
        }
    }
    printf("piece limit: %zu branches, %zu pieces, %zu checked, worst %.3g eps_D\n", nb, total,
           checked, worst / eps_d);
    CHECK(total == (size_t)pieces);
    CHECK(checked > 10);
    CHECK(worst <= eps_d);
    CHECK(last_end == PROJCURVE_END_LIMIT);
    projcurve_result_destroy(r);
    projcurve_context_destroy(ctx);
}

static void test_point_limit(const projcurve_surface *s, const projcurve_curve *c)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0));
    /* 200,000 steps over the curve's domain [0, 1] */
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_PARAM_STEP, 5e-6));
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_result *r = NULL;
    const double before = peak_rss_mib();
    CHECK_STATUS(projcurve_project_orthogonal(ctx, s, c, o, &r), PROJCURVE_ERR_LIMIT_REACHED);
    const double growth = peak_rss_mib() - before;
    printf("point limit: %s; peak RSS grew by %.1f MiB\n", projcurve_context_message(ctx), growth);
    CHECK(growth < MEMORY_FACTOR * MEMORY_LIMIT_MIB);
    CHECK(r != NULL);
    double points = 0.0;
    CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_POINTS, &points));
    CHECK(points > 0.9 * DEFAULT_MAX_POINTS && points <= DEFAULT_MAX_POINTS);
    const size_t nb = projcurve_result_branch_count(r);
    CHECK(nb >= 1);
    size_t total = 0;
    double worst = 0.0;
    projcurve_branch_end end = PROJCURVE_END_CURVE_END;
    for (size_t b = 0; b < nb; ++b) {
        size_t n = 0;
        CHECK_OK(projcurve_result_branch_info(NULL, r, b, NULL, NULL, &end, &n, NULL));
        double *p = malloc(sizeof *p * 3 * (n ? n : 1));
        CHECK(p != NULL);
        size_t got = 0;
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, n, p, &got));
        CHECK(got == n);
        for (size_t k = 0; k < n; k += 101, ++total) { /* the foot of P(t) on z = 0: (x, y) */
            double q[3];
            CHECK_OK(projcurve_curve_eval(NULL, c, p[3 * k], 0, q));
            worst = fmax(worst, hypot(p[3 * k + 1] - q[0], p[3 * k + 2] - q[1]));
        }
        free(p);
    }
    printf("point limit: %zu branches, %.0f points, worst foot error %.3g\n", nb, points, worst);
    CHECK(total > 100);
    CHECK(worst <= 1e-9);
    CHECK(end == PROJCURVE_END_LIMIT);
    projcurve_result_destroy(r);
    projcurve_context_destroy(ctx);
    projcurve_options_destroy(o);
}

int main(void)
{
    test_default_limits();
    projcurve_surface *s = unit_square();
    projcurve_curve *c = zigzag();
    /* the smaller call first: the peak resident set only grows */
    test_point_limit(s, c);
    test_piece_limit(s, c);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    return pc_test_finish("test_api_memory_limit");
}
