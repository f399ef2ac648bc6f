/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The curve parameter ranges that can reach a face (shapeproj/t_ranges.h)
 * never leave out a hit, on the real models hammer.iges, bearing.iges and
 * linkrods.step (every shape) with a line, a cubic and a rational circle
 * over each model's box, projected along an axis and from an eye point:
 * - at dense t outside a face's ranges, the ray from P(t) (along Dir, or
 *   from the eye through P(t), beyond P(t)) misses the face's 3D box, by a
 *   slab test written here (the box holds the untrimmed surface);
 * - at sparser t outside the ranges, the ray has no forward hit on the
 *   face's untrimmed surface (projcurve_surface_intersect_line);
 * - every face the shape projection skips (no range) has no branch when
 *   projected over the whole curve (pc_face_project, brute force).
 * And the ranges restrict something: some (t, face) pairs are left out, so
 * that the checks above are not vacuous.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"

#include "api/project.h"
#include "brep/shape.h"
#include "check.h"
#include "faceproj/face_project.h"
#include "shapeproj/face_select.h"
#include "shapeproj/t_ranges.h"

#define BOX_SAMPLES 1500 /* t samples of the slab test */
#define RAY_SAMPLES 97   /* t samples of the surface intersections */
#define MAX_HITS 16

typedef struct run {
    const projcurve_shape *shape;
    const projcurve_curve *curve;
    pc_projection_spec spec;
    double size;
    const char *name;
} run;

static int in_ranges(const pc_t_ranges *r, double t)
{
    for (size_t i = 0; i < r->count; ++i)
        if (t >= r->items[i].a && t <= r->items[i].b)
            return 1;
    return 0;
}

/* The ray's origin P(t) and unit direction. */
static void ray_at(const run *rn, double t, double p[3], double d[3])
{
    CHECK_OK(projcurve_curve_eval(NULL, rn->curve, t, 0, p));
    const pc_vec3 v = rn->spec.vec;
    if (rn->spec.kind == PROJCURVE_PROJECT_CONICAL) {
        const double e[3] = {p[0] - v.x, p[1] - v.y, p[2] - v.z};
        const double n = sqrt(e[0] * e[0] + e[1] * e[1] + e[2] * e[2]);
        for (int i = 0; i < 3; ++i)
            d[i] = e[i] / n;
    } else {
        d[0] = v.x;
        d[1] = v.y;
        d[2] = v.z;
    }
}

/* 1 when the ray p + lambda d, lambda >= 0, meets the box (slab test). */
static int ray_meets_box(const double p[3], const double d[3], const double box[6])
{
    double lo = 0.0, hi = INFINITY;
    for (int i = 0; i < 3; ++i) {
        if (d[i] == 0.0) {
            if (p[i] < box[i] || p[i] > box[i + 3])
                return 0;
            continue;
        }
        const double a = (box[i] - p[i]) / d[i], b = (box[i + 3] - p[i]) / d[i];
        lo = fmax(lo, fmin(a, b));
        hi = fmin(hi, fmax(a, b));
    }
    return lo <= hi;
}

static void check_run(const run *rn, size_t *left_out, size_t *pairs)
{
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    pc_params p;
    pc_budget budget;
    CHECK_OK(pc_projection_params(ctx, NULL, rn->size, &budget, &p));
    pc_curve_boxes cb;
    CHECK_OK(pc_curve_boxes_build(ctx, rn->curve, &rn->spec, &cb));
    CHECK(cb.n_segments > 0);
    double whole[6];
    CHECK(pc_curve_box(rn->curve, whole));
    /* the rays are checked against the face box itself: the padding
     * (1e-6 of the size) only widens the ranges */
    const double pad = pc_t_range_pad(&p, rn->size);
    const double t0 = rn->curve->t0, t1 = rn->curve->t1;
    pc_t_ranges ranges = {0};
    size_t box_misses = 0, ray_misses = 0, skip_misses = 0, skipped = 0;
    for (size_t fi = 0; fi < rn->shape->n_faces; ++fi) {
        const projcurve_face *f = rn->shape->faces[fi];
        CHECK_OK(pc_t_ranges_find(ctx, &cb, &rn->spec, f->box, pad, &ranges));
        for (int i = 0; i <= BOX_SAMPLES; ++i) {
            const double t = t0 + (t1 - t0) * i / BOX_SAMPLES;
            ++*pairs;
            if (in_ranges(&ranges, t))
                continue;
            ++*left_out;
            double o[3], d[3];
            ray_at(rn, t, o, d);
            if (ray_meets_box(o, d, f->box) && box_misses++ < 3)
                pc_test_fail_at(__FILE__, __LINE__, "%s: face %zu: ray at t %.17g meets the "
                                "face box outside the ranges", rn->name, fi, t);
        }
        for (int i = 0; i <= RAY_SAMPLES; ++i) {
            const double t = t0 + (t1 - t0) * (i + 0.5) / (RAY_SAMPLES + 1);
            if (in_ranges(&ranges, t))
                continue;
            double o[3], d[3], hits[3 * MAX_HITS];
            size_t n = 0;
            ray_at(rn, t, o, d);
            CHECK_OK(projcurve_surface_intersect_line(NULL, f->surface, o, d, 1, MAX_HITS,
                                                      hits, NULL, &n));
            if (n > 0 && ray_misses++ < 3)
                pc_test_fail_at(__FILE__, __LINE__, "%s: face %zu: ray at t %.17g hits the "
                                "surface outside the ranges", rn->name, fi, t);
        }
        /* a face the shape projection skips: selected by the whole curve's
         * box, reached by none of its pieces */
        const int selected = rn->spec.kind == PROJCURVE_PROJECT_CONICAL
                                 ? pc_cone_box_meets(whole, rn->spec.vec, f->box)
                                 : pc_swept_box_meets(whole, rn->spec.vec, f->box);
        if (ranges.count == 0 && selected) {
            ++skipped;
            projcurve_result *r = NULL;
            pc_branch_trim *trims = NULL;
            size_t unrefined = 0;
            CHECK_OK(pc_face_project(ctx, f, rn->curve, &rn->spec, &p, &r, &trims, &unrefined));
            if (r != NULL && r->n_branches > 0 && skip_misses++ < 3)
                pc_test_fail_at(__FILE__, __LINE__, "%s: face %zu skipped, but its projection "
                                "has %zu branch(es)", rn->name, fi, r->n_branches);
            projcurve_result_destroy(r);
            free(trims);
        }
    }
    CHECK(box_misses == 0);
    CHECK(ray_misses == 0);
    CHECK(skip_misses == 0);
    printf("%s: %zu faces, %zu skipped by the ranges\n", rn->name, rn->shape->n_faces,
           skipped);
    PC_ARRAY_FREE(&ranges);
    pc_curve_boxes_free(&cb);
    projcurve_context_destroy(ctx);
}

static projcurve_curve *line(const double a[3], const double b[3])
{
    const double ctrl[6] = {a[0], a[1], a[2], b[0], b[1], b[2]}, knots[4] = {0, 0, 1, 1};
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 1, 2, ctrl, NULL, knots, &c));
    return c;
}

/* The full circle of radius r about (cx, cy) at height z: 9 rational
 * quadratic poles (weights 1, sqrt(2)/2 at the corners). */
static projcurve_curve *circle(double cx, double cy, double z, double r)
{
    static const double dx[9] = {1, 1, 0, -1, -1, -1, 0, 1, 1};
    static const double dy[9] = {0, 1, 1, 1, 0, -1, -1, -1, 0};
    static const double knots[12] = {0, 0, 0, 0.25, 0.25, 0.5, 0.5, 0.75, 0.75, 1, 1, 1};
    double ctrl[27], w[9];
    for (int i = 0; i < 9; ++i) {
        ctrl[3 * i] = cx + r * dx[i];
        ctrl[3 * i + 1] = cy + r * dy[i];
        ctrl[3 * i + 2] = z;
        w[i] = i % 2 ? sqrt(0.5) : 1.0;
    }
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 2, 9, ctrl, w, knots, &c));
    return c;
}

static void run_shape(const char *file, size_t si, const projcurve_shape *shape,
                      size_t *left_out, size_t *pairs)
{
    double b[6];
    box_empty(b);
    for (size_t i = 0; i < shape->n_faces; ++i)
        box_add_box(b, shape->boxes + 6 * i);
    const double w[3] = {b[3] - b[0], b[4] - b[1], b[5] - b[2]};
    const double size = sqrt(w[0] * w[0] + w[1] * w[1] + w[2] * w[2]);
    const double mid[3] = {(b[0] + b[3]) / 2, (b[1] + b[4]) / 2, (b[2] + b[5]) / 2};
    const double above = b[5] + 0.1 * size;
    const double a0[3] = {b[0] + 0.05 * w[0], mid[1] + 0.03 * w[1], above};
    const double a1[3] = {b[3] - 0.05 * w[0], mid[1] + 0.07 * w[1], above};
    const double x = b[3] + 0.1 * size;
    const double cubic_ctrl[12] = {x, b[1] + 0.1 * w[1], mid[2] - 0.2 * w[2],
                                   x, b[1] + 0.4 * w[1], mid[2] + 0.4 * w[2],
                                   x, b[1] + 0.6 * w[1], mid[2] - 0.4 * w[2],
                                   x, b[1] + 0.9 * w[1], mid[2] + 0.2 * w[2]};
    const double cubic_knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    projcurve_curve *curves[3] = {line(a0, a1), NULL,
                                  circle(mid[0], mid[1], above, 0.3 * fmax(w[0], w[1]))};
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 3, 4, cubic_ctrl, NULL, cubic_knots, &curves[1]));
    const pc_vec3 dirs[3] = {vec3(0, 0, -1), vec3(-1, 0, 0), vec3(0, 0, -1)};
    static const char *const names[3] = {"line", "cubic", "circle"};
    const pc_vec3 eye = vec3(mid[0], mid[1], above + size);
    for (int k = 0; k < 3; ++k) {
        for (int conical = 0; conical < 2 && curves[k] != NULL; ++conical) {
            if (conical && k == 1)
                continue; /* the cubic beside the box: along -x only */
            char name[300];
            snprintf(name, sizeof name, "%s shape %zu %s %s", file, si, names[k],
                     conical ? "conical" : "dir");
            const run rn = {shape, curves[k],
                            {conical ? PROJCURVE_PROJECT_CONICAL : PROJCURVE_PROJECT_DIRECTIONAL,
                             conical ? eye : dirs[k]},
                            size, name};
            check_run(&rn, left_out, pairs);
        }
        projcurve_curve_destroy(curves[k]);
    }
}

int main(void)
{
    static const char *const files[] = {"hammer.iges", "bearing.iges", "linkrods.step"};
    size_t left_out = 0, pairs = 0;
    for (size_t m = 0; m < sizeof files / sizeof files[0]; ++m) {
        char path[256];
        snprintf(path, sizeof path, "real/%s", files[m]);
        projcurve_model *model = NULL;
        CHECK_OK(projcurve_model_read_file(NULL, pc_test_data_path(path), &model));
        if (model == NULL)
            continue;
        for (size_t si = 0; si < projcurve_model_shape_count(model); ++si)
            run_shape(files[m], si, projcurve_model_shape(model, si), &left_out, &pairs);
        projcurve_model_destroy(model);
    }
    printf("%zu of %zu (t, face) pairs left out by the ranges\n", left_out, pairs);
    /* not vacuous: most faces are reached over a part of each curve only */
    CHECK(left_out > pairs / 4);
    return pc_test_finish("test_shapeproj_t_ranges");
}
