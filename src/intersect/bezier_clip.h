/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Bezier clipping (Nishita, Sederberg & Kakimoto 1990) of a planar Bezier
 * patch Q(s, t) = (X, Y) against the origin: the patch's net is the ray
 * frame's (X, Y) (see ray_patch.h), so the zeros of Q are the line's hits.
 *
 * For a unit vector n, f = n . Q is a scalar Bezier function with control
 * values n . Q_ij, and by linear precision the points (s, f(s, t)) lie in
 * the convex hull of {(i / m, n . Q_ij)}. A zero of Q therefore has its s in
 * the interval where that hull meets f = 0; the net is cut down to it by de
 * Casteljau subdivision, and the same is done in t. n is chosen across the
 * patch's t edges for an s clip (so that f varies mostly with s) and the
 * perpendicular functional is used too; both give valid intervals.
 */
#ifndef PC_INTERSECT_BEZIER_CLIP_H
#define PC_INTERSECT_BEZIER_CLIP_H

/* A clipping box's sides are converged below this width (local
 * parameters): Newton then starts within ~1e-9 of a simple root. */
#define PC_CLIP_WIDTH_TOL 1e-9

typedef enum pc_clip_outcome {
    PC_CLIP_EMPTY,     /* no zero in the box */
    PC_CLIP_PROGRESS,  /* a side shrank by the progress factor or more */
    PC_CLIP_STALLED,   /* no side shrank enough: subdivide */
    PC_CLIP_CONVERGED  /* both sides below PC_CLIP_WIDTH_TOL */
} pc_clip_outcome;

/* One clipping round in s then t. net holds 2 * (m + 1) * (n + 1) values
 * (X, Y per point, s index fastest) describing the patch over
 * box = {s0, s1, t0, t1}; both are updated in place. m, n >= 1. Control
 * values within +-zero_tol count as zero (their rounding error), so that a
 * root on the box's edge is not clipped away by the sign of a rounding. */
pc_clip_outcome pc_bezier_clip_step(double *net, int m, int n, double zero_tol, double box[4]);

/* Whether the planar net is a sliver through the origin: its extent
 * across its longer corner-to-corner direction is at most width and
 * that band contains 0. Near a tangent point the box's image is such a
 * sliver (the Jacobian has rank one) and clipping cannot shrink it. */
int pc_bezier_clip_is_sliver(const double *net, int m, int n, double width);

/* Restricts a net over [0, 1]^2 to box = {s0, s1, t0, t1} (de Casteljau). */
void pc_bezier_clip_restrict(double *net, int m, int n, const double box[4]);

/* Halves the box in direction dir (0: s, 1: t): net/box keep the lower
 * half, other_net/other_box receive the upper half. */
void pc_bezier_clip_split(double *net, double *other_net, int m, int n, int dir, double box[4],
                          double other_box[4]);

#endif /* PC_INTERSECT_BEZIER_CLIP_H */
