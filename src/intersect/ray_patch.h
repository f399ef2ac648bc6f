/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * One line against one Bezier patch, in the line's frame (ray_frame.h):
 * control-net culling, Bezier clipping (bezier_clip.h), certified Newton,
 * least squares at grazing points and poles (frame_net.h); and the hit
 * list's growth and final pass (hit_list.c).
 */
#ifndef PC_INTERSECT_RAY_PATCH_H
#define PC_INTERSECT_RAY_PATCH_H

#include <stddef.h>

#include "bezier/bezier.h"
#include "common/vec.h"
#include "intersect/intersect.h"
#include "intersect/ray_frame.h"

/* Number of doubles of scratch that pc_ray_patch_hits needs for a patch of
 * degrees (deg_u, deg_v); 0 when the size overflows. */
size_t pc_ray_patch_work_size(int deg_u, int deg_v);

/* Appends to `hits` every intersection of the line with the patch: u, v in
 * the surface's parameters, lambda, and PROJCURVE_HIT_TANGENT for grazing
 * hits (boundary flags, sorting and merging of duplicates are the caller's).
 * `work` holds pc_ray_patch_work_size doubles. Statuses: OK, NO_MEMORY. */
projcurve_status pc_ray_patch_hits(projcurve_context *ctx, const pc_ray_frame *frame,
                                   const pc_bezier_patch *patch, double *work,
                                   pc_hit_list *hits);

/* Appends one hit, growing the list. Statuses: OK, NO_MEMORY. */
projcurve_status pc_hit_list_push(projcurve_context *ctx, pc_hit_list *list, pc_hit hit);

/* Makes sure list->work holds at least n doubles. Statuses: OK, NO_MEMORY. */
projcurve_status pc_hit_list_reserve_work(projcurve_context *ctx, pc_hit_list *list, size_t n);

/* Decides whether two grazing hits near each other on the line are one
 * touching point (the surface between them stays on the line). */
typedef struct pc_graze_test {
    int (*same)(const void *user, const pc_hit *a, const pc_hit *b);
    const void *user;
} pc_graze_test;

/* Sorts the hits by lambda, merges the ones that are one point of the line
 * (shared edges and corners, neighbouring clipping boxes, poles, the two
 * sides of a seam, sheets folded onto each other; grazing copies also when
 * close in parameters or when graze says so), keeping one copy (hit_list.c:
 * the smallest (u, v) among exact ones, else the nearest the line), and
 * flags hits on the boundary of the domain {u0, u1, v0, v1}. dir_norm =
 * |dir|; scale is the model's size plus its coordinates' magnitude;
 * tol_residual the hit tolerance (pc_ray_frame). graze may be NULL. */
void pc_hit_list_finish(pc_hit_list *list, const double domain[4], double dir_norm,
                        double scale, double tol_residual, const pc_graze_test *graze);

#endif /* PC_INTERSECT_RAY_PATCH_H */
