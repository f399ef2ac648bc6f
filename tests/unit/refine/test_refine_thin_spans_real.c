/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Knot lines the projection cannot be followed across: linkrods.step
 * surface 16 (degree 6 x 10, rational) has in v ~ -3.6128 a run of 26
 * spans of width down to ~1.8e-8 between two C0 knots, whose nets
 * rounding blew up: their image loops ~0.2 away from the neighbouring
 * spans. The orthogonal projections of curves 26 and 87 run across them;
 * the tracer steps over the run in one segment, whose knot crossings the
 * corrector cannot reach inside it. The refinement made that whole traced
 * segment a gap, and the foot points on either side of the run (0.1 of t
 * for curve 26) were lost: the real-data sweep found the foot point of
 * P(1.27627) 3.25 eps_D (curve 87: 7.17 eps_D) from every piece. Checked
 * with the sweep's own verifier and mesh (support/sweep_verify.c): every
 * local foot point found by brute force at 32 evenly spaced t lies within
 * eps_D of a piece, every piece sample within eps_D of the exact
 * projection.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "ray_oracle.h"
#include "sweep_verify.h"

#define SURFACE 16

static void check_curve(const projcurve_model *m, const pc_oracle_mesh *mesh, size_t curve)
{
    const projcurve_surface *s = projcurve_model_surface(m, SURFACE);
    const projcurve_curve *c = projcurve_model_curve(m, curve);
    double box[6], eps_d = 0.0, diag = 0.0;
    projcurve_surface_bounds(NULL, s, box);
    for (int k = 0; k < 3; ++k)
        diag += (box[k + 3] - box[k]) * (box[k + 3] - box[k]);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, NULL, &r));
    projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &eps_d);
    const pc_sweep_input in = {s, c, 1, {0, 0, 0}, mesh, eps_d, sqrt(diag), 2.0 * eps_d, 32,
                               40000};
    pc_sweep_report rep;
    pc_sweep_verify(&in, r, &rep);
    printf("curve %zu: %zu pieces, %zu samples (far %zu); %zu foot points, %zu missed "
           "(first at t %g, %.3g eps_D)\n",
           curve, rep.pieces, rep.samples, rep.far_from_exact, rep.oracle_points, rep.missed,
           rep.missed_t, rep.worst_missed);
    CHECK(rep.samples > 0);
    CHECK(rep.oracle_points > 0);
    CHECK(rep.missed == 0);
    CHECK(rep.far_from_exact == 0);
    CHECK(rep.off_projection == 0);
    CHECK(rep.accessor_failures == 0);
    projcurve_result_destroy(r);
}

int main(void)
{
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/linkrods.step"), &m) !=
        PROJCURVE_OK)
        pc_test_missing_data("real/linkrods.step");
    const projcurve_surface *s = projcurve_model_surface(m, SURFACE);
    double dom[4];
    size_t su = 1, sv = 1;
    projcurve_surface_domain(NULL, s, dom);
    projcurve_surface_info(NULL, s, NULL, NULL, NULL, NULL, &su, &sv, NULL);
    pc_oracle_mesh mesh;
    CHECK(pc_oracle_mesh_build(&mesh, pc_sweep_surface_eval, (void *)s, dom, pc_sweep_mesh_cells(su),
                               pc_sweep_mesh_cells(sv)));
    check_curve(m, &mesh, 26);
    check_curve(m, &mesh, 87);
    pc_oracle_mesh_free(&mesh);
    projcurve_model_destroy(m);
    return pc_test_finish("test_refine_thin_spans_real");
}
