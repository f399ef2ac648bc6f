/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Orthogonal projection of a curve lying on S: the answer is the curve
 * itself (every point is its own foot point, at distance 0), the same on a
 * one-patch plane and on a plane of many knot spans, one branch over the
 * whole curve. The oracle is the curve: every composed piece, sampled, must
 * lie within eps_D of P (its nearest point near the piece's t range).
 *
 * Issue 14 defect 3: a circle of radius 1000 in z = 0 onto the 31 x 31
 * bilinear plane z = 0 of test_pipe_out_true.step gave one branch of
 * 999,977 pieces at one t (ending at the piece limit) and a FAILED branch
 * 6.5e-17 long: the circle starts on a patch corner, the traced start
 * vertex lay 2e-14 beside the knot line v = 0, and the refinement saw a
 * knot-line crossing 2.3e-17 later in t, a run too short for its
 * corrector.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "on_surface.h"
#include "shapes.h"

/* Samples per piece against P(t). */
#define PIECE_SAMPLES 8
/* Golden-section steps of the foot search on P: the bracket shrinks to
 * 0.618^200 of its width, far below rounding. */
#define FOOT_STEPS 200

static double dist_to_curve_at(const projcurve_curve *c, const double x[3], double t)
{
    double p[3];
    projcurve_curve_eval(NULL, c, t, 0, p);
    return hypot(hypot(x[0] - p[0], x[1] - p[1]), x[2] - p[2]);
}

/* Distance from x to P over [lo, hi] (a piece's t range widened by half
 * its length on each side, clamped to P's domain), by golden section: the
 * distance is unimodal there, the range being far shorter than the
 * curves' radii of curvature. */
static double dist_to_curve(const projcurve_curve *c, const double x[3], double lo, double hi)
{
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    double a = lo, b = hi;
    for (int it = 0; it < FOOT_STEPS; ++it) {
        const double m1 = b - g * (b - a), m2 = a + g * (b - a);
        if (dist_to_curve_at(c, x, m1) <= dist_to_curve_at(c, x, m2))
            b = m2;
        else
            a = m1;
    }
    return fmin(dist_to_curve_at(c, x, 0.5 * (a + b)),
                fmin(dist_to_curve_at(c, x, lo), dist_to_curve_at(c, x, hi)));
}

/* Largest distance between a composed piece's samples and the curve. The
 * piece is within eps_D of the curve as a set (the Hausdorff bound): its
 * point at s is compared with the nearest point of P, not with P at the
 * matching t, from which a cubic pcurve's point may lie farther along
 * the curve (on the 1 x 1 span planes 1.3e-4 at eps_D = 1e-5 while
 * 9e-6 from the curve). */
static double worst_piece_distance(const projcurve_result *r, const projcurve_curve *c)
{
    double worst = 0.0, t0 = 0.0, t1 = 0.0;
    projcurve_curve_domain(NULL, c, &t0, &t1);
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        size_t n_pieces = 0;
        projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, NULL, &n_pieces);
        for (size_t k = 0; k < n_pieces; ++k) {
            int degree = 0;
            double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS], range[2];
            if (projcurve_result_piece(NULL, r, b, k, &degree, ctrl, w, range, NULL) !=
                PROJCURVE_OK)
                return INFINITY;
            const double half = 0.5 * (range[1] - range[0]);
            const double lo = fmax(t0, range[0] - half), hi = fmin(t1, range[1] + half);
            for (int i = 0; i <= PIECE_SAMPLES; ++i) {
                double x[3];
                pc_test_piece_point(degree, ctrl, w, (double)i / PIECE_SAMPLES, x);
                worst = fmax(worst, dist_to_curve(c, x, lo, hi));
            }
        }
    }
    return worst;
}

/* One branch over the whole curve, from its start to its end, every piece
 * within eps_D of the curve. Returns the number of pieces. */
static size_t check_curve_itself(const char *name, const projcurve_surface *s,
                                 const projcurve_curve *c, double eps_d)
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    if (eps_d > 0.0)
        CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, eps_d));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, o, &r));
    projcurve_options_destroy(o);
    double t0 = 0.0, t1 = 0.0, eps = 0.0;
    projcurve_curve_domain(NULL, c, &t0, &t1);
    projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &eps);
    const size_t nb = projcurve_result_branch_count(r);
    size_t pieces = 0;
    double range[2] = {0.0, 0.0};
    projcurve_branch_start start = PROJCURVE_START_JUMP;
    projcurve_branch_end end = PROJCURVE_END_FAILED;
    if (nb >= 1)
        CHECK_OK(projcurve_result_branch_info(NULL, r, 0, range, &start, &end, NULL, &pieces));
    const double dist = worst_piece_distance(r, c);
    printf("%s: %zu branch(es), t [%.17g, %.17g], %zu pieces, start %d end %d, "
           "piece-curve distance %.3g (eps_D %.3g)\n",
           name, nb, range[0], range[1], pieces, (int)start, (int)end, dist, eps);
    CHECK(nb == 1);
    CHECK(range[0] == t0 && range[1] == t1);
    CHECK(start == PROJCURVE_START_CURVE_START);
    CHECK(end == PROJCURVE_END_CURVE_END);
    CHECK(dist <= eps);
    pc_on_surface_check(name, r, s, 3); /* the default degree: 3 */
    projcurve_result_destroy(r);
    return pieces;
}

/* A circle through patch corners (centre (0, 0.5), radius 0.6: it starts
 * at (0.6, 0.5), on the knot lines u = 0.8 and v = 0.5 of the 10 x 10
 * plane) on one patch and on many spans, of degree 1 and 3: the same
 * answer, with about as many pieces (the spans add at most one piece per
 * knot line crossed, ~30 here). */
static void test_circle_on_planes(void)
{
    const double centre[3] = {0.0, 0.5, 0.0};
    pc_shape_curve circle = pc_shape_circle(centre, 0.6);
    projcurve_curve *c = pc_shape_curve_create(&circle);
    const double eps_d = 1e-5;
    static const struct {
        int degree;
        size_t spans;
    } planes[] = {{1, 1}, {1, 10}, {3, 1}, {3, 10}, {1, 30}};
    size_t one_patch = 0;
    for (size_t i = 0; i < sizeof planes / sizeof planes[0]; ++i) {
        pc_shape_surface data = pc_shape_plane(planes[i].degree, planes[i].degree,
                                               planes[i].spans, planes[i].spans);
        projcurve_surface *s = pc_shape_surface_create(&data);
        pc_shape_surface_free(&data);
        char name[64];
        snprintf(name, sizeof name, "circle on a degree-%d plane, %zu x %zu spans",
                 planes[i].degree, planes[i].spans, planes[i].spans);
        const size_t pieces = check_curve_itself(name, s, c, eps_d);
        if (planes[i].spans == 1)
            one_patch = pieces;
        else
            CHECK(pieces <= 2 * one_patch + 4 * planes[i].spans);
        projcurve_surface_destroy(s);
    }
    projcurve_curve_destroy(c);
    pc_shape_curve_free(&circle);
}

/* The instance of issue 14: curve 1 onto surface 1 of test_pipe_out_true. */
static void test_pipe_circle(void)
{
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/test_pipe_out_true.step"),
                                  &m) != PROJCURVE_OK) {
        pc_test_missing_data("real/test_pipe_out_true.step");
    }
    const projcurve_surface *s = projcurve_model_surface(m, 1);
    const projcurve_curve *c = projcurve_model_curve(m, 1);
    CHECK(s != NULL && c != NULL);
    if (s != NULL && c != NULL) {
        /* well below the 1000 pieces a circle needs at the default eps_T */
        const size_t pieces = check_curve_itself("test_pipe_out_true curve 1 on surface 1", s, c,
                                                 0.0);
        CHECK(pieces < 2000);
    }
    projcurve_model_destroy(m);
}

int main(void)
{
    test_circle_on_planes();
    test_pipe_circle();
    return pc_test_finish("test_ortho_on_surface");
}
