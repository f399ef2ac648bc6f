/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The refinement march must advance in t at every vertex it outputs.
 * linkrods.step surface 15 with the real-data sweep's lifted diagonal (a
 * cubic through the image of the domain's diagonal, 2 % to 98 %, lifted by
 * 3 % of the surface size along its average normal), projected along -N:
 * a knot-line crossing found at the current vertex itself was a candidate
 * of zero length, accepted over and over at t = 0.981287 until the piece
 * limit of 1,000,000 (LIMIT_REACHED after ~9 s and over 360 MiB). With
 * cubic pcurves, the cubic march stayed invalid beside a fold there and
 * went on from ever shorter steps (LIMIT_REACHED). The call must return OK
 * with a bounded number of pieces, with either pcurve degree. A hang guard (alarm)
 * ends the program if the call does not return; nothing is timed.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"

#define HANG_GUARD_SECONDS 120
#define DIAGONAL_POLES 12
#define LIFT_REL 0.03
/* after the fix: 2418 pieces with straight pcurves, 1,400 with cubic ones */
#define MAX_PIECES 20000.0

static double norm3(const double a[3])
{
    return sqrt(a[0] * a[0] + a[1] * a[1] + a[2] * a[2]);
}

/* The unit normal average over a 5 x 5 grid of the domain (the sweep's;
 * this surface is open, the average does not cancel). */
static void average_normal(const projcurve_surface *s, const double dom[4], double out[3])
{
    double sum[3] = {0, 0, 0};
    for (int i = 0; i < 5; ++i)
        for (int j = 0; j < 5; ++j) {
            double f[9];
            projcurve_surface_eval(NULL, s, dom[0] + (dom[1] - dom[0]) * (0.1 + 0.2 * i),
                                   dom[2] + (dom[3] - dom[2]) * (0.1 + 0.2 * j), 1, f);
            const double n[3] = {f[4] * f[8] - f[5] * f[7], f[5] * f[6] - f[3] * f[8],
                                 f[3] * f[7] - f[4] * f[6]};
            const double l = norm3(n);
            for (int c = 0; c < 3 && l > 0.0; ++c)
                sum[c] += n[c] / l;
        }
    for (int c = 0; c < 3; ++c)
        out[c] = sum[c] / norm3(sum);
}

static projcurve_curve *lifted_diagonal(const projcurve_surface *s)
{
    double dom[4], box[6], n[3];
    projcurve_surface_domain(NULL, s, dom);
    projcurve_surface_bounds(NULL, s, box);
    const double ext[3] = {box[3] - box[0], box[4] - box[1], box[5] - box[2]};
    const double h = LIFT_REL * norm3(ext);
    average_normal(s, dom, n);
    double poles[3 * DIAGONAL_POLES], knots[DIAGONAL_POLES + 4];
    for (int k = 0; k < DIAGONAL_POLES; ++k) {
        const double a = 0.02 + 0.96 * k / (DIAGONAL_POLES - 1);
        double p[3] = {0, 0, 0};
        projcurve_surface_eval(NULL, s, dom[0] + a * (dom[1] - dom[0]),
                               dom[2] + a * (dom[3] - dom[2]), 0, p);
        for (int c = 0; c < 3; ++c)
            poles[3 * k + c] = p[c] + h * n[c];
    }
    for (int k = 0; k < DIAGONAL_POLES + 4; ++k) {
        const int inner = k - 3;
        knots[k] = inner <= 0 ? 0.0
                   : inner >= DIAGONAL_POLES - 3 ? 1.0
                                                  : (double)inner / (DIAGONAL_POLES - 3);
    }
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 3, DIAGONAL_POLES, poles, NULL, knots, &c));
    return c;
}

int main(void)
{
    pc_test_hang_guard(HANG_GUARD_SECONDS);
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/linkrods.step"), &m) !=
        PROJCURVE_OK)
        pc_test_missing_data("real/linkrods.step");
    const projcurve_surface *s = projcurve_model_surface(m, 15);
    CHECK(s != NULL);
    projcurve_curve *c = lifted_diagonal(s);
    const double dir[3] = {-0.104859, -0.688708, 0.717416}; /* -N, as the sweep */
    /* straight pcurves, then cubic ones: the cubic march handed the
     * straight one ever shorter stretches there (1/32 of the step each
     * time), to rounding-sized ones, until the call's limit */
    for (int degree = 1; degree <= 3; degree += 2) {
        projcurve_options *o = NULL;
        CHECK_OK(projcurve_options_create(NULL, &o));
        CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_PCURVE_DEGREE, degree));
        projcurve_result *r = NULL;
        CHECK_OK(projcurve_project_directional(NULL, s, c, dir, o, &r));
        double pieces = NAN;
        CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_PIECES, &pieces));
        printf("linkrods.step surface 15, lifted diagonal, pcurve degree %d: %zu branches, "
               "%.0f pieces, %zu failures\n",
               degree, projcurve_result_branch_count(r), pieces, projcurve_result_failure_count(r));
        CHECK(pieces <= MAX_PIECES);
        projcurve_result_destroy(r);
        projcurve_options_destroy(o);
    }
    projcurve_curve_destroy(c);
    projcurve_model_destroy(m);
    return pc_test_finish("test_refine_knot_progress");
}
