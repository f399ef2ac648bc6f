/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Faces made through the public API on the unit square (a bilinear plane),
 * classified against the analytic answer on dense grids: a square with a
 * circular hole (exact rational arcs), a square with several holes, a
 * star of 600 line pieces against an independent even-odd count, points on
 * and near the boundary, loops given in the wrong orientation, the bad
 * loops a caller can give, and one face classified by four threads at once.
 */
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#include "check.h"
#include "projcurve.h"

#define TOL_UV 1e-6
#define MAX_PIECES 4096

static projcurve_surface *unit_square(void)
{
    static const double net[] = {0, 0, 0, 1, 0, 0, 0, 1, 0, 1, 1, 0}, knots[] = {0, 0, 1, 1};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 1, 1, 2, 2, net, NULL, knots, knots, &s));
    return s;
}

/* Pieces of the loops being assembled. */
typedef struct loops {
    size_t n_loops, loop_pieces[16], n;
    int degree[MAX_PIECES];
    size_t n_ctrl[MAX_PIECES];
    double ctrl[MAX_PIECES][18], weights[MAX_PIECES][9], knots[MAX_PIECES][12];
    const double *ctrl_p[MAX_PIECES], *weights_p[MAX_PIECES], *knots_p[MAX_PIECES];
} loops;

static void begin_loop(loops *L)
{
    L->loop_pieces[L->n_loops++] = 0;
}

static void add_line(loops *L, double x0, double y0, double x1, double y1)
{
    const size_t j = L->n++;
    L->degree[j] = 1;
    L->n_ctrl[j] = 2;
    const double c[4] = {x0, y0, x1, y1}, k[4] = {0, 0, 1, 1};
    memcpy(L->ctrl[j], c, sizeof c);
    memcpy(L->knots[j], k, sizeof k);
    L->ctrl_p[j] = L->ctrl[j], L->knots_p[j] = L->knots[j], L->weights_p[j] = NULL;
    ++L->loop_pieces[L->n_loops - 1];
}

/* A full circle as two rational quadratic pieces of two quarter arcs each;
 * ccw = 0 runs it clockwise. */
static void add_circle(loops *L, double cx, double cy, double r, int ccw)
{
    const double h = sqrt(0.5);
    for (int half = 0; half < 2; ++half) {
        const size_t j = L->n++;
        L->degree[j] = 2;
        L->n_ctrl[j] = 5;
        static const double k[8] = {0, 0, 0, 1, 1, 2, 2, 2};
        memcpy(L->knots[j], k, sizeof k);
        const double s = half ? -1.0 : 1.0;
        /* ccw: (r,0) (r,r) (0,r) (-r,r) (-r,0), mirrored for the second half */
        const double px[5] = {r, r, 0, -r, -r}, py[5] = {0, r, r, r, 0};
        const double w[5] = {1, h, 1, h, 1};
        for (int i = 0; i < 5; ++i) {
            const double x = s * px[i], y = s * py[i];
            L->ctrl[j][2 * i] = cx + x;
            L->ctrl[j][2 * i + 1] = cy + (ccw ? y : -y);
            L->weights[j][i] = w[i];
        }
        L->ctrl_p[j] = L->ctrl[j], L->knots_p[j] = L->knots[j], L->weights_p[j] = L->weights[j];
        ++L->loop_pieces[L->n_loops - 1];
    }
}

static void add_square(loops *L, double x0, double y0, double x1, double y1)
{
    begin_loop(L);
    add_line(L, x0, y0, x1, y0);
    add_line(L, x1, y0, x1, y1);
    add_line(L, x1, y1, x0, y1);
    add_line(L, x0, y1, x0, y0);
}

static projcurve_status make_face(projcurve_context *ctx, const projcurve_surface *s,
                                  const loops *L, projcurve_face **f)
{
    return projcurve_face_create(ctx, s, L->n_loops, L->loop_pieces, L->degree, L->n_ctrl,
                                 L->ctrl_p, L->weights_p, L->knots_p, TOL_UV, f);
}

typedef struct hole {
    double cx, cy, r;
} hole;

/* Signed distance to the boundary of [a, b]^2 minus the circles: > 0
 * inside the face. */
static double face_distance(double u, double v, double a, double b, const hole *holes, int n)
{
    double d = fmin(fmin(u - a, b - u), fmin(v - a, b - v));
    for (int k = 0; k < n; ++k)
        d = fmin(d, hypot(u - holes[k].cx, v - holes[k].cy) - holes[k].r);
    return d;
}

/* Every point of an n x n grid (and of a grid shifted by a third of a
 * cell) beyond 1.25 tol of the boundary is classified by its side; points
 * within 0.75 tol are ON (the polygon is within tol / 4 of the loops). */
static void check_grid(const projcurve_face *f, const hole *holes, int n_holes, int n,
                       const char *name)
{
    int wrong = 0;
    for (int shift = 0; shift < 2; ++shift)
        for (int i = 0; i <= n; ++i)
            for (int j = 0; j <= n; ++j) {
                const double u = -0.1 + 1.2 * (i + shift / 3.0) / n;
                const double v = -0.1 + 1.2 * (j + shift / 3.0) / n;
                const double d = face_distance(u, v, 0.0, 1.0, holes, n_holes);
                projcurve_where w = PROJCURVE_ON;
                CHECK_OK(projcurve_face_classify(NULL, f, u, v, &w));
                projcurve_where expect = d > 1.25 * TOL_UV ? PROJCURVE_IN
                                         : d < -1.25 * TOL_UV ? PROJCURVE_OUT
                                                              : (fabs(d) < 0.75 * TOL_UV ? PROJCURVE_ON : w);
                if (w != expect && wrong++ < 5)
                    pc_test_fail_at(__FILE__, __LINE__, "%s: (%.17g, %.17g) at distance %g is %d, expected %d",
                                    name, u, v, d, (int)w, (int)expect);
            }
    CHECK(wrong == 0);
}

static void square_with_hole(const projcurve_surface *s)
{
    for (int ccw = 0; ccw < 2; ++ccw) { /* the hole's orientation does not matter */
        loops L = {0};
        add_square(&L, 0, 0, 1, 1);
        begin_loop(&L);
        add_circle(&L, 0.5, 0.5, 0.25, ccw);
        projcurve_face *f = NULL;
        CHECK_OK(make_face(NULL, s, &L, &f));
        const hole h = {0.5, 0.5, 0.25};
        check_grid(f, &h, 1, 400, "square with a hole");
        CHECK(projcurve_face_loop_count(f) == 2);
        /* points on the circle, and just inside and outside its tolerance */
        for (int k = 0; k < 360; ++k) {
            const double a = k * M_PI / 180.0 + 0.001;
            for (int m = -3; m <= 3; ++m) {
                const double r = 0.25 + m * 0.5 * TOL_UV;
                projcurve_where w;
                CHECK_OK(projcurve_face_classify(NULL, f, 0.5 + r * cos(a), 0.5 + r * sin(a), &w));
                const projcurve_where expect = m == 0 || abs(m) == 1 ? PROJCURVE_ON
                                               : m >= 3 ? PROJCURVE_IN
                                               : m <= -3 ? PROJCURVE_OUT : w;
                if (w != expect)
                    pc_test_fail_at(__FILE__, __LINE__, "angle %d, offset %d tol/2: %d, expected %d",
                                    k, m, (int)w, (int)expect);
            }
        }
        int degree = 0;
        size_t n_ctrl = 0, pieces = 0;
        const double *ctrl = NULL, *weights = NULL;
        CHECK_OK(projcurve_face_loop_piece_count(NULL, f, 1, &pieces));
        CHECK(pieces == 2);
        CHECK_OK(projcurve_face_piece_curve(NULL, f, 1, 1, &degree, &n_ctrl, &ctrl, &weights, NULL, NULL));
        CHECK(degree == 2 && n_ctrl == 5 && weights != NULL && ctrl[0] == L.ctrl[L.n - 1][0]);
        projcurve_face_destroy(f);
    }
}

static void several_holes(const projcurve_surface *s)
{
    loops L = {0};
    /* the outer loop clockwise: it is turned round */
    begin_loop(&L);
    add_line(&L, 0, 0, 0, 1);
    add_line(&L, 0, 1, 1, 1);
    add_line(&L, 1, 1, 1, 0);
    add_line(&L, 1, 0, 0, 0);
    const hole holes[3] = {{0.25, 0.25, 0.15}, {0.75, 0.3, 0.1}, {0.3, 0.75, 0.2}};
    for (int k = 0; k < 3; ++k) {
        begin_loop(&L);
        add_circle(&L, holes[k].cx, holes[k].cy, holes[k].r, k % 2);
    }
    add_square(&L, 0.6, 0.6, 0.9, 0.9);
    projcurve_face *f = NULL;
    CHECK_OK(make_face(NULL, s, &L, &f));
    CHECK(projcurve_face_loop_count(f) == 5);
    /* the square hole by its own distance */
    int wrong = 0;
    for (int i = 0; i <= 300; ++i)
        for (int j = 0; j <= 300; ++j) {
            const double u = i / 300.0 + 1e-4, v = j / 300.0 + 3e-4;
            double d = face_distance(u, v, 0.0, 1.0, holes, 3);
            const double dx = fmax(0.6 - u, u - 0.9), dy = fmax(0.6 - v, v - 0.9);
            const double out_sq = (dx > 0 || dy > 0) ? hypot(fmax(dx, 0), fmax(dy, 0)) : fmax(dx, dy);
            d = fmin(d, out_sq);
            projcurve_where w;
            CHECK_OK(projcurve_face_classify(NULL, f, u, v, &w));
            const projcurve_where expect = d > 1.25 * TOL_UV ? PROJCURVE_IN
                                           : d < -1.25 * TOL_UV ? PROJCURVE_OUT : w;
            if (w != expect && wrong++ < 5)
                pc_test_fail_at(__FILE__, __LINE__, "(%g, %g): %d, expected %d", u, v, (int)w, (int)expect);
        }
    CHECK(wrong == 0);
    projcurve_face_destroy(f);
}

/* Even-odd count over the star's vertices, written apart from the library. */
static int star_inside(double (*p)[2], int n, double x, double y)
{
    int in = 0;
    for (int i = 0, j = n - 1; i < n; j = i++)
        if ((p[i][1] > y) != (p[j][1] > y) &&
            x < (p[j][0] - p[i][0]) * (y - p[i][1]) / (p[j][1] - p[i][1]) + p[i][0])
            in = !in;
    return in;
}

static double star_distance(double (*p)[2], int n, double x, double y)
{
    double d = INFINITY;
    for (int i = 0, j = n - 1; i < n; j = i++) {
        const double ex = p[i][0] - p[j][0], ey = p[i][1] - p[j][1];
        double t = ((x - p[j][0]) * ex + (y - p[j][1]) * ey) / (ex * ex + ey * ey);
        t = fmin(fmax(t, 0.0), 1.0);
        d = fmin(d, hypot(x - p[j][0] - t * ex, y - p[j][1] - t * ey));
    }
    return d;
}

static void star(const projcurve_surface *s)
{
    enum { N = 600 };
    static double p[N][2];
    for (int k = 0; k < N; ++k) {
        const double a = 2.0 * M_PI * k / N, r = 0.3 + 0.15 * ((k % 2) ? 1.0 : 0.2 * sin(7 * a));
        p[k][0] = 0.5 + r * cos(a);
        p[k][1] = 0.5 + r * sin(a);
    }
    static loops L;
    memset(&L, 0, sizeof L);
    begin_loop(&L);
    for (int k = 0; k < N; ++k)
        add_line(&L, p[k][0], p[k][1], p[(k + 1) % N][0], p[(k + 1) % N][1]);
    projcurve_face *f = NULL;
    CHECK_OK(make_face(NULL, s, &L, &f));
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 17);
    int wrong = 0;
    for (int q = 0; q < 200000; ++q) {
        const double x = pc_test_rng_uniform(&rng, 0.1, 0.9), y = pc_test_rng_uniform(&rng, 0.1, 0.9);
        const double d = star_distance(p, N, x, y);
        projcurve_where w;
        CHECK_OK(projcurve_face_classify(NULL, f, x, y, &w));
        const projcurve_where expect = d <= TOL_UV ? PROJCURVE_ON
                                       : (star_inside(p, N, x, y) ? PROJCURVE_IN : PROJCURVE_OUT);
        if (w != expect && wrong++ < 5)
            pc_test_fail_at(__FILE__, __LINE__, "star (%.17g, %.17g) d %g: %d, expected %d", x, y, d, (int)w, (int)expect);
    }
    /* the vertices and the middles of the sides are ON */
    for (int k = 0; k < N; ++k) {
        projcurve_where w, m;
        CHECK_OK(projcurve_face_classify(NULL, f, p[k][0], p[k][1], &w));
        CHECK_OK(projcurve_face_classify(NULL, f, 0.5 * (p[k][0] + p[(k + 1) % N][0]),
                                         0.5 * (p[k][1] + p[(k + 1) % N][1]), &m));
        wrong += w != PROJCURVE_ON || m != PROJCURVE_ON;
    }
    CHECK(wrong == 0);
    projcurve_face_destroy(f);
}

/* A star of 3000 vertices alternating between radius 0.05 and 0.45: every
 * spike's box covers a good part of the face, so the grid's lists would
 * grow quadratically; the grid is coarsened instead (classify.c), and
 * the answers still agree with the independent even-odd count. */
static void long_spikes(const projcurve_surface *s)
{
    enum { N = 3000 };
    static double p[N][2];
    for (int k = 0; k < N; ++k) {
        const double a = 2.0 * M_PI * k / N, r = (k % 2) ? 0.45 : 0.05;
        p[k][0] = 0.5 + r * cos(a);
        p[k][1] = 0.5 + r * sin(a);
    }
    static loops L;
    memset(&L, 0, sizeof L);
    begin_loop(&L);
    for (int k = 0; k < N; ++k)
        add_line(&L, p[k][0], p[k][1], p[(k + 1) % N][0], p[(k + 1) % N][1]);
    projcurve_face *f = NULL;
    CHECK_OK(projcurve_face_create(NULL, s, L.n_loops, L.loop_pieces, L.degree, L.n_ctrl,
                                   L.ctrl_p, L.weights_p, L.knots_p, 1e-9, &f));
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 23);
    int wrong = 0;
    for (int q = 0; q < 20000 && f != NULL; ++q) {
        const double x = pc_test_rng_uniform(&rng, 0.0, 1.0), y = pc_test_rng_uniform(&rng, 0.0, 1.0);
        const double d = star_distance(p, N, x, y);
        projcurve_where w;
        CHECK_OK(projcurve_face_classify(NULL, f, x, y, &w));
        const projcurve_where expect = d <= 1e-9 ? PROJCURVE_ON
                                       : (star_inside(p, N, x, y) ? PROJCURVE_IN : PROJCURVE_OUT);
        if (w != expect && wrong++ < 5)
            pc_test_fail_at(__FILE__, __LINE__, "spikes (%.17g, %.17g) d %g: %d, expected %d", x, y, d, (int)w, (int)expect);
    }
    CHECK(wrong == 0);
    projcurve_face_destroy(f);
}

static void natural_boundary(const projcurve_surface *s)
{
    projcurve_face *f = NULL;
    CHECK_OK(projcurve_face_create(NULL, s, 0, NULL, NULL, NULL, NULL, NULL, NULL, 0.0, &f));
    CHECK(projcurve_face_loop_count(f) == 1);
    check_grid(f, NULL, 0, 100, "natural boundary");
    unsigned flags = 0;
    long edge = 0;
    CHECK_OK(projcurve_face_piece_edge(NULL, f, 0, 0, &edge, NULL, &flags));
    CHECK(edge == -1 && (flags & PROJCURVE_PIECE_NATURAL));
    projcurve_face_destroy(f);
}

static void expect_failure(const projcurve_surface *s, const loops *L, projcurve_status status,
                           const char *words)
{
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_face *f = NULL;
    CHECK_STATUS(make_face(ctx, s, L, &f), status);
    CHECK(f == NULL);
    const char *msg = projcurve_context_message(ctx);
    if (strstr(msg, words) == NULL)
        pc_test_fail_at(__FILE__, __LINE__, "message \"%s\" does not say \"%s\"", msg, words);
    projcurve_context_destroy(ctx);
}

static void bad_loops(const projcurve_surface *s)
{
    loops L = {0};
    begin_loop(&L);
    add_line(&L, 0, 0, 1, 0);
    add_line(&L, 1, 0, 1, 1);
    add_line(&L, 1, 1, 0, 1); /* the way back is missing */
    expect_failure(s, &L, PROJCURVE_ERR_INVALID_ARGUMENT, "loop 0 is open: piece 2 ends");

    memset(&L, 0, sizeof L);
    add_square(&L, 0, 0, 0.5, 0.5);
    add_square(&L, 0.7, 0.7, 0.9, 0.9);
    expect_failure(s, &L, PROJCURVE_ERR_INVALID_ARGUMENT, "loop 1 (a hole) is outside the outer loop");

    memset(&L, 0, sizeof L);
    add_square(&L, 0, 0, 1, 1);
    L.ctrl[2][1] = NAN;
    expect_failure(s, &L, PROJCURVE_ERR_NOT_FINITE, "loop 0 piece 2: control point 0 is not finite");

    memset(&L, 0, sizeof L);
    add_square(&L, 0, 0, 1, 1);
    L.knots[1][2] = -1.0;
    expect_failure(s, &L, PROJCURVE_ERR_BAD_KNOTS, "loop 0 piece 1: knot vector decreases");

    memset(&L, 0, sizeof L);
    begin_loop(&L);
    add_line(&L, 0, 0, 1, 0);
    add_line(&L, 1, 0, 0, 0); /* there and back: no area */
    expect_failure(s, &L, PROJCURVE_ERR_INVALID_ARGUMENT, "encloses no area");

    projcurve_face *f = NULL;
    CHECK_STATUS(projcurve_face_create(NULL, NULL, 0, NULL, NULL, NULL, NULL, NULL, NULL, 0.0, &f),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_face_create(NULL, s, 0, NULL, NULL, NULL, NULL, NULL, NULL, -1.0, &f),
                 PROJCURVE_ERR_OUT_OF_RANGE);
    projcurve_where w;
    CHECK_STATUS(projcurve_face_classify(NULL, NULL, 0.5, 0.5, &w), PROJCURVE_ERR_NULL_ARGUMENT);
}

/* One face read by several threads at once: every thread gets the
 * answers of a single-threaded pass (the face is immutable). */
enum { THREADS = 4, THREAD_POINTS = 20000 };
typedef struct thread_job {
    const projcurve_face *face;
    const double *uv;
    projcurve_where *out;
} thread_job;

static void *classify_all(void *arg)
{
    thread_job *job = arg;
    for (int i = 0; i < THREAD_POINTS; ++i)
        projcurve_face_classify(NULL, job->face, job->uv[2 * i], job->uv[2 * i + 1], &job->out[i]);
    return NULL;
}

static void threads(const projcurve_surface *s)
{
    loops L = {0};
    add_square(&L, 0, 0, 1, 1);
    begin_loop(&L);
    add_circle(&L, 0.5, 0.5, 0.25, 1);
    projcurve_face *f = NULL;
    CHECK_OK(make_face(NULL, s, &L, &f));
    static double uv[2 * THREAD_POINTS];
    static projcurve_where single[THREAD_POINTS], multi[THREADS][THREAD_POINTS];
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 5);
    for (int i = 0; i < 2 * THREAD_POINTS; ++i)
        uv[i] = pc_test_rng_uniform(&rng, -0.1, 1.1);
    thread_job one = {f, uv, single};
    classify_all(&one);
    pthread_t t[THREADS];
    thread_job jobs[THREADS];
    for (int k = 0; k < THREADS; ++k) {
        jobs[k] = (thread_job){f, uv, multi[k]};
        CHECK(pthread_create(&t[k], NULL, classify_all, &jobs[k]) == 0);
    }
    for (int k = 0; k < THREADS; ++k)
        pthread_join(t[k], NULL);
    int differ = 0;
    for (int k = 0; k < THREADS; ++k)
        differ += memcmp(single, multi[k], sizeof single) != 0;
    CHECK(differ == 0);
    projcurve_face_destroy(f);
}

int main(void)
{
    projcurve_surface *s = unit_square();
    square_with_hole(s);
    several_holes(s);
    star(s);
    long_spikes(s);
    natural_boundary(s);
    bad_loops(s);
    threads(s);
    projcurve_surface_destroy(s);
    return pc_test_finish("test_brep_classify");
}
