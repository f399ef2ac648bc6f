/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Where the exact projection q(t) is less smooth than a spline of the fit's
 * degree between simple knots: the knot lines of S that the branch crosses
 * (q is C^k there when S is, k = degree - multiplicity of the knot), the
 * knots of the curve P (the same through P), and the branch's creases
 * (pieces meeting at an angle: C0). The fit puts knots there with the
 * multiplicity that lets it follow (fit degree - k), so that it need not
 * approximate a kink by many short spans.
 */
#ifndef PC_FIT_FEATURES_H
#define PC_FIT_FEATURES_H

#include <stddef.h>

#include "fit/branch_view.h"

typedef struct pc_fit_feature {
    double t;
    int continuity; /* q is C^continuity at t (0: a crease) */
} pc_fit_feature;

typedef struct pc_fit_features {
    pc_fit_feature *items; /* increasing t, inside (t_lo, t_hi) */
    size_t count, capacity;
} pc_fit_features;

/* Finds the features of the branch; crease_deg: the joint angle above
 * which two pieces meet at a crease. Statuses: OK, NO_MEMORY. */
projcurve_status pc_fit_features_find(projcurve_context *ctx, pc_fit_branch *fb,
                                      double crease_deg, pc_fit_features *out);
void pc_fit_features_free(pc_fit_features *f);

#endif /* PC_FIT_FEATURES_H */
