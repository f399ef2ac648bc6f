/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Whether a projection result belongs to a surface: the writers are given
 * both, and a result of another surface would be written as pcurves on a
 * surface they do not lie on.
 */
#ifndef PC_API_RESULT_SURFACE_H
#define PC_API_RESULT_SURFACE_H

#include "projcurve.h"

/* OK when every composed branch of r starts on s: S(u(t0), v(t0)) of its
 * first piece within 4 eps_D (plus 1e-9 of s's size, for rounding) of
 * the piece's first point, which lies on the surface projected onto to
 * rounding; a traced-only branch is checked by its first (u, v) lying in
 * s's domain. Statuses: OK, INVALID_ARGUMENT (naming the branch). */
projcurve_status pc_result_check_surface(projcurve_context *ctx, const projcurve_result *r,
                                         const projcurve_surface *s);

#endif /* PC_API_RESULT_SURFACE_H */
