/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Branch ends on a crease (a knot line where S is only C0): the vertex
 * there is a foot point of the patch its piece lies in, with that patch's
 * one-sided derivatives; measured with the other patch's it is not.
 *  - linkrods.step surface 9 (every knot in v of multiplicity = degree),
 *    curve 69, orthogonal: the branch of minima starts on the crease
 *    v = -0.2789 at t = 0.0609 (residual 4e-4 with the other patch's
 *    normal, 6e-15 with its own); the verification dropped its only piece
 *    and the call returned OK with 0 branches.
 *  - test_pipe_out_true.step surface 0 (bilinear, 30 x 30 facets: every
 *    knot a crease), curves 0 and 2, orthogonal: pieces ending on facet
 *    edges were cut off the same way.
 * Checked with the sweep's own verifier and mesh (support/sweep_verify.c),
 * which samples piece ends on their piece's side too: every local foot
 * point found by brute force at 32 evenly spaced t lies within eps_D of a
 * piece, every piece sample within eps_D of the exact projection.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "ray_oracle.h"
#include "sweep_verify.h"

static void check_pair(const char *file, size_t surface, size_t curve)
{
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path(file), &m) != PROJCURVE_OK) {
        pc_test_missing_data(file);
        return;
    }
    const projcurve_surface *s = projcurve_model_surface(m, surface);
    const projcurve_curve *c = projcurve_model_curve(m, curve);
    double dom[4], box[6], eps_d = 0.0, diag = 0.0;
    size_t su = 1, sv = 1;
    projcurve_surface_domain(NULL, s, dom);
    projcurve_surface_bounds(NULL, s, box);
    projcurve_surface_info(NULL, s, NULL, NULL, NULL, NULL, &su, &sv, NULL);
    for (int k = 0; k < 3; ++k)
        diag += (box[k + 3] - box[k]) * (box[k + 3] - box[k]);
    pc_oracle_mesh mesh;
    CHECK(pc_oracle_mesh_build(&mesh, pc_sweep_surface_eval, (void *)s, dom, pc_sweep_mesh_cells(su),
                               pc_sweep_mesh_cells(sv)));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, NULL, &r));
    projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &eps_d);
    const pc_sweep_input in = {s, c, 1, {0, 0, 0}, &mesh, eps_d, sqrt(diag), 2.0 * eps_d, 32,
                               40000};
    pc_sweep_report rep;
    pc_sweep_verify(&in, r, &rep);
    printf("%s surface %zu curve %zu: %zu branches, %zu pieces, %zu samples (far %zu); "
           "%zu foot points, %zu missed (first at t %g, %.3g eps_D)\n",
           file, surface, curve, projcurve_result_branch_count(r), rep.pieces, rep.samples,
           rep.far_from_exact, rep.oracle_points, rep.missed, rep.missed_t, rep.worst_missed);
    CHECK(projcurve_result_branch_count(r) > 0);
    CHECK(rep.samples > 0);
    CHECK(rep.oracle_points > 0);
    CHECK(rep.missed == 0);
    CHECK(rep.far_from_exact == 0);
    CHECK(rep.off_projection == 0);
    CHECK(rep.accessor_failures == 0);
    projcurve_result_destroy(r);
    pc_oracle_mesh_free(&mesh);
    projcurve_model_destroy(m);
}

int main(void)
{
    check_pair("real/linkrods.step", 9, 69);
    check_pair("real/test_pipe_out_true.step", 0, 0);
    check_pair("real/test_pipe_out_true.step", 0, 2);
    return pc_test_finish("test_verify_crease_real");
}
