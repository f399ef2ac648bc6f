/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The patch BVH of a long strip: a bilinear plane z = 0 over x in [0, 100],
 * y in [0, 1], of 80,000 x 2 patches. Its patches are listed row by row,
 * two runs already sorted along x, on which the median selection's middle
 * pivot is the smallest centre and each quickselect round removed one
 * patch: 40,000 patches took 2.3 s to build, 80,000 about 9 s. Now 0.44 s
 * (the range is sorted after PC_BVH_SELECT_ROUNDS rounds); the hang guard
 * of 3 s (times PC_TEST_SLOWDOWN) fails the quadratic build. The tree is
 * then checked through its queries: vertical lines at 200 pseudo-random
 * (x, y) each hit the strip once, at (u, v) = (x / 100, y) to 1e-12, and
 * lines beside the strip miss it.
 */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "projcurve.h"

#define SPANS 80000

int main(void)
{
    pc_test_hang_guard(3);
    const size_t nu = SPANS + 1, nv = 3;
    double *ctrl = malloc(3 * nu * nv * sizeof *ctrl), *ku = malloc((nu + 2) * sizeof *ku);
    const double kv[5] = {0.0, 0.0, 0.5, 1.0, 1.0};
    CHECK(ctrl != NULL && ku != NULL);
    if (ctrl == NULL || ku == NULL)
        return pc_test_finish("test_bezier_bvh_strip");
    for (size_t j = 0; j < nv; ++j)
        for (size_t i = 0; i < nu; ++i) {
            double *p = ctrl + 3 * (j * nu + i);
            p[0] = 100.0 * (double)i / SPANS, p[1] = 0.5 * (double)j, p[2] = 0.0;
        }
    ku[0] = 0.0;
    for (size_t i = 0; i < nu; ++i)
        ku[i + 1] = (double)i / SPANS;
    ku[nu + 1] = 1.0;
    projcurve_surface *s = NULL;
    CHECK_OK(projcurve_surface_create_nurbs(NULL, 1, 1, nu, nv, ctrl, NULL, ku, kv, &s));
    free(ctrl);
    free(ku);
    if (s == NULL)
        return pc_test_finish("test_bezier_bvh_strip");
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 2026);
    const double down[3] = {0.0, 0.0, -1.0};
    int wrong = 0;
    for (int k = 0; k < 200; ++k) {
        const double x = pc_test_rng_uniform(&rng, 0.001, 99.999);
        const double y = pc_test_rng_uniform(&rng, 0.001, 0.999);
        const double origin[3] = {x, y, 1.0};
        double hit[3 * 4];
        size_t count = 0;
        CHECK_OK(projcurve_surface_intersect_line(NULL, s, origin, down, 1, 4, hit, NULL, &count));
        wrong += count != 1 || !(fabs(hit[0] - x / 100.0) <= 1e-12) || !(fabs(hit[1] - y) <= 1e-12);
        const double beside[3] = {x, y + 2.0, 1.0};
        CHECK_OK(projcurve_surface_intersect_line(NULL, s, beside, down, 1, 4, hit, NULL, &count));
        wrong += count != 0;
    }
    CHECK(wrong == 0);
    projcurve_surface_destroy(s);
    return pc_test_finish("test_bezier_bvh_strip");
}
