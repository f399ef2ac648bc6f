/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The foot-point search skips BVH subtrees by the tangent boxes
 * (bezier/tangent_boxes.h). Two facts are checked on the polynomial
 * surfaces of tests/data/real and tests/data/cases:
 *
 * - the boxes hold what they claim: Su and Sv at random points of every
 *   patch lie in the boxes of its leaf, and every node's boxes contain its
 *   children's;
 * - the culled search finds every foot point of the exhaustive one (every
 *   patch subdivided), and each foot point it reports is one
 *   ((S - p).Su = (S - p).Sv = 0 to the corrector's accuracy), for points
 *   near the surface (lifted along the normal by up to 0.3 of the model
 *   size, on either side) and for points anywhere in the surface's box
 *   grown by half its size. (The culled search may find more: where two
 *   foot points nearly merge, the exhaustive one can skip the second as
 *   already found, depending on the order it meets the patches.)
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "point/point.h"

/* Rounding of the evaluations and of the hodograph nets, relative to the
 * tangent's scale. */
#define TOL_BOX 1e-12
/* Foot points found from different Newton starts agree to the corrector's
 * accuracy; two feet closer than 1e-8 of the domain are merged by the
 * search itself (FEET_SAME_PARAM), so 1e-7 of the domain separates
 * "the same foot" from "another one" with room on both sides. */
#define TOL_SAME_FOOT 1e-7
/* Distances of the same foot agree to the corrector's tolerance. */
#define TOL_DIST 1e-9
/* A foot point: |(S - p).S_u| <= this times |S - p| |S_u| (the sine of the
 * angle off 90 degrees), likewise for S_v. */
#define TOL_FOOT 1e-8

static const char *const k_files[] = {
    "real/sunglasses_lens.igs", "real/bladex_upper.iges", "real/hammer.iges",
    "real/test-joinsurf_04.stp", "real/horn.xml", "real/teapot_newell_spd.txt",
    "cases/bumpy_bicubic_8x8_down.igs", "cases/deg5_quintic_9x8_down.igs",
    "cases/fold_c_sheet_jump.igs"};

#define MAX_SURFACES 3 /* per file, spread over it */
#define POINTS 12      /* per surface */

static int in_box(const double box[6], pc_vec3 x, double slack)
{
    return x.x >= box[0] - slack && x.y >= box[1] - slack && x.z >= box[2] - slack &&
           x.x <= box[3] + slack && x.y <= box[4] + slack && x.z <= box[5] + slack;
}

static double box_scale(const double box[6])
{
    double m = 0.0;
    for (int k = 0; k < 6; ++k)
        m = fmax(m, fabs(box[k]));
    return m;
}

static void check_boxes(const projcurve_surface *s, const char *name, pc_test_rng *rng)
{
    const pc_bvh *bvh = &s->bvh;
    const double *tb = s->tangents.node;
    for (size_t k = 0; k < bvh->n_nodes; ++k) {
        const pc_bvh_node *n = &bvh->nodes[k];
        const double *box = tb + 12 * k;
        if (n->count == 0) {
            for (uint32_t c = n->first; c <= n->first + 1; ++c)
                for (int half = 0; half < 2; ++half) {
                    const double *child = tb + 12 * (size_t)c + 6 * (size_t)half;
                    const pc_vec3 lo = vec3(child[0], child[1], child[2]);
                    const pc_vec3 hi = vec3(child[3], child[4], child[5]);
                    ++pc_test_checks;
                    if (!in_box(box + 6 * half, lo, 0.0) || !in_box(box + 6 * half, hi, 0.0))
                        pc_test_fail_at(__FILE__, __LINE__, "%s: node %zu does not hold child %u",
                                        name, k, c);
                }
            continue;
        }
        for (uint32_t i = n->first; i < n->first + n->count; ++i) {
            const pc_bezier_patch *patch = &s->grid.patches[bvh->order[i]];
            for (int r = 0; r < 4; ++r) {
                const double u = pc_test_rng_uniform(rng, patch->u0, patch->u1);
                const double v = pc_test_rng_uniform(rng, patch->v0, patch->v1);
                pc_vec3 d[3];
                pc_nurbs_surface_eval(&s->nurbs, u, v, 1, NULL, NULL, d);
                for (int half = 0; half < 2; ++half) {
                    const double *b = box + 6 * half;
                    ++pc_test_checks;
                    if (!in_box(b, d[1 + half], TOL_BOX * box_scale(b)))
                        pc_test_fail_at(__FILE__, __LINE__,
                                        "%s: S%s(%.17g, %.17g) = (%g, %g, %g) outside leaf %zu", name,
                                        half ? "v" : "u", u, v, d[1 + half].x, d[1 + half].y,
                                        d[1 + half].z, k);
                }
            }
        }
    }
}

static void compare_feet(const projcurve_surface *s, const char *name, pc_vec3 p)
{
    pc_foot_list culled = {NULL, 0, 0}, all = {NULL, 0, 0};
    CHECK_OK(pc_surface_foot_points(NULL, s, p, &culled));
    CHECK_OK(pc_surface_foot_points_exhaustive(NULL, s, p, &all));
    const double *dom = s->nurbs.domain;
    const double tol_u = TOL_SAME_FOOT * (dom[1] - dom[0]), tol_v = TOL_SAME_FOOT * (dom[3] - dom[2]);
    for (size_t j = 0; j < culled.count; ++j) {
        const pc_surface_point *c = &culled.items[j];
        pc_vec3 d[3];
        pc_nurbs_surface_eval(&s->nurbs, c->u, c->v, 1, NULL, NULL, d);
        const pc_vec3 diff = vec3_sub(d[0], p);
        const double r = vec3_norm(diff);
        const double gu = fabs(vec3_dot(diff, d[1])), gv = fabs(vec3_dot(diff, d[2]));
        ++pc_test_checks;
        if (!(gu <= TOL_FOOT * r * vec3_norm(d[1]) + 1e-12 * s->size * vec3_norm(d[1]) &&
              gv <= TOL_FOOT * r * vec3_norm(d[2]) + 1e-12 * s->size * vec3_norm(d[2])))
            pc_test_fail_at(__FILE__, __LINE__, "%s, p = (%.17g, %.17g, %.17g): (%.17g, %.17g) is "
                            "no foot point: (S-p).Su = %.3g, (S-p).Sv = %.3g", name, p.x, p.y, p.z,
                            c->u, c->v, gu, gv);
    }
    for (size_t i = 0; i < all.count; ++i) {
        const pc_surface_point *a = &all.items[i];
        int found = 0;
        for (size_t j = 0; j < culled.count && !found; ++j) {
            const pc_surface_point *c = &culled.items[j];
            found = fabs(c->u - a->u) <= tol_u && fabs(c->v - a->v) <= tol_v &&
                    fabs(c->dist - a->dist) <= TOL_DIST * s->size;
        }
        ++pc_test_checks;
        if (!found)
            pc_test_fail_at(__FILE__, __LINE__, "%s, p = (%.17g, %.17g, %.17g): foot (%.17g, %.17g) "
                            "at %.17g missed by the culled search", name, p.x, p.y, p.z, a->u, a->v,
                            a->dist);
    }
    pc_foot_list_free(&culled);
    pc_foot_list_free(&all);
}

static void check_surface(const projcurve_surface *s, const char *name, pc_test_rng *rng)
{
    if (s->nurbs.rational) { /* no tangent boxes: nothing is culled */
        CHECK(s->tangents.node == NULL);
        return;
    }
    CHECK(s->tangents.node != NULL);
    check_boxes(s, name, rng);
    const double *dom = s->nurbs.domain;
    for (int k = 0; k < POINTS; ++k) {
        pc_vec3 p;
        if (k % 3 == 2) { /* anywhere around the surface */
            const double h = 0.5 * s->size;
            p = vec3(pc_test_rng_uniform(rng, s->box[0] - h, s->box[3] + h),
                     pc_test_rng_uniform(rng, s->box[1] - h, s->box[4] + h),
                     pc_test_rng_uniform(rng, s->box[2] - h, s->box[5] + h));
        } else { /* off a surface point along its normal */
            const double u = pc_test_rng_uniform(rng, dom[0], dom[1]);
            const double v = pc_test_rng_uniform(rng, dom[2], dom[3]);
            pc_vec3 d[3];
            pc_nurbs_surface_eval(&s->nurbs, u, v, 1, NULL, NULL, d);
            const pc_vec3 n = vec3_cross(d[1], d[2]);
            if (!(vec3_norm(n) > 0.0))
                continue;
            const double lift = pc_test_rng_uniform(rng, -0.3, 0.3) * s->size;
            p = vec3_axpy(d[0], lift, vec3_normalize(n));
        }
        compare_feet(s, name, p);
    }
}

int main(void)
{
    FILE *probe = fopen(pc_test_data_path("real/SOURCES.md"), "r");
    if (probe == NULL)
        pc_test_missing_data("real/SOURCES.md");
    fclose(probe);
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 77);
    for (size_t f = 0; f < sizeof k_files / sizeof *k_files; ++f) {
        projcurve_model *m = NULL;
        if (projcurve_model_read_file(NULL, pc_test_data_path(k_files[f]), &m) != PROJCURVE_OK) {
            pc_test_fail_at(__FILE__, __LINE__, "%s does not load", k_files[f]);
            continue;
        }
        const size_t count = projcurve_model_surface_count(m);
        const size_t step = count > MAX_SURFACES ? count / MAX_SURFACES : 1;
        for (size_t i = 0; i < count; i += step) {
            char name[300];
            snprintf(name, sizeof name, "%s surface %zu", k_files[f], i);
            check_surface(projcurve_model_surface(m, i), name, &rng);
        }
        projcurve_model_destroy(m);
    }
    return pc_test_finish("test_point_feet_tree");
}
