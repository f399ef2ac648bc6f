/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The engine's parameters (common/params.h): their defaults are the ones
 * projcurve_option_info tells for every option the engine reads (the
 * public table and the engine agree), and eps_D resolves as projcurve.h
 * says: 1e-4 of the model size while unset, the caller's value when the
 * corrector can meet it, OUT_OF_RANGE below max(NEWTON_TOL, 1e-12) of the
 * size.
 */
#include <stdio.h>

#include "check.h"
#include "common/params.h"

static void check_default(projcurve_option key, const char *name, double engine)
{
    double public_default = -1.0;
    CHECK_OK(projcurve_option_info(NULL, key, NULL, NULL, NULL, &public_default));
    if (public_default != engine)
        printf("%s: public default %.17g, engine default %.17g\n", name, public_default, engine);
    CHECK(public_default == engine);
}

static void test_defaults(void)
{
    pc_params p;
    pc_params_defaults(&p);
    check_default(PROJCURVE_OPT_TOL_DISTANCE, "TOL_DISTANCE", p.tol_distance);
    check_default(PROJCURVE_OPT_TOL_ANGLE_DEG, "TOL_ANGLE_DEG", p.tol_angle_deg);
    check_default(PROJCURVE_OPT_NEWTON_TOL, "NEWTON_TOL", p.newton_tol);
    check_default(PROJCURVE_OPT_NEWTON_MAX_ITER, "NEWTON_MAX_ITER", (double)p.newton_max_iter);
    check_default(PROJCURVE_OPT_METHOD, "METHOD", (double)p.method);
    check_default(PROJCURVE_OPT_PARAM_STEP, "PARAM_STEP", p.param_step);
    check_default(PROJCURVE_OPT_ARC_STEP_FRACTION, "ARC_STEP_FRACTION", p.arc_step_fraction);
    check_default(PROJCURVE_OPT_MAX_POINTS, "MAX_POINTS", (double)p.max_points);
    check_default(PROJCURVE_OPT_MAX_PIECES, "MAX_PIECES", (double)p.max_pieces);
    check_default(PROJCURVE_OPT_COMPOSE, "COMPOSE", (double)p.compose);
    check_default(PROJCURVE_OPT_JUMP_DETECTION, "JUMP_DETECTION", (double)p.jump_detection);
    check_default(PROJCURVE_OPT_PCURVE_DEGREE, "PCURVE_DEGREE", (double)p.pcurve_degree);
    check_default(PROJCURVE_OPT_FOOT_POINTS, "FOOT_POINTS", (double)p.foot_points);
    CHECK(p.budget == NULL && p.sweep_criteria_only == 0);
}

static void test_distance_tolerance(void)
{
    const double size = 250.0;
    pc_params p;
    pc_params_defaults(&p);
    double eps = 0.0;
    CHECK_OK(pc_params_distance_tolerance(NULL, &p, size, &eps));
    CHECK(eps == PC_AUTO_TOL_DISTANCE * size);
    p.tol_distance = 0.01;
    CHECK_OK(pc_params_distance_tolerance(NULL, &p, size, &eps));
    CHECK(eps == 0.01);
    /* below NEWTON_TOL (1e-12) of the size: 2.5e-10 cannot be met */
    p.tol_distance = 1e-10;
    eps = -1.0;
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK_STATUS(pc_params_distance_tolerance(ctx, &p, size, &eps), PROJCURVE_ERR_OUT_OF_RANGE);
    printf("message: %s\n", projcurve_context_message(ctx));
    CHECK(eps == -1.0);
    /* a coarser NEWTON_TOL raises the floor with it */
    p.newton_tol = 1e-6;
    p.tol_distance = 1e-4; /* below 1e-6 x 250 */
    CHECK(pc_params_precision(&p) == 1e-6);
    CHECK_STATUS(pc_params_distance_tolerance(ctx, &p, size, &eps), PROJCURVE_ERR_OUT_OF_RANGE);
    projcurve_context_destroy(ctx);
}

int main(void)
{
    test_defaults();
    test_distance_tolerance();
    return pc_test_finish("test_common_params");
}
