/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Tolerance control end to end on the shapes of the tracing tests
 * (tests/support/trace_shapes): a plane seen along a slanted direction, the
 * exact rational half cylinder, a sphere whose two branches are born and end
 * on the silhouette (Dir tangent to S, det J -> 0), a line over the sphere's
 * pole (a collapsed edge, Su = 0), a rational bumpy sheet, the paper's
 * Example 1, the C-folded sheet over its flat parts, past the tip of its bend
 * and reversed (branches ending on, and born on, the silhouette), the
 * Z-folded sheet met three times, and a bumpy sheet left and re-entered and
 * overrun at both ends (branches ending on the boundary). For eps_D = 1e-2,
 * 1e-3, 1e-4, 1e-5, 1e-6 of the model size at eps_T = 1 degree, and 1e-3 at
 * 10 degrees, with straight and cubic pcurves (PROJCURVE_OPT_PCURVE_DEGREE 1
 * and 3), every branch is measured by the oracles of
 * tests/support/piece_oracle (the exact projection by the oracle's own
 * Newton): Hausdorff distance both ways <= eps_D, joints <= eps_T, joins,
 * piece ends on the projection, one patch per piece; every piece, read
 * through the public accessors, equals S at its pcurve at 100 parameters
 * (tests/support/on_surface); and the branch as one NURBS curve handle
 * traces its pieces. Also: eps_D left unset is 1e-4 of the model size, and
 * the values the setter rejects leave it so.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "on_surface.h"
#include "piece_oracle.h"
#include "shapes.h"
#include "trace_shapes.h"

typedef struct shape_case {
    const char *name;
    projcurve_surface *surface;
    projcurve_curve *curve;
    double dir[3];
    size_t branches;
} shape_case;

/* The branch as one NURBS curve (projcurve_result_branch_curve) traces the
 * same points as its pieces: the piece over [t0, t1] at s is the curve at
 * t = t0 + s (t1 - t0). The piece is evaluated at the s of t as rounded
 * (t - t0 is exact): next to a fold a piece may span 1e-12 in t for 1e-5 in
 * length, and one ulp of t would move the point by 1e-9. */
static void check_branch_curves(const projcurve_result *r, double size)
{
    for (size_t i = 0; i < r->n_branches; ++i) {
        const pc_branch *b = &r->branches[i];
        projcurve_curve *joined = NULL;
        CHECK_OK(projcurve_result_branch_curve(NULL, r, i, &joined));
        if (joined == NULL)
            continue;
        double worst = 0.0;
        int eval_failures = 0;
        for (size_t k = 0; k < b->n_pieces; ++k) {
            const pc_piece *pc = &b->pieces[k];
            for (int j = 0; j <= 4; ++j) {
                const double t = pc->t0 + j / 4.0 * (pc->t1 - pc->t0);
                pc_vec3 x;
                double y[3];
                pc_oracle_piece_eval(pc, (t - pc->t0) / (pc->t1 - pc->t0), &x, NULL);
                eval_failures += projcurve_curve_eval(NULL, joined, t, 0, y) != PROJCURVE_OK;
                worst = fmax(worst, vec3_dist(x, vec3_load(y)));
            }
        }
        CHECK(eval_failures == 0);
        if (!(worst <= 1e-11 * size))
            fprintf(stderr, "branch %zu (%zu pieces): joined curve off its pieces by %.3g "
                            "(bound %.3g)\n",
                    i, b->n_pieces, worst, 1e-11 * size);
        CHECK(worst <= 1e-11 * size);
        projcurve_curve_destroy(joined);
    }
}

static void run(const shape_case *c, double rel_eps, double angle, int pcurve_degree)
{
    const projcurve_surface *s = c->surface;
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, rel_eps * s->size));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_ANGLE_DEG, angle));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_PCURVE_DEGREE, pcurve_degree));
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c->curve, c->dir, o, &r));
    projcurve_options_destroy(o);
    if (r == NULL)
        return;
    CHECK(projcurve_result_branch_count(r) == c->branches);
    pc_oracle_dir d;
    pc_projector proj;
    pc_oracle_projector(s, c->curve, c->dir, &d, &proj);
    pc_oracle_summary sum;
    pc_oracle_measure_result(r, &proj, &s->grid, &sum);
    const double off_surface = pc_on_surface_check(c->name, r, s, pcurve_degree);
    printf("%-26s pcurve %d eps_D %.0e eps_T %4.1f: %zu branches, %4zu pieces, Hausdorff "
           "%.2f eps_D, joints <= %.3f deg, on S to %.1e size\n",
           c->name, pcurve_degree, rel_eps, angle, projcurve_result_branch_count(r), sum.pieces,
           sum.worst.hausdorff / (rel_eps * s->size), sum.worst.max_angle, off_surface);
    CHECK(sum.branches_without_pieces == 0);
    CHECK(sum.failures == 0);
    CHECK(sum.loose_points == 0); /* the oracle's exact points to 1e-12 of the size */
    CHECK(sum.worst.hausdorff <= rel_eps * s->size);
    CHECK(sum.worst.max_angle <= angle * (1.0 + 1e-9));
    CHECK(sum.worst.max_gap <= 1e-12 * s->size);
    CHECK(sum.worst.max_end_err <= 1e-9 * s->size);
    CHECK(sum.worst.off_patch == 0);
    check_branch_curves(r, s->size);
    projcurve_result_destroy(r);
}

/* Model size as projcurve.h defines it: the diagonal of the bounding box. */
static double model_size(const projcurve_surface *s)
{
    double box[6] = {0, 0, 0, 0, 0, 0};
    CHECK_OK(projcurve_surface_bounds(NULL, s, box));
    return sqrt((box[3] - box[0]) * (box[3] - box[0]) + (box[4] - box[1]) * (box[4] - box[1]) +
                (box[5] - box[2]) * (box[5] - box[2]));
}

/* PROJCURVE_STAT_TOL_DISTANCE of a projection of c with o (NULL: defaults),
 * directional or orthogonal; NAN when it fails. Checks that the result is
 * within that eps_D of the exact projection. */
static double used_distance(const shape_case *c, const projcurve_options *o, int orthogonal)
{
    projcurve_result *r = NULL;
    const projcurve_status st =
        orthogonal ? projcurve_project_orthogonal(NULL, c->surface, c->curve, o, &r)
                   : projcurve_project_directional(NULL, c->surface, c->curve, c->dir, o, &r);
    CHECK_OK(st);
    double eps = NAN;
    if (r == NULL)
        return eps;
    CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &eps));
    pc_oracle_dir d;
    pc_projector proj;
    if (orthogonal)
        pc_oracle_projector_orthogonal(c->surface, c->curve, &proj);
    else
        pc_oracle_projector(c->surface, c->curve, c->dir, &d, &proj);
    pc_oracle_summary sum;
    pc_oracle_measure_result(r, &proj, &c->surface->grid, &sum);
    CHECK(sum.pieces > 0 && sum.failures == 0);
    CHECK(sum.worst.hausdorff <= eps);
    projcurve_result_destroy(r);
    return eps;
}

/* eps_D left unset is automatic: 1e-4 of the model size (projcurve.h),
 * which the result reports. 0 (of either sign), negative values, NaN and
 * infinities are rejected with a message naming the option, and leave the
 * handle as it was: unset (still automatic), then set (still that value). */
static void test_distance_option(const shape_case *c)
{
    const double size = model_size(c->surface);
    /* the library's diagonal may round differently: a few ulps */
    const double ulps = 8.0 * 2.2204460492503131e-16;
    projcurve_context *ctx = NULL;
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK_OK(projcurve_options_create(ctx, &o));
    for (int orthogonal = 0; orthogonal <= 1; ++orthogonal) {
        CHECK_NEAR(used_distance(c, o, orthogonal), 1e-4 * size, ulps * 1e-4 * size);
        CHECK_NEAR(used_distance(c, NULL, orthogonal), 1e-4 * size, ulps * 1e-4 * size);
    }
    static const double bad[] = {0.0, -0.0, -1.0, -1e300, NAN, INFINITY, -INFINITY};
    static const projcurve_status why[] = {
        PROJCURVE_ERR_OUT_OF_RANGE, PROJCURVE_ERR_OUT_OF_RANGE, PROJCURVE_ERR_OUT_OF_RANGE,
        PROJCURVE_ERR_OUT_OF_RANGE, PROJCURVE_ERR_NOT_FINITE,   PROJCURVE_ERR_NOT_FINITE,
        PROJCURVE_ERR_NOT_FINITE};
    const double set = 1e-3 * size;
    for (int round = 0; round < 2; ++round) {
        if (round == 1)
            CHECK_OK(projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TOL_DISTANCE, set));
        for (size_t k = 0; k < sizeof bad / sizeof bad[0]; ++k) {
            CHECK_STATUS(projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TOL_DISTANCE, bad[k]),
                         why[k]);
            const char *msg = projcurve_context_message(ctx);
            if (strstr(msg, "TOL_DISTANCE") == NULL)
                fprintf(stderr, "setting TOL_DISTANCE to %g: message '%s'\n", bad[k], msg);
            CHECK(strstr(msg, "TOL_DISTANCE") != NULL);
        }
        double v = NAN;
        CHECK_OK(projcurve_options_get_double(ctx, o, PROJCURVE_OPT_TOL_DISTANCE, &v));
        CHECK(v == (round == 0 ? 0.0 : set)); /* 0 is how the getter shows "unset" */
        CHECK_NEAR(used_distance(c, o, 0), round == 0 ? 1e-4 * size : set,
                   round == 0 ? ulps * 1e-4 * size : 0.0);
    }
    projcurve_options_destroy(o);
    projcurve_context_destroy(ctx);
}

int main(void)
{
    const double plane_o[3] = {0, 0, 0}, plane_a[3] = {10, 0, 1}, plane_b[3] = {0, 10, 2};
    const double plane_curve[18] = {2, 2, 30, 4, 3, 31, 5, 6, 29, 6, 4, 30, 7, 7, 32, 8, 8, 30};
    const double cyl_curve[18] = {-25, 10, 50, -10, 30, 55, 0, 40, 45,
                                  10, 60, 50, 20, 70, 52, 25, 90, 50};
    const double sphere_line[6] = {-15, 3, 20, 15, 3, 20};
    const double pole_line[6] = {-5, 0, 20, 5, 0, 20};
    const double bumpy_curve[15] = {0.1, 0.2, 1, 0.3, 0.8, 1.2, 0.5, 0.3,
                                    0.9, 0.7, 0.9, 1.1, 0.85, 0.6, 1};
    const double fold_flat[6] = {-10, 50, 40, 70, 50, 40};
    const double fold_past[6] = {-10, 50, 40, 125, 50, 40};
    const double fold_back[6] = {125, 50, 40, -10, 50, 40};
    const double z_line[6] = {90, 50, 60, 45, 50, 60};
    const double out_back[15] = {40, 20, 45, 90, 35, 45, 125, 50, 45, 90, 65, 45, 40, 80, 45};
    const double longer[12] = {-20, 30, 45, 30, 60, 50, 70, 40, 40, 120, 70, 45};
    pc_shape_surface bumpy = pc_shape_bumpy(2024, 5, 5, 0.15, 1);

    /* the branch counts are test_trace_shapes' and test_trace_jumps' */
    shape_case cases[] = {
        {"plane", shape_plane(plane_o, plane_a, plane_b), shape_bspline_curve(3, 6, plane_curve),
         {0.05, -0.05, -1}, 1},
        {"half cylinder", shape_half_cylinder(30.0, 100.0), shape_bspline_curve(3, 6, cyl_curve),
         {0, 0, -1}, 1},
        {"sphere silhouettes", shape_sphere(10.0), shape_bspline_curve(1, 2, sphere_line),
         {0, 0, -1}, 2},
        /* four traced branches, two once joined at the poles (src/seam/) */
        {"sphere pole", shape_sphere(10.0), shape_bspline_curve(1, 2, pole_line), {0, 0, -1}, 2},
        {"rational bumpy", pc_shape_surface_create(&bumpy), shape_bspline_curve(3, 5, bumpy_curve),
         {0.05, 0.02, -1}, 1},
        {"example 1", shape_example1_surface(), shape_example1_curve(), {-1, 0, 0}, 1},
        {"c-fold flat", shape_c_fold(), shape_bspline_curve(1, 2, fold_flat), {0, 0, -1}, 2},
        {"c-fold past the tip", shape_c_fold(), shape_bspline_curve(1, 2, fold_past), {0, 0, -1},
         2},
        {"c-fold reversed", shape_c_fold(), shape_bspline_curve(1, 2, fold_back), {0, 0, -1}, 2},
        {"z-fold", shape_z_fold(), shape_bspline_curve(1, 2, z_line), {0, 0, -1}, 3},
        {"bumpy exit and re-entry", shape_bumpy(8.0, 12345), shape_bspline_curve(3, 5, out_back),
         {0, 0, -1}, 2},
        {"bumpy longer at both ends", shape_bumpy(8.0, 12345), shape_bspline_curve(3, 4, longer),
         {0, 0, -1}, 1},
    };
    pc_shape_surface_free(&bumpy);
    if (cases[0].surface != NULL && cases[0].curve != NULL)
        test_distance_option(&cases[0]);
    static const double rel_eps[] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
    static const int pcurve_degrees[] = {1, 3};
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        CHECK(cases[k].surface != NULL && cases[k].curve != NULL);
        if (cases[k].surface == NULL || cases[k].curve == NULL)
            continue;
        for (size_t m = 0; m < 2; ++m) {
            for (size_t e = 0; e < sizeof rel_eps / sizeof rel_eps[0]; ++e)
                run(&cases[k], rel_eps[e], 1.0, pcurve_degrees[m]);
            run(&cases[k], 1e-3, 10.0, pcurve_degrees[m]);
        }
    }
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        projcurve_surface_destroy(cases[k].surface);
        projcurve_curve_destroy(cases[k].curve);
    }
    return pc_test_finish("test_refine_shapes");
}
