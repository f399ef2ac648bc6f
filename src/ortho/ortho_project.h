/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The orthogonal projections ([PW96]) start to end: onto a NURBS surface
 * through the shared tracing / refining / composing machinery, and onto an
 * implicit surface with the 3-space tracer of ortho/implicit.h.
 */
#ifndef PC_ORTHO_ORTHO_PROJECT_H
#define PC_ORTHO_ORTHO_PROJECT_H

#include "common/params.h"
#include "geom/curve.h"
#include "geom/surface.h"

/* Projects curve orthogonally onto surface with the resolved parameters p
 * (eps_D in model units, p->budget set by the caller). A curve that is a
 * point to the model's precision is SINGULAR. Statuses: those of
 * projcurve_project_orthogonal; *out is set for OK and the partial
 * results, untouched otherwise. */
projcurve_status pc_ortho_project(projcurve_context *ctx, const projcurve_surface *surface,
                                  const projcurve_curve *curve, const pc_params *p,
                                  projcurve_result **out);

/* The same onto the implicit surface fn(user, x) = 0 of size model_size
 * (> 0, finite: checked by the caller). Statuses: those of
 * projcurve_project_orthogonal_implicit. */
projcurve_status pc_ortho_project_implicit(projcurve_context *ctx, projcurve_implicit_fn fn,
                                           void *user, double model_size,
                                           const projcurve_curve *curve, const pc_params *p,
                                           projcurve_result **out);

#endif /* PC_ORTHO_ORTHO_PROJECT_H */
