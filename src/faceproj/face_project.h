/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The projection of a curve onto one face: onto its untrimmed surface by
 * the kind's driver (surface_projection.h), then clipped to its loops
 * (face_clip.h).
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
