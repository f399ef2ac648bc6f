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
 * The same split where the projection from one end stops before the line
 * (a fold): surface 9 (every knot in v a crease), curve 21, whose branch
 * from a centre of curvature at t = 2.6158 folds at t = 2.6263 beside the
 * crease v = -0.1466 while the next sheet reaches it from the crease
 * v = -0.1742; the traced segment between them was a gap whole, and the
 * foot point of P(2.65072) lay 114 eps_D from every piece.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "ray_oracle.h"
#include "sweep_verify.h"

static void oracle_eval(void *user, double u, double v, int n_deriv, double out[9])
{
    if (projcurve_surface_eval(NULL, user, u, v, n_deriv, out) != PROJCURVE_OK)
        for (int k = 0; k < 9; ++k)
            out[k] = NAN;
}

/* The sweep's mesh: 8 cells per span, 48 to 256 per side. */
static int mesh_cells(size_t spans)
{
    return spans * 8 < 48 ? 48 : (spans * 8 > 256 ? 256 : (int)spans * 8);
}

static void check_pair(const projcurve_model *m, size_t surface, size_t curve)
{
    const projcurve_surface *s = projcurve_model_surface(m, surface);
    const projcurve_curve *c = projcurve_model_curve(m, curve);
    double dom[4], box[6], eps_d = 0.0, diag = 0.0;
    size_t su = 1, sv = 1;
    projcurve_surface_domain(NULL, s, dom);
    projcurve_surface_info(NULL, s, NULL, NULL, NULL, NULL, &su, &sv, NULL);
    pc_oracle_mesh mesh;
    CHECK(pc_oracle_mesh_build(&mesh, oracle_eval, (void *)s, dom, mesh_cells(su),
                               mesh_cells(sv)));
    projcurve_surface_bounds(NULL, s, box);
    for (int k = 0; k < 3; ++k)
        diag += (box[k + 3] - box[k]) * (box[k + 3] - box[k]);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, NULL, &r));
    projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &eps_d);
    const pc_sweep_input in = {s, c, 1, {0, 0, 0}, &mesh, eps_d, sqrt(diag), 2.0 * eps_d, 32,
                               40000};
    pc_sweep_report rep;
    pc_sweep_verify(&in, r, &rep);
    printf("surface %zu curve %zu: %zu pieces, %zu samples (far %zu); %zu foot points, %zu missed "
           "(first at t %g, %.3g eps_D)\n",
           surface, curve, rep.pieces, rep.samples, rep.far_from_exact, rep.oracle_points, rep.missed,
           rep.missed_t, rep.worst_missed);
    CHECK(rep.samples > 0);
    CHECK(rep.oracle_points > 0);
    CHECK(rep.missed == 0);
    CHECK(rep.far_from_exact == 0);
    CHECK(rep.off_projection == 0);
    CHECK(rep.accessor_failures == 0);
    projcurve_result_destroy(r);
    pc_oracle_mesh_free(&mesh);
}

int main(void)
{
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/linkrods.step"), &m) !=
        PROJCURVE_OK)
        pc_test_missing_data("real/linkrods.step");
    check_pair(m, 16, 26);
    check_pair(m, 16, 87);
    check_pair(m, 9, 21);
    projcurve_model_destroy(m);
    return pc_test_finish("test_refine_thin_spans_real");
}
