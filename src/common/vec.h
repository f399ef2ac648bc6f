/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Small vector helpers, inline so that the formulas in the numerical code
 * read like the papers' equations and cost nothing.
 */
#ifndef PC_COMMON_VEC_H
#define PC_COMMON_VEC_H

#include <math.h>

typedef struct pc_vec3 {
    double x, y, z;
} pc_vec3;
/* Arrays of pc_vec3 are copied to and from arrays of 3 doubles as bytes. */
_Static_assert(sizeof(pc_vec3) == 3 * sizeof(double), "pc_vec3 is three packed doubles");

static inline pc_vec3 vec3(double x, double y, double z)
{
    pc_vec3 r = {x, y, z};
    return r;
}
static inline pc_vec3 vec3_load(const double *p) { return vec3(p[0], p[1], p[2]); }
static inline void vec3_store(pc_vec3 a, double *p)
{
    p[0] = a.x;
    p[1] = a.y;
    p[2] = a.z;
}
static inline pc_vec3 vec3_add(pc_vec3 a, pc_vec3 b) { return vec3(a.x + b.x, a.y + b.y, a.z + b.z); }
static inline pc_vec3 vec3_sub(pc_vec3 a, pc_vec3 b) { return vec3(a.x - b.x, a.y - b.y, a.z - b.z); }
static inline pc_vec3 vec3_scale(pc_vec3 a, double s) { return vec3(a.x * s, a.y * s, a.z * s); }
/* a + s * b */
static inline pc_vec3 vec3_axpy(pc_vec3 a, double s, pc_vec3 b)
{
    return vec3(a.x + s * b.x, a.y + s * b.y, a.z + s * b.z);
}
static inline double vec3_dot(pc_vec3 a, pc_vec3 b) { return a.x * b.x + a.y * b.y + a.z * b.z; }
static inline pc_vec3 vec3_cross(pc_vec3 a, pc_vec3 b)
{
    return vec3(a.y * b.z - a.z * b.y, a.z * b.x - a.x * b.z, a.x * b.y - a.y * b.x);
}
static inline double vec3_norm(pc_vec3 a) { return sqrt(vec3_dot(a, a)); }
static inline double vec3_dist(pc_vec3 a, pc_vec3 b) { return vec3_norm(vec3_sub(a, b)); }
static inline int vec3_is_finite(pc_vec3 a) { return isfinite(a.x) && isfinite(a.y) && isfinite(a.z); }

/* Unit vector along a; a must not be zero. */
static inline pc_vec3 vec3_normalize(pc_vec3 a) { return vec3_scale(a, 1.0 / vec3_norm(a)); }

/* An orthonormal pair (e1, e2) perpendicular to the unit vector d, chosen
 * deterministically from d alone (Frisvad-style branch on the sign of z). */
static inline void vec3_orthonormal_pair(pc_vec3 d, pc_vec3 *e1, pc_vec3 *e2)
{
    const double sign = d.z >= 0.0 ? 1.0 : -1.0;
    const double a = -1.0 / (sign + d.z);
    const double b = d.x * d.y * a;
    *e1 = vec3(1.0 + sign * d.x * d.x * a, sign * b, -sign * d.x);
    *e2 = vec3(b, sign + d.y * d.y * a, -d.y);
}

/* Solves the 2x2 system [a b; c d] x = r. Returns 0 and leaves x untouched
 * when |det| <= tiny * (scale of the matrix)^2. */
static inline int mat2_solve(double a, double b, double c, double d, const double r[2],
                             double x[2])
{
    const double det = a * d - b * c;
    const double scale = fabs(a) + fabs(b) + fabs(c) + fabs(d);
    if (!(fabs(det) > 1e-300) || fabs(det) <= 1e-15 * scale * scale)
        return 0;
    x[0] = (d * r[0] - b * r[1]) / det;
    x[1] = (a * r[1] - c * r[0]) / det;
    return 1;
}

/* Axis-aligned boxes as {xmin, ymin, zmin, xmax, ymax, zmax}. */
static inline void box_empty(double box[6])
{
    box[0] = box[1] = box[2] = INFINITY;
    box[3] = box[4] = box[5] = -INFINITY;
}
static inline void box_add_point(double box[6], const double p[3])
{
    for (int k = 0; k < 3; ++k) {
        if (p[k] < box[k]) box[k] = p[k];
        if (p[k] > box[k + 3]) box[k + 3] = p[k];
    }
}
static inline void box_add_box(double box[6], const double other[6])
{
    for (int k = 0; k < 3; ++k) {
        if (other[k] < box[k]) box[k] = other[k];
        if (other[k + 3] > box[k + 3]) box[k + 3] = other[k + 3];
    }
}
static inline double box_diagonal(const double box[6])
{
    return vec3_norm(vec3(box[3] - box[0], box[4] - box[1], box[5] - box[2]));
}

#endif /* PC_COMMON_VEC_H */
