/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The projection of a curve onto one face: onto its untrimmed surface by
 * the kind's driver (surface_projection.h), then clipped to its loops
 * (face_clip.h). The driver stops before its compact fits (fit/) and seam
 * joins (seam/); the compact forms are then fitted after clipping, on the
 * kept stretches only, unless a branch may be joined at a seam or pole
 * (a closed surface, or one with a collapsed edge, and a branch at the
 * domain's boundary): then the fits and joins are made on the untrimmed
 * branches in the driver's order (a joined branch's compact forms are
 * made one from the fits of its sides) and clipping restricts the fits.
 */
#ifndef PC_FACEPROJ_FACE_PROJECT_H
#define PC_FACEPROJ_FACE_PROJECT_H

#include "faceproj/face_clip.h"
#include "faceproj/surface_projection.h"

/* The clipped projection of curve onto face in *out with its branch ends
 * in *trims (see pc_face_clip). Statuses: those of the kind's driver (with
 * *out set for OK and the partial results), and NO_MEMORY from clipping. */
projcurve_status pc_face_project(projcurve_context *ctx, const projcurve_face *face,
                                 const projcurve_curve *curve, const pc_projection_spec *spec,
                                 const pc_params *p, projcurve_result **out,
                                 pc_branch_trim **trims, size_t *unrefined);

#endif /* PC_FACEPROJ_FACE_PROJECT_H */
