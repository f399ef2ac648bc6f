/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The conical (central) projection of a curve onto a surface from an eye
 * point, start to end: the conical equations and seeds, the tracing engine,
 * tolerance control and composition when asked, verification and the
 * compact forms; the generic stages are those of the directional
 * projection.
 */
#ifndef PC_CONICAL_CONICAL_PROJECT_H
#define PC_CONICAL_CONICAL_PROJECT_H

#include "common/params.h"
#include "common/vec.h"
#include "geom/curve.h"
#include "geom/surface.h"

/* Projects curve onto surface from the finite point eye with the resolved
 * parameters p (eps_D in model units, p->budget set by the caller: its
 * stages are shared out here). A curve that is a point to the model's
 * precision, or that passes through the eye to that precision (its
 * closest point to the eye, pc_curve_closest), is SINGULAR. Statuses:
 * those of projcurve_project_conical; *out is set for OK and the partial
 * results (pc_status_keeps_result), untouched otherwise. */
projcurve_status pc_conical_project(projcurve_context *ctx, const projcurve_surface *surface,
                                    const projcurve_curve *curve, pc_vec3 eye,
                                    const pc_params *p, projcurve_result **out);

/* SINGULAR (with a message) when curve passes within tol of eye (its
 * closest point to the eye, pc_curve_closest): the ray of that point has
 * no direction. Statuses: OK, SINGULAR, those of pc_curve_closest. */
projcurve_status pc_conical_refuse_eye_on_curve(projcurve_context *ctx,
                                                const projcurve_curve *curve, pc_vec3 eye,
                                                double tol);

#endif /* PC_CONICAL_CONICAL_PROJECT_H */
