/*
 * One ray against one Bezier patch, in the ray's own frame.
 *
 * The line o + lambda * dir is the intersection of the planes
 * e1.(x - o) = 0 and e2.(x - o) = 0, with (e1, e2, d = dir / |dir|)
 * orthonormal. In that frame a homogeneous control point (w x, w) becomes
 * (w e1.(x - o), w e2.(x - o), w d.(x - o), w): the patch's two distance
 * functions d1 = e1.(S - o), d2 = e2.(S - o) times the weight are polynomial
 * Bezier functions whose control values are the first two coordinates, and
 * the line meets the patch exactly where both vanish (w > 0).
 */
#ifndef PC_INTERSECT_RAY_PATCH_H
#define PC_INTERSECT_RAY_PATCH_H

#include <stddef.h>

#include "bezier/bezier.h"
#include "common/vec.h"
#include "intersect/intersect.h"

typedef struct pc_ray_frame {
    pc_vec3 origin;
    pc_vec3 e1, e2, d;     /* orthonormal, d along dir */
    double origin_e1, origin_e2, origin_d; /* e1.o, e2.o, d.o */
    double inv_dir_norm;   /* 1 / |dir|: lambda = d.(S - o) / |dir| */
    double tol_residual;   /* a hit's distance to the line, model units */
    double tol_zero;       /* rounding level of distances, model units */
    int ray_only;          /* keep only lambda > 0 */
} pc_ray_frame;

/* |a| without overflow or underflow of the squares (a finite). */
double pc_vec3_length_robust(pc_vec3 a);

/* The frame of the line o + lambda * dir (dir finite and non-zero) with
 * the tolerances for hits: `size` is the model's size, `magnitude` that of
 * the coordinates involved (|centre| + |o - centre| of the model's box),
 * which bounds their rounding errors. */
void pc_ray_frame_init(pc_ray_frame *frame, pc_vec3 origin, pc_vec3 dir, double size,
                       double magnitude, int ray_only);

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

/* Sorts the hits by lambda, merges the ones that are the same point of the
 * surface found twice (shared edges and corners, neighbouring clipping
 * boxes, poles; grazing copies also when graze says so) and flags hits on
 * the boundary of the domain {u0, u1, v0, v1}. dir_norm = |dir|; scale is
 * the model's size plus its coordinates' magnitude. graze may be NULL. */
void pc_hit_list_finish(pc_hit_list *list, const double domain[4], double dir_norm,
                        double scale, const pc_graze_test *graze);

#endif /* PC_INTERSECT_RAY_PATCH_H */
