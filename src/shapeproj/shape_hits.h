/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The nearest hits across the faces of a shape (PROJCURVE_OPT_HITS
 * nearest; docs/hits.md).
 *
 * Each face is projected with every hit kept (a hit on the untrimmed
 * surface outside the face's loops is no hit, so it must not occlude) and
 * clipped; then each face piece -- every branch of every face, those of
 * its own face included -- is cut where a piece of any face becomes nearer
 * (|S(q(t)) - P(t)|, the distance along the ray; orthogonal: the foot
 * point's distance) and the parts that are not the nearest are dropped.
 * The candidate cuts of a piece are its ends, the ends of every piece
 * overlapping it in t, and the crossings of its distance with theirs
 * (sign changes at the vertices of either, located by the Illinois
 * variant of regula falsi on exact distances, each piece on its own
 * face's equations); between consecutive candidates whether it is kept is
 * constant and decided at the midpoint; ties within the tolerance go to
 * the lower (face, branch). A kept part ends with PROJCURVE_END_OCCLUDED /
 * starts with PROJCURVE_START_VISIBLE at a cut (its trim end is then on no
 * loop, so chaining does not continue it), with the exact point there,
 * its composed pieces cut by subdivision at the pcurve's point nearest it
 * (faceproj/piece_cut.h) and its compact forms restricted by knot
 * insertion. MAX_DISTANCE needs no cross-face pass: it is a property of
 * each point, applied by the surface stage and kept by clipping.
 *
 * Assumes, as hits/ does, that a branch runs with t increasing; a branch
 * of fewer than 2 points is kept whole and occludes nothing.
 */
#ifndef PC_SHAPEPROJ_SHAPE_HITS_H
#define PC_SHAPEPROJ_SHAPE_HITS_H

#include "common/params.h"
#include "faceproj/surface_projection.h"
#include "shapeproj/shape_result.h"

/* The cuts are located to this fraction of the model size in the distance
 * difference (as hits/). */
#define PC_SHAPE_HITS_ROOT_TOL 1e-10

/* Bound of the root iteration (Illinois with bisection when the secant
 * leaves the bracket, as hits/): at the bound the last iterate is taken. */
#define PC_SHAPE_HITS_MAX_ITER 100

/* The shortest part kept and the shortest overlap in t of two pieces
 * considered, as a fraction of the curve's domain: shorter ones are the
 * rounding of two pieces meeting on a shared edge (their crossings are
 * located to ~1e-10 of the model size). */
#define PC_SHAPE_HITS_MIN_PART 1e-9

/* Replaces the results and trims of r's parts (each face projected with
 * every hit and clipped) by the nearest parts across all of them.
 * model_size scales the tolerance. Each exact distance is a unit of
 * p->budget when it has not stopped on entry. Statuses: OK, NO_MEMORY,
 * CALLBACK (the curve callback failed; on these r is left as it was),
 * LIMIT_REACHED and CANCELLED (the budget stopped the selection: r holds
 * the nearest parts of the pieces selected so far, the others dropped). */
projcurve_status pc_shape_hits_select(projcurve_context *ctx, projcurve_shape_result *r,
                                      const projcurve_curve *curve,
                                      const pc_projection_spec *spec, const pc_params *p,
                                      double model_size);

#endif /* PC_SHAPEPROJ_SHAPE_HITS_H */
