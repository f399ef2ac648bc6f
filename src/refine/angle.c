/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Angle control ([SY13] s2 step 4): the pieces meet with eps_T-G1
 * continuity, i.e. the end tangents of adjacent composed pieces differ by at
 * most eps_T. Each piece's end tangent deviates from the exact projection's
 * tangent at the joint by about half its turning angle, which halves when the
 * piece is halved; so at a joint that fails, the side that deviates more from
 * the exact tangent is split at its middle (the halves go through the knot
 * line and Hausdorff control again), and the passes repeat until every joint
 * is within eps_T. A joint on a crease of S (the one-sided exact tangents
 * differ by more than eps_T) is a corner of the exact projection: left alone,
 * and so is a vertex next to a gap (no joint there).
 */
#include <math.h>
#include <stdlib.h>

#include "common/error.h"
#include "compose/compose.h"
#include "refine/refine_internal.h"

/* Bound of the passes; each halves the pieces next to a failing joint, so 60
 * passes shrink them by 2^-60 (min_dt stops them well before). */
#define PC_ANGLE_MAX_PASSES 60

/* Start and end tangent directions of the composed segment a-b (zero vectors
 * for a degenerate piece): the first non-zero control point differences. */
static void end_tangents(const pc_refiner *r, const pc_rvertex *a, const pc_rvertex *b,
                         pc_vec3 *t0, pc_vec3 *t1)
{
    *t0 = *t1 = vec3(0.0, 0.0, 0.0);
    const pc_bezier_patch *patch = a->gap ? NULL : pc_refine_common_patch(r, a, b);
    if (patch == NULL)
        return;
    double cw[PC_PIECE_MAX_CW], ctrl[3 * (PC_PIECE_MAX_DEGREE + 1)], w[PC_PIECE_MAX_DEGREE + 1];
    const int n = pc_refine_compose(patch, a, b, cw);
    pc_compose_to_cartesian(n, cw, ctrl, w);
    const pc_vec3 first = vec3_load(ctrl), last = vec3_load(ctrl + 3 * n);
    for (int k = 1; k <= n; ++k) {
        const pc_vec3 d = vec3_sub(vec3_load(ctrl + 3 * k), first);
        if (vec3_norm(d) > 0.0) {
            *t0 = d;
            break;
        }
    }
    for (int k = n - 1; k >= 0; --k) {
        const pc_vec3 d = vec3_sub(last, vec3_load(ctrl + 3 * k));
        if (vec3_norm(d) > 0.0) {
            *t1 = d;
            break;
        }
    }
}

/* cos of the angle between a and b; 1 when either is zero (no direction). */
static double cos_angle(pc_vec3 a, pc_vec3 b)
{
    const double na = vec3_norm(a), nb = vec3_norm(b);
    if (!(na > 0.0) || !(nb > 0.0))
        return 1.0;
    return vec3_dot(a, b) / (na * nb);
}

/* Marks (split[i] = 1) the segments to halve in this pass; returns how many. */
static size_t mark_joints(pc_refiner *r, const pc_vertex_list *list, unsigned char *split)
{
    const pc_rvertex *v = list->items;
    size_t marked = 0;
    pc_vec3 prev_t0, prev_t1;
    end_tangents(r, &v[0], &v[1], &prev_t0, &prev_t1);
    split[0] = 0;
    for (size_t j = 1; j + 1 < list->count; ++j) {
        pc_vec3 t0, t1;
        end_tangents(r, &v[j], &v[j + 1], &t0, &t1);
        split[j] = 0;
        /* no joint across a gap */
        if (!v[j - 1].gap && !v[j].gap && cos_angle(prev_t1, t0) < r->cos_eps_t) {
            const pc_vec3 exact_in = pc_refine_exact_tangent(r, &v[j], &v[j - 1]);
            const pc_vec3 exact = pc_refine_exact_tangent(r, &v[j], &v[j + 1]);
            /* a crease of S: the exact curve turns here itself */
            if (cos_angle(exact_in, exact) < r->cos_eps_t) {
                prev_t1 = t1;
                continue;
            }
            const int left_ok = fabs(v[j].t - v[j - 1].t) > r->min_dt;
            const int right_ok = fabs(v[j + 1].t - v[j].t) > r->min_dt;
            /* the side that turns away more from the exact tangent */
            const int left = cos_angle(prev_t1, exact_in) <= cos_angle(t0, exact);
            if (left && left_ok)
                split[j - 1] = 1;
            else if (right_ok)
                split[j] = 1;
            else if (left_ok)
                split[j - 1] = 1;
            marked += split[j - 1] + split[j];
        }
        prev_t1 = t1;
    }
    return marked;
}

/* Rebuilds list into out with the marked segments halved; *n_split counts
 * the halvings done (the corrector may refuse some). */
static projcurve_status split_marked(pc_refiner *r, const pc_vertex_list *list,
                                     const unsigned char *split, pc_vertex_list *out,
                                     size_t *n_split)
{
    *n_split = 0;
    const pc_rvertex *v = list->items;
    out->count = 0;
    projcurve_status st = pc_refine_output(r, out, &v[0]);
    for (size_t i = 0; i + 1 < list->count && st == PROJCURVE_OK; ++i) {
        pc_rvertex mid;
        if (split[i] && pc_refine_exact_point(r, &v[i], &v[i + 1], 0.5 * (v[i].t + v[i + 1].t),
                                              &mid)) {
            ++*n_split;
            st = pc_refine_split(r, &v[i], &mid, 1, out);
            if (st == PROJCURVE_OK)
                st = pc_refine_split(r, &mid, &v[i + 1], 1, out);
        } else {
            st = pc_refine_output(r, out, &v[i + 1]);
        }
    }
    return st;
}

projcurve_status pc_refine_angles(pc_refiner *r, pc_vertex_list *list, pc_vertex_list *scratch)
{
    projcurve_status st = PROJCURVE_OK;
    unsigned char *split = NULL;
    size_t split_capacity = 0;
    for (int pass = 0; pass < PC_ANGLE_MAX_PASSES && list->count > 2; ++pass) {
        if (split_capacity < list->count) { /* one mark per segment */
            free(split);
            split_capacity = 2 * list->count;
            split = malloc(split_capacity);
            if (split == NULL) {
                st = pc_fail(r->ctx, PROJCURVE_ERR_NO_MEMORY,
                             "out of memory marking %zu joints", list->count);
                break;
            }
        }
        if (mark_joints(r, list, split) == 0)
            break;
        size_t n_split = 0;
        st = split_marked(r, list, split, scratch, &n_split);
        const pc_vertex_list tmp = *list;
        *list = *scratch;
        *scratch = tmp;
        if (st != PROJCURVE_OK || n_split == 0)
            break;
    }
    free(split);
    return st;
}
