/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve_project_orthogonal where the parametrisation is degenerate:
 * lines over the pole of an exact NURBS sphere (the edges v = 0, 1 are each
 * collapsed to a point, a regular point of the sphere) and lines past the
 * apex of a NURBS cone (the edge v = 0 collapsed to a point that is no
 * regular point of S). Oracles: the foot points are radial on the sphere,
 * q = +-R P / |P|, and on the cone x^2 + y^2 = z^2 the projection of P onto
 * the generator in P's meridian plane, for each line in closed form. Checked:
 * branch count, where and why each branch starts and ends (the collapsed
 * edge is a side of the domain: BOUNDARY, never FAILED or a centre of
 * curvature), every vertex on the exact foot point, and the Hausdorff
 * distance between the composed pieces and the dense exact curve, both
 * ways, within eps_D.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "on_surface.h"
#include "shapes.h"
#include "unjoined.h"

/* The exact foot point of family `which` of P on the shape; 0 where that
 * family has no foot point. */
typedef enum shape_kind { SPHERE, CONE } shape_kind;

static int exact_foot(shape_kind k, double radius, int which, const double p[3], double q[3])
{
    if (k == SPHERE) {
        const double n = sqrt(p[0] * p[0] + p[1] * p[1] + p[2] * p[2]);
        const double sg = which ? -1.0 : 1.0;   /* 0: near, 1: far (antipodal) */
        for (int i = 0; i < 3; ++i)
            q[i] = sg * radius * p[i] / n;
        return 1;
    }
    /* Cone: the generator g = (cos a, sin a, 1) / sqrt 2 of the meridian
     * half-plane of P (which = 0) or the opposite one (which = 1); the
     * foot point s g with s = P.g > 0 (else it would lie on the other
     * nappe, which the NURBS cone does not have). On the axis (rho = 0)
     * every generator is one: the family is undefined. */
    const double rho = hypot(p[0], p[1]);
    if (!(rho > 0.0))
        return 0;
    const double sg = which ? -1.0 : 1.0;
    const double g[3] = {sg * p[0] / rho / sqrt(2.0), sg * p[1] / rho / sqrt(2.0), 1 / sqrt(2.0)};
    const double s = p[0] * g[0] + p[1] * g[1] + p[2] * g[2];
    if (!(s >= 0.0))
        return 0;
    for (int i = 0; i < 3; ++i)
        q[i] = s * g[i];
    return 1;
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Distance from x to the polyline pts[0..n). */
static double to_polyline(const double *x, const double *pts, size_t n)
{
    double best = n == 1 ? dist3(x, pts) : INFINITY;
    for (size_t i = 0; i + 1 < n; ++i) {
        const double *a = pts + 3 * i, *b = a + 3;
        double ab[3], l2 = 0.0, s = 0.0;
        for (int k = 0; k < 3; ++k) {
            ab[k] = b[k] - a[k];
            l2 += ab[k] * ab[k];
            s += ab[k] * (x[k] - a[k]);
        }
        s = l2 > 0.0 ? fmin(1.0, fmax(0.0, s / l2)) : 0.0;
        const double c[3] = {a[0] + s * ab[0], a[1] + s * ab[1], a[2] + s * ab[2]};
        best = fmin(best, dist3(x, c));
    }
    return best;
}

/* Samples per piece: the chord error of the sampled polyline of a piece
 * spanning a quarter of the sphere is below 1e-6 (eps_D / 100). */
#define PIECE_SAMPLES 513
#define PIECE_CAP 400
#define DENSE 4000

/* Samples of piece k of branch b (rational Bezier by de Casteljau in
 * homogeneous coordinates) into out; its t-range into range. */
static void sample_piece(const projcurve_result *r, size_t b, size_t k, double *out,
                         double range[2])
{
    int deg = 0;
    double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS];
    CHECK_OK(projcurve_result_piece(NULL, r, b, k, &deg, ctrl, w, range, NULL));
    for (int j = 0; j < PIECE_SAMPLES; ++j)
        pc_test_piece_point(deg, ctrl, w, j / (double)(PIECE_SAMPLES - 1), out + 3 * j);
}

/* What a case expects of one branch. */
typedef struct expected_branch {
    double t0, t1;
    projcurve_branch_start start;
    projcurve_branch_end end;
} expected_branch;

typedef struct degenerate_case {
    const char *name;
    shape_kind kind;
    double size;        /* sphere radius, cone height */
    pc_shape_line l;
    double t0, t1;
    size_t n_branches;
    expected_branch branches[4];   /* in increasing (t0, t1) order */
} degenerate_case;

/* The ends at the collapsed edge: the exit locator snaps the branch onto
 * the edge within PC_TRACE_BOUNDARY_TOL (1e-12) of the domain when the
 * corrector converges there, which it does along the regular direction; a
 * branch traced back from a seed found beside the edge starts where that
 * search found it, and seeds within the collapsed zone (|Su| < 1e-6 |Sv|,
 * 4.5e-7 of the sphere's radius around the pole) are dropped: 1.5e-7 in t
 * was measured at one start of the seam case. 1e-6 in t is 8e-7 in space
 * here (|q'| <= 0.8): far below eps_D. */
#define T_END_TOL 1e-6
/* Ends at a centre of curvature: where |det K| / (|Su||Sv|)^2 < 1e-6, the
 * engine's fold threshold; det vanishes linearly in the distance of P from
 * the cone's axis here (3e-7 in t measured; docs/orthogonal.md: ~2e-6 for
 * transversal crossings). */
#define T_CENTRE_TOL 1e-5
/* Vertices are foot points to newton_tol (1e-12 of the model size) where
 * the parametrisation is regular; in the collapsed zone the component of
 * S - P along Su is resolved only to the rounding of Su over its length
 * (collapsed.h): ~1e-8 here. */
#define VERTEX_TOL 1e-7

static int branch_order(const void *a, const void *b)
{
    const double *x = a, *y = b;
    if (x[0] != y[0])
        return x[0] < y[0] ? -1 : 1;
    return (x[1] > y[1]) - (x[1] < y[1]);
}

static void run_case(const degenerate_case *c)
{
    const double eps_d = 1e-4;
    pc_shape_surface data = c->kind == SPHERE
                                ? pc_shape_sphere((const double[3]){0, 0, 0}, c->size)
                                : pc_shape_cone(c->size);
    projcurve_surface *surf = pc_shape_surface_create(&data);
    pc_shape_surface_free(&data);
    projcurve_curve *curve = NULL;
    CHECK_OK(projcurve_curve_create_callback(NULL, pc_shape_line_fn, (void *)&c->l, c->t0, c->t1,
                                             &curve));
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    /* far-side feet (saddles, maxima) are part of the expected answer */
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_FOOT_POINTS,
                                       PROJCURVE_FOOT_POINTS_ALL));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, eps_d));
    projcurve_result *r = NULL;
    /* the tracer's own ends at the poles and seams, which the seam stage
     * (src/seam/, tested in tests/unit/seam/) would join */
    CHECK_OK(pc_test_project_unjoined(NULL, surf, curve, NULL, o, &r));
    const size_t nb = r ? projcurve_result_branch_count(r) : 0;
    printf("%s: %zu branches (expected %zu)\n", c->name, nb, c->n_branches);
    CHECK(nb == c->n_branches);
    /* (t0, t1, index) sorted, to pair them with the expected list */
    double order[8][3];
    for (size_t b = 0; b < nb && b < 8; ++b) {
        double range[2] = {0, 0};
        projcurve_result_branch_info(NULL, r, b, range, NULL, NULL, NULL, NULL);
        order[b][0] = range[0];
        order[b][1] = range[1];
        order[b][2] = (double)b;
    }
    qsort(order, nb < 8 ? nb : 8, sizeof order[0], branch_order);
    static double exact[3 * (DENSE + 1)], piece_pts[3 * PIECE_SAMPLES * PIECE_CAP],
        ranges[2 * PIECE_CAP];
    for (size_t j = 0; j < nb && j < 8 && nb == c->n_branches; ++j) {
        const size_t b = (size_t)order[j][2];
        const expected_branch *e = &c->branches[j];
        double range[2];
        projcurve_branch_start start;
        projcurve_branch_end end;
        size_t n_points = 0, n_pieces = 0;
        CHECK_OK(projcurve_result_branch_info(NULL, r, b, range, &start, &end, &n_points,
                                              &n_pieces));
        /* the family of the branch: that of its middle vertex */
        double *pts = malloc(3 * n_points * sizeof *pts);
        size_t got = 0;
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, n_points, pts, &got));
        int fam = -1;
        double worst_vertex = 0.0;
        for (size_t i = 0; i < got; ++i) {
            double x[3], pv[9], q[3];
            projcurve_surface_eval(NULL, surf, pts[3 * i + 1], pts[3 * i + 2], 0, x);
            pc_shape_line_fn((void *)&c->l, pts[3 * i], pv);
            if (fam < 0) {
                const double *m = pts + 3 * (got / 2);
                double xm[3], pm[9], q0[3], q1[3];
                projcurve_surface_eval(NULL, surf, m[1], m[2], 0, xm);
                pc_shape_line_fn((void *)&c->l, m[0], pm);
                const double d0 = exact_foot(c->kind, c->size, 0, pm, q0) ? dist3(xm, q0) : INFINITY;
                const double d1 = exact_foot(c->kind, c->size, 1, pm, q1) ? dist3(xm, q1) : INFINITY;
                fam = d0 <= d1 ? 0 : 1;
            }
            /* at the apex (P on the generator's normal plane through it)
             * the foot point is the apex itself */
            double dv = exact_foot(c->kind, c->size, fam, pv, q) ? dist3(x, q) : dist3(x, (double[3]){0, 0, 0});
            worst_vertex = fmax(worst_vertex, dv);
        }
        free(pts);
        /* Hausdorff both ways against the exact curve over the branch's range */
        for (size_t i = 0; i <= DENSE; ++i) {
            double pv[9];
            pc_shape_line_fn((void *)&c->l, range[0] + (range[1] - range[0]) * (double)i / DENSE,
                             pv);
            if (!exact_foot(c->kind, c->size, fam, pv, exact + 3 * i))
                memset(exact + 3 * i, 0, 3 * sizeof *exact);   /* the apex */
        }
        if (n_pieces > PIECE_CAP)
            n_pieces = PIECE_CAP;
        for (size_t k = 0; k < n_pieces; ++k)
            sample_piece(r, b, k, piece_pts + 3 * PIECE_SAMPLES * k, ranges + 2 * k);
        const double dt = (range[1] - range[0]) / DENSE, margin = 3.0 * dt;
        double one = 0.0, other = 0.0;
        for (size_t k = 0; k < n_pieces; ++k) {
            long lo = (long)floor((ranges[2 * k] - margin - range[0]) / dt);
            long hi = (long)ceil((ranges[2 * k + 1] + margin - range[0]) / dt);
            lo = lo < 0 ? 0 : lo;
            hi = hi > DENSE ? DENSE : hi;
            for (size_t s = 0; s < PIECE_SAMPLES; ++s)
                one = fmax(one, to_polyline(piece_pts + 3 * (PIECE_SAMPLES * k + s),
                                            exact + 3 * lo, (size_t)(hi - lo + 1)));
        }
        for (size_t i = 0; i <= DENSE; ++i) {
            const double t = range[0] + dt * (double)i;
            double best = INFINITY;
            for (size_t k = 0; k < n_pieces; ++k)
                if (ranges[2 * k] - margin <= t && t <= ranges[2 * k + 1] + margin)
                    best = fmin(best, to_polyline(exact + 3 * i, piece_pts + 3 * PIECE_SAMPLES * k,
                                                  PIECE_SAMPLES));
            other = fmax(other, best);
        }
        printf("  branch t [%.9f, %.9f] (expected [%g, %g]) start %d (%d) end %d (%d) "
               "family %d vertices %zu err %.1e pieces %zu Hausdorff %.1e / %.1e\n",
               range[0], range[1], e->t0, e->t1, (int)start, (int)e->start, (int)end,
               (int)e->end, fam, got, worst_vertex, n_pieces, one, other);
        CHECK_NEAR(range[0], e->t0,
                   e->start == PROJCURVE_START_SILHOUETTE ? T_CENTRE_TOL : T_END_TOL);
        CHECK_NEAR(range[1], e->t1,
                   e->end == PROJCURVE_END_CURVATURE_CENTRE ? T_CENTRE_TOL : T_END_TOL);
        CHECK(start == e->start);
        CHECK(end == e->end);
        CHECK(worst_vertex <= VERTEX_TOL);
        CHECK(n_pieces > 0);
        CHECK(one <= eps_d);
        CHECK(other <= eps_d);
    }
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(curve);
    projcurve_surface_destroy(surf);
}

int main(void)
{
    const projcurve_branch_start CS = PROJCURVE_START_CURVE_START, SB = PROJCURVE_START_BOUNDARY;
    const projcurve_branch_start SC = PROJCURVE_START_SILHOUETTE;
    const projcurve_branch_end CE = PROJCURVE_END_CURVE_END, EB = PROJCURVE_END_BOUNDARY,
                               EC = PROJCURVE_END_CURVATURE_CENTRE;
    /* Sphere R = 10; the lines at height 12 cross the z axis at t = 3,
     * where the near foot point passes the north pole and the far one the
     * south pole: each is two branches, one ending on the collapsed edge,
     * one starting on it on the opposite meridian, at t = 3. */
    const degenerate_case cases[] = {
        {"sphere, line over the pole along y", SPHERE, 10.0, {{0, -3, 12}, {0, 1, 0}}, 0, 6, 4,
         {{0, 3, CS, EB}, {0, 3, CS, EB}, {3, 6, SB, CE}, {3, 6, SB, CE}}},
        /* in the plane y = 0: the far foot point before the pole and the
         * near one after it run along the seam u = 0 = 1 */
        {"sphere, line over the pole along x (seam)", SPHERE, 10.0, {{-3, 0, 12}, {1, 0, 0}}, 0, 6,
         4, {{0, 3, CS, EB}, {0, 3, CS, EB}, {3, 6, SB, CE}, {3, 6, SB, CE}}},
        {"sphere, diagonal line over the pole", SPHERE, 10.0, {{-3, -3, 12}, {1, 1, 0}}, 0, 6, 4,
         {{0, 3, CS, EB}, {0, 3, CS, EB}, {3, 6, SB, CE}, {3, 6, SB, CE}}},
        /* Cone, apex at the origin; P = (0, y, -1) with y = t - 3: the foot
         * point on the generator of P's side is (|y| - 1) / 2 (0, sign y, 1),
         * reaching the apex at y = -1 (t = 2) and leaving it at y = 1
         * (t = 4); in between P has no foot point. */
        {"cone, line below the apex", CONE, 3.0, {{0, -3, -1}, {0, 1, 0}}, 0, 6, 2,
         {{0, 2, CS, EB}, {4, 6, SB, CE}}},
        /* through the apex (normal to the generators there): in at t = 3,
         * out at t = 3 on the opposite generator */
        {"cone, line through the apex", CONE, 3.0, {{0, -3, 0}, {0, 1, 0}}, 0, 6, 2,
         {{0, 3, CS, EB}, {3, 6, SB, CE}}},
        /* above the apex, P = (0, y, 1): the near foot point (|y| + 1) / 2
         * (0, sign y, 1) on P's side; the far one (1 - |y|) / 2 (0, -sign y,
         * 1) exists for |y| < 1, leaving the apex at t = 2 and returning
         * to it at t = 4. At t = 3 P is on the axis, a centre of curvature
         * of every point of the circle z = 1 / 2: both end there and two
         * are born. Near the apex the circles around it have a curvature
         * that diverges, with the sign that says on which side of them P
         * is: no branch may end at a false centre or fail. */
        {"cone, line above the apex", CONE, 3.0, {{0, -3, 1}, {0, 1, 0}}, 0, 6, 4,
         {{0, 3, CS, EC}, {2, 3, SB, EC}, {3, 4, SC, EB}, {3, 6, SC, CE}}},
    };
    for (size_t i = 0; i < sizeof cases / sizeof cases[0]; ++i)
        run_case(&cases[i]);
    return pc_test_finish("test_ortho_degenerate");
}
