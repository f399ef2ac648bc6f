/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Point classification against a set of closed polygons (the flattened
 * loops of a face, outer loop counter-clockwise and holes clockwise): in,
 * out, or on the boundary within a tolerance.
 *
 * A uniform grid over the polygons' box holds, for each cell, the segments
 * whose box grown by the tolerance meets the cell, and a reference point of
 * the cell with its winding number. A query looks at its cell only: a
 * segment within tol of the point makes it ON; otherwise its winding number
 * is the reference's plus the signed crossings of the segment from the
 * reference to the point with the cell's segments (the path stays in the
 * cell, so no other segment can cross it). Reference points are at least
 * tol away from every segment, so both counts are decided by orientation
 * tests on points clear of the segments; a vertex on the path's line is
 * given one side for both segments that share it, so crossings through
 * vertices are counted once.
 */
#ifndef PC_BREP_CLASSIFY_H
#define PC_BREP_CLASSIFY_H

#include <stddef.h>

#include "projcurve.h"

typedef struct pc_classifier {
    double *seg;        /* 4 per segment: ax, ay, bx, by */
    size_t n_seg;
    double x0, y0, dx, dy; /* grid origin and cell size */
    size_t nx, ny;
    size_t *cell_start; /* nx * ny + 1: the segments of cell c are cell_seg[start[c]..start[c+1]) */
    size_t *cell_seg;
    double *ref;        /* 2 per cell */
    int *ref_winding;
    double tol;
} pc_classifier;

typedef enum pc_where { PC_OUT = 0, PC_IN = 1, PC_ON = 2 } pc_where;

/* Cells per segment aimed at: a few segments a cell on average. */
#define PC_CLASSIFY_CELLS_PER_SEGMENT 1.0
#define PC_CLASSIFY_MAX_CELLS ((size_t)1 << 22)
/* Cell-list entries a segment may cost on average before the grid is
 * coarsened (classify.c, coarsen_grid). */
#define PC_CLASSIFY_MAX_LISTED_PER_SEGMENT 64

/* Builds the classifier of the closed polygons polys[k] (n_pts[k] points,
 * 2 doubles each, the closing segment implied). tol > 0. Statuses: OK,
 * NO_MEMORY. */
projcurve_status pc_classifier_build(projcurve_context *ctx, pc_classifier *c, size_t n_polys,
                                     const double *const *polys, const size_t *n_pts, double tol);
void pc_classifier_free(pc_classifier *c);

/* IN when the winding number is not 0, ON within tol of a segment. */
pc_where pc_classify(const pc_classifier *c, double x, double y);

/* The winding number of (x, y) about the polygons by a ray to +x over
 * every segment: the brute-force rule that the grid's references use. */
int pc_winding_brute(const double *seg, size_t n_seg, double x, double y);

#endif /* PC_BREP_CLASSIFY_H */
