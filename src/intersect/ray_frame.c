/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The ray frame: an orthonormal frame (e1, e2, d) on the line, the line's
 * tolerances, and a patch's control net expressed in it.
 */
#include "intersect/ray_frame.h"

#include <float.h>
#include <math.h>

/* A hit's distance to the line may be at most this fraction of the model
 * size, plus PC_HIT_ROUNDING_ULPS ulps of the coordinates' magnitude (where
 * the model is and how far the origin is from it): Newton reaches ~1e-16
 * of them, and an exactly tangent line gives a least-squares minimum at
 * rounding level; a line that misses by less counts as tangent. */
#define PC_HIT_RESIDUAL_REL 1e-12
#define PC_HIT_ROUNDING_ULPS 64.0
/* Control values in the ray frame carry rounding errors of a few ulps of
 * the coordinates' magnitude; clipping treats values this small as zero. */
#define PC_CLIP_ZERO_REL (16.0 * DBL_EPSILON)

void pc_ray_frame_init(pc_ray_frame *frame, pc_vec3 origin, pc_vec3 dir, double size,
                       double magnitude, int ray_only)
{
    const double norm = pc_vec3_length_robust(dir);
    frame->origin = origin;
    /* Scaled first, so that tiny or huge (finite) directions stay exact. */
    const double big = fmax(fabs(dir.x), fmax(fabs(dir.y), fabs(dir.z)));
    frame->d = vec3_normalize(vec3_scale(dir, 1.0 / big));
    vec3_orthonormal_pair(frame->d, &frame->e1, &frame->e2);
    frame->inv_dir_norm = 1.0 / norm;
    frame->origin_e1 = vec3_dot(frame->e1, origin);
    frame->origin_e2 = vec3_dot(frame->e2, origin);
    frame->origin_d = vec3_dot(frame->d, origin);
    frame->tol_residual = PC_HIT_RESIDUAL_REL * size + PC_HIT_ROUNDING_ULPS * DBL_EPSILON * magnitude;
    frame->tol_zero = PC_CLIP_ZERO_REL * (size + magnitude);
    frame->ray_only = ray_only;
}

double pc_vec3_length_robust(pc_vec3 a)
{
    const double big = fmax(fabs(a.x), fmax(fabs(a.y), fabs(a.z)));
    if (!(big > 0.0) || !isfinite(big))
        return big > 0.0 ? big : 0.0;
    return big * vec3_norm(vec3_scale(a, 1.0 / big));
}

static inline double min2(double a, double b) { return a < b ? a : b; }
static inline double max2(double a, double b) { return a > b ? a : b; }

/* The third coordinate is computed only for nets that pass the cull. The
 * net can meet the line only if X and Y each take both signs (within the
 * hit tolerance) over the control points: min (X - tol w) <= 0 <=
 * max (X + tol w), the same for Y. */
int pc_ray_frame_project(const pc_ray_frame *f, const pc_bezier_patch *patch, double *q,
                         double *w_max, double *w_min)
{
    const size_t np = (size_t)(patch->deg_u + 1) * (size_t)(patch->deg_v + 1);
    const double tol = f->tol_residual;
    const pc_vec3 e1 = f->e1, e2 = f->e2;
    double x_lo = INFINITY, x_hi = -INFINITY, y_lo = INFINITY, y_hi = -INFINITY;
    double w_top = 0.0, w_low = INFINITY;
    for (size_t k = 0; k < np; ++k) {
        const double *cw = patch->cw + 4 * k;
        const double w = cw[3];
        double *out = q + 4 * k;
        const double x = e1.x * cw[0] + e1.y * cw[1] + e1.z * cw[2] - w * f->origin_e1;
        const double y = e2.x * cw[0] + e2.y * cw[1] + e2.z * cw[2] - w * f->origin_e2;
        out[0] = x;
        out[1] = y;
        out[3] = w;
        w_top = max2(w_top, w);
        w_low = min2(w_low, w);
        const double slack = tol * w;
        x_lo = min2(x_lo, x - slack);
        x_hi = max2(x_hi, x + slack);
        y_lo = min2(y_lo, y - slack);
        y_hi = max2(y_hi, y + slack);
    }
    if (!(x_lo <= 0.0 && x_hi >= 0.0 && y_lo <= 0.0 && y_hi >= 0.0))
        return 0;
    const pc_vec3 d = f->d;
    double z_hi = -INFINITY;
    for (size_t k = 0; k < np; ++k) {
        const double *cw = patch->cw + 4 * k;
        const double z = d.x * cw[0] + d.y * cw[1] + d.z * cw[2] - cw[3] * f->origin_d;
        q[4 * k + 2] = z;
        z_hi = max2(z_hi, z + tol * cw[3]);
    }
    *w_max = w_top;
    *w_min = w_low;
    return z_hi >= 0.0 || !f->ray_only;
}
