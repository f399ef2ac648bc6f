/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Seams and poles (docs/seams.md): which edges of a surface's domain are
 * identified with one another (a closed or periodic direction) or collapsed
 * to a point (a pole), and the stage that joins the branches the tracer
 * ended at such an edge with those that start on its other side, at the same
 * curve parameter and the same 3D point, into one branch whose pcurve jumps
 * there by a recorded (du, dv).
 */
#ifndef PC_SEAM_SEAM_H
#define PC_SEAM_SEAM_H

#include "common/params.h"
#include "geom/surface.h"
#include "trace/result.h"

/* The edges of the domain, bit i of a side mask: u0, u1, v0, v1. */
enum { PC_SIDE_U0 = 1, PC_SIDE_U1 = 2, PC_SIDE_V0 = 4, PC_SIDE_V1 = 8 };

typedef struct pc_closure {
    /* S(u0, v) = S(u1, v) for every v (closed_u), S(u, v0) = S(u, v1) for
     * every u (closed_v). */
    int closed_u, closed_v;
    /* PC_SIDE_* bits of the edges collapsed to one point (poles). */
    unsigned collapsed;
} pc_closure;

/* The closure of s to the distance tol (model units), read on the control
 * net (s is clamped: its edge curves are the B-splines of its first and
 * last rows and columns of poles, over the same knots):
 * - closed in u when, for every column j, the Cartesian poles P(0, j) and
 *   P(n_u - 1, j) are within tol and the weight ratios w(0, j) / w(n_u - 1, j)
 *   agree to 1e-12 relative: the two edge curves then have the same poles
 *   and proportional weights, the same curve; (v alike);
 * - an edge collapsed when all its Cartesian poles lie within tol of its
 *   first (the edge curve lies in their convex hull). */
void pc_surface_closure(const pc_nurbs_surface *s, double tol, pc_closure *out);

/* The joining distance for a projection with parameters p onto a model of
 * size `size`: 1000 times the model's precision (pc_params_precision;
 * 1e-9 of the size by default). The tracer places the exit at an edge to
 * the corrector's tolerance in space and snaps it to the edge from within
 * 1e-9 of the domain's width at most (trace/boundary_exit.c), so both
 * sides of a seam meet within far less; distinct branches are farther
 * apart than that. */
double pc_seam_join_tolerance(const pc_params *p, double size);

/* Joins, in r (a parametric result), every branch that ends with
 * PROJCURVE_END_BOUNDARY to the branch that starts with
 * PROJCURVE_START_BOUNDARY where P(t) and S(u, v) are the same points
 * within the joining distance, both (u, v) on identified edges of the
 * surface (a closed direction, or the same collapsed edge). The joined
 * branch keeps its points (the vertex at the jump appears on both sides:
 * two vertices with the same t), its pieces in increasing t, one record
 * pc_seam_record per jump, and compact forms made one (seam/compact.c).
 * Statuses: OK, NO_MEMORY (r then is left with the joins made so far,
 * every branch valid). */
projcurve_status pc_seam_join(projcurve_context *ctx, const projcurve_surface *surface,
                              const projcurve_curve *curve, const pc_params *p,
                              projcurve_result *r);

/* The seam stage of a projection driver, last: pc_seam_join when
 * p->join_seams and st keeps a result; st returned unless joining ran out
 * of memory. */
projcurve_status pc_seam_stage(projcurve_context *ctx, const projcurve_surface *surface,
                               const projcurve_curve *curve, const pc_params *p,
                               projcurve_result *r, projcurve_status st);

/* Joins the compact forms of b (over [.., t]) and next (over [t, ..]) into
 * b's: the pcurves in unwrapped (u, v), next's poles shifted by -shift
 * (the sum of b's jumps and this one), the 3D curves as one curve, each C0
 * at t with the joint the mean of the two ends. next's are left to the
 * caller to free. Statuses: OK, NO_MEMORY. */
projcurve_status pc_seam_join_compact(projcurve_context *ctx, pc_branch *b,
                                      const pc_branch *next, const double shift[2]);

/* The sum of b's jumps at or before t into shift: a point of b at t in the
 * domain minus shift is its unwrapped (u, v). */
void pc_seam_unwrap_shift(const pc_branch *b, double t, double shift[2]);

/* The seam records of the part [a, b] of src (a < b, in t) into dst, a
 * branch made of that part (its compact forms already restricted to
 * [a, b], pc_bspline_restrict): the records of src with a < t_k < b
 * (dst's own are replaced), and dst's compact pcurve shifted by the sum
 * of src's jumps at or before a (pc_seam_unwrap_shift), so that it starts
 * in the domain and (u, v) on S at t is its value plus the sum of dst's
 * jumps with t_k <= t, as for any branch (docs/seams.md). A constant shift
 * of the poles moves a rational B-spline by that constant, exactly.
 * Statuses: OK, NO_MEMORY (dst unchanged). */
projcurve_status pc_seam_restrict_records(projcurve_context *ctx, const pc_branch *src,
                                          double a, double b, pc_branch *dst);

#endif /* PC_SEAM_SEAM_H */
