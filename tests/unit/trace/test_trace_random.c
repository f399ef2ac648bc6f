/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Random configurations: bumpy bicubic surfaces (polynomial and rational)
 * with folds seen from slanted directions, random cubic curves whose rays
 * land on and off the surface. Dense brute force must find no branch the
 * tracer missed, and every vertex must satisfy the projection equation.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "shapes.h"
#include "trace_oracle.h"
#include "trace_shapes.h"

#define N_CASES 16
#define N_SAMPLES 1500
#define RESIDUAL_TOL 1e-9

int main(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 20131);
    for (int k = 0; k < N_CASES; ++k) {
        const double amp = pc_test_rng_uniform(&rng, 0.1, 1.5);
        pc_shape_surface arrays = pc_shape_bumpy(500 + (unsigned long long)k, 4, 4, amp, k % 3 == 0);
        projcurve_surface *s = pc_shape_surface_create(&arrays);
        pc_shape_surface_free(&arrays);
        const double d[3] = {pc_test_rng_uniform(&rng, -1.5, 1.5),
                             pc_test_rng_uniform(&rng, -1.5, 1.5), -1.0};
        /* control points whose rays land in [-0.3, 1.3]^2 around the
         * surface's domain [0, 1]^2 (x = u, y = v) */
        double pts[18];
        for (int i = 0; i < 6; ++i) {
            const double z = pc_test_rng_uniform(&rng, 3.0, 5.0);
            pts[3 * i + 0] = pc_test_rng_uniform(&rng, -0.3, 1.3) - d[0] * z;
            pts[3 * i + 1] = pc_test_rng_uniform(&rng, -0.3, 1.3) - d[1] * z;
            pts[3 * i + 2] = z;
        }
        projcurve_curve *c = shape_bspline_curve(3, 6, pts);
        CHECK(s != NULL && c != NULL);
        projcurve_options *o = NULL;
        projcurve_options_create(NULL, &o);
        projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0);
        projcurve_result *r = NULL;
        CHECK_OK(projcurve_project_directional(NULL, s, c, d, o, &r));
        trace_oracle_report rep;
        trace_oracle_check(s, c, d, r, N_SAMPLES, &rep);
        char name[64];
        snprintf(name, sizeof name, "case %d (%zu branches)", k, projcurve_result_branch_count(r));
        trace_oracle_print(name, &rep);
        /* a branch born and gone within two steps may be missed (it falls
         * between the sweep's checks); nothing longer */
        CHECK(!trace_oracle_missed_branch(&rep));
        CHECK(rep.max_residual <= RESIDUAL_TOL);
        CHECK(rep.behind == 0);
        projcurve_result_destroy(r);
        projcurve_options_destroy(o);
        projcurve_curve_destroy(c);
        projcurve_surface_destroy(s);
    }
    return pc_test_finish("test_trace_random");
}
