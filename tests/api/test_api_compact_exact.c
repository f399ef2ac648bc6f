/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve_result_branch_compact_exact: S o q of the compact pcurve as
 * one NURBS curve. Oracles, independent of the library's evaluators and
 * composer: de Boor on the raw arrays (tests/support/deboor.c) of the
 * compact pcurve q (read back through the public API), unwrapped by the
 * recorded seam jumps, and of the surface; every sample of the exact curve
 * must equal S(q(t)) to EXACT_REL of the model size. The knot-line
 * crossings are found by dense sampling and bisection of q. The knots of
 * the exact curve at its joins (q's knots, its seam jumps, the crossings)
 * are checked against the continuity of S o q there (check_joins).
 * Surfaces: a bicubic plane, the rational
 * cylinder and sphere (with a seam and poles), bicubic B-spline and
 * rational graphs; and the statuses of bad input.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "deboor.h"
#include "shapes.h"

/* Both sides are the same polynomial (rational) curve in two bases: the
 * composer forms convex combinations of the patch's control points (no
 * cancellation while q's control points lie in the patch's box), de Boor
 * likewise, so each is within a few hundred ulps of the model size at
 * degree 18 (a few n eps |P| per de Casteljau level). 1e-12 is ~4500 ulps:
 * room for both, and 1e8 times below eps_D. */
#define EXACT_REL 1e-12
/* Samples of the exact curve per branch. */
#define SAMPLES 500
/* Dense scan for knot-line crossings of q, then bisection to 1e-15 of the
 * range; a crossing must be a knot of the exact curve to 1e-12 of it (the
 * library locates it to 2^-52 of a span of q). */
#define SCAN 4000
#define CROSS_TOL 1e-12
/* A join with another closer than this (of the range) is not expected
 * to lose all the copies its continuity allows: removal there solves
 * with insertion weights near 0 or 1, which magnify the rounding of the
 * poles by up to the ratio of the parts' lengths. The fit puts knots of
 * q near crossings: measured 1e-13 apart (three pairs) on the bicubic
 * graph, 1e-6 to 1e-5 (six) on the rational one. */
#define ISOLATED 1e-4
#define MAX_FEATURES 128

/* The places where S o q may be less smooth than analytic: t and the
 * continuity order there (C^k). */
typedef struct features {
    size_t n;
    double t[MAX_FEATURES];
    int k[MAX_FEATURES];
} features;

static void add_feature(features *f, double t, int k)
{
    CHECK(f->n < MAX_FEATURES);
    if (f->n < MAX_FEATURES) {
        f->t[f->n] = t;
        f->k[f->n++] = k;
    }
}

static double model_size(const pc_shape_surface *s)
{
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t i = 0; i < s->n_u * s->n_v; ++i)
        for (int c = 0; c < 3; ++c) {
            lo[c] = fmin(lo[c], s->ctrl[3 * i + c]);
            hi[c] = fmax(hi[c], s->ctrl[3 * i + c]);
        }
    return sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                (hi[2] - lo[2]) * (hi[2] - lo[2]));
}

/* The curve handle's NURBS data as raw arrays (freed by pc_shape_curve_free). */
static pc_shape_curve arrays_of(const projcurve_curve *c)
{
    pc_shape_curve a = {0, 0, NULL, NULL, NULL};
    size_t n_knots = 0;
    int rational = 0;
    CHECK_OK(projcurve_curve_nurbs_info(NULL, c, &a.degree, &a.n_ctrl, &n_knots, &rational));
    a.ctrl = malloc(3 * a.n_ctrl * sizeof *a.ctrl);
    a.weights = rational ? malloc(a.n_ctrl * sizeof *a.weights) : NULL;
    a.knots = malloc(n_knots * sizeof *a.knots);
    CHECK_OK(projcurve_curve_nurbs_data(NULL, c, a.ctrl, a.weights, a.knots));
    return a;
}

typedef struct seams {
    size_t n;
    double t[8], du[8], dv[8];
} seams;

/* (u, v) on S at t: q(t) plus the jumps at or before t, in the domain. */
static void wrapped(const pc_shape_curve *q, const seams *j, const pc_shape_surface *sa,
                    double t, double uv[2])
{
    double x[3];
    pc_deboor_curve(q, t, x);
    for (size_t k = 0; k < j->n; ++k)
        if (j->t[k] <= t) {
            x[0] += j->du[k];
            x[1] += j->dv[k];
        }
    const double u0 = sa->knots_u[sa->deg_u], u1 = sa->knots_u[sa->n_u];
    const double v0 = sa->knots_v[sa->deg_v], v1 = sa->knots_v[sa->n_v];
    uv[0] = fmin(fmax(x[0], u0), u1);
    uv[1] = fmin(fmax(x[1], v0), v1);
}

/* The crossings of coordinate c of q with the value k, by scanning and
 * bisection, added to feat with continuity cont. Returns how many. */
static size_t check_crossings(const pc_shape_curve *q, const seams *j,
                              const pc_shape_surface *sa, int c, double k, int cont,
                              features *feat)
{
    const double lo = q->knots[0], hi = q->knots[q->n_ctrl + (size_t)q->degree];
    size_t found = 0;
    double uv[2], prev_t = lo;
    wrapped(q, j, sa, lo, uv);
    double prev = uv[c] - k;
    for (int i = 1; i <= SCAN + 1; ++i) { /* off the grid of round t: a zero at a sample */
        const double t = i > SCAN ? hi : lo + (hi - lo) * (i - 0.381966) / SCAN;
        wrapped(q, j, sa, t, uv);
        const double f = uv[c] - k;
        /* a sign change that is not a seam's jump (those move by ~ the period) */
        if (prev * f < 0 && fabs(f - prev) < 0.25) {
            double a = prev_t, b = t, fa = prev;
            for (int it = 0; it < 200 && b - a > 1e-15 * (hi - lo); ++it) {
                const double m = 0.5 * (a + b);
                wrapped(q, j, sa, m, uv);
                if ((uv[c] - k) * fa > 0) {
                    a = m;
                    fa = uv[c] - k;
                } else {
                    b = m;
                }
            }
            ++found;
            add_feature(feat, 0.5 * (a + b), cont);
        }
        prev = f;
        prev_t = t;
    }
    return found;
}

/* The multiplicity of the knot of e nearest t, within tol (0: none). */
static int multiplicity_at(const pc_shape_curve *e, double t, double tol)
{
    int m = 0;
    for (size_t i = 0; i < e->n_ctrl + (size_t)e->degree + 1; ++i)
        m += fabs(e->knots[i] - t) <= tol;
    return m;
}

/* The joins of e against the continuity theory of S o q: where S o q is
 * only C0 by construction (a seam or pole jump, a crease of q or of S) the
 * knot keeps its n copies; at C^k (k >= 1: a knot of q of multiplicity
 * 3 - k, a knot line of S of degree p and multiplicity p - k) the curve
 * is smoother than C0 and an isolated join keeps at most n - k copies
 * (the removal took those the theory allows); unless S is affine (then
 * S o q is as smooth as q across its knot lines and every copy may go),
 * it keeps at least n - k: a copy more would change the curve by the
 * jump of a derivative, far above rounding. Every knot of e is a
 * feature. */
static void check_joins(const char *name, const pc_shape_curve *e, const features *f, int affine,
                        double range)
{
    const int n = e->degree;
    const double tol = CROSS_TOL * range;
    for (size_t i = 0; i < f->n; ++i) {
        int k = f->k[i], isolated = 1;
        for (size_t j = 0; j < f->n; ++j)
            if (fabs(f->t[j] - f->t[i]) <= tol)
                k = f->k[j] < k ? f->k[j] : k;
        for (size_t j = 1; j < e->n_ctrl + (size_t)n + 1; ++j) /* another join near */
            if (e->knots[j] != e->knots[j - 1] && fabs(e->knots[j] - f->t[i]) <= ISOLATED * range &&
                fabs(e->knots[j - 1] - f->t[i]) <= ISOLATED * range)
                isolated = 0;
        const int m = multiplicity_at(e, f->t[i], tol);
        const int ok = k == 0 ? m == n
                              : (!isolated || m <= n - k) && (affine || (m >= n - k && m > 0));
        if (!ok)
            pc_test_fail_at(__FILE__, __LINE__,
                            "%s: the join at t = %.17g (C^%d%s) has multiplicity %d of degree %d",
                            name, f->t[i], k, isolated ? "" : ", not isolated", m, n);
    }
    for (size_t i = (size_t)n + 1; i < e->n_ctrl; ++i) {
        int known = 0;
        for (size_t j = 0; j < f->n; ++j)
            known |= fabs(f->t[j] - e->knots[i]) <= tol;
        if (!known)
            pc_test_fail_at(__FILE__, __LINE__, "%s: knot %.17g of the exact curve is no join",
                            name, e->knots[i]);
    }
}

/* The exact curve of branch b against S(q(t)); returns the number of
 * knot-line crossings of q. */
static size_t check_exact(const char *name, const pc_shape_surface *sa, const projcurve_surface *s,
                          const projcurve_result *r, size_t b, int want_degree, int affine)
{
    projcurve_curve *qc = NULL, *ec = NULL;
    CHECK_OK(projcurve_result_branch_compact_pcurve(NULL, r, b, &qc));
    CHECK_OK(projcurve_result_branch_compact_exact(NULL, r, s, b, &ec));
    if (qc == NULL || ec == NULL) {
        projcurve_curve_destroy(qc);
        projcurve_curve_destroy(ec);
        return 0;
    }
    pc_shape_curve q = arrays_of(qc), e = arrays_of(ec);
    seams j = {0, {0}, {0}, {0}};
    CHECK_OK(projcurve_result_branch_seam_count(NULL, r, b, &j.n));
    CHECK(j.n <= 8);
    for (size_t k = 0; k < j.n && k < 8; ++k)
        CHECK_OK(projcurve_result_branch_seam(NULL, r, b, k, &j.t[k], &j.du[k], &j.dv[k]));
    CHECK(e.degree == want_degree);
    CHECK((e.weights != NULL) == (sa->weights != NULL || q.weights != NULL));
    const double lo = q.knots[0], hi = q.knots[q.n_ctrl + (size_t)q.degree];
    CHECK_NEAR(e.knots[0], lo, 0.0);
    CHECK_NEAR(e.knots[e.n_ctrl + (size_t)e.degree], hi, 0.0);
    features f = {0, {0}, {0}};
    for (size_t k = 0; k < j.n && k < 8; ++k)
        add_feature(&f, j.t[k], 0);
    for (size_t i = (size_t)q.degree + 1; i < q.n_ctrl; ++i) {
        int m = 1;
        while (i + (size_t)m < q.n_ctrl && q.knots[i + (size_t)m] == q.knots[i])
            ++m;
        add_feature(&f, q.knots[i], q.degree - m > 0 ? q.degree - m : 0);
        i += (size_t)m - 1;
    }
    const double size = model_size(sa);
    double worst = 0.0;
    for (int i = 0; i <= SAMPLES; ++i) {
        /* irrational offsets keep the samples off the jumps' t */
        const double t = i == 0 ? lo : (i == SAMPLES ? hi : lo + (hi - lo) * (i - 0.381966) / (SAMPLES - 1));
        double uv[2], x[3], y[3];
        wrapped(&q, &j, sa, t, uv);
        pc_deboor_surface(sa, uv[0], uv[1], x);
        pc_deboor_curve(&e, t, y);
        const double d = sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                              (x[2] - y[2]) * (x[2] - y[2]));
        worst = fmax(worst, d);
    }
    if (!(worst <= EXACT_REL * size))
        pc_test_fail_at(__FILE__, __LINE__, "%s branch %zu: |C(t) - S(q(t))| = %.3g > %.3g", name,
                        b, worst, EXACT_REL * size);
    size_t crossings = 0;
    for (int c = 0; c < 2; ++c) {
        const double *kn = c == 0 ? sa->knots_u : sa->knots_v;
        const int deg = c == 0 ? sa->deg_u : sa->deg_v;
        const size_t n = c == 0 ? sa->n_u : sa->n_v;
        for (size_t i = (size_t)deg + 1; i < n; ++i)
            if (kn[i] > kn[i - 1]) {
                int m = 1;
                while (i + (size_t)m < n && kn[i + (size_t)m] == kn[i])
                    ++m;
                crossings += check_crossings(&q, &j, sa, c, kn[i], deg - m > 0 ? deg - m : 0, &f);
            }
    }
    check_joins(name, &e, &f, affine, hi - lo);
    printf("%s branch %zu: degree %d, %zu poles, %zu knot-line crossings, %zu jumps, "
           "max |C - S o q| %.2e (size %.3g)\n",
           name, b, e.degree, e.n_ctrl, crossings, j.n, worst, size);
    pc_shape_curve_free(&q);
    pc_shape_curve_free(&e);
    projcurve_curve_destroy(qc);
    projcurve_curve_destroy(ec);
    return crossings;
}

static projcurve_curve *nurbs_curve(int degree, size_t n, const double *ctrl)
{
    double knots[32];
    pc_shape_uniform_knots(degree, n, knots);
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, degree, n, ctrl, NULL, knots, &c));
    return c;
}

static projcurve_result *project(const projcurve_surface *s, const projcurve_curve *c,
                                 const double dir[3], int compose)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, compose));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, dir, o, &r));
    projcurve_options_destroy(o);
    return r;
}

/* A line over the bicubic plane S(u, v) = (2u - 1, 3v - 1, 0) with 4 x 4
 * spans, from (u, v) = (0.05, 0.1) to (0.95, 0.85): q is the line itself
 * (the curve's own space, degree 1), S o q has degree 1 (3 + 3) = 6 and
 * the line crosses u = 1/4, 1/2, 3/4 at t = 2/9, 1/2, 7/9 and v = 1/4,
 * 1/2, 3/4 at t = 1/5, 8/15, 13/15: seven parts, 43 poles. */
static void test_plane_line(void)
{
    pc_shape_surface sa = pc_shape_plane(3, 3, 4, 4);
    projcurve_surface *s = pc_shape_surface_create(&sa);
    const double ctrl[6] = {-0.9, -0.7, 1.0, 0.9, 1.55, 1.0};
    projcurve_curve *c = nurbs_curve(1, 2, ctrl);
    const double dir[3] = {0, 0, -1};
    projcurve_result *r = project(s, c, dir, 1);
    CHECK(projcurve_result_branch_count(r) == 1);
    CHECK(check_exact("plane, line", &sa, s, r, 0, 6, 1) == 6);
    projcurve_curve *e = NULL;
    CHECK_OK(projcurve_result_branch_compact_exact(NULL, r, s, 0, &e));
    size_t n_ctrl = 0, n_knots = 0;
    CHECK_OK(projcurve_curve_nurbs_info(NULL, e, NULL, &n_ctrl, &n_knots, NULL));
    /* S o q is one polynomial of degree 6: every copy of the 6 joins' 36
     * could go, each further one a higher difference of rounded poles;
     * measured 30 within the bound, 13 poles. The generic C2 theory
     * (check_joins) guarantees 12 (at most 31 poles). */
    CHECK(n_ctrl <= 19);
    /* what is left of the joins are the analytic t */
    const double want[6] = {0.2, 2.0 / 9, 0.5, 8.0 / 15, 7.0 / 9, 13.0 / 15};
    double knots[50];
    CHECK(n_knots <= 50);
    CHECK_OK(projcurve_curve_nurbs_data(NULL, e, NULL, NULL, knots));
    for (size_t i = 7; i + 7 < n_knots && i < 50; ++i) {
        double gap = 1.0;
        for (int k = 0; k < 6; ++k)
            gap = fmin(gap, fabs(knots[i] - want[k]));
        CHECK_NEAR(gap, 0.0, 1e-14);
    }
    projcurve_curve_destroy(e);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&sa);
}

/* A wavy cubic over a bumpy bicubic graph (4 x 4 spans), polynomial and
 * rational: q crosses several knot lines; degree 3 (3 + 3) = 18. */
static void test_bumpy(int rational)
{
    pc_shape_surface sa = pc_shape_bumpy(11, 4, 4, 0.15, rational);
    projcurve_surface *s = pc_shape_surface_create(&sa);
    const double ctrl[15] = {0.08, 0.1, 2, 0.3, 0.95, 2, 0.55, -0.2, 2, 0.75, 1.0, 2, 0.93, 0.6, 2};
    projcurve_curve *c = nurbs_curve(3, 5, ctrl);
    const double dir[3] = {0, 0, -1};
    projcurve_result *r = project(s, c, dir, 1);
    CHECK(projcurve_result_branch_count(r) == 1);
    const char *name = rational ? "rational bicubic graph" : "bicubic graph";
    CHECK(check_exact(name, &sa, s, r, 0, 18, 0) >= 6);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&sa);
}

/* The full cylinder (rational, degrees (2, 1)) along -x: the front branch
 * crosses the seam at t = 1/2 (one jump), the back one the knot line
 * u = 1/2 (y = 0, x < 0); degree 3 (2 + 1) = 9. */
static void test_cylinder(void)
{
    pc_shape_surface sa = pc_shape_cylinder(1.0, 2.0);
    projcurve_surface *s = pc_shape_surface_create(&sa);
    const double ctrl[6] = {3, -0.8, 0.5, 3, 0.8, 1.5};
    projcurve_curve *c = nurbs_curve(1, 2, ctrl);
    const double dir[3] = {-1, 0, 0};
    projcurve_result *r = project(s, c, dir, 1);
    CHECK(projcurve_result_branch_count(r) == 2);
    size_t jumps = 0, crossings = 0;
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        size_t n = 0;
        CHECK_OK(projcurve_result_branch_seam_count(NULL, r, b, &n));
        jumps += n;
        crossings += check_exact("cylinder", &sa, s, r, b, 9, 0);
    }
    CHECK(jumps == 1);
    CHECK(crossings >= 1);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&sa);
}

/* The sphere (rational, degrees (2, 2)) along -z over both poles: one
 * pole jump on each branch; degree 3 (2 + 2) = 12. */
static void test_sphere(void)
{
    const double o[3] = {0, 0, 0}, ca = cos(1.0), sa_ = sin(1.0);
    pc_shape_surface sa = pc_shape_sphere(o, 1.0);
    projcurve_surface *s = pc_shape_surface_create(&sa);
    const double ctrl[6] = {-0.6 * ca, -0.6 * sa_, 3, 0.6 * ca, 0.6 * sa_, 3};
    projcurve_curve *c = nurbs_curve(1, 2, ctrl);
    const double dir[3] = {0, 0, -1};
    projcurve_result *r = project(s, c, dir, 1);
    CHECK(projcurve_result_branch_count(r) == 2);
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b)
        check_exact("sphere", &sa, s, r, b, 12, 0);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&sa);
}

/* A circle of radius 0.4 about (0, 0, 1) onto the bicubic plane (2 x 2
 * spans) along -z: q is in the circle's rational space (degree 2, double
 * knots: C0 in form at the quarters), S o q is rational of degree
 * 2 (3 + 3) = 12 and is the circle about the origin in z = 0: every one of
 * SAMPLES points at distance 0.4 from it to EXACT_REL of the size (the
 * composition is convex combinations of the plane's poles and the
 * circle's homogeneous points; q itself is the circle's image to the
 * fit's 1e-12: measured 2e-12), besides the check against S(q(t)). The
 * circle crosses the knot line u = 1/2 twice: six parts, 73 poles as
 * composed, 49 once the crossings' knots are removed. */
static void test_circle(void)
{
    pc_shape_surface sa = pc_shape_plane(3, 3, 2, 2);
    projcurve_surface *s = pc_shape_surface_create(&sa);
    const double centre[3] = {0, 0, 1}, dir[3] = {0, 0, -1};
    pc_shape_curve ca = pc_shape_circle(centre, 0.4);
    projcurve_curve *circle = pc_shape_curve_create(&ca);
    projcurve_result *r = project(s, circle, dir, 1);
    CHECK(projcurve_result_branch_count(r) == 1);
    CHECK(check_exact("plane, circle", &sa, s, r, 0, 12, 1) == 2); /* u = 1/2 */
    projcurve_curve *ec = NULL;
    CHECK_OK(projcurve_result_branch_compact_exact(NULL, r, s, 0, &ec));
    if (ec != NULL) {
        pc_shape_curve e = arrays_of(ec);
        CHECK(e.weights != NULL);
        const double lo = e.knots[0], hi = e.knots[e.n_ctrl + (size_t)e.degree];
        double worst = 0.0;
        for (int i = 0; i <= SAMPLES; ++i) {
            double x[3];
            pc_deboor_curve(&e, lo + (hi - lo) * i / SAMPLES, x);
            worst = fmax(worst, fmax(fabs(hypot(x[0], x[1]) - 0.4), fabs(x[2])));
        }
        const double size = model_size(&sa);
        if (!(worst <= EXACT_REL * size))
            pc_test_fail_at(__FILE__, __LINE__, "circle: off the circle by %.3g > %.3g", worst,
                            EXACT_REL * size);
        printf("plane, circle: %zu poles of degree %d, off the circle by %.2e\n", e.n_ctrl,
               e.degree, worst);
        pc_shape_curve_free(&e);
    }
    projcurve_curve_destroy(ec);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(circle);
    pc_shape_curve_free(&ca);
    projcurve_surface_destroy(s);
    pc_shape_surface_free(&sa);
}

/* Bad input and what is not offered. */
static void test_statuses(void)
{
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    pc_shape_surface pa = pc_shape_plane(3, 3, 2, 2), ba = pc_shape_bumpy(3, 2, 2, 0.2, 0);
    projcurve_surface *plane = pc_shape_surface_create(&pa), *bumpy = pc_shape_surface_create(&ba);
    const double ctrl[6] = {-0.5, -0.5, 1.0, 0.5, 1.0, 1.0};
    projcurve_curve *line = nurbs_curve(1, 2, ctrl), *e = NULL;
    const double dir[3] = {0, 0, -1};
    projcurve_result *r = project(plane, line, dir, 1);
    CHECK_STATUS(projcurve_result_branch_compact_exact(ctx, NULL, plane, 0, &e),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_result_branch_compact_exact(ctx, r, NULL, 0, &e),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_result_branch_compact_exact(ctx, r, plane, 0, NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_result_branch_compact_exact(ctx, r, plane, 1, &e), PROJCURVE_ERR_INDEX);
    /* another surface: its S(q(t0)) is the bump's height away */
    CHECK_STATUS(projcurve_result_branch_compact_exact(ctx, r, bumpy, 0, &e),
                 PROJCURVE_ERR_INVALID_ARGUMENT);
    CHECK(e == NULL);
    projcurve_result_destroy(r);
    /* not composed: no compact forms */
    r = project(plane, line, dir, 0);
    CHECK_STATUS(projcurve_result_branch_compact_exact(ctx, r, plane, 0, &e),
                 PROJCURVE_ERR_INVALID_ARGUMENT);
    projcurve_result_destroy(r);
    /* degrees (5, 6) with a cubic pcurve: 33, above PROJCURVE_MAX_DEGREE */
    pc_shape_surface ha = pc_shape_plane(5, 6, 1, 1);
    projcurve_surface *high = pc_shape_surface_create(&ha);
    pc_shape_line ln = {{-0.5, -0.5, 1.0}, {1.0, 1.5, 0.0}};
    projcurve_curve *cb = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, pc_shape_line_fn, &ln, 0.0, 1.0, &cb));
    r = project(high, cb, dir, 1);
    CHECK_STATUS(projcurve_result_branch_compact_exact(ctx, r, high, 0, &e),
                 PROJCURVE_ERR_UNSUPPORTED);
    printf("degrees (5, 6): %s\n", projcurve_context_message(ctx));
    CHECK(e == NULL);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(cb);
    projcurve_surface_destroy(high);
    pc_shape_surface_free(&ha);
    projcurve_curve_destroy(line);
    projcurve_surface_destroy(plane);
    projcurve_surface_destroy(bumpy);
    pc_shape_surface_free(&pa);
    pc_shape_surface_free(&ba);
    projcurve_context_destroy(ctx);
}

int main(void)
{
    test_plane_line();
    test_bumpy(0);
    test_bumpy(1);
    test_cylinder();
    test_sphere();
    test_circle();
    test_statuses();
    return pc_test_finish("test_api_compact_exact");
}
