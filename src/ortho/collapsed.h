/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Degenerate points of a parametrisation: where one partial derivative of
 * S(u, v) vanishes although the surface is regular there. An exact NURBS
 * sphere has its poles on the edges v = 0 and v = 1, each collapsed to one
 * point (Su = 0 along the whole edge); so have the apex of a cone or a
 * paraboloid of revolution and any triangular patch made from a square one.
 *
 * At such a point the first fundamental form g is singular, and so is the
 * orthogonal projective tensor K = g + (S - P).S_ij, though no centre of
 * curvature is anywhere near: det K / (|Su||Sv|)^2 is 0/0. Near it, the
 * tangential residual along Su is (S - P).Su / |Su| with the rounding of Su
 * (~DBL_EPSILON times the size of the control net, whatever |Su| is)
 * divided by a vanishing |Su|, and the u of a foot point is ill-determined
 * (moving u moves S by |Su| du). ortho_projector.c treats the points where
 * |Su| < PC_COLLAPSED_RATIO |Sv| (or the other way round) as the collapsed
 * direction's edge: the foot point is corrected along the regular
 * direction only, q' has no component along the collapsed one.
 */
#ifndef PC_ORTHO_COLLAPSED_H
#define PC_ORTHO_COLLAPSED_H

#include "common/vec.h"

/* Below this ratio of |Su| to |Sv| (or of |Sv| to |Su|) a point counts as
 * collapsed. On the NURBS sphere of tests/support/shapes.c that is within
 * 1.6e-7 of the pole in v, 4.5e-7 of the radius in space. Above it K is still well enough
 * conditioned for the 2 x 2 solves: its smaller diagonal entry is
 * ~ratio^2 times the larger, 1e-12, against the 1e-15 floor of mat2_solve,
 * and the rounding of Su is 1e-16 / 1e-6 = 1e-10 of its length. */
#define PC_COLLAPSED_RATIO 1e-6

typedef enum pc_collapse {
    PC_COLLAPSE_NONE = 0,
    PC_COLLAPSE_U = 1,   /* Su ~ 0: an edge v = const collapsed to a point */
    PC_COLLAPSE_V = 2    /* Sv ~ 0: an edge u = const collapsed to a point */
} pc_collapse;

static inline pc_collapse pc_collapsed_direction(pc_vec3 su, pc_vec3 sv)
{
    const double nu = vec3_norm(su), nv = vec3_norm(sv);
    if (nu < PC_COLLAPSED_RATIO * nv)
        return PC_COLLAPSE_U;
    if (nv < PC_COLLAPSED_RATIO * nu)
        return PC_COLLAPSE_V;
    return PC_COLLAPSE_NONE;
}

#endif /* PC_ORTHO_COLLAPSED_H */
