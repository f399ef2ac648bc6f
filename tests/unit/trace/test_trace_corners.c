/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Curves with corners: polylines (degree 1) and cubics with a double (C1)
 * or triple (C0) interior knot, projected along a ray and orthogonally onto
 * a plane and a sphere (exact oracles), along the ray onto the bumpy
 * bicubic case, orthogonally onto the bumpy "hover" case and the half
 * cylinder; a hairpin and a branch born just before a corner. The
 * projection of such a curve is continuous at each break of P, so each
 * connected stretch must come out as one branch, with no failure, a traced
 * vertex exactly at every break (t equal to the knot), no composed piece
 * straddling a C0 break, and the compact curves passing through the
 * projected vertex.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "projcurve.h"
#include "trace_shapes.h"

#define MAX_KNOTS 64
/* The plane z = 0 is spanned by a bilinear patch over [0, 100]^2 with
 * (u, v) = (x, y): the projection of P along -z or orthogonally is
 * (P.x, P.y), so the traced vertices are exact to the corrector's tolerance
 * (1e-9 of the model size and rounding: 1e-9 here). */
#define PLANE_TOL 1e-9
/* The compact forms have a C0 knot at a corner of P and interpolate the
 * pieces' common end point there (fit/features.c keeps it): rounding only
 * (measured 1e-15), not the fit's eps_D. */
#define COMPACT_CORNER_TOL 1e-9
/* eps_D of the calls (model units, the bumpy case's manifest value). */
#define EPS_D 1e-3

typedef struct test_curve {
    const char *name;
    int degree;
    size_t n_ctrl;
    double ctrl[3 * MAX_KNOTS];
    double knots[MAX_KNOTS];
    int enters; /* starts outside the surface: the branch starts on its boundary */
} test_curve;

/* A zigzag polyline of n segments over [x0, x1] x [y0, y1] at height z,
 * knots 0 0 1 .. n n (a corner at each interior integer). */
static void polyline(test_curve *c, const char *name, size_t n, double x0, double x1,
                     double y0, double y1, double z)
{
    c->name = name;
    c->enters = 0;
    c->degree = 1;
    c->n_ctrl = n + 1;
    for (size_t k = 0; k <= n; ++k) {
        c->ctrl[3 * k] = x0 + (x1 - x0) * (double)k / (double)n;
        c->ctrl[3 * k + 1] = (k % 2 == 0) ? y0 : y1;
        c->ctrl[3 * k + 2] = z + 0.5 * (double)(k % 3);
        c->knots[k + 1] = (double)k;
    }
    c->knots[0] = 0.0;
    c->knots[n + 2] = (double)n;
}

/* A cubic with one interior knot 1 of multiplicity m (2: C1, 3: C0) over
 * [0, 2]; m = 3 puts the middle control point on the curve (the corner). */
static void cubic_break(test_curve *c, const char *name, int m, double x0, double x1,
                        double y0, double y1, double z)
{
    c->name = name;
    c->enters = 0;
    c->degree = 3;
    c->n_ctrl = (size_t)(4 + m);
    size_t nk = 0;
    for (int k = 0; k < 4; ++k)
        c->knots[nk++] = 0.0;
    for (int k = 0; k < m; ++k)
        c->knots[nk++] = 1.0;
    for (int k = 0; k < 4; ++k)
        c->knots[nk++] = 2.0;
    for (size_t k = 0; k < c->n_ctrl; ++k) {
        const double s = (double)k / (double)(c->n_ctrl - 1);
        c->ctrl[3 * k] = x0 + (x1 - x0) * s;
        /* a tent in y: the corner points up, the rest wiggle */
        c->ctrl[3 * k + 1] = y0 + (y1 - y0) * (1.0 - fabs(2.0 * s - 1.0)) + 3.0 * (double)(k % 2);
        c->ctrl[3 * k + 2] = z;
    }
}

static projcurve_curve *make_curve(const test_curve *c)
{
    projcurve_curve *out = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, c->degree, c->n_ctrl, c->ctrl, NULL, c->knots,
                                          &out));
    return out;
}

/* The interior knots of c where P is C0 or C1 (multiplicity >= degree - 1),
 * and which of them are C0. */
static size_t breaks_of(const test_curve *c, double *at, int *c0)
{
    size_t n = 0;
    const size_t nk = c->n_ctrl + (size_t)c->degree + 1;
    for (size_t k = (size_t)c->degree + 1; k < c->n_ctrl;) {
        size_t m = 1;
        while (k + m < c->n_ctrl && c->knots[k + m] == c->knots[k])
            ++m;
        (void)nk;
        if ((int)m >= c->degree - 1 || c->degree == 1) {
            at[n] = c->knots[k];
            c0[n] = (int)m >= c->degree;
            ++n;
        }
        k += m;
    }
    return n;
}

static projcurve_surface *plane(void)
{
    const double ctrl[12] = {0, 0, 0, 100, 0, 0, 0, 100, 0, 100, 100, 0};
    const double knots[4] = {0, 0, 100, 100};
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 1, 1, 2, 2, ctrl, NULL, knots, knots, &s));
    return s;
}

static projcurve_model *read_case(const char *name)
{
    char path[512];
    snprintf(path, sizeof path, "%s/cases/%s.igs", PC_TEST_DATA_DIR, name);
    projcurve_model *m = NULL;
    CHECK_OK(projcurve_model_read_file(NULL, path, &m));
    return m;
}

typedef enum kind { DIRECTIONAL, ORTHOGONAL } kind;

static projcurve_result *project(kind k, const projcurve_surface *s, const projcurve_curve *c,
                                 int compose, int pcurve_degree)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, EPS_D));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, compose));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_PCURVE_DEGREE, pcurve_degree));
    projcurve_result *r = NULL;
    const double down[3] = {0, 0, -1};
    if (k == DIRECTIONAL)
        CHECK_OK(projcurve_project_directional(NULL, s, c, down, o, &r));
    else
        CHECK_OK(projcurve_project_orthogonal(NULL, s, c, o, &r));
    projcurve_options_destroy(o);
    return r;
}

/* Bezier point of a piece at s in [0, 1] (de Casteljau, rational). */
static void piece_point(int degree, const double *ctrl, const double *w, double s, double x[3])
{
    double h[PROJCURVE_MAX_PIECE_POINTS][4];
    for (int i = 0; i <= degree; ++i) {
        for (int m = 0; m < 3; ++m)
            h[i][m] = ctrl[3 * i + m] * w[i];
        h[i][3] = w[i];
    }
    for (int r = 1; r <= degree; ++r)
        for (int i = 0; i <= degree - r; ++i)
            for (int m = 0; m < 4; ++m)
                h[i][m] = (1.0 - s) * h[i][m] + s * h[i + 1][m];
    for (int m = 0; m < 3; ++m)
        x[m] = h[0][m] / h[0][3];
}

static void curve_point(const projcurve_curve *c, double t, double x[3])
{
    double d[9];
    CHECK_OK(projcurve_curve_eval(NULL, c, t, 0, d));
    memcpy(x, d, 3 * sizeof *x);
}

/* The sphere of radius SPHERE_R about the origin: the foot point of P is
 * SPHERE_R P / |P| (nearest for P outside). */
#define SPHERE_R 10.0

/* sphere 0: squared distance in (x, y) of y from P(t), the distance of y
 * from the ray P(t) - lambda z; sphere 1: squared distance of y from the
 * foot point of P(t) on the sphere. */
static double ray_distance2(const projcurve_curve *c, double t, const double y[3], int sphere)
{
    double x[3];
    curve_point(c, t, x);
    if (sphere) {
        const double len = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        double d2 = 0.0;
        for (int m = 0; m < 3; ++m)
            d2 += (SPHERE_R * x[m] / len - y[m]) * (SPHERE_R * x[m] / len - y[m]);
        return d2;
    }
    return (x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]);
}

/* Distance of y from the nearest ray of P over [lo, hi] (the brute-force
 * oracle of a piece on the plane): the best of 64 samples, then a golden
 * section search over its two neighbouring intervals (100 passes shrink
 * them by 0.618^100, far below rounding). */
static double ray_distance(const projcurve_curve *c, double lo, double hi, const double y[3],
                           int sphere)
{
    const int n = 64;
    int best = 0;
    double best_d = INFINITY;
    for (int k = 0; k <= n; ++k) {
        const double d = ray_distance2(c, lo + (hi - lo) * k / n, y, sphere);
        if (d < best_d) {
            best_d = d;
            best = k;
        }
    }
    double a = lo + (hi - lo) * (best > 0 ? best - 1 : 0) / n;
    double b = lo + (hi - lo) * (best < n ? best + 1 : n) / n;
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    for (int pass = 0; pass < 100; ++pass) {
        const double m1 = b - g * (b - a), m2 = a + g * (b - a);
        if (ray_distance2(c, m1, y, sphere) < ray_distance2(c, m2, y, sphere))
            b = m2;
        else
            a = m1;
    }
    return sqrt(fmin(best_d, ray_distance2(c, 0.5 * (a + b), y, sphere)));
}

/* Checks one result: one branch, no failure, a vertex at every break, no
 * piece across a C0 break, piece ends at a break exactly on the vertex's
 * point; on the plane every vertex and piece sample (x, y) = P(t).(x, y). */
static void check_compact(const char *what, const test_curve *tc, const projcurve_surface *s,
                          const projcurve_result *r, size_t b, const double *p, size_t n);
static void check_foot_points(const char *what, const projcurve_curve *c,
                              const projcurve_surface *s, const double *p, size_t n);

static void check_result(const char *what, kind k_proj, const test_curve *tc,
                         const projcurve_curve *c, const projcurve_surface *s,
                         const projcurve_result *r, int on_plane)
{
    const int on_sphere = on_plane == 2;
    on_plane = on_plane == 1;
    double at[MAX_KNOTS];
    int c0[MAX_KNOTS];
    const size_t nb_breaks = breaks_of(tc, at, c0);
    const size_t nb = projcurve_result_branch_count(r);
    const size_t fails = projcurve_result_failure_count(r);
    printf("%s %s: %zu branch(es), %zu failure(s)\n", what, tc->name, nb, fails);
    CHECK(fails == 0);
    CHECK(nb == 1);
    for (size_t b = 0; b < nb; ++b) {
        double range[2];
        projcurve_branch_start st;
        projcurve_branch_end en;
        size_t n = 0, n_pieces = 0;
        CHECK_OK(projcurve_result_branch_info(NULL, r, b, range, &st, &en, &n, &n_pieces));
        printf("  branch %zu: t [%g, %g] start %d end %d, %zu points, %zu pieces\n", b,
               range[0], range[1], (int)st, (int)en, n, n_pieces);
        CHECK(st == (tc->enters ? PROJCURVE_START_BOUNDARY : PROJCURVE_START_CURVE_START) &&
              en == PROJCURVE_END_CURVE_END);
        double *p = malloc(3 * n * sizeof *p);
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, n, p, &n));
        for (size_t k = 0; k < nb_breaks; ++k) {
            if (!c0[k]) /* the refined polyline keeps the corners only */
                continue;
            int found = 0;
            for (size_t i = 0; i < n; ++i)
                found |= p[3 * i] == at[k];
            if (!found)
                pc_test_fail_at(__FILE__, __LINE__, "%s %s: no vertex at the break t = %g",
                                what, tc->name, at[k]);
        }
        if (on_plane) {
            double worst = 0.0;
            for (size_t i = 0; i < n; ++i) {
                double x[3];
                curve_point(c, p[3 * i], x);
                worst = fmax(worst, fmax(fabs(x[0] - p[3 * i + 1]), fabs(x[1] - p[3 * i + 2])));
            }
            CHECK(worst <= PLANE_TOL);
        }
        if (k_proj == ORTHOGONAL)
            check_foot_points(what, c, s, p, n);
        /* every vertex the exact foot point, to the corrector's tolerance
         * (1e-9 of the model size, 2 R here) with a margin of 5 */
        if (on_sphere) {
            double worst = 0.0;
            for (size_t i = 0; i < n; ++i) {
                double y[3];
                CHECK_OK(projcurve_surface_eval(NULL, s, p[3 * i + 1], p[3 * i + 2], 0, y));
                worst = fmax(worst, sqrt(ray_distance2(c, p[3 * i], y, 1)));
            }
            printf("  sphere: vertices within %.3g of the exact foot points\n", worst);
            CHECK(worst <= PLANE_TOL * SPHERE_R);
        }
        check_compact(what, tc, s, r, b, p, n);
        free(p);
        for (size_t q = 0; q < n_pieces; ++q) {
            int deg = 0;
            double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS], pr[2];
            CHECK_OK(projcurve_result_piece(NULL, r, b, q, &deg, ctrl, w, pr, NULL));
            const double lo = fmin(pr[0], pr[1]), hi = fmax(pr[0], pr[1]);
            for (size_t k = 0; k < nb_breaks; ++k) {
                if (c0[k] && lo < at[k] && at[k] < hi)
                    pc_test_fail_at(__FILE__, __LINE__,
                                    "%s %s: piece [%g, %g] straddles the C0 break %g", what,
                                    tc->name, lo, hi, at[k]);
                /* a piece ending at a break ends on the projected vertex */
                for (int e = 0; e < 2; ++e) {
                    if (pr[e] != at[k] || !on_plane)
                        continue;
                    double x[3], y[3];
                    curve_point(c, at[k], x);
                    memcpy(y, ctrl + (e == 0 ? 0 : 3 * deg), sizeof y);
                    CHECK(fabs(x[0] - y[0]) <= PLANE_TOL && fabs(x[1] - y[1]) <= PLANE_TOL &&
                          fabs(y[2]) <= PLANE_TOL);
                }
            }
            /* every sample of the piece on a ray of its range (the rays are
             * vertical: directional along -z, orthogonal onto z = 0) */
            if (on_plane || k_proj == DIRECTIONAL || on_sphere) {
                for (int k = 0; k <= 8; ++k) {
                    double y[3];
                    piece_point(deg, ctrl, w, k / 8.0, y);
                    CHECK(ray_distance(c, lo, hi, y, on_sphere) <= EPS_D);
                    if (on_plane)
                        CHECK(fabs(y[2]) <= EPS_D);
                }
            }
        }
        (void)s;
    }
}

/* Multiplicity of x among the knots of curve (0 when not a knot). */
static size_t multiplicity(const projcurve_curve *curve, double x, int *degree)
{
    size_t n_ctrl = 0, n_knots = 0;
    CHECK_OK(projcurve_curve_nurbs_info(NULL, curve, degree, &n_ctrl, &n_knots, NULL));
    double *knots = malloc(n_knots * sizeof *knots);
    CHECK_OK(projcurve_curve_nurbs_data(NULL, curve, NULL, NULL, knots));
    size_t m = 0;
    for (size_t k = 0; k < n_knots; ++k)
        m += knots[k] == x;
    free(knots);
    return m;
}

/* The compact forms of branch b have a corner exactly at each C0 break of
 * P: a knot of multiplicity >= their degree there (C0), and pass through
 * the traced vertex's point (COMPACT_CORNER_TOL); the compact pcurve's
 * S o q too. */
static void check_compact(const char *what, const test_curve *tc, const projcurve_surface *s,
                          const projcurve_result *r, size_t b, const double *p, size_t n)
{
    double at[MAX_KNOTS];
    int c0[MAX_KNOTS];
    const size_t nb_breaks = breaks_of(tc, at, c0);
    projcurve_curve *curve = NULL, *pcurve = NULL;
    CHECK_OK(projcurve_result_branch_compact_curve(NULL, r, b, &curve));
    CHECK_OK(projcurve_result_branch_compact_pcurve(NULL, r, b, &pcurve));
    if (curve == NULL || pcurve == NULL) {
        projcurve_curve_destroy(curve);
        projcurve_curve_destroy(pcurve);
        return;
    }
    double worst = 0.0;
    for (size_t k = 0; k < nb_breaks; ++k) {
        if (!c0[k])
            continue;
        size_t i = 0;
        while (i < n && p[3 * i] != at[k])
            ++i;
        if (i == n)
            continue; /* reported by check_result */
        double vertex[3], x[3], q[3], sq[3];
        CHECK_OK(projcurve_surface_eval(NULL, s, p[3 * i + 1], p[3 * i + 2], 0, vertex));
        curve_point(curve, at[k], x);
        curve_point(pcurve, at[k], q);
        CHECK_OK(projcurve_surface_eval(NULL, s, q[0], q[1], 0, sq));
        const double dx = sqrt((x[0] - vertex[0]) * (x[0] - vertex[0]) +
                               (x[1] - vertex[1]) * (x[1] - vertex[1]) +
                               (x[2] - vertex[2]) * (x[2] - vertex[2]));
        const double dq = sqrt((sq[0] - vertex[0]) * (sq[0] - vertex[0]) +
                               (sq[1] - vertex[1]) * (sq[1] - vertex[1]) +
                               (sq[2] - vertex[2]) * (sq[2] - vertex[2]));
        worst = fmax(worst, fmax(dx, dq));
        CHECK(dx <= COMPACT_CORNER_TOL && dq <= COMPACT_CORNER_TOL);
        int deg_c = 0, deg_q = 0;
        const size_t mc = multiplicity(curve, at[k], &deg_c);
        const size_t mq = multiplicity(pcurve, at[k], &deg_q);
        if (!((int)mc >= deg_c && (int)mq >= deg_q))
            pc_test_fail_at(__FILE__, __LINE__,
                            "%s %s: compact knots at the corner %g: multiplicity %zu (degree "
                            "%d), pcurve %zu (degree %d)",
                            what, tc->name, at[k], mc, deg_c, mq, deg_q);
    }
    printf("  compact forms at the corners: within %.3g of the vertices\n", worst);
    projcurve_curve_destroy(curve);
    projcurve_curve_destroy(pcurve);
}

/* Orthogonal results: at every vertex S(u, v) - P(t) is normal to S (its
 * components along Su and Sv vanish) to 1e-8 of the offset's length plus
 * the model size (the corrector's tolerance is 1e-9 of the model). */
static void check_foot_points(const char *what, const projcurve_curve *c,
                              const projcurve_surface *s, const double *p, size_t n)
{
    double box[6];
    CHECK_OK(projcurve_surface_bounds(NULL, s, box));
    const double size = hypot(hypot(box[3] - box[0], box[4] - box[1]), box[5] - box[2]);
    double worst = 0.0;
    for (size_t i = 0; i < n; ++i) {
        double x[3], d[9];
        curve_point(c, p[3 * i], x);
        CHECK_OK(projcurve_surface_eval(NULL, s, p[3 * i + 1], p[3 * i + 2], 1, d));
        for (int j = 1; j <= 2; ++j) {
            const double *su = d + 3 * j;
            const double len = sqrt(su[0] * su[0] + su[1] * su[1] + su[2] * su[2]);
            const double along =
                ((x[0] - d[0]) * su[0] + (x[1] - d[1]) * su[1] + (x[2] - d[2]) * su[2]) / len;
            worst = fmax(worst, fabs(along) / size);
        }
    }
    printf("  %s: foot points tangential offset <= %.3g of the model size\n", what, worst);
    CHECK(worst <= 1e-8);
}

/* A polyline through the control points of curve (x, y, z + lift). */
static void control_polygon(test_curve *tc, const char *name, const projcurve_curve *curve,
                            double lift)
{
    size_t n_ctrl = 0;
    CHECK_OK(projcurve_curve_nurbs_info(NULL, curve, NULL, &n_ctrl, NULL, NULL));
    CHECK(n_ctrl >= 2 && n_ctrl + 2 <= MAX_KNOTS);
    double *ctrl = malloc(3 * n_ctrl * sizeof *ctrl);
    CHECK_OK(projcurve_curve_nurbs_data(NULL, curve, ctrl, NULL, NULL));
    tc->name = name;
    tc->enters = 0;
    tc->degree = 1;
    tc->n_ctrl = n_ctrl;
    for (size_t k = 0; k < n_ctrl; ++k) {
        tc->ctrl[3 * k] = ctrl[3 * k];
        tc->ctrl[3 * k + 1] = ctrl[3 * k + 1];
        tc->ctrl[3 * k + 2] = ctrl[3 * k + 2] + lift;
        tc->knots[k + 1] = (double)k;
    }
    tc->knots[0] = 0.0;
    tc->knots[n_ctrl + 1] = (double)(n_ctrl - 1);
    free(ctrl);
}

/* Traced only: one branch with a vertex exactly at every corner of P (the
 * tracer lands on the C0 knots; at C1 knots it steps across, as q' is
 * continuous there). */
static void check_traced(const char *what, const test_curve *tc, const projcurve_result *r)
{
    double at[MAX_KNOTS];
    int c0[MAX_KNOTS];
    const size_t nb_breaks = breaks_of(tc, at, c0);
    CHECK(projcurve_result_branch_count(r) == 1);
    CHECK(projcurve_result_failure_count(r) == 0);
    size_t n = 0;
    CHECK_OK(projcurve_result_branch_info(NULL, r, 0, NULL, NULL, NULL, &n, NULL));
    double *p = malloc(3 * (n + 1) * sizeof *p);
    CHECK_OK(projcurve_result_branch_points(NULL, r, 0, n, p, &n));
    for (size_t k = 0; k < nb_breaks; ++k) {
        if (!c0[k])
            continue;
        int found = 0;
        for (size_t i = 0; i < n; ++i)
            found |= p[3 * i] == at[k];
        if (!found)
            pc_test_fail_at(__FILE__, __LINE__, "%s %s traced: no vertex at the break t = %g",
                            what, tc->name, at[k]);
    }
    free(p);
}

/* on_plane: 1 the plane z = 0, 2 the sphere of radius SPHERE_R about the
 * origin (exact oracles), 0 neither. */
static void run_degree(const char *what, kind k, const test_curve *tc,
                       const projcurve_surface *s, int on_plane, int pcurve_degree)
{
    projcurve_curve *c = make_curve(tc);
    projcurve_result *r = project(k, s, c, 0, pcurve_degree);
    check_traced(what, tc, r);
    projcurve_result_destroy(r);
    r = project(k, s, c, 1, pcurve_degree);
    check_result(what, k, tc, c, s, r, on_plane);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
}

/* With the default straight pcurves. */
static void run(const char *what, kind k, const test_curve *tc, const projcurve_surface *s,
                int on_plane)
{
    run_degree(what, k, tc, s, on_plane, 1);
}

int main(void)
{
    test_curve tc;
    projcurve_surface *pl = plane();
    polyline(&tc, "polyline_1", 1, 10, 90, 20, 70, 5);
    run("plane dir", DIRECTIONAL, &tc, pl, 1);
    polyline(&tc, "polyline_3", 3, 10, 90, 20, 70, 5);
    run("plane dir", DIRECTIONAL, &tc, pl, 1);
    run("plane ortho", ORTHOGONAL, &tc, pl, 1);
    polyline(&tc, "polyline_10", 10, 10, 90, 20, 70, 5);
    run("plane dir", DIRECTIONAL, &tc, pl, 1);
    run("plane ortho", ORTHOGONAL, &tc, pl, 1);
    cubic_break(&tc, "cubic_c1", 2, 10, 90, 20, 70, 5);
    run("plane dir", DIRECTIONAL, &tc, pl, 1);
    cubic_break(&tc, "cubic_c0", 3, 10, 90, 20, 70, 5);
    run("plane dir", DIRECTIONAL, &tc, pl, 1);
    run_degree("plane dir cubic pcurves", DIRECTIONAL, &tc, pl, 1, 3);
    run("plane ortho", ORTHOGONAL, &tc, pl, 1);
    /* a hairpin: the second leg returns within a degree of the first, so
     * near the corner both legs' rays hit S close together (the jump
     * sweep must see one branch) */
    polyline(&tc, "hairpin", 2, 10, 90, 20, 70, 5);
    tc.ctrl[6] = 12.0;
    tc.ctrl[7] = 20.0 + 2.0;
    run("plane dir", DIRECTIONAL, &tc, pl, 1);
    run("plane ortho", ORTHOGONAL, &tc, pl, 1);
    /* entering from outside the surface 0.01 before a corner: the branch is
     * born mid-curve and traced back across the corner to the boundary */
    polyline(&tc, "entering", 3, 10, 90, 20, 70, 5);
    tc.ctrl[0] = -5.0;
    tc.ctrl[3] = 0.05;
    tc.enters = 1;
    run("plane dir", DIRECTIONAL, &tc, pl, 1);
    projcurve_surface_destroy(pl);

    projcurve_model *m = read_case("bumpy_bicubic_8x8_down");
    const projcurve_surface *bumpy = projcurve_model_surface(m, 0);
    double box[6];
    CHECK_OK(projcurve_surface_bounds(NULL, bumpy, box));
    const double x0 = box[0] + 0.1 * (box[3] - box[0]), x1 = box[3] - 0.1 * (box[3] - box[0]);
    const double y0 = box[1] + 0.1 * (box[4] - box[1]), y1 = box[4] - 0.1 * (box[4] - box[1]);
    polyline(&tc, "bumpy_polyline_3", 3, x0, x1, y0, y1, box[5] + 10);
    run("bumpy dir", DIRECTIONAL, &tc, bumpy, 0);
    polyline(&tc, "bumpy_polyline_10", 10, x0, x1, y0, y1, box[5] + 10);
    run("bumpy dir", DIRECTIONAL, &tc, bumpy, 0);
    run_degree("bumpy dir cubic pcurves", DIRECTIONAL, &tc, bumpy, 0, 3);
    cubic_break(&tc, "bumpy_cubic_c0", 3, x0, x1, y0, y1, box[5] + 10);
    run("bumpy dir", DIRECTIONAL, &tc, bumpy, 0);
    run_degree("bumpy dir cubic pcurves", DIRECTIONAL, &tc, bumpy, 0, 3);
    polyline(&tc, "bumpy_hairpin", 2, x0, x1, y0, y1, box[5] + 10);
    tc.ctrl[6] = x0 + 0.02 * (x1 - x0);
    tc.ctrl[7] = y0 + 0.05 * (y1 - y0);
    run("bumpy dir", DIRECTIONAL, &tc, bumpy, 0);
    projcurve_model_destroy(m);

    /* orthogonal onto a sphere: a polyline around the z axis (away from
     * the seam at u = 0 and the poles), crossing the sphere's C0 knot lines */
    projcurve_surface *sphere = shape_sphere(SPHERE_R);
    tc.name = "sphere_polyline";
    tc.enters = 0;
    tc.degree = 1;
    tc.n_ctrl = 5;
    for (size_t k = 0; k < 5; ++k) {
        const double angle = (60.0 + 55.0 * (double)k) * 3.14159265358979323846 / 180.0;
        tc.ctrl[3 * k] = 15.0 * cos(angle);
        tc.ctrl[3 * k + 1] = 15.0 * sin(angle);
        tc.ctrl[3 * k + 2] = (k % 2 == 0) ? 8.0 : -3.0;
        tc.knots[k + 1] = (double)k;
    }
    tc.knots[0] = 0.0;
    tc.knots[6] = 4.0;
    run("sphere ortho", ORTHOGONAL, &tc, sphere, 2);
    run_degree("sphere ortho cubic pcurves", ORTHOGONAL, &tc, sphere, 2, 3);
    projcurve_surface_destroy(sphere);

    /* orthogonal onto curved surfaces: the control polygons of the cases'
     * own curves */
    const char *ortho_cases[2] = {"ortho_bumpy_bicubic_hover", "ortho_nurbs_half_cylinder"};
    for (int i = 0; i < 2; ++i) {
        m = read_case(ortho_cases[i]);
        control_polygon(&tc, ortho_cases[i], projcurve_model_curve(m, 0), 0.0);
        run("ortho", ORTHOGONAL, &tc, projcurve_model_surface(m, 0), 0);
        projcurve_model_destroy(m);
    }
    return pc_test_finish("test_trace_corners");
}
