/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Point projection ([Ook] and its surface analogue): closest points of
 * curves and surfaces, and every foot point of a point on a surface.
 *
 * A foot point of p on S is a (u, v) where S - p is normal to S:
 *     G(u, v) = [(S - p).Su, (S - p).Sv] = 0        ([Ook], d(u) = 0, in 2D)
 * The closest point is the least distant of the interior foot points and
 * the minima along the boundary. Both searches walk the Bezier patches
 * (near first, through the BVH) and subdivide them, discarding sub-patches
 * that provably hold no candidate, so that Newton starts in every basin
 * that matters (see docs/geometry.md).
 */
#ifndef PC_POINT_H
#define PC_POINT_H

#include <stddef.h>

#include "common/budget.h"
#include "common/vec.h"
#include "geom/curve.h"
#include "geom/surface.h"

/* Closest point of a surface: parameters, point and distance. */
typedef struct pc_surface_point {
    double u, v;
    pc_vec3 q;
    double dist;
} pc_surface_point;

/* Closest point of p on the surface (edges and corners included).
 * Statuses: OK, NO_MEMORY. */
projcurve_status pc_surface_closest(projcurve_context *ctx, const projcurve_surface *s,
                                    pc_vec3 p, pc_surface_point *out);

/* A growable list of foot points owned by the caller. */
typedef struct pc_foot_list {
    pc_surface_point *items;
    size_t count, capacity;
} pc_foot_list;

void pc_foot_list_free(pc_foot_list *list);

/* Every interior foot point of p (G = 0, minima, maxima and saddles of the
 * distance), each once, sorted by distance. `list` is cleared first. Whole
 * BVH subtrees where (S - p).Su or (S - p).Sv keeps its sign are skipped
 * (bezier/tangent_boxes.h).
 * Degenerate inputs with a continuum of foot points (p at the centre of a
 * sphere) give a finite sample of it. Statuses: OK, NO_MEMORY. */
projcurve_status pc_surface_foot_points(projcurve_context *ctx, const projcurve_surface *s,
                                        pc_vec3 p, pc_foot_list *list);

/* pc_surface_foot_points into the caller's array, as
 * projcurve_surface_foot_points gives them (up to capacity (u, v) pairs,
 * *count = the number found), polling budget (may be NULL) once per
 * sub-patch examined: a search on a large surface is long enough to need
 * it. Once the budget stops the call, the search ends with the feet found
 * so far (the caller sees the budget's status at its next poll).
 * Statuses: OK, NO_MEMORY. */
projcurve_status pc_surface_foot_points_uv(projcurve_context *ctx, const projcurve_surface *s,
                                           pc_vec3 p, pc_budget *budget, size_t capacity,
                                           double *uv, size_t *count);

/* The same search without the BVH culling (every patch subdivided): the
 * reference that the culled search must agree with (tests). */
projcurve_status pc_surface_foot_points_exhaustive(projcurve_context *ctx,
                                                   const projcurve_surface *s, pc_vec3 p,
                                                   pc_foot_list *list);

/* Newton on G = 0 from uv (updated in place, kept in the domain), damped by
 * backtracking on |G|^2, with steps limited to max_step_u, max_step_v
 * (parameter units); it gives up when it strays more than 4 such steps from
 * its start. Returns 1 when it converged to a foot point. Both solvers
 * keep out of knot spans of rounding width at the ends of the domain
 * (surface_newton.c, THIN_END_SPAN): their inner end is the same curve of
 * S, with meaningful derivatives. */
int pc_surface_foot_newton(const pc_nurbs_surface *s, pc_vec3 p, double model_size,
                           double max_step_u, double max_step_v, double uv[2]);

/* Local minimum of |S - p| over the domain from uv (updated in place):
 * Newton with a Gauss-Newton fallback, backtracking, bounds handled by an
 * active set, so minima on edges and corners are found too. Returns the
 * squared distance reached. */
double pc_surface_minimize(const pc_nurbs_surface *s, pc_vec3 p, double model_size,
                           double uv[2]);

/* The same along the iso-line through uv: only u (dir 0) or v (dir 1)
 * moves. For minima on creases, where S is only C^0 across the line. */
double pc_surface_minimize_along(const pc_nurbs_surface *s, pc_vec3 p, double model_size,
                                 double uv[2], int dir);

/* Closest point of p on the curve (ends included): *t, *q, *dist.
 * Statuses: OK, CALLBACK (a callback failed), NO_MEMORY. */
projcurve_status pc_curve_closest(projcurve_context *ctx, const projcurve_curve *c, pc_vec3 p,
                                  double *t, pc_vec3 *q, double *dist);

#endif /* PC_POINT_H */
