/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A knot that is C0 by its multiplicity only: linkrods.step curve 92 is a
 * rational quadratic circle (9 control points, double knots at every
 * quarter, where P' keeps its direction), projected orthogonally onto
 * surface 9, a tube that folds onto itself (its v lines reverse). When the
 * refinement took those knots for corners of P (fixed vertices, one-sided
 * tangents by differences), its runs changed and the part of the
 * projection after t ~ 5.5 was lost: the real-data sweep (cases #4720 and
 * #4756) found the foot point of P(5.596) 25 eps_D from every piece. Checked
 * here with the sweep's own verifier (support/sweep_verify.c) and its mesh:
 * every local foot point found by brute force at 32 evenly spaced t lies
 * within eps_D of a piece, and every piece sample within eps_D of the exact
 * projection.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "ray_oracle.h"
#include "sweep_verify.h"

#define SURFACE 9
#define CURVE 92

int main(void)
{
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/linkrods.step"), &m) !=
        PROJCURVE_OK)
        pc_test_missing_data("real/linkrods.step");
    const projcurve_surface *s = projcurve_model_surface(m, SURFACE);
    const projcurve_curve *c = projcurve_model_curve(m, CURVE);
    double dom[4], box[6], eps_d = 0.0;
    projcurve_surface_domain(NULL, s, dom);
    projcurve_surface_bounds(NULL, s, box);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, NULL, &r));
    projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &eps_d);
    size_t su = 1, sv = 1;
    projcurve_surface_info(NULL, s, NULL, NULL, NULL, NULL, &su, &sv, NULL);
    /* The sweep's mesh: 8 cells per span, 48 to 256 per side. */
    const int cu = pc_sweep_mesh_cells(su);
    const int cv = pc_sweep_mesh_cells(sv);
    pc_oracle_mesh mesh;
    CHECK(pc_oracle_mesh_build(&mesh, pc_sweep_surface_eval, (void *)s, dom, cu, cv));
    double diag = 0.0;
    for (int k = 0; k < 3; ++k)
        diag += (box[k + 3] - box[k]) * (box[k + 3] - box[k]);
    const pc_sweep_input in = {s, c, 1, {0, 0, 0}, &mesh, eps_d, sqrt(diag), 2.0 * eps_d, 32,
                               40000};
    pc_sweep_report rep;
    pc_sweep_verify(&in, r, &rep);
    printf("sweep verifier: %zu pieces, %zu samples (far %zu); %zu foot points, %zu missed "
           "(first at t %g, %.3g eps_D)\n",
           rep.pieces, rep.samples, rep.far_from_exact, rep.oracle_points, rep.missed,
           rep.missed_t, rep.worst_missed);
    CHECK(rep.samples > 0);
    CHECK(rep.oracle_points > 0);
    CHECK(rep.missed == 0);
    CHECK(rep.far_from_exact == 0);
    CHECK(rep.off_projection == 0);
    CHECK(rep.accessor_failures == 0);
    pc_oracle_mesh_free(&mesh);
    projcurve_result_destroy(r);
    projcurve_model_destroy(m);
    return pc_test_finish("test_refine_corners_real");
}
