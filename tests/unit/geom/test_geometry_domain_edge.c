/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Every point of a returned pcurve can be evaluated on S. linkrods.step
 * curve 89 projected along (0, 0, -1) onto surface 6 gives 4 branches whose
 * pcurves run along the edge v = vmax of the domain; a point of one,
 * (1 - s) a + s b with a and b on the edge, rounds an ulp outside (v =
 * -0.0031420979018159994 for vmax = -0.0031420979018159999), and
 * projcurve_surface_eval refused it (OUT_OF_DOMAIN; the real-data sweep
 * counted accessor failures). Within rounding of the domain a parameter is
 * on its edge; farther out it is still refused.
 */
#include <stdio.h>

#include "check.h"

/* samples per piece: finer than any caller needs, so that rounding of the
 * convex combination shows */
#define SAMPLES 64

int main(void)
{
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/linkrods.step"), &m) !=
        PROJCURVE_OK)
        pc_test_missing_data("real/linkrods.step");
    const projcurve_surface *s = projcurve_model_surface(m, 6);
    const projcurve_curve *c = projcurve_model_curve(m, 89);
    CHECK(s != NULL && c != NULL);
    const double dir[3] = {0, 0, -1};
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, dir, NULL, &r));
    CHECK(projcurve_result_branch_count(r) > 0);
    size_t samples = 0, refused = 0;
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        size_t n_pieces = 0;
        CHECK_OK(projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, NULL, &n_pieces));
        for (size_t k = 0; k < n_pieces; ++k) {
            int degree = 0;
            double uv[2 * PROJCURVE_MAX_PCURVE_POINTS];
            CHECK_OK(projcurve_result_piece_pcurve(NULL, r, b, k, &degree, uv));
            for (int i = 0; i <= SAMPLES; ++i) {
                /* de Casteljau, as a caller evaluates a Bezier pcurve */
                const double t = (double)i / SAMPLES;
                double w[2 * PROJCURVE_MAX_PCURVE_POINTS];
                for (int j = 0; j < 2 * (degree + 1); ++j)
                    w[j] = uv[j];
                for (int q = 1; q <= degree; ++q)
                    for (int j = 0; j <= degree - q; ++j)
                        for (int a = 0; a < 2; ++a)
                            w[2 * j + a] = (1.0 - t) * w[2 * j + a] + t * w[2 * (j + 1) + a];
                double f[9];
                ++samples;
                refused += projcurve_surface_eval(NULL, s, w[0], w[1], 1, f) != PROJCURVE_OK;
            }
        }
    }
    printf("linkrods.step curve 89 / surface 6: %zu pcurve samples, %zu refused\n", samples,
           refused);
    CHECK(refused == 0);
    /* a parameter really outside is still refused */
    double dom[4], f[3];
    CHECK_OK(projcurve_surface_domain(NULL, s, dom));
    CHECK(projcurve_surface_eval(NULL, s, 0.5 * (dom[0] + dom[1]), dom[3] + 1e-9, 0, f) ==
          PROJCURVE_ERR_OUT_OF_DOMAIN);
    projcurve_result_destroy(r);
    projcurve_model_destroy(m);
    return pc_test_finish("test_geometry_domain_edge");
}
