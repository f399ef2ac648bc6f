/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A line through the centre of a sphere (R = 1 at the origin), P(t) =
 * (t - 1/2) d on [0, 1]: the foot points are c +- R P / |P|, fixed while P
 * moves along the normal, and at t = 1/2 every point of the sphere is a
 * foot point (an umbilic centre of curvature: det K = (|P| / R)^2 |g|,
 * touching 0 without changing sign). The near point is the minimum before
 * the centre and the maximum after it, the antipode the other way round.
 *
 * The defined answer (docs/orthogonal.md): the branches end at the centre
 * with PROJCURVE_END_CURVATURE_CENTRE and restart after it with
 * PROJCURVE_START_SILHOUETTE; by default (minima) one branch on the near
 * point over [0, 1/2) and one on the antipode over (1/2, 1], every foot
 * point two branches each side. Before, the split at the centre bisected
 * onto t = 1/2 exactly (the engine's and the bisection's parameters are
 * dyadic), where the corrector converges to any point (the pole), and the
 * branch ended at t = 0.484.
 *
 * The traced branches are checked (COMPOSE = 0): this is the tracing and
 * split stage; the composition of a foot point at rest is refine/'s.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "shapes.h"

/* The ends are the last points with det K / (|Su||Sv|)^2 = (|P| / R)^2 >=
 * 1e-6 found by bisection (ortho_centres.c): |t - 1/2| >= 3.4e-4 here
 * (|d| = 2.97), and within a few bisection steps of that; 4e-3 of the
 * domain is |P| <= 0.012 R. */
#define END_T_TOL 4e-3
/* Vertices on the closed-form foot points: the corrector's 1e-12 of the
 * size, far above rounding, far below the 2R between the two points. */
#define FOOT_TOL 1e-9

static const double dir[3] = {2.4, 1.5, 0.9};

typedef struct summary {
    double t0, t1;
    projcurve_branch_start start;
    projcurve_branch_end end;
    int sheet;   /* +1 near point c + R d / |d|, -1 the antipode, 0 neither */
} summary;

static int sheet_of(const double x[3])
{
    const double nd = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    double e_near = 0.0, e_far = 0.0;
    for (int k = 0; k < 3; ++k) {
        /* the point of the sphere on the side of P(t) for t < 1/2 is -d */
        e_near += (x[k] + dir[k] / nd) * (x[k] + dir[k] / nd);
        e_far += (x[k] - dir[k] / nd) * (x[k] - dir[k] / nd);
    }
    return sqrt(e_near) <= FOOT_TOL ? 1 : (sqrt(e_far) <= FOOT_TOL ? -1 : 0);
}

static size_t project(const projcurve_surface *s, const projcurve_curve *c, int all,
                      summary *out, size_t max)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0));
    if (all)
        CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_FOOT_POINTS,
                                           PROJCURVE_FOOT_POINTS_ALL));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, o, &r));
    const size_t nb = r ? projcurve_result_branch_count(r) : 0;
    for (size_t b = 0; b < nb && b < max; ++b) {
        double tr[2];
        size_t n = 0;
        CHECK_OK(projcurve_result_branch_info(NULL, r, b, tr, &out[b].start, &out[b].end, &n,
                                              NULL));
        double *pts = malloc(3 * (n ? n : 1) * sizeof *pts);
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, n, pts, &n));
        out[b].t0 = tr[0];
        out[b].t1 = tr[1];
        out[b].sheet = 2;
        for (size_t i = 0; i < n; ++i) {
            double x[3];
            projcurve_surface_eval(NULL, s, pts[3 * i + 1], pts[3 * i + 2], 0, x);
            const int sh = sheet_of(x);
            out[b].sheet = out[b].sheet == 2 || out[b].sheet == sh ? sh : 0;
        }
        printf("  branch %zu: t [%.9g, %.9g], start %d, end %d, %zu vertices, sheet %d\n", b,
               tr[0], tr[1], out[b].start, out[b].end, n, out[b].sheet);
        free(pts);
    }
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    return nb;
}

/* A branch on `sheet` before the centre (ending there) or after it. */
static int has(const summary *br, size_t nb, int sheet, int before)
{
    for (size_t b = 0; b < nb; ++b) {
        if (br[b].sheet != sheet)
            continue;
        if (before && br[b].t0 == 0.0 && br[b].start == PROJCURVE_START_CURVE_START &&
            br[b].end == PROJCURVE_END_CURVATURE_CENTRE && br[b].t1 < 0.5 &&
            br[b].t1 >= 0.5 - END_T_TOL)
            return 1;
        if (!before && br[b].t1 == 1.0 && br[b].end == PROJCURVE_END_CURVE_END &&
            br[b].start == PROJCURVE_START_SILHOUETTE && br[b].t0 > 0.5 &&
            br[b].t0 <= 0.5 + END_T_TOL)
            return 1;
    }
    return 0;
}

int main(void)
{
    const double centre[3] = {0.0, 0.0, 0.0};
    pc_shape_surface data = pc_shape_sphere(centre, 1.0);
    projcurve_surface *s = pc_shape_surface_create(&data);
    pc_shape_surface_free(&data);
    pc_shape_line line = {{-0.5 * dir[0], -0.5 * dir[1], -0.5 * dir[2]},
                          {dir[0], dir[1], dir[2]}};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, pc_shape_line_fn, &line, 0.0, 1.0, &c));
    summary br[16];

    printf("minima (default)\n");
    size_t nb = project(s, c, 0, br, 16);
    CHECK(nb == 2);
    CHECK(has(br, nb, 1, 1));    /* near point, the minimum up to the centre */
    CHECK(has(br, nb, -1, 0));   /* the antipode, the minimum after it */

    printf("every foot point\n");
    nb = project(s, c, 1, br, 16);
    CHECK(nb == 4);
    CHECK(has(br, nb, 1, 1) && has(br, nb, 1, 0));
    CHECK(has(br, nb, -1, 1) && has(br, nb, -1, 0));

    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    return pc_test_finish("test_ortho_sphere_centre");
}
