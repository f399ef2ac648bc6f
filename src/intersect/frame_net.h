/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A Bezier patch seen from a ray: its homogeneous control net expressed in
 * the ray frame (see ray_patch.h), evaluated with first derivatives, and the
 * two ways of finishing a root of (X, Y)(s, t) = 0 there: Newton for a
 * simple root, a damped least-squares descent on X^2 + Y^2 for a double
 * (tangent) root where Newton's Jacobian is singular.
 *
 * (s, t) are the patch's local parameters in [0, 1]^2.
 */
#ifndef PC_INTERSECT_FRAME_NET_H
#define PC_INTERSECT_FRAME_NET_H

typedef struct pc_frame_net {
    int deg_u, deg_v;
    const double *q; /* 4 * (deg_u + 1) * (deg_v + 1): (X, Y, Z, W), u fastest */
} pc_frame_net;

/* A root candidate and the geometry there, in the ray frame. */
typedef struct pc_frame_root {
    double s, t;
    double x, y, z;  /* the surface point: z = d.(S - o) */
    double residual; /* sqrt(x^2 + y^2): distance to the line */
    double cos_dir;  /* |d . n| / |n| (0 where the normal vanishes) */
    double jac[4];   /* X_s, X_t, Y_s, Y_t: the Jacobian Newton uses */
} pc_frame_root;

/* D = (X, Y, Z, W) at (s, t) and its partial derivatives (any of ds, dt may
 * be NULL). No allocation; degrees up to PROJCURVE_MAX_DEGREE. */
void pc_frame_net_eval(const pc_frame_net *net, double s, double t, double d[4], double ds[4],
                       double dt[4]);

/* Fills `out` with the point at (s, t). */
void pc_frame_net_point(const pc_frame_net *net, double s, double t, pc_frame_root *out);

/* Bounds on the Jacobian J = [X_s X_t; Y_s Y_t] over the patch, from the
 * net's differences (a Bezier function's derivatives lie in the hull of its
 * differences times the degree factors): *lipschitz = L with
 * |J(a) - J(b)|_F <= L |a - b|, and *jac_max >= |J|_F everywhere. */
void pc_frame_net_jacobian_bounds(const pc_frame_net *net, double *lipschitz, double *jac_max);

/* Sides of the patch (bit 0: t = 0, bit 1: t = 1, bit 2: s = 0, bit 3:
 * s = 1) whose control points all coincide within tol (a pole of the
 * parametrisation, e.g. of a sphere or a cone) at a point within tol of the
 * line (X = Y = 0). */
unsigned pc_frame_net_poles_on_line(const pc_frame_net *net, double tol);

/* Whether all control points coincide within tol (a patch that is one
 * point). */
int pc_frame_net_is_point(const pc_frame_net *net, double tol);

/* Newton on (X, Y) = 0 from (s, t). Returns 1 when the step fell below the
 * step tolerance within the iteration bound, 0 when the Jacobian was
 * singular, the iterate left the patch or the bound was hit; out holds the
 * last iterate either way. */
int pc_frame_net_newton(const pc_frame_net *net, double s, double t, pc_frame_root *out);

/* Least-squares descent (Levenberg-Marquardt) on X^2 + Y^2 from the centre
 * of box = {s0, s1, t0, t1}, kept inside the box widened by its own size
 * and clamped to the patch. out holds the best point found. Returns 1 when
 * that point is a local minimum of the region's interior (or of the
 * patch's edge), 0 when the widened box held it back: then the box only
 * borders a minimum that a neighbouring box owns. */
int pc_frame_net_minimize(const pc_frame_net *net, const double box[4], pc_frame_root *out);

#endif /* PC_INTERSECT_FRAME_NET_H */
