/* SPDX-License-Identifier: BSD-3-Clause */
#include "fit/own_space.h"

#include <math.h>
#include <stdlib.h>

#include "common/error.h"

/* The branch covers P's domain when its ends agree with P's to this
 * fraction of the domain (the tracer starts and ends on them exactly). */
#define PC_FIT_DOMAIN_REL 1e-12

projcurve_status pc_fit_own_space(projcurve_context *ctx, pc_fit_branch *fb, int dim,
                                  int max_degree, double target, double limit,
                                  pc_fit_samples *data, pc_fit_curve *out, int *ok)
{
    *ok = 0;
    const projcurve_curve *curve = fb->proj->curve;
    if (curve == NULL || curve->kind != PC_CURVE_NURBS)
        return PROJCURVE_OK;
    const pc_nurbs_curve *c = &curve->nurbs;
    const double slack = PC_FIT_DOMAIN_REL * (c->t1 - c->t0);
    if (c->degree > max_degree || fabs(fb->t_lo - c->t0) > slack ||
        fabs(fb->t_hi - c->t1) > slack)
        return PROJCURVE_OK;
    double *weights = NULL;
    if (c->rational) {
        weights = malloc(c->n_ctrl * sizeof *weights);
        if (weights == NULL)
            return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a fit");
        for (size_t k = 0; k < c->n_ctrl; ++k)
            weights[k] = c->cw[4 * k + 3];
    }
    const pc_fit_goal goal = {c->degree, dim, target, limit, c->n_ctrl, 0};
    const projcurve_status st = pc_fit_adaptive(ctx, fb, &goal, c->knots,
                                                c->n_ctrl + (size_t)c->degree + 1, weights,
                                                data, out, ok);
    free(weights);
    return st;
}
