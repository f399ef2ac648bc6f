/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The tracer's step of the directional projector (pc_projector.advance):
 * from Taylor predictions ([SY13] eq. (3.5)) along Example 1 at the
 * paper's coarsest step, each corrected point must lie on the projection
 * (a fresh evaluation's residual within the corrector's tolerance, although
 * the step may end without evaluating S there), and the derivatives it
 * returns, which may keep S's second derivatives from before the last Newton
 * step, must move the next prediction by at most the documented fraction of
 * the correction: h |dq'| + h^2 |dq''| / 2 <= 1e-3 |d|.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "directional/directional.h"
#include "trace/tracer.h"
#include "trace_shapes.h"

#define STEP 1e-2
#define NEWTON_TOL 1e-12
/* PC_PREDICTION_DRIFT of directional.c */
#define PREDICTION_DRIFT 1e-3

static double norm2(double a, double b) { return sqrt(a * a + b * b); }

int main(void)
{
    projcurve_surface *s = shape_example1_surface();
    projcurve_curve *c = shape_example1_curve();
    CHECK(s != NULL && c != NULL);
    if (s == NULL || c == NULL)
        return pc_test_finish("test_trace_advance");
    /* the traced vertices are the starting points */
    projcurve_options *o = NULL;
    projcurve_options_create(NULL, &o);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0);
    projcurve_options_set_double(NULL, o, PROJCURVE_OPT_PARAM_STEP, STEP);
    const double dir[3] = {-1, 0, 0};
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, dir, o, &r));
    size_t n = 0;
    CHECK_OK(projcurve_result_branch_points(NULL, r, 0, 0, NULL, &n));
    double *pts = malloc(3 * (n ? n : 1) * sizeof *pts);
    CHECK(pts != NULL && n > 10);
    if (pts)
        CHECK_OK(projcurve_result_branch_points(NULL, r, 0, n, pts, &n));

    pc_projector proj;
    pc_directional_data data;
    pc_directional_cache cache;
    pc_directional_init(&proj, &data, &cache, s, c, vec3(-1, 0, 0), NEWTON_TOL, 20);
    const double eps1 = proj.newton_tol;
    double worst_res = 0.0, worst_shift = 0.0;
    int steps = 0;
    for (size_t k = 0; pts && k + 1 < n; ++k) {
        const double t = pts[3 * k], h = pts[3 * (k + 1)] - t;
        pc_proj_point cur, next, fresh;
        cache.surf_valid = 0;
        CHECK(proj.derivatives(&proj, t, pts[3 * k + 1], pts[3 * k + 2], &cur));
        double uv[2], pred[2];
        pc_predict_taylor(&cur, h, pred);
        uv[0] = pred[0];
        uv[1] = pred[1];
        int it = 0;
        CHECK(proj.advance(&proj, t + h, h, uv, &it, &next) == 1);
        /* a fresh evaluation at the corrected point */
        cache.surf_valid = 0;
        const double res = proj.residual(&proj, t + h, uv[0], uv[1]);
        CHECK(proj.derivatives(&proj, t + h, uv[0], uv[1], &fresh));
        const double d = norm2(uv[0] - pred[0], uv[1] - pred[1]);
        const double shift = fabs(h) * norm2(next.du - fresh.du, next.dv - fresh.dv) +
                             0.5 * h * h * norm2(next.ddu - fresh.ddu, next.ddv - fresh.ddv);
        worst_res = fmax(worst_res, res / eps1);
        if (d > 0.0)
            worst_shift = fmax(worst_shift, shift / d);
        CHECK(next.u == uv[0] && next.v == uv[1] && next.t == t + h);
        ++steps;
    }
    printf("%d steps of %g: residual <= %.3g eps1, next prediction moved <= %.3g |d|\n", steps,
           STEP, worst_res, worst_shift);
    CHECK(steps > 10);
    CHECK(worst_res <= 1.0);
    CHECK(worst_shift <= PREDICTION_DRIFT);
    free(pts);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_surface_destroy(s);
    projcurve_curve_destroy(c);
    return pc_test_finish("test_trace_advance");
}
