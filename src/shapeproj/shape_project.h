/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The projection of a curve onto a shape (or one face): the faces it can
 * reach (face_select.h), each projected and clipped (faceproj/), the
 * pieces chained into connected curves (chain.h).
 */
#ifndef PC_SHAPEPROJ_SHAPE_PROJECT_H
#define PC_SHAPEPROJ_SHAPE_PROJECT_H

#include "faceproj/surface_projection.h"
#include "shapeproj/shape_result.h"

/* Chaining tolerance relative to the model size, when the model states no
 * larger precision: a little above the crossings' accuracy (1e-10). */
#define PC_CHAIN_MIN_TOL 1e-9

/* Projects curve onto shape (face NULL) or onto face alone (shape NULL).
 * model_size: the scale of the chaining tolerance. A face whose projection
 * fails keeps its status and message; the call goes on. Statuses: OK,
 * LIMIT_REACHED, CANCELLED (partial result: the faces not reached carry
 * that status), NO_MEMORY, CALLBACK; and for a lone face, the status of
 * its projection. *out is set for OK and the partial results. */
projcurve_status pc_shape_project(projcurve_context *ctx, const projcurve_shape *shape,
                                  const projcurve_face *face, const projcurve_curve *curve,
                                  const pc_projection_spec *spec, const pc_params *p,
                                  double model_size, projcurve_shape_result **out);

#endif /* PC_SHAPEPROJ_SHAPE_PROJECT_H */
