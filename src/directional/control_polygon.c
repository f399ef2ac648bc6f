/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Ray / control-polygon hits (Moller-Trumbore on each triangle of the net).
 */
#include "directional/control_polygon.h"

/* Triangles whose |det| is below this fraction of |e1||e2||dir| are
 * degenerate (or parallel to the ray) and skipped. */
#define PC_POLYGON_DEGENERATE 1e-14

static pc_vec3 net_point(const pc_bezier_patch *patch, int i, int j)
{
    const double *c = patch->cw + 4 * ((size_t)j * (size_t)(patch->deg_u + 1) + (size_t)i);
    const double w = c[3] != 0.0 ? c[3] : 1.0;
    return vec3(c[0] / w, c[1] / w, c[2] / w);
}

/* Ray parameter of the hit with triangle (a, b, c), or -1. Barycentric
 * bounds are closed so that a ray through a shared edge is not lost. */
static double ray_triangle(pc_vec3 o, pc_vec3 d, pc_vec3 a, pc_vec3 b, pc_vec3 c)
{
    const pc_vec3 e1 = vec3_sub(b, a), e2 = vec3_sub(c, a);
    const pc_vec3 pv = vec3_cross(d, e2);
    const double det = vec3_dot(e1, pv);
    const double scale = vec3_norm(e1) * vec3_norm(e2) * vec3_norm(d);
    if (!(fabs(det) > PC_POLYGON_DEGENERATE * scale))
        return -1.0;
    const double inv = 1.0 / det;
    const pc_vec3 tv = vec3_sub(o, a);
    const double bu = vec3_dot(tv, pv) * inv;
    if (bu < 0.0 || bu > 1.0)
        return -1.0;
    const pc_vec3 qv = vec3_cross(tv, e1);
    const double bv = vec3_dot(d, qv) * inv;
    if (bv < 0.0 || bu + bv > 1.0)
        return -1.0;
    return vec3_dot(e2, qv) * inv;
}

size_t pc_control_polygon_ray_hits(const pc_bezier_patch *patch, pc_vec3 origin, pc_vec3 dir,
                                   pc_vec3 *out, size_t max)
{
    size_t n = 0;
    for (int j = 0; j < patch->deg_v; ++j) {
        for (int i = 0; i < patch->deg_u; ++i) {
            const pc_vec3 p00 = net_point(patch, i, j), p10 = net_point(patch, i + 1, j);
            const pc_vec3 p01 = net_point(patch, i, j + 1), p11 = net_point(patch, i + 1, j + 1);
            const double lam[2] = {ray_triangle(origin, dir, p00, p10, p11),
                                   ray_triangle(origin, dir, p00, p11, p01)};
            for (int k = 0; k < 2; ++k) {
                if (!(lam[k] > 0.0))
                    continue;
                if (n < max)
                    out[n] = vec3_axpy(origin, lam[k], dir);
                ++n;
            }
        }
    }
    return n;
}
