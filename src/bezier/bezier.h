/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Bezier decomposition of a NURBS surface: one Bezier patch per non-empty
 * knot span pair, with its homogeneous control net, parameter box, grid
 * position and a bounding box of its (projected) control net, which contains
 * the patch by the convex hull property.
 */
#ifndef PC_BEZIER_H
#define PC_BEZIER_H

#include <stddef.h>

#include "common/vec.h"
#include "nurbs/nurbs.h"

typedef struct pc_bezier_patch {
    int deg_u, deg_v;
    double u0, u1, v0, v1;  /* parameter box in the surface's parameters */
    const double *cw;       /* 4 * (deg_u + 1) * (deg_v + 1), u fastest */
    double box[6];          /* bounding box of the Cartesian control points */
    size_t iu, iv;          /* position in the patch grid */
    /* Kept by the patch grid for point queries (NULL / 0 in patches made
     * elsewhere): the Cartesian control points, 3 each, and the net's
     * pc_bezier_net_flatness. */
    const double *xyz;
    double flatness;
} pc_bezier_patch;

typedef struct pc_patch_grid {
    size_t spans_u, spans_v;  /* patches = spans_u * spans_v, iu fastest */
    pc_bezier_patch *patches;
    double *breaks_u;         /* spans_u + 1 distinct knot values */
    double *breaks_v;         /* spans_v + 1 */
    /* Per break: 1 where the surface may be only C^0 across it (the domain
     * boundary, or a knot of multiplicity >= degree). */
    unsigned char *crease_u;  /* spans_u + 1 */
    unsigned char *crease_v;  /* spans_v + 1 */
    double *cw;               /* storage of all patch nets */
    double *xyz;              /* storage of all their Cartesian points */
} pc_patch_grid;

/* Decomposes s by knot insertion. Statuses: OK, NO_MEMORY, OVERFLOW. */
projcurve_status pc_patch_grid_build(projcurve_context *ctx, pc_patch_grid *grid,
                                     const pc_nurbs_surface *s);
void pc_patch_grid_free(pc_patch_grid *grid);

/* Index of the patch containing (u, v) (clamped to the domain). */
size_t pc_patch_grid_locate(const pc_patch_grid *grid, double u, double v);

/* Patch at grid position (iu, iv), or NULL outside the grid (neighbours are
 * (iu +- 1, iv) and (iu, iv +- 1)). */
const pc_bezier_patch *pc_patch_grid_at(const pc_patch_grid *grid, size_t iu, size_t iv);

/* Point and derivatives (as pc_nurbs_surface_eval) of a patch at surface
 * parameters (u, v) inside its box. */
void pc_bezier_patch_eval(const pc_bezier_patch *patch, double u, double v, int n_deriv,
                          pc_vec3 *out);

/* Curve decomposition: Bezier segments of a NURBS curve (degree + 1
 * homogeneous points each, 4 doubles per point) and the breakpoints. */
typedef struct pc_bezier_curves {
    int degree;
    size_t n_segments;
    double *breaks;  /* n_segments + 1 */
    double *cw;      /* 4 * (degree + 1) * n_segments */
} pc_bezier_curves;

projcurve_status pc_bezier_curves_build(projcurve_context *ctx, pc_bezier_curves *out,
                                        const pc_nurbs_curve *c);
void pc_bezier_curves_free(pc_bezier_curves *b);

#endif /* PC_BEZIER_H */
