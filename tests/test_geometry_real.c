/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The geometry module on the real CAD surfaces of tests/data/real:
 * evaluation routes agree (de Boor on the clamped data, basis functions,
 * Bezier patches), patch boxes contain the surface, a point lifted off the
 * surface along the normal has its base point among its foot points and is
 * at most the lift away from the surface, and closest points of points near
 * and around the surface equal a brute-force search (dense sampling plus a
 * pattern-search polish from every sampled local minimum).
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include <stdlib.h>

#include "check.h"
#include "closest_oracle.h"
#include "deboor.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "point/point.h"

/* Rounding of evaluations on real data, relative to the surface size. */
#define TOL_EVAL 1e-11
/* Surfaces checked per file and points per surface (runtime bound). */
#define MAX_SURFACES 6
#define POINTS 3
#define LIFT 1e-3 /* of the surface size */
/* Brute force: points per surface and uniform grid intervals per direction
 * (the oracle adds 8 samples per knot span, which real data needs: linkrods
 * has features in spans of 1e-5 of its domain). With 40 points per surface
 * the library and the oracle agreed everywhere; 3 keep the test short
 * (most of its time under the sanitizers). */
#define BRUTE_POINTS 3
#define BRUTE_GRID 60
/* Two independent minimisers of |S - p| agree to rounding of the distance;
 * relative to the surface size. */
#define TOL_DIST 1e-10

static const char *const k_files[] = {"sunglasses_lens.igs", "bladex_upper.iges", "hammer.iges",
                                      "bearing.iges",        "linkrods.step",     "test-joinsurf_01.stp",
                                      "test_pipe_out_true.step", "car_shell1.xml", "horn.xml",
                                      "shroud_kaplan.xml",   "egg.xml",           "teapot_newell_spd.txt",
                                      "test-joinsurf_04.stp"};

/* A view of the library's clamped data as user arrays for the oracle. */
static pc_shape_surface as_shape(const pc_nurbs_surface *n)
{
    const size_t count = n->n_u * n->n_v;
    pc_shape_surface s = {n->deg_u, n->deg_v, n->n_u, n->n_v, malloc(3 * count * sizeof(double)),
                          malloc(count * sizeof(double)), n->knots_u, n->knots_v};
    for (size_t i = 0; i < count; ++i) {
        const double w = n->cw[4 * i + 3];
        for (size_t k = 0; k < 3; ++k)
            s.ctrl[3 * i + k] = n->cw[4 * i + k] / w;
        s.weights[i] = w;
    }
    return s;
}

static void check_surface(const projcurve_surface *s, const char *file, size_t index,
                          pc_test_rng *rng)
{
    const pc_nurbs_surface *n = &s->nurbs;
    const double *dom = n->domain;
    pc_shape_surface view = as_shape(n);
    for (int k = 0; k < 20; ++k) {
        const double u = pc_test_rng_uniform(rng, dom[0], dom[1]);
        const double v = pc_test_rng_uniform(rng, dom[2], dom[3]);
        double ref[3];
        pc_deboor_surface(&view, u, v, ref);
        pc_vec3 a[6], b[6];
        pc_nurbs_surface_eval(n, u, v, 2, NULL, NULL, a);
        const pc_bezier_patch *patch = &s->grid.patches[pc_patch_grid_locate(&s->grid, u, v)];
        pc_bezier_patch_eval(patch, u, v, 2, b);
        const double e1 = vec3_dist(a[0], vec3_load(ref)), e2 = vec3_dist(b[0], a[0]);
        if (!(e1 <= TOL_EVAL * s->size && e2 <= TOL_EVAL * s->size))
            pc_test_fail_at(__FILE__, __LINE__, "%s surface %zu at (%g, %g): de Boor %.3g, Bezier %.3g",
                            file, index, u, v, e1, e2);
        ++pc_test_checks;
        const double pt[3] = {a[0].x, a[0].y, a[0].z};
        int inside = 1;
        for (int c = 0; c < 3; ++c)
            inside &= pt[c] >= patch->box[c] - TOL_EVAL * s->size &&
                      pt[c] <= patch->box[c + 3] + TOL_EVAL * s->size;
        CHECK(inside);
    }
    free(view.ctrl);
    free(view.weights);

    pc_foot_list feet = {NULL, 0, 0};
    for (int k = 0; k < POINTS; ++k) {
        /* Stay off the boundary and off singular points. */
        const double u = dom[0] + (dom[1] - dom[0]) * pc_test_rng_uniform(rng, 0.05, 0.95);
        const double v = dom[2] + (dom[3] - dom[2]) * pc_test_rng_uniform(rng, 0.05, 0.95);
        pc_vec3 d[3];
        pc_nurbs_surface_eval(n, u, v, 1, NULL, NULL, d);
        const pc_vec3 normal = vec3_cross(d[1], d[2]);
        if (!(vec3_norm(normal) > 1e-6 * (vec3_dot(d[1], d[1]) + vec3_dot(d[2], d[2]))))
            continue;
        const pc_vec3 p = vec3_axpy(d[0], LIFT * s->size, vec3_normalize(normal));
        pc_surface_point best;
        CHECK_OK(pc_surface_closest(NULL, s, p, &best));
        if (!(best.dist <= LIFT * s->size * (1.0 + 1e-9)))
            pc_test_fail_at(__FILE__, __LINE__,
                            "%s surface %zu: p = (%.17g, %.17g, %.17g) lifted from (%.17g, %.17g): "
                            "closest %.17g at (%.17g, %.17g) > lift %.17g",
                            file, index, p.x, p.y, p.z, u, v, best.dist, best.u, best.v,
                            LIFT * s->size);
        ++pc_test_checks;
        CHECK_OK(pc_surface_foot_points(NULL, s, p, &feet));
        int found = 0;
        for (size_t f = 0; f < feet.count; ++f)
            found |= vec3_dist(feet.items[f].q, d[0]) <= 1e-7 * s->size;
        if (!found)
            pc_test_fail_at(__FILE__, __LINE__,
                            "%s surface %zu: base point (%.9g, %.9g) not among %zu foot points", file,
                            index, u, v, feet.count);
        ++pc_test_checks;
    }
    pc_foot_list_free(&feet);

    /* Points around the surface: off a random point along the normal by up
     * to 5 % of the size on either side, moved sideways by up to 5 %, so
     * that the nearest point may also be on an edge or a corner. */
    for (int k = 0; k < BRUTE_POINTS; ++k) {
        const double u = pc_test_rng_uniform(rng, dom[0], dom[1]);
        const double v = pc_test_rng_uniform(rng, dom[2], dom[3]);
        pc_vec3 d[3];
        pc_nurbs_surface_eval(n, u, v, 1, NULL, NULL, d);
        const pc_vec3 normal = vec3_cross(d[1], d[2]);
        pc_vec3 p = d[0];
        if (vec3_norm(normal) > 0.0)
            p = vec3_axpy(p, pc_test_rng_uniform(rng, -0.05, 0.05) * s->size, vec3_normalize(normal));
        p = vec3_add(p, vec3_scale(vec3(pc_test_rng_uniform(rng, -1, 1), pc_test_rng_uniform(rng, -1, 1),
                                        pc_test_rng_uniform(rng, -1, 1)),
                                   0.05 * s->size));
        const double pa[3] = {p.x, p.y, p.z};
        double uv[2], q[3], dist, buv[2];
        CHECK_OK(projcurve_surface_closest_point(NULL, s, pa, uv, q, &dist));
        const double ref = pc_oracle_surface_closest(s, pa, BRUTE_GRID, buv);
        if (!(fabs(dist - ref) <= TOL_DIST * s->size))
            pc_test_fail_at(__FILE__, __LINE__,
                            "%s surface %zu, p = (%.17g, %.17g, %.17g): library %.17g at (%.9g, "
                            "%.9g), brute force %.17g at (%.9g, %.9g)",
                            file, index, pa[0], pa[1], pa[2], dist, uv[0], uv[1], ref, buv[0],
                            buv[1]);
        ++pc_test_checks;
    }
}

/* Fixed hard cases: a point lifted by LIFT off (u, v) of a surface. On
 * linkrods.step surface 15 (degrees 6 x 10, C^0 knot lines every few
 * spans) the nearest patch is a thin one next to the crease v = 3.60141;
 * the first minimiser run stops on the crease, and the patch that holds the
 * true foot point (v = 3.48) has the crease as its edge. */
static const struct {
    const char *file;
    size_t surface;
    double u, v;
} k_lift_cases[] = {{"linkrods.step", 15, -0.59979875158888851, 3.4824617092059866}};

static void check_lift_cases(void)
{
    for (size_t k = 0; k < sizeof k_lift_cases / sizeof *k_lift_cases; ++k) {
        char rel[256];
        snprintf(rel, sizeof rel, "real/%s", k_lift_cases[k].file);
        projcurve_model *m = NULL;
        CHECK_OK(projcurve_model_read_file(NULL, pc_test_data_path(rel), &m));
        if (m == NULL)
            continue;
        const projcurve_surface *s = projcurve_model_surface(m, k_lift_cases[k].surface);
        pc_vec3 d[3];
        pc_nurbs_surface_eval(&s->nurbs, k_lift_cases[k].u, k_lift_cases[k].v, 1, NULL, NULL, d);
        const pc_vec3 p = vec3_axpy(d[0], LIFT * s->size, vec3_normalize(vec3_cross(d[1], d[2])));
        const double pa[3] = {p.x, p.y, p.z};
        double uv[2], dist, buv[2];
        CHECK_OK(projcurve_surface_closest_point(NULL, s, pa, uv, NULL, &dist));
        const double ref = pc_oracle_surface_closest(s, pa, BRUTE_GRID, buv);
        if (!(dist <= LIFT * s->size * (1.0 + 1e-9) && fabs(dist - ref) <= TOL_DIST * s->size))
            pc_test_fail_at(__FILE__, __LINE__,
                            "%s surface %zu lifted from (%.17g, %.17g): library %.17g at (%.17g, "
                            "%.17g), brute force %.17g at (%.17g, %.17g), lift %.17g",
                            k_lift_cases[k].file, k_lift_cases[k].surface, k_lift_cases[k].u,
                            k_lift_cases[k].v, dist, uv[0], uv[1], ref, buv[0], buv[1],
                            LIFT * s->size);
        ++pc_test_checks;
        projcurve_model_destroy(m);
    }
}

int main(void)
{
    FILE *probe = fopen(pc_test_data_path("real/SOURCES.md"), "r");
    if (probe == NULL)
        pc_test_missing_data("real/SOURCES.md");
    fclose(probe);
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 2026);
    for (size_t f = 0; f < sizeof k_files / sizeof *k_files; ++f) {
        char rel[256];
        snprintf(rel, sizeof rel, "real/%s", k_files[f]);
        projcurve_model *m = NULL;
        if (projcurve_model_read_file(NULL, pc_test_data_path(rel), &m) != PROJCURVE_OK) {
            pc_test_fail_at(__FILE__, __LINE__, "%s does not load", rel);
            continue;
        }
        /* The B-spline surfaces, which come first: the analytic ones that
         * STEP files add after them are checked against their exact
         * geometry by test_analytic_surfaces and test_io_step_analytic,
         * and leaving them out keeps the random points drawn here. */
        size_t count = 0;
        while (count < projcurve_model_surface_count(m) &&
               strcmp(projcurve_model_surface_kind(m, count), "bspline") == 0)
            ++count;
        /* Spread the checked surfaces over the file. */
        const size_t step = count > MAX_SURFACES ? count / MAX_SURFACES : 1;
        for (size_t i = 0; i < count; i += step)
            check_surface(projcurve_model_surface(m, i), k_files[f], i, &rng);
        projcurve_model_destroy(m);
    }
    check_lift_cases();
    return pc_test_finish("test_geometry_real");
}
