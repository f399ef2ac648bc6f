/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A pleated surface seen along Dir: linkrods.step surface 11 is a fillet
 * whose parametrisation folds in v inside its last span (Sv vanishes and
 * reverses at v ~ -0.0270, -0.0215 and -0.0124 for u ~ -1.28), so S
 * doubles back on itself in a pleat of three layers 1e-5 to 1e-4 apart (eps_D
 * is 7.4e-5). The circles curves 78 and 79 (z = 1.34993) projected along
 * (0, 0, -1) meet it for t in [0.6, 1.95]; for t in [1.659, 1.739] each ray
 * meets all three layers, born and gone at the cusps of the
 * parametrisation, where the normalised det J jumps from about -0.33 to
 * +0.32 without passing 0. (Over t in [0.950, 1.036] the same three
 * layers are met in the other order.)
 *
 * Each layer is a branch ending on the cusps where it meets the next, as
 * at a fold (docs/tracing.md, "Pleats"): five branches, none FAILED, and
 * as many alive inside each pleat as the rays meet layers. The layers lie
 * closer to each other than eps_D, so the ray-hit completeness check below
 * takes a hit on a layer nobody traced as covered by the layer next to it;
 * hence the count of branches alive against the count of independent ray
 * hits at t inside the pleats. (Before the tracer knew cusps, a step of
 * 0.094 in t passed a pleat onto the layer beyond the next: 9 branches, 8
 * ending or starting FAILED, two alive where three layers are.)
 *
 * What must hold in any case (issue 14: no silent wrong answer, no missed
 * branch): every returned piece is verified, and whatever ray hit the
 * pieces do not cover is reported by projcurve_result_failure_count.
 * Checked with the real-data sweep's own verifier and its mesh
 * (support/sweep_verify.c): independent ray/mesh hits at evenly spaced t
 * against the pieces, and every piece sample against the exact
 * projection. The geometry is checked too: Sv reverses across each cusp.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "ray_oracle.h"
#include "sweep_verify.h"

#define SURFACE 11
/* t samples of the completeness check (the sweep takes 32); fewer in the
 * slow builds */
#define SAMPLES (256 / PC_TEST_SLOWDOWN > 32 ? 256 / PC_TEST_SLOWDOWN : 32)

/* Sv at (u, v) reverses between v0 and v1: the cusp of a folded v line. */
static int sv_reverses(const projcurve_surface *s, double u, double v0, double v1)
{
    double a[9], b[9];
    CHECK_OK(projcurve_surface_eval(NULL, s, u, v0, 1, a));
    CHECK_OK(projcurve_surface_eval(NULL, s, u, v1, 1, b));
    return a[6] * b[6] + a[7] * b[7] + a[8] * b[8] < 0.0;
}

static void check_curve(const projcurve_model *m, const pc_oracle_mesh *mesh,
                        const pc_oracle_mesh *band, double size, size_t curve)
{
    const projcurve_surface *s = projcurve_model_surface(m, SURFACE);
    const projcurve_curve *c = projcurve_model_curve(m, curve);
    const double dir[3] = {0, 0, -1};
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, dir, NULL, &r));
    double eps_d = 0.0;
    projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &eps_d);
    const pc_sweep_input in = {s, c, 0, {0, 0, -1}, mesh, eps_d, size, 2.0 * eps_d, SAMPLES,
                               40000};
    pc_sweep_report rep;
    pc_sweep_verify(&in, r, &rep);
    const size_t failures = projcurve_result_failure_count(r);
    printf("curve %zu: %zu branches, %zu pieces, %zu failures; %zu samples (far %zu, off %zu); "
           "%zu ray hits, %zu missed (first at t %g, %.3g eps_D)\n",
           curve, rep.branches, rep.pieces, failures, rep.samples, rep.far_from_exact,
           rep.off_projection, rep.oracle_points, rep.missed, rep.missed_t, rep.worst_missed);
    /* soundness: what is returned is verified */
    CHECK(rep.samples > 0);
    CHECK(rep.pieces_skipped == 0);
    CHECK(rep.off_surface == 0);
    CHECK(rep.off_projection == 0);
    CHECK(rep.far_from_exact == 0);
    CHECK(rep.accessor_failures == 0);
    CHECK((long)rep.failed_ends <= (long)failures);
    /* completeness: a hit left uncovered is reported, never silent; and
     * here there is none, nothing is left to report */
    CHECK(rep.oracle_points > 0);
    CHECK(rep.missed == 0 || failures > 0);
    CHECK(rep.missed == 0);
    CHECK(rep.point_image_points == 0);
    CHECK(failures == 0);
    /* every layer followed: as many branches alive as layers met */
    const size_t nb = projcurve_result_branch_count(r);
    CHECK(nb == 5);
    for (size_t b = 0; b < nb; ++b) {
        projcurve_branch_start start;
        projcurve_branch_end end;
        CHECK_OK(projcurve_result_branch_info(NULL, r, b, NULL, &start, &end, NULL, NULL));
        CHECK(start != PROJCURVE_START_FAILED && end != PROJCURVE_END_FAILED);
    }
    static const struct { double t; size_t layers; } k_inside[] = {
        {0.99, 3}, {1.30, 1}, {1.70, 3}};
    for (size_t k = 0; k < sizeof k_inside / sizeof k_inside[0]; ++k) {
        const double t = k_inside[k].t;
        double p[3];
        pc_oracle_hit hits[32];
        CHECK_OK(projcurve_curve_eval(NULL, c, t, 0, p));
        const size_t n_all = pc_oracle_line_hits(band, p, dir, 1, hits, 32);
        /* as the verifier counts them: the curve also runs along the
         * surface's edge v1, where S is vertical (every ray grazes it
         * within 1e-6 of P), which neither counts */
        const double grazing = sin(PC_VERIFY_GRAZING_DEG * 3.14159265358979323846 / 180.0);
        size_t n_hits = 0;
        for (size_t i = 0; i < n_all && i < 32; ++i)
            n_hits += hits[i].lambda >= in.lambda_min && hits[i].cos_dir >= grazing;
        size_t alive = 0;
        for (size_t b = 0; b < nb; ++b) {
            double range[2];
            CHECK_OK(projcurve_result_branch_info(NULL, r, b, range, NULL, NULL, NULL, NULL));
            alive += range[0] <= t && t <= range[1];
        }
        if (n_hits != k_inside[k].layers || alive != n_hits)
            printf("curve %zu, t %g: %zu layers expected, %zu ray hits, %zu branches alive\n",
                   curve, t, k_inside[k].layers, n_hits, alive);
        CHECK(n_hits == k_inside[k].layers);
        CHECK(alive == n_hits);
    }
    projcurve_result_destroy(r);
}

int main(void)
{
    pc_test_hang_guard(60);
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/linkrods.step"), &m) !=
        PROJCURVE_OK)
        pc_test_missing_data("real/linkrods.step");
    const projcurve_surface *s = projcurve_model_surface(m, SURFACE);
    /* the pleat: three cusps of the v line at u = -1.28 */
    CHECK(sv_reverses(s, -1.28, -0.0280, -0.0260));
    CHECK(sv_reverses(s, -1.28, -0.0225, -0.0205));
    CHECK(sv_reverses(s, -1.28, -0.0134, -0.0114));
    double dom[4], box[6];
    projcurve_surface_domain(NULL, s, dom);
    projcurve_surface_bounds(NULL, s, box);
    size_t su = 1, sv = 1;
    projcurve_surface_info(NULL, s, NULL, NULL, NULL, NULL, &su, &sv, NULL);
    /* the sweep's mesh: 8 cells per span, 48 to 256 per side */
    const int cu = pc_sweep_mesh_cells(su);
    const int cv = pc_sweep_mesh_cells(sv);
    pc_oracle_mesh mesh;
    CHECK(pc_oracle_mesh_build(&mesh, pc_sweep_surface_eval, (void *)s, dom, cu, cv));
    double diag = 0.0;
    for (int k = 0; k < 3; ++k)
        diag += (box[k + 3] - box[k]) * (box[k + 3] - box[k]);
    /* The layers, 1e-5 apart, are resolved by a mesh of the band of the
     * pleat only (v in [-0.04, v1], cells 1.4e-4 in v; the sweep's mesh
     * of 256 x 256 cells over the domain sees two of the three at t =
     * 0.99); every hit of the three curve points lies in it (the rays meet
     * S nowhere else: 1 or 3 hits by projcurve_surface_intersect_line). */
    const double band_dom[4] = {dom[0], dom[1], -0.04, dom[3]};
    pc_oracle_mesh band;
    CHECK(pc_oracle_mesh_build(&band, pc_sweep_surface_eval, (void *)s, band_dom, 256, 256));
    check_curve(m, &mesh, &band, sqrt(diag), 78);
    check_curve(m, &mesh, &band, sqrt(diag), 79);
    pc_oracle_mesh_free(&band);
    pc_oracle_mesh_free(&mesh);
    projcurve_model_destroy(m);
    return pc_test_finish("test_trace_pleat_real");
}
