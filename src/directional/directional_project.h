/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The directional projection ([SY13]) of a curve onto a surface, start to
 * end: the directional equations and seeds, the tracing engine, tolerance
 * control and composition when asked, and verification.
 */
#ifndef PC_DIRECTIONAL_DIRECTIONAL_PROJECT_H
#define PC_DIRECTIONAL_DIRECTIONAL_PROJECT_H

#include "common/params.h"
#include "common/vec.h"
#include "geom/curve.h"
#include "geom/surface.h"

/* Projects curve onto surface along the unit direction dir with the
 * resolved parameters p (eps_D in model units, p->budget set by the
 * caller: its stages are shared out here). A curve that is a point to the
 * model's precision is SINGULAR. Statuses: those of
 * projcurve_project_directional; *out is set for OK and the partial
 * results (pc_status_keeps_result), untouched otherwise. */
projcurve_status pc_directional_project(projcurve_context *ctx, const projcurve_surface *surface,
                                        const projcurve_curve *curve, pc_vec3 dir,
                                        const pc_params *p, projcurve_result **out);

#endif /* PC_DIRECTIONAL_DIRECTIONAL_PROJECT_H */
