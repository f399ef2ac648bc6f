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

/* The third coordinate is computed only for nets that pass the cull. */
int pc_ray_frame_project(const pc_ray_frame *f, const pc_bezier_patch *patch, double *q,
                         double *w_max, double *w_min)
{
    const size_t np = (size_t)(patch->deg_u + 1) * (size_t)(patch->deg_v + 1);
    const double tol = f->tol_residual;
    int neg_x = 0, pos_x = 0, neg_y = 0, pos_y = 0;
    double w_top = 0.0, w_low = INFINITY;
    for (size_t k = 0; k < np; ++k) {
        const double *cw = patch->cw + 4 * k;
        const pc_vec3 p = vec3(cw[0], cw[1], cw[2]);
        const double w = cw[3];
        double *out = q + 4 * k;
        out[0] = vec3_dot(f->e1, p) - w * f->origin_e1;
        out[1] = vec3_dot(f->e2, p) - w * f->origin_e2;
        out[3] = w;
        w_top = w > w_top ? w : w_top;
        w_low = w < w_low ? w : w_low;
        const double slack = tol * w;
        neg_x |= out[0] <= slack;
        pos_x |= out[0] >= -slack;
        neg_y |= out[1] <= slack;
        pos_y |= out[1] >= -slack;
    }
    if (!(neg_x && pos_x && neg_y && pos_y))
        return 0;
    int ahead = 0;
    for (size_t k = 0; k < np; ++k) {
        const double *cw = patch->cw + 4 * k;
        double *out = q + 4 * k;
        out[2] = vec3_dot(f->d, vec3(cw[0], cw[1], cw[2])) - cw[3] * f->origin_d;
        ahead |= out[2] >= -tol * cw[3];
    }
    *w_max = w_top;
    *w_min = w_low;
    return ahead || !f->ray_only;
}

