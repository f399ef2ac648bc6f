/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The fallback pcurve: the pieces' own pcurves (degree 1 or 3) raised to
 * cubic and joined over t, knots of multiplicity 3 at the joins. S composed
 * with it is the composed pieces themselves, which verify/ checked.
 */
#ifndef PC_FIT_JOINED_H
#define PC_FIT_JOINED_H

#include "fit/adaptive.h"

/* Fills *out (degree 3, dim 2, 3 n_pieces + 1 poles; error 0: not
 * measured here). Statuses: OK, NO_MEMORY. */
projcurve_status pc_fit_joined_pcurve(projcurve_context *ctx, const pc_fit_branch *fb,
                                      pc_fit_curve *out);

#endif /* PC_FIT_JOINED_H */
