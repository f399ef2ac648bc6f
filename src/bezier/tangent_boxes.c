/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Tangent-vector boxes over the patch BVH (tangent_boxes.h).
 */
#include "bezier/tangent_boxes.h"

#include <math.h>
#include <stdlib.h>

#include "common/error.h"

/* Relative slack of the interval test: the enclosure is computed in
 * floating point, so a bound within rounding of 0 counts as containing it. */
#define PC_TANGENT_SLACK 1e-12

/* Boxes of the u- and v-hodograph nets of a polynomial Bezier patch (w = 1):
 * out[0..5] bounds Su, out[6..11] bounds Sv over the patch. */
static void patch_tangent_boxes(const pc_bezier_patch *patch, double out[12])
{
    const int p = patch->deg_u, q = patch->deg_v;
    const size_t row = (size_t)p + 1;
    const double su = p / (patch->u1 - patch->u0), sv = q / (patch->v1 - patch->v0);
    box_empty(out);
    box_empty(out + 6);
    for (int j = 0; j <= q; ++j)
        for (int i = 0; i <= p; ++i) {
            const double *c = patch->cw + 4 * ((size_t)j * row + (size_t)i);
            if (i < p) {
                const double *r = c + 4;
                const double d[3] = {su * (r[0] - c[0]), su * (r[1] - c[1]), su * (r[2] - c[2])};
                box_add_point(out, d);
            }
            if (j < q) {
                const double *a = c + 4 * row;
                const double d[3] = {sv * (a[0] - c[0]), sv * (a[1] - c[1]), sv * (a[2] - c[2])};
                box_add_point(out + 6, d);
            }
        }
}

projcurve_status pc_tangent_boxes_build(projcurve_context *ctx, pc_tangent_boxes *tb,
                                        const pc_bvh *bvh, const pc_patch_grid *grid,
                                        int rational)
{
    tb->node = NULL;
    if (rational || bvh->n_nodes == 0)
        return PROJCURVE_OK;
    double *node = malloc(12 * bvh->n_nodes * sizeof *node);
    if (node == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for the tangent boxes");
    /* children come after their parent (bvh.c), so a backward sweep
     * completes both children before the parent needs them */
    for (size_t k = bvh->n_nodes; k-- > 0;) {
        const pc_bvh_node *n = &bvh->nodes[k];
        double *box = node + 12 * k;
        box_empty(box);
        box_empty(box + 6);
        if (n->count > 0) {
            for (uint32_t i = n->first; i < n->first + n->count; ++i) {
                double patch_box[12];
                patch_tangent_boxes(&grid->patches[bvh->order[i]], patch_box);
                box_add_box(box, patch_box);
                box_add_box(box + 6, patch_box + 6);
            }
        } else {
            for (uint32_t c = n->first; c <= n->first + 1; ++c) {
                box_add_box(box, node + 12 * (size_t)c);
                box_add_box(box + 6, node + 12 * (size_t)c + 6);
            }
        }
    }
    tb->node = node;
    return PROJCURVE_OK;
}

void pc_tangent_boxes_free(pc_tangent_boxes *tb)
{
    if (tb == NULL)
        return;
    free(tb->node);
    tb->node = NULL;
}

/* Whether the interval enclosure of d.t, d in box `diff` (min, max per
 * axis) and t in box `tangent`, contains 0 (within rounding). */
static int dot_may_vanish(const double diff[6], const double tangent[6])
{
    double lo = 0.0, hi = 0.0, scale = 0.0;
    for (int k = 0; k < 3; ++k) {
        const double a = diff[k], b = diff[k + 3], c = tangent[k], d = tangent[k + 3];
        const double ac = a * c, ad = a * d, bc = b * c, bd = b * d;
        lo += fmin(fmin(ac, ad), fmin(bc, bd));
        hi += fmax(fmax(ac, ad), fmax(bc, bd));
        scale += fmax(fabs(a), fabs(b)) * fmax(fabs(c), fabs(d));
    }
    const double slack = PC_TANGENT_SLACK * scale;
    return lo <= slack && hi >= -slack;
}

int pc_tangent_boxes_may_hold_foot(const pc_tangent_boxes *tb, const pc_bvh *bvh, size_t k,
                                   pc_vec3 p)
{
    if (tb->node == NULL)
        return 1;
    const double *box = bvh->nodes[k].box;
    const double diff[6] = {box[0] - p.x, box[1] - p.y, box[2] - p.z,
                            box[3] - p.x, box[4] - p.y, box[5] - p.z};
    const double *t = tb->node + 12 * k;
    return dot_may_vanish(diff, t) && dot_may_vanish(diff, t + 6);
}
