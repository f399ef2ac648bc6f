/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The frame of a line o + lambda * dir.
 *
 * The line is the intersection of the planes e1.(x - o) = 0 and
 * e2.(x - o) = 0, with (e1, e2, d = dir / |dir|) orthonormal. In that frame
 * a homogeneous control point (w x, w) becomes
 * (w e1.(x - o), w e2.(x - o), w d.(x - o), w): the patch's two distance
 * functions d1 = e1.(S - o), d2 = e2.(S - o) times the weight are
 * polynomial Bezier functions whose control values are the first two
 * coordinates, and the line meets the patch exactly where both vanish
 * (w > 0).
 */
#ifndef PC_INTERSECT_RAY_FRAME_H
#define PC_INTERSECT_RAY_FRAME_H

#include "bezier/bezier.h"
#include "common/vec.h"

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

/* Writes the patch's net in the frame into q (4 values per control point:
 * X, Y, Z, W) and its largest and smallest weights. Returns 0 when the
 * control net lies entirely on one side of one of the two planes through
 * the line (or, for a ray, behind its origin): the convex hull then misses
 * the line, and q is only partly written. */
int pc_ray_frame_project(const pc_ray_frame *f, const pc_bezier_patch *patch, double *q,
                         double *w_max, double *w_min);

#endif /* PC_INTERSECT_RAY_FRAME_H */
