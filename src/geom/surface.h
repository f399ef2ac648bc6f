/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The engine's surface: the NURBS surface with what every projection reads
 * from it, built once when the public handle is created (the patch grid,
 * its BVH, the tangent boxes, the bounding box and the model size).
 * projcurve_surface in projcurve.h is this struct; only the library sees
 * its layout.
 */
#ifndef PC_GEOM_SURFACE_H
#define PC_GEOM_SURFACE_H

#include <stddef.h>

#include "bezier/bezier.h"
#include "bezier/bvh.h"
#include "bezier/tangent_boxes.h"
#include "nurbs/nurbs.h"
#include "projcurve.h"

struct projcurve_surface {
    pc_nurbs_surface nurbs;
    pc_patch_grid grid;   /* Bezier patches, built at creation */
    pc_bvh bvh;           /* over grid.patches, built at creation */
    pc_tangent_boxes tangents; /* of Su, Sv over the BVH nodes, at creation */
    double box[6];        /* bounding box of the control net */
    double size;          /* its diagonal: the model scale for relative tolerances */
};

/* A new surface from validated-on-the-way NURBS data (the arguments of
 * projcurve_surface_create_nurbs, which see), with its grid, BVH, tangent
 * boxes, box and size. Statuses: those of pc_nurbs_surface_init, the
 * builders' NO_MEMORY; on failure *out is untouched and nothing is kept. */
projcurve_status pc_surface_create(projcurve_context *ctx, int deg_u, int deg_v, size_t n_u,
                                   size_t n_v, const double *ctrl, const double *weights,
                                   const double *knots_u, const double *knots_v,
                                   projcurve_surface **out);

/* Releases s and everything it holds; NULL is allowed. */
void pc_surface_destroy(projcurve_surface *s);

#endif /* PC_GEOM_SURFACE_H */
