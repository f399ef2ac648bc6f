/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Seeds of the orthogonal projection on the rational, high-degree surfaces
 * of linkrods.step (issue 14, defects 6 and 11), against independent
 * oracles:
 *
 * - surface 11 (a tube of radius 0.125, degree 6 x 8, C0 knots in v),
 *   curves 39 and 40: every returned vertex is a foot point. Before, the
 *   finder answered checks without a search with the live branches' points
 *   interpolated on their polylines; one of them went unmatched and started
 *   a branch off the projection (residual 0.068, 900 x eps_D), and the
 *   sweep, restarting such branches at every check, did not end (> 5 min).
 * - surface 16 (degree 6 x 10, 30 spans in v refined geometrically down to
 *   1.8e-8 towards one point), curve 0: the foot point that a dense grid
 *   finds (a saddle of the distance) lies on a branch when every foot point
 *   is asked for. Before, every foot-point search ran
 *   into its cap of 4096 Newton starts in the thin spans without finding
 *   it: 0 branches, 3 s.
 * - surface 16, curve 16 at t = 0.1: the interior local minimum of the
 *   distance that a dense grid finds (polished by Newton, checked against
 *   a ring around it) lies on a branch of the default projection. Before,
 *   the foot-point search spent its 4096 Newton starts in the spans of
 *   width 1.8e-8 (their Bezier nets blown up to ~30 across by rounding)
 *   before it reached the last span, which held the minimum: the only
 *   branch started at t = 3.5.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "foot_step.h"

/* Vertices are foot points to this fraction of the model size: the
 * corrector's tolerance is 1e-12 of it, the rounding of the measure
 * ~1e-14 |S - P| / min(|Su|, |Sv|) (no collapsed edge here). */
#define FOOT_REL 1e-9
/* Brute-force grid per direction for the closest interior point. */
#define GRID 400
/* A brute-force foot point on a branch: within this fraction of the size
 * of the chord between the branch's vertices around t (the chords are
 * within eps_D = 1e-4 of the size of the branch). */
#define MATCH_REL 1e-3

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Distance from the domain's edges, as a fraction of its width, at which
 * tangential() evaluates: inside the first and last knot spans of real
 * extent, never in a span of rounding width at the edge (hammer.iges
 * surface 9 has [-1.5e-14, 0] in u), whose derivatives are not the
 * surface's. S moves by ~1e-12 of the size: within the tolerances here. */
#define EDGE_INSET 1e-12

/* The part of S(u, v) - p tangent to S: zero at a foot point. */
static double tangential(const projcurve_surface *s, const double p[3], double u, double v)
{
    double e[9], dom[4];
    projcurve_surface_domain(NULL, s, dom);
    const double iu = EDGE_INSET * (dom[1] - dom[0]), iv = EDGE_INSET * (dom[3] - dom[2]);
    u = fmin(dom[1] - iu, fmax(dom[0] + iu, u));
    v = fmin(dom[3] - iv, fmax(dom[2] + iv, v));
    projcurve_surface_eval(NULL, s, u, v, 1, e);
    const double d[3] = {e[0] - p[0], e[1] - p[1], e[2] - p[2]};
    const double n[3] = {e[4] * e[8] - e[5] * e[7], e[5] * e[6] - e[3] * e[8],
                         e[3] * e[7] - e[4] * e[6]};
    const double nn = n[0] * n[0] + n[1] * n[1] + n[2] * n[2];
    const double dn = (d[0] * n[0] + d[1] * n[1] + d[2] * n[2]) / nn;
    const double t[3] = {d[0] - dn * n[0], d[1] - dn * n[1], d[2] - dn * n[2]};
    return sqrt(t[0] * t[0] + t[1] * t[1] + t[2] * t[2]);
}

static projcurve_result *project(const projcurve_surface *s, const projcurve_curve *c)
{
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, NULL, &r));
    return r;
}

static double model_size(const projcurve_surface *s)
{
    double box[6];
    projcurve_surface_bounds(NULL, s, box);
    return dist3(box, box + 3);
}

/* Every vertex of every branch a foot point of P(t). */
static void check_vertices(const char *name, const projcurve_surface *s,
                           const projcurve_curve *c)
{
    projcurve_result *r = project(s, c);
    const double size = model_size(s);
    double worst = 0.0;
    size_t n_vertices = 0;
    for (size_t b = 0; r != NULL && b < projcurve_result_branch_count(r); ++b) {
        size_t n = 0;
        projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, &n, NULL);
        double *pts = malloc(3 * (n ? n : 1) * sizeof *pts);
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, n, pts, &n));
        for (size_t i = 0; i < n; ++i) {
            double p[3];
            projcurve_curve_eval(NULL, c, pts[3 * i], 0, p);
            worst = fmax(worst, tangential(s, p, pts[3 * i + 1], pts[3 * i + 2]));
        }
        n_vertices += n;
        free(pts);
    }
    printf("%s: %zu branch(es), %zu vertices, worst tangential residual %.3g (%.3g of the size)\n",
           name, projcurve_result_branch_count(r), n_vertices, worst, worst / size);
    CHECK(worst <= FOOT_REL * size);
    projcurve_result_destroy(r);
}

/* Newton on the foot-point equations from uv (the Hessian of the squared
 * distance, steps capped at 1/20 of the domain). Returns 0 where it is
 * singular. */
static int newton_foot(const projcurve_surface *s, const double p[3], double uv[2])
{
    double dom[4];
    projcurve_surface_domain(NULL, s, dom);
    for (int it = 0; it < 60; ++it) {
        double e[18], step[2];
        if (!pc_test_foot_step(s, p, uv, step, e))
            return 0;
        double du = step[0], dv = step[1];
        const double cap_u = 0.05 * (dom[1] - dom[0]), cap_v = 0.05 * (dom[3] - dom[2]);
        du = fmax(-cap_u, fmin(cap_u, du));
        dv = fmax(-cap_v, fmin(cap_v, dv));
        uv[0] = fmin(dom[1], fmax(dom[0], uv[0] + du));
        uv[1] = fmin(dom[3], fmax(dom[2], uv[1] + dv));
        if (fabs(du) <= 1e-15 * (dom[1] - dom[0]) && fabs(dv) <= 1e-15 * (dom[3] - dom[2]))
            return 1;
    }
    return 1;
}

/* Distance from q to the nearest point at t of r's branches (their
 * polylines interpolated in (u, v)); infinity when no branch spans t. */
static double nearest_branch_point(const projcurve_surface *s, const projcurve_result *r,
                                   double t, const double q[3])
{
    double nearest = INFINITY;
    for (size_t b = 0; r != NULL && b < projcurve_result_branch_count(r); ++b) {
        size_t n = 0;
        projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, &n, NULL);
        double *pts = malloc(3 * (n ? n : 1) * sizeof *pts);
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, n, pts, &n));
        for (size_t i = 0; i + 1 < n; ++i) {
            const double *a = pts + 3 * i, *e = a + 3;
            if ((a[0] - t) * (e[0] - t) > 0.0)
                continue;
            const double w = e[0] != a[0] ? (t - a[0]) / (e[0] - a[0]) : 0.0;
            double x[3];
            projcurve_surface_eval(NULL, s, a[1] + w * (e[1] - a[1]), a[2] + w * (e[2] - a[2]), 0,
                                   x);
            nearest = fmin(nearest, dist3(x, q));
        }
        free(pts);
    }
    return nearest;
}

/* The interior grid point of S where S - P(t) is closest to normal (the
 * smallest tangential part relative to |S - P|), polished by Newton: a
 * foot point, which must lie on a branch when every foot point is asked
 * for (it is a saddle of the distance here: the minima of P(t) lie on the
 * boundary). */
static void check_grid_foot(const char *name, const projcurve_surface *s,
                            const projcurve_curve *c, double t)
{
    double dom[4], p[3];
    projcurve_surface_domain(NULL, s, dom);
    projcurve_curve_eval(NULL, c, t, 0, p);
    double best = INFINITY, uv[2] = {0, 0};
    for (int i = 1; i < GRID; ++i)
        for (int j = 1; j < GRID; ++j) {
            const double u = dom[0] + (dom[1] - dom[0]) * i / GRID;
            const double v = dom[2] + (dom[3] - dom[2]) * j / GRID;
            double x[3];
            projcurve_surface_eval(NULL, s, u, v, 0, x);
            const double d = tangential(s, p, u, v) / dist3(x, p);
            if (d < best) {
                best = d;
                uv[0] = u;
                uv[1] = v;
            }
        }
    const double size = model_size(s);
    const int found = newton_foot(s, p, uv);
    const int interior = uv[0] > dom[0] && uv[0] < dom[1] && uv[1] > dom[2] && uv[1] < dom[3];
    CHECK(found && interior && tangential(s, p, uv[0], uv[1]) <= FOOT_REL * size);
    double q[3];
    projcurve_surface_eval(NULL, s, uv[0], uv[1], 0, q);

    projcurve_options *all = NULL;
    CHECK_OK(projcurve_options_create(NULL, &all));
    CHECK_OK(projcurve_options_set_int(NULL, all, PROJCURVE_OPT_FOOT_POINTS,
                                       PROJCURVE_FOOT_POINTS_ALL));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, all, &r));
    projcurve_options_destroy(all);
    const double nearest = nearest_branch_point(s, r, t, q);
    printf("%s: grid foot point at t = %g, (u, v) = (%.6f, %.6f), angle %.3g; "
           "nearest branch point %.3g (%zu branches)\n",
           name, t, uv[0], uv[1], best, nearest, projcurve_result_branch_count(r));
    CHECK(nearest <= MATCH_REL * size);
    projcurve_result_destroy(r);
}

/* 1 when S(uv) is closer to p than every point of a ring of 16 around it
 * at radius `ring` of the domain (brute force: no derivative). */
static int ring_minimum(const projcurve_surface *s, const double p[3], const double uv[2],
                        double ring)
{
    double dom[4], q[3];
    projcurve_surface_domain(NULL, s, dom);
    projcurve_surface_eval(NULL, s, uv[0], uv[1], 0, q);
    const double d = dist3(q, p);
    for (int k = 0; k < 16; ++k) {
        const double a = 2.0 * 3.14159265358979323846 * k / 16.0;
        const double u = uv[0] + ring * (dom[1] - dom[0]) * cos(a);
        const double v = uv[1] + ring * (dom[3] - dom[2]) * sin(a);
        if (u < dom[0] || u > dom[1] || v < dom[2] || v > dom[3])
            return 0;
        double x[3];
        projcurve_surface_eval(NULL, s, u, v, 0, x);
        if (!(dist3(x, p) > d))
            return 0;
    }
    return 1;
}

/* Every interior local minimum of |S - P(t)| that a GRID x GRID scan finds
 * (a grid point closer than its 8 neighbours, polished by newton_foot and
 * confirmed by ring_minimum) lies on a branch of the default projection
 * (local minima only). Returns the number of such minima. */
static int check_grid_minima(const char *name, const projcurve_surface *s,
                             const projcurve_curve *c, double t)
{
    double dom[4], p[3];
    projcurve_surface_domain(NULL, s, dom);
    projcurve_curve_eval(NULL, c, t, 0, p);
    double *d = malloc((size_t)(GRID + 1) * (GRID + 1) * sizeof *d);
    for (int j = 0; j <= GRID; ++j)
        for (int i = 0; i <= GRID; ++i) {
            double x[3];
            projcurve_surface_eval(NULL, s, dom[0] + (dom[1] - dom[0]) * i / GRID,
                                   dom[2] + (dom[3] - dom[2]) * j / GRID, 0, x);
            d[j * (GRID + 1) + i] = dist3(x, p);
        }
    projcurve_result *r = project(s, c);
    const double size = model_size(s);
    int minima = 0;
    for (int j = 1; j < GRID; ++j)
        for (int i = 1; i < GRID; ++i) {
            const double di = d[j * (GRID + 1) + i];
            int is_min = 1;
            for (int b = -1; b <= 1 && is_min; ++b)
                for (int a = -1; a <= 1 && is_min; ++a)
                    is_min = (a == 0 && b == 0) || d[(j + b) * (GRID + 1) + i + a] >= di;
            double uv[2] = {dom[0] + (dom[1] - dom[0]) * i / GRID,
                            dom[2] + (dom[3] - dom[2]) * j / GRID};
            if (!is_min || !newton_foot(s, p, uv) || !ring_minimum(s, p, uv, 1e-4) ||
                !(tangential(s, p, uv[0], uv[1]) <= FOOT_REL * size))
                continue;
            double q[3];
            projcurve_surface_eval(NULL, s, uv[0], uv[1], 0, q);
            const double nearest = nearest_branch_point(s, r, t, q);
            printf("%s: grid minimum at t = %g, (u, v) = (%.6f, %.6f), distance %.6g; "
                   "nearest branch point %.3g (%zu branches)\n",
                   name, t, uv[0], uv[1], dist3(q, p), nearest, projcurve_result_branch_count(r));
            CHECK(nearest <= MATCH_REL * size);
            ++minima;
        }
    projcurve_result_destroy(r);
    free(d);
    return minima;
}

/* A cubic through four points of the surface's diagonal (at 10 %, 37 %,
 * 63 %, 90 % of the domain), each lifted along the normal by `lift` of the
 * model size: a curve hovering over the surface (as issue 14's sweep). */
static projcurve_curve *lifted_diagonal(const projcurve_surface *s, double lift)
{
    double dom[4], ctrl[12];
    projcurve_surface_domain(NULL, s, dom);
    const double size = model_size(s);
    for (int i = 0; i < 4; ++i) {
        const double f = 0.1 + 0.8 * i / 3.0;
        double e[9];
        projcurve_surface_eval(NULL, s, dom[0] + f * (dom[1] - dom[0]), dom[2] + f * (dom[3] - dom[2]),
                               1, e);
        const double n[3] = {e[4] * e[8] - e[5] * e[7], e[5] * e[6] - e[3] * e[8],
                             e[3] * e[7] - e[4] * e[6]};
        const double nn = sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
        for (int k = 0; k < 3; ++k)
            ctrl[3 * i + k] = e[k] + lift * size * n[k] / nn;
    }
    static const double knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 3, 4, ctrl, NULL, knots, &c));
    return c;
}

/* hammer.iges surface 9 (rational biquadratic, a knot span of width
 * 1.5e-14 at u = 0 and one of 5.9e-15 at v = 0): the seeds Newton found
 * inside those spans satisfied G = 0 for their derivatives only; the
 * branches traced from them had residuals of 225 to 350 (eps_D 0.34). */
static void test_hammer(void)
{
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/hammer.iges"), &m) !=
        PROJCURVE_OK) {
        pc_test_missing_data("real/hammer.iges");
    }
    const projcurve_surface *s = projcurve_model_surface(m, 9);
    CHECK(s != NULL);
    if (s != NULL) {
        projcurve_curve *c = lifted_diagonal(s, 0.05);
        check_vertices("hammer surface 9, lifted diagonal", s, c);
        projcurve_curve_destroy(c);
    }
    projcurve_model_destroy(m);
}

int main(void)
{
    test_hammer();
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/linkrods.step"), &m) !=
        PROJCURVE_OK)
        pc_test_missing_data("real/linkrods.step");
    const projcurve_surface *tube = projcurve_model_surface(m, 11);
    const projcurve_surface *thin = projcurve_model_surface(m, 16);
    CHECK(tube != NULL && thin != NULL);
    if (tube != NULL && thin != NULL) {
        check_vertices("surface 11, curve 39", tube, projcurve_model_curve(m, 39));
        check_vertices("surface 11, curve 40", tube, projcurve_model_curve(m, 40));
        check_grid_foot("surface 16, curve 0", thin, projcurve_model_curve(m, 0), 4.0);
        /* the grid finds one interior minimum there (the real-data
         * sweep's check found it too, 7.5 eps_D from every branch) */
        CHECK(check_grid_minima("surface 16, curve 16", thin, projcurve_model_curve(m, 16), 0.1) >= 1);
    }
    projcurve_model_destroy(m);
    return pc_test_finish("test_ortho_seeds_real");
}
