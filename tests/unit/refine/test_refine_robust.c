/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Tolerance control where the exact projection cannot be followed
 * everywhere: bumpy sheets folded over themselves seen from slanted
 * directions (the random configurations of test_trace_random, composed),
 * where traced branches end on silhouettes (|det J| -> 0) and a traced step
 * may land on another sheet across a fold; and a curve whose projection
 * touches the silhouette of a sphere.
 *
 * Facts checked, by the oracle projector of tests/support/piece_oracle
 * (its own Newton, independent of the library): the projection ends with
 * OK (never the piece limit), every composed piece starts and ends on the
 * exact projection (the residual of the projection equation at its (u, v)
 * ends is below 1e-9 of the model size: no vertex replaced by a point off
 * the projection), consecutive pieces of a branch join and meet within
 * eps_T, the piece count stays that of a smooth curve of this length
 * (below PIECES_MAX, where the default limit is 50,000), and every composed
 * branch is within eps_D of the exact projection: the Hausdorff distance
 * both ways on dense samples, each output sample projected onto the exact
 * curve by the oracle's Newton on t (pc_oracle_measure_result).
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "piece_oracle.h"
#include "shapes.h"
#include "trace_shapes.h"

#define EPS_D_REL 1e-3
#define EPS_T_DEG 1.0
#define END_RESIDUAL_REL 1e-9
/* The smooth configurations of the same family need 500-4,000 pieces. */
#define PIECES_MAX 20000

/* Angle between the end tangent of a and the start tangent of b (Bezier
 * end tangents lie along the first and last control point differences,
 * rational or not), degrees. */
static double joint_angle_deg(const pc_piece *a, const pc_piece *b)
{
    const int n = a->degree;
    pc_vec3 ta = vec3(0, 0, 0), tb = vec3(0, 0, 0);
    for (int k = n - 1; k >= 0 && !(vec3_norm(ta) > 0.0); --k)
        ta = vec3_sub(vec3_load(a->ctrl + 3 * n), vec3_load(a->ctrl + 3 * k));
    for (int k = 1; k <= b->degree && !(vec3_norm(tb) > 0.0); ++k)
        tb = vec3_sub(vec3_load(b->ctrl + 3 * k), vec3_load(b->ctrl));
    if (!(vec3_norm(ta) > 0.0) || !(vec3_norm(tb) > 0.0))
        return 0.0;
    return atan2(vec3_norm(vec3_cross(ta, tb)), vec3_dot(ta, tb)) * 180.0 / 3.14159265358979323846;
}

static void check_result(const char *name, const projcurve_surface *s, const projcurve_curve *c,
                         const double dir[3])
{
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE,
                                          EPS_D_REL * s->size));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_ANGLE_DEG, EPS_T_DEG));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, dir, o, &r));
    projcurve_options_destroy(o);
    if (r == NULL)
        return;
    pc_oracle_dir d;
    pc_projector proj;
    pc_oracle_projector(s, c, dir, &d, &proj);
    double worst_residual = 0.0, worst_angle = 0.0, worst_gap = 0.0;
    size_t pieces = 0, silhouette_ends = 0;
    for (size_t i = 0; i < r->n_branches; ++i) {
        const pc_branch *b = &r->branches[i];
        silhouette_ends += b->end == PROJCURVE_END_SILHOUETTE;
        pieces += b->n_pieces;
        for (size_t k = 0; k < b->n_pieces; ++k) {
            const pc_piece *pc = &b->pieces[k];
            worst_residual = fmax(worst_residual, proj.residual(&proj, pc->t0, pc->uv[0], pc->uv[1]));
            worst_residual = fmax(worst_residual, proj.residual(&proj, pc->t1, pc->uv[2], pc->uv[3]));
        }
        for (size_t k = 0; k + 1 < b->n_pieces; ++k) {
            worst_angle = fmax(worst_angle, joint_angle_deg(&b->pieces[k], &b->pieces[k + 1]));
            const int n = b->pieces[k].degree;
            worst_gap = fmax(worst_gap, vec3_dist(vec3_load(b->pieces[k].ctrl + 3 * n),
                                                  vec3_load(b->pieces[k + 1].ctrl)));
        }
    }
    pc_oracle_summary sum;
    pc_oracle_measure_result(r, &proj, NULL, &sum);
    printf("%-28s %2zu branches (%zu end on a silhouette), %5zu pieces, piece ends off the "
           "projection by <= %.2g, Hausdorff %.2f eps_D (%d exact points next to folds to "
           "1e-9 only)\n",
           name, r->n_branches, silhouette_ends, pieces, worst_residual,
           sum.worst.hausdorff / (EPS_D_REL * s->size), sum.loose_points);
    CHECK(sum.failures == 0);
    CHECK(sum.worst.hausdorff <= EPS_D_REL * s->size);
    CHECK(pieces > 0);
    CHECK(pieces < PIECES_MAX);
    CHECK(worst_residual <= END_RESIDUAL_REL * s->size);
    CHECK(worst_angle <= EPS_T_DEG * (1.0 + 1e-9));
    CHECK(worst_gap <= 1e-12 * s->size);
    projcurve_result_destroy(r);
}

/* Configurations 0 and 3 of test_trace_random (same generator and seed):
 * folds seen at a slant, with traced steps across a fold. */
static void test_folded_slanted(void)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 20131);
    for (int k = 0; k < 4; ++k) {
        const double amp = pc_test_rng_uniform(&rng, 0.1, 1.5);
        pc_shape_surface arrays = pc_shape_bumpy(500 + (unsigned long long)k, 4, 4, amp, k % 3 == 0);
        projcurve_surface *s = pc_shape_surface_create(&arrays);
        pc_shape_surface_free(&arrays);
        const double d[3] = {pc_test_rng_uniform(&rng, -1.5, 1.5),
                             pc_test_rng_uniform(&rng, -1.5, 1.5), -1.0};
        double pts[18];
        for (int i = 0; i < 6; ++i) {
            const double z = pc_test_rng_uniform(&rng, 3.0, 5.0);
            pts[3 * i + 0] = pc_test_rng_uniform(&rng, -0.3, 1.3) - d[0] * z;
            pts[3 * i + 1] = pc_test_rng_uniform(&rng, -0.3, 1.3) - d[1] * z;
            pts[3 * i + 2] = z;
        }
        projcurve_curve *c = shape_bspline_curve(3, 6, pts);
        CHECK(s != NULL && c != NULL);
        if (s != NULL && c != NULL && (k == 0 || k == 3)) {
            char name[64];
            snprintf(name, sizeof name, "folded, slanted (case %d)", k);
            check_result(name, s, c, d);
        }
        projcurve_curve_destroy(c);
        projcurve_surface_destroy(s);
    }
}

/* The parabola y = 10 - x^2 / 10 at z = 20 touches the equator of the
 * sphere of radius 10 at x = 0 from inside: seen along -z, its projection
 * reaches the silhouette there (det J = 0) and turns back up. */
static void test_touching_silhouette(void)
{
    const double parabola[9] = {-5, 7.5, 20, 0, 12.5, 20, 5, 7.5, 20};
    const double down[3] = {0, 0, -1};
    projcurve_surface *s = shape_sphere(10.0);
    projcurve_curve *c = shape_bspline_curve(2, 3, parabola);
    CHECK(s != NULL && c != NULL);
    if (s != NULL && c != NULL)
        check_result("touching a silhouette", s, c, down);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

int main(void)
{
    test_folded_slanted();
    test_touching_silhouette();
    return pc_test_finish("test_refine_robust");
}
