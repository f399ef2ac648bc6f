/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve_project_orthogonal on exact NURBS spheres, cylinders, tori and
 * planes: branch counts from the analytic foot points, every vertex an
 * exact foot point, Hausdorff distance between the composed pieces and the
 * densely sampled analytic foot-point curves within eps_D (both ways),
 * boundary exits, centres of curvature, agreement with the implicit route,
 * bad input.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "on_surface.h"
#include "shapes.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* P(t) = c + (a cos t, a sin t, h sin 2t) + t * lin. */
typedef struct wave {
    double c[3], a, h, lin[3];
    int nan_after;   /* 1: P is NaN for t > 1 */
} wave;

static int wave_fn(void *user, double t, double out[9])
{
    const wave *w = user;
    if (w->nan_after && t > 1.0) {
        for (int i = 0; i < 9; ++i)
            out[i] = NAN;
        return 0;
    }
    const double v[9] = {w->c[0] + w->a * cos(t) + t * w->lin[0],
                         w->c[1] + w->a * sin(t) + t * w->lin[1],
                         w->c[2] + w->h * sin(2 * t) + t * w->lin[2],
                         -w->a * sin(t) + w->lin[0], w->a * cos(t) + w->lin[1],
                         2 * w->h * cos(2 * t) + w->lin[2], -w->a * cos(t), -w->a * sin(t),
                         -4 * w->h * sin(2 * t)};
    memcpy(out, v, sizeof v);
    return 0;
}

/* Analytic foot points: up to 4 families, chosen by `which`; returns 0
 * when the family does not exist for this shape. */
typedef enum kind { SPHERE, CYLINDER, TORUS, PLANE } kind;
typedef struct shape {
    kind k;
    double a, b;
} shape;

static int foot(const shape *s, int which, const double p[3], double q[3])
{
    switch (s->k) {
    case SPHERE: {
        if (which > 1)
            return 0;
        const double n = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        const double sg = which ? -1.0 : 1.0;
        for (int i = 0; i < 3; ++i)
            q[i] = sg * s->a * p[i] / n;
        return 1;
    }
    case CYLINDER: {
        if (which > 1)
            return 0;
        const double n = hypot(p[0], p[1]), sg = which ? -1.0 : 1.0;
        q[0] = sg * s->a * p[0] / n;
        q[1] = sg * s->a * p[1] / n;
        q[2] = p[2];
        return 1;
    }
    case TORUS: {
        if (which > 3)
            return 0;
        const double n = hypot(p[0], p[1]), side = (which & 1) ? -1.0 : 1.0;
        const double c[3] = {side * s->a * p[0] / n, side * s->a * p[1] / n, 0.0};
        const double d[3] = {p[0] - c[0], p[1] - c[1], p[2]};
        const double dn = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        const double tube = (which & 2) ? -1.0 : 1.0;
        for (int i = 0; i < 3; ++i)
            q[i] = c[i] + tube * s->b * d[i] / dn;
        return 1;
    }
    case PLANE:
        if (which > 0)
            return 0;
        q[0] = p[0];
        q[1] = p[1];
        q[2] = 0.0;
        return 1;
    }
    return 0;
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Distance from x to the polyline pts[0..n) (3 doubles per point). */
static double to_polyline(const double *x, const double *pts, size_t n)
{
    double best = INFINITY;
    for (size_t i = 0; i + 1 < n; ++i) {
        const double *a = pts + 3 * i, *b = pts + 3 * i + 3;
        double ab[3], ax[3], l2 = 0.0, s = 0.0;
        for (int k = 0; k < 3; ++k) {
            ab[k] = b[k] - a[k];
            ax[k] = x[k] - a[k];
            l2 += ab[k] * ab[k];
            s += ab[k] * ax[k];
        }
        s = l2 > 0.0 ? fmin(1.0, fmax(0.0, s / l2)) : 0.0;
        const double c[3] = {a[0] + s * ab[0], a[1] + s * ab[1], a[2] + s * ab[2]};
        best = fmin(best, dist3(x, c));
    }
    if (n == 1)
        best = dist3(x, pts);
    return best;
}

/* The pieces' samples are joined by chords: 256 of them keep the chords'
 * sagitta (L^2 / (8 * 256^2 * radius)) far below eps_D on the long cubic
 * pieces here; 48 gave 1.5 eps_D from the exact curve to the chords of
 * pieces 8.2e-5 from it. */
#define PIECE_SAMPLES 257

/* Samples of a branch's composed pieces (rational Bezier, de Casteljau in
 * homogeneous coordinates): PIECE_SAMPLES per piece into out (3 doubles
 * each) and each piece's curve-parameter range into ranges (2 each).
 * Returns the number of pieces sampled. */
static size_t sample_pieces(const projcurve_result *r, size_t branch, double *out,
                            double *ranges, size_t cap_pieces)
{
    size_t n_pieces = 0;
    projcurve_result_branch_info(NULL, r, branch, NULL, NULL, NULL, NULL, &n_pieces);
    if (n_pieces > cap_pieces)
        n_pieces = cap_pieces;
    for (size_t k = 0; k < n_pieces; ++k) {
        int deg = 0;
        double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS];
        CHECK_OK(projcurve_result_piece(NULL, r, branch, k, &deg, ctrl, w, ranges + 2 * k,
                                        NULL));
        for (int j = 0; j < PIECE_SAMPLES; ++j)
            pc_test_piece_point(deg, ctrl, w, j / (double)(PIECE_SAMPLES - 1),
                                out + 3 * (k * PIECE_SAMPLES + (size_t)j));
    }
    return n_pieces;
}

#define DENSE 2000
#define PIECE_CAP 2000 /* pieces sampled per branch (at most 16 here) */

/* Hausdorff distance between the pieces and the exact polyline exact[0..DENSE]
 * sampled uniformly over [t0, t1], both ways. Both are parametrised by the
 * curve parameter, so each piece is compared only with the exact samples
 * over its own t-range (plus a few samples), and each exact sample with the
 * pieces whose range is near its t. */
static void hausdorff(const double *exact, double t0, double t1, const double *piece_pts,
                      const double *ranges, size_t n_pieces, double *one, double *other)
{
    const double dt = (t1 - t0) / DENSE, margin = 3.0 * dt;
    *one = *other = 0.0;
    for (size_t k = 0; k < n_pieces; ++k) {
        long lo = (long)floor((ranges[2 * k] - margin - t0) / dt);
        long hi = (long)ceil((ranges[2 * k + 1] + margin - t0) / dt);
        lo = lo < 0 ? 0 : lo;
        hi = hi > DENSE ? DENSE : hi;
        for (size_t j = 0; j < PIECE_SAMPLES; ++j)
            *one = fmax(*one, to_polyline(piece_pts + 3 * (k * PIECE_SAMPLES + j),
                                          exact + 3 * lo, (size_t)(hi - lo + 1)));
    }
    for (size_t i = 0; i <= DENSE; ++i) {
        const double t = t0 + dt * (double)i;
        double best = INFINITY;
        for (size_t k = 0; k < n_pieces; ++k)
            if (ranges[2 * k] - margin <= t && t <= ranges[2 * k + 1] + margin)
                best = fmin(best, to_polyline(exact + 3 * i, piece_pts + 3 * k * PIECE_SAMPLES,
                                              PIECE_SAMPLES));
        *other = fmax(*other, best);
    }
}

/* Every branch: vertices are exact foot points of one family, pieces are
 * within eps_D of that family's curve, and that family's curve over the
 * branch's t-range is within eps_D of the pieces (Hausdorff both ways).
 * families[b] receives the family of branch b (up to 8 branches). */
static void check_branches(const char *name, const projcurve_result *r,
                           const projcurve_surface *surf, const shape *s, const wave *w,
                           double eps_d, int families[8])
{
    static double exact[3 * (DENSE + 1)], piece_pts[3 * PIECE_CAP * PIECE_SAMPLES],
        ranges[2 * PIECE_CAP];
    const size_t nb = projcurve_result_branch_count(r);
    for (size_t b = 0; b < nb; ++b) {
        double range[2];
        size_t n_points = 0;
        CHECK_OK(projcurve_result_branch_info(NULL, r, b, range, NULL, NULL, &n_points, NULL));
        double *pts = malloc(3 * n_points * sizeof *pts);
        size_t got = 0;
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, n_points, pts, &got));
        int fam = -1, mixed = 0;
        double worst_vertex = 0.0;
        for (size_t i = 0; i < got; ++i) {
            double x[3], pv[9], q[3];
            CHECK_OK(projcurve_surface_eval(NULL, surf, pts[3 * i + 1], pts[3 * i + 2], 0, x));
            wave_fn((void *)w, pts[3 * i], pv);
            int best = -1;
            double best_d = INFINITY;
            for (int f = 0; foot(s, f, pv, q); ++f)
                if (dist3(x, q) < best_d) {
                    best_d = dist3(x, q);
                    best = f;
                }
            worst_vertex = fmax(worst_vertex, best_d);
            if (fam < 0)
                fam = best;
            else if (best != fam)
                mixed = 1;
        }
        free(pts);
        if (b < 8)
            families[b] = fam;
        for (size_t i = 0; i <= DENSE; ++i) {
            double pv[9];
            wave_fn((void *)w, range[0] + (range[1] - range[0]) * (double)i / DENSE, pv);
            foot(s, fam, pv, exact + 3 * i);
        }
        const size_t np = sample_pieces(r, b, piece_pts, ranges, PIECE_CAP);
        double one = 0.0, other = 0.0;
        hausdorff(exact, range[0], range[1], piece_pts, ranges, np, &one, &other);
        printf("%-22s branch %zu family %d t [%.6f, %.6f] vertices %zu err %.1e, "
               "Hausdorff %.1e / %.1e (eps_D %.0e)\n",
               name, b, fam, range[0], range[1], got, worst_vertex, one, other, eps_d);
        CHECK(!mixed);
        CHECK(worst_vertex <= 1e-8);
        CHECK(np > 0);
        CHECK(one <= eps_d);
        CHECK(other <= eps_d);
    }
}

static projcurve_options *options(double eps_d)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    /* far-side feet (saddles, maxima) are part of the expected answer */
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_FOOT_POINTS,
                                       PROJCURVE_FOOT_POINTS_ALL));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, eps_d));
    return o;
}

/* Projects w onto the shape and checks branch count, ends and Hausdorff. */
static projcurve_result *run(const char *name, pc_shape_surface shape_data, const shape *s,
                             const wave *w, double t0, double t1, size_t expected_branches,
                             long long method, int families[8], projcurve_surface **surf_out)
{
    const double eps_d = 1e-4;
    projcurve_surface *surf = pc_shape_surface_create(&shape_data);
    pc_shape_surface_free(&shape_data);
    projcurve_curve *curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, (void *)w, t0, t1, &curve));
    projcurve_options *o = options(eps_d);
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_METHOD, method));
    projcurve_result *r = NULL;
    projcurve_context *ctx = NULL;
    projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx);
    const projcurve_status st = projcurve_project_orthogonal(ctx, surf, curve, o, &r);
    if (st != PROJCURVE_OK)
        printf("%s: %s (%s)\n", name, projcurve_status_string(st), projcurve_context_message(ctx));
    CHECK_OK(st);
    if (r) {
        printf("%s: %zu branches (expected %zu)\n", name, projcurve_result_branch_count(r),
               expected_branches);
        CHECK(projcurve_result_branch_count(r) == expected_branches);
        check_branches(name, r, surf, s, w, eps_d, families);
    }
    projcurve_context_destroy(ctx);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(curve);
    *surf_out = surf;
    return r;
}

static void expect_whole(const projcurve_result *r, size_t b, double t0, double t1)
{
    double range[2] = {0, 0};
    projcurve_branch_start start = PROJCURVE_START_JUMP;
    projcurve_branch_end end = PROJCURVE_END_FAILED;
    CHECK_OK(projcurve_result_branch_info(NULL, r, b, range, &start, &end, NULL, NULL));
    CHECK(start == PROJCURVE_START_CURVE_START);
    CHECK(end == PROJCURVE_END_CURVE_END);
    CHECK_NEAR(range[0], t0, 1e-12);
    CHECK_NEAR(range[1], t1, 1e-12);
}

/* The same shapes as implicit functions f(x) = 0, for the implicit route:
 * sphere |x|^2 - a^2, cylinder x^2 + y^2 - a^2, torus (|x|^2 + a^2 - b^2)^2
 * - 4 a^2 (x^2 + y^2), plane z. */
static int shape_fn(void *user, const double x[3], double *value, double grad[3],
                    double hess[9])
{
    const shape *s = user;
    memset(hess, 0, 9 * sizeof *hess);
    switch (s->k) {
    case SPHERE:
    case CYLINDER: {
        const int n = s->k == SPHERE ? 3 : 2;
        *value = -s->a * s->a;
        for (int i = 0; i < 3; ++i) {
            const int on = i < n;
            *value += on ? x[i] * x[i] : 0.0;
            grad[i] = on ? 2 * x[i] : 0.0;
            hess[4 * i] = on ? 2 : 0;
        }
        return 0;
    }
    case TORUS: {
        const double q = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] + s->a * s->a - s->b * s->b;
        const double a2 = s->a * s->a;
        *value = q * q - 4 * a2 * (x[0] * x[0] + x[1] * x[1]);
        for (int i = 0; i < 3; ++i) {
            grad[i] = 4 * q * x[i] - (i < 2 ? 8 * a2 * x[i] : 0.0);
            for (int j = 0; j < 3; ++j)
                hess[3 * i + j] = 8 * x[i] * x[j] + (i == j ? 4 * q - (i < 2 ? 8 * a2 : 0.0) : 0.0);
        }
        return 0;
    }
    case PLANE:
        *value = x[2];
        grad[0] = grad[1] = 0;
        grad[2] = 1;
        return 0;
    }
    return 1;
}

/* One-sided Hausdorff distance from the pieces of branch ba of ra to those
 * of the branches of rb listed in bb[0..nbb): every sample of a piece of ba
 * against the sampled pieces of bb whose t-range comes within `window` of
 * the piece's. Both are parametrised by the curve's t, so a point is
 * compared with the other route's curve near the same t only. */
static double pieces_distance(const projcurve_result *ra, size_t ba, const projcurve_result *rb,
                              const size_t *bb, size_t nbb, double window)
{
    static double a_pts[3 * PIECE_CAP * PIECE_SAMPLES], a_rng[2 * PIECE_CAP],
        b_pts[3 * PIECE_CAP * PIECE_SAMPLES], b_rng[2 * PIECE_CAP];
    const size_t na = sample_pieces(ra, ba, a_pts, a_rng, PIECE_CAP);
    double worst = na > 0 ? 0.0 : INFINITY;
    double *best = malloc((na * PIECE_SAMPLES + 1) * sizeof *best);
    for (size_t i = 0; i < na * PIECE_SAMPLES; ++i)
        best[i] = INFINITY;
    for (size_t j = 0; j < nbb; ++j) {
        const size_t nb = sample_pieces(rb, bb[j], b_pts, b_rng, PIECE_CAP);
        for (size_t ka = 0; ka < na; ++ka)
            for (size_t kb = 0; kb < nb; ++kb) {
                if (b_rng[2 * kb + 1] < a_rng[2 * ka] - window ||
                    b_rng[2 * kb] > a_rng[2 * ka + 1] + window)
                    continue;
                for (size_t i = 0; i < PIECE_SAMPLES; ++i) {
                    double *d = best + ka * PIECE_SAMPLES + i;
                    *d = fmin(*d, to_polyline(a_pts + 3 * (ka * PIECE_SAMPLES + i),
                                              b_pts + 3 * kb * PIECE_SAMPLES, PIECE_SAMPLES));
                }
            }
    }
    for (size_t i = 0; i < na * PIECE_SAMPLES; ++i)
        worst = fmax(worst, best[i]);
    free(best);
    return worst;
}

/* The implicit route on the same shape and curve traces the foot point
 * nearest P(t0) (family 0 of foot()); its pieces and those of the
 * parametric branches of family 0 must be within 2 eps_D of each other
 * both ways (Hausdorff): each is within eps_D of the exact curve (checked
 * above for the parametric route, in test_ortho_implicit for the other),
 * so 2 eps_D is what the triangle inequality allows; the polylines through
 * PIECE_SAMPLES samples per piece add a chord error below 1e-3 eps_D on
 * these pieces. The implicit branch must cover the same range as the
 * parametric family. */
static void check_agreement(const char *name, const projcurve_result *r, const int families[8],
                            const shape *s, const wave *w, double t0, double t1,
                            double model_size)
{
    const double eps_d = 1e-4;
    projcurve_curve *curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, (void *)w, t0, t1, &curve));
    projcurve_options *o = options(eps_d);
    projcurve_result *ri = NULL;
    CHECK_OK(projcurve_project_orthogonal_implicit(NULL, shape_fn, (void *)s, model_size, curve,
                                                   o, &ri));
    size_t near[8], n_near = 0;
    for (size_t b = 0; b < projcurve_result_branch_count(r) && b < 8; ++b)
        if (families[b] == 0)
            near[n_near++] = b;
    CHECK(n_near > 0);
    if (ri && projcurve_result_branch_count(ri) == 1) {
        double range[2] = {0, 0};
        projcurve_result_branch_info(NULL, ri, 0, range, NULL, NULL, NULL, NULL);
        CHECK_NEAR(range[0], t0, 1e-12);
        CHECK_NEAR(range[1], t1, 1e-12);
        const double window = 1e-9 * (t1 - t0);
        const size_t implicit_branch = 0;
        const double to_param = pieces_distance(ri, 0, r, near, n_near, window);
        double to_implicit = 0.0;
        for (size_t j = 0; j < n_near; ++j)
            to_implicit = fmax(to_implicit,
                               pieces_distance(r, near[j], ri, &implicit_branch, 1, window));
        printf("%s: implicit vs parametric pieces %.1e, parametric vs implicit %.1e "
               "(bound 2 eps_D = %.0e)\n",
               name, to_param, to_implicit, 2 * eps_d);
        CHECK(to_param <= 2 * eps_d);
        CHECK(to_implicit <= 2 * eps_d);
    } else {
        CHECK(ri != NULL && projcurve_result_branch_count(ri) == 1);
    }
    projcurve_result_destroy(ri);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(curve);
}

static void test_sphere(void)
{
    const double centre[3] = {0, 0, 0};
    const double R = 10.0;
    const shape s = {SPHERE, R, 0};
    const wave w = {{0, 0, 0}, 13.0, 3.0, {0, 0, 0}, 0};
    int fam[8] = {-1, -1, -1, -1, -1, -1, -1, -1};
    projcurve_surface *surf = NULL;
    projcurve_result *r = run("sphere", pc_shape_sphere(centre, R), &s, &w, 0.5, 2.5, 2,
                              PROJCURVE_METHOD_SECOND_ORDER, fam, &surf);
    if (r && projcurve_result_branch_count(r) == 2) {
        expect_whole(r, 0, 0.5, 2.5);
        expect_whole(r, 1, 0.5, 2.5);
        CHECK(fam[0] + fam[1] == 1);   /* one near, one far */
        check_agreement("sphere", r, fam, &s, &w, 0.5, 2.5, 20.0);
    }
    projcurve_result_destroy(r);
    projcurve_surface_destroy(surf);
}

static void test_cylinder_torus_plane(void)
{
    int fam[8];
    projcurve_surface *surf = NULL;
    /* Cylinder R = 5, z in [0, 10]; the curve at radius 7 over angles
     * 0.3..1.3: near and far foot points; traced with the RK4 baseline. */
    const shape cyl = {CYLINDER, 5.0, 0};
    const wave wc = {{0, 0, 5}, 7.0, 3.0, {0, 0, 0}, 0};
    projcurve_result *r = run("cylinder", pc_shape_cylinder(5.0, 10.0), &cyl, &wc, 0.3, 1.3, 2,
                              PROJCURVE_METHOD_RK4, fam, &surf);
    if (r && projcurve_result_branch_count(r) == 2)
        check_agreement("cylinder", r, fam, &cyl, &wc, 0.3, 1.3, 15.0);
    projcurve_result_destroy(r);
    projcurve_surface_destroy(surf);

    /* Torus (10, 3): four foot points (tube near/far x axis side near/far). */
    const shape tor = {TORUS, 10.0, 3.0};
    const wave wt = {{0, 0, 1}, 11.0, 0.5, {0, 0, 0}, 0};
    r = run("torus", pc_shape_torus(10.0, 3.0), &tor, &wt, 0.3, 2.8, 4,
            PROJCURVE_METHOD_SECOND_ORDER, fam, &surf);
    if (r && projcurve_result_branch_count(r) == 4)
        check_agreement("torus", r, fam, &tor, &wt, 0.3, 2.8, 30.0);
    projcurve_result_destroy(r);
    projcurve_surface_destroy(surf);

    /* Plane S(u, v) = (2u - 1, 3v - 1, 0): a circle inside, one branch. */
    const shape pl = {PLANE, 0, 0};
    const wave wp = {{0, 0.5, 0.3}, 0.8, 0.2, {0, 0, 0}, 0};
    r = run("plane", pc_shape_plane(3, 3, 2, 2), &pl, &wp, 0.0, 6.0, 1,
            PROJCURVE_METHOD_SECOND_ORDER, fam, &surf);
    if (r && projcurve_result_branch_count(r) == 1) {
        expect_whole(r, 0, 0.0, 6.0);
        check_agreement("plane", r, fam, &pl, &wp, 0.0, 6.0, 4.0);
    }
    projcurve_result_destroy(r);
    projcurve_surface_destroy(surf);

    /* Foot points leaving the plane through x = 1 at t = 1.5: the branch
     * ends on the boundary, exactly at u = 1. */
    const wave wl = {{-0.5, 0.5, 0.3}, 0.0, 0.0, {1, 0, 0}, 0};
    r = run("plane exit", pc_shape_plane(3, 3, 2, 2), &pl, &wl, 0.0, 2.0, 1,
            PROJCURVE_METHOD_RK4, fam, &surf);
    if (r && projcurve_result_branch_count(r) == 1) {
        double range[2] = {0, 0}, last[3] = {0, 0, 0};
        projcurve_branch_end end = PROJCURVE_END_FAILED;
        size_t n = 0;
        projcurve_result_branch_info(NULL, r, 0, range, NULL, &end, &n, NULL);
        CHECK(end == PROJCURVE_END_BOUNDARY);
        CHECK_NEAR(range[1], 1.5, 1e-9);
        double *pts = malloc(3 * n * sizeof *pts);
        size_t got = 0;
        projcurve_result_branch_points(NULL, r, 0, n, pts, &got);
        if (got == n && n > 0)
            memcpy(last, pts + 3 * (n - 1), sizeof last);
        CHECK_NEAR(last[1], 1.0, 1e-12);
        free(pts);
    }
    projcurve_result_destroy(r);
    projcurve_surface_destroy(surf);
}

/* Branches that reach a centre of curvature end there, reported as such:
 * a line through the axis of a cylinder (det K changes sign) and a circle
 * through the centre of a sphere (umbilic: det K touches zero). */
/* A branch stops where |det K| / (|Su||Sv|)^2 < 1e-6 (the engine's fold
 * threshold, also kept by the split of ortho_centres.c): P is then ~1e-6 R
 * from the centre where det K vanishes linearly (cylinder axis: ~2e-6 in t
 * here) and ~1e-3 R where it vanishes quadratically (sphere centre, an
 * umbilic: ~3e-3 in t here); t_tol allows for that. */
static void expect_centre_end(const char *name, const projcurve_result *r, double t_centre,
                              double t_tol)
{
    int found = 0;
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        double range[2];
        projcurve_branch_end end;
        projcurve_result_branch_info(NULL, r, b, range, NULL, &end, NULL, NULL);
        printf("%s: branch %zu t [%.9f, %.9f] end %d\n", name, b, range[0], range[1], (int)end);
        if (end == PROJCURVE_END_CURVATURE_CENTRE && fabs(range[1] - t_centre) <= t_tol)
            found = 1;
        /* No branch may run across the centre without being cut there. */
        CHECK(!(range[0] < t_centre - t_tol && range[1] > t_centre + t_tol));
    }
    CHECK(found);
}

static void test_centres(void)
{
    pc_shape_surface cyl_data = pc_shape_cylinder(5.0, 10.0);
    projcurve_surface *cyl = pc_shape_surface_create(&cyl_data);
    pc_shape_surface_free(&cyl_data);
    const wave line = {{-2, -1, 4}, 0.0, 0.0, {1, 0.5, 0.5}, 0};   /* axis at t = 2 */
    projcurve_curve *curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, (void *)&line, 0.0, 4.0, &curve));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, cyl, curve, NULL, &r));
    if (r)
        expect_centre_end("cylinder axis", r, 2.0, 1e-5);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(curve);
    projcurve_surface_destroy(cyl);

    const double centre[3] = {0, 0, 0};
    pc_shape_surface sph_data = pc_shape_sphere(centre, 10.0);
    projcurve_surface *sph = pc_shape_surface_create(&sph_data);
    pc_shape_surface_free(&sph_data);
    const wave circle = {{5, 0, 0.0}, 5.0, 0.0, {0, 0, 0}, 0};   /* centre at t = pi */
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, (void *)&circle, 0.5 * M_PI,
                                             1.4 * M_PI, &curve));
    r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, sph, curve, NULL, &r));
    if (r)
        expect_centre_end("sphere centre", r, M_PI, 5e-3);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(curve);
    projcurve_surface_destroy(sph);
}

static void test_bad_input(void)
{
    pc_shape_surface data = pc_shape_plane(3, 3, 2, 2);
    projcurve_surface *surf = pc_shape_surface_create(&data);
    pc_shape_surface_free(&data);
    const wave ok = {{0, 0.5, 0.3}, 0.8, 0.2, {0, 0, 0}, 0};
    const wave bad = {{0, 0.5, 0.3}, 0.8, 0.2, {0, 0, 0}, 1};
    projcurve_curve *curve = NULL, *bad_curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, (void *)&ok, 0.0, 2.0, &curve));
    CHECK_OK(projcurve_curve_create_callback(NULL, wave_fn, (void *)&bad, 0.0, 2.0, &bad_curve));
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_result *r = NULL;
    CHECK_STATUS(projcurve_project_orthogonal(ctx, NULL, curve, NULL, &r),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_project_orthogonal(ctx, surf, NULL, NULL, &r),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_project_orthogonal(ctx, surf, curve, NULL, NULL),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_project_orthogonal(ctx, surf, bad_curve, NULL, &r),
                 PROJCURVE_ERR_CALLBACK);
    CHECK(r == NULL);
    CHECK(strlen(projcurve_context_message(ctx)) > 0);
    projcurve_context_destroy(ctx);
    projcurve_curve_destroy(curve);
    projcurve_curve_destroy(bad_curve);
    projcurve_surface_destroy(surf);
}

int main(void)
{
    test_sphere();
    test_cylinder_torus_plane();
    test_centres();
    test_bad_input();
    return pc_test_finish("test_ortho_parametric");
}
