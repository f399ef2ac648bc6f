/* SPDX-License-Identifier: BSD-3-Clause */
#include "api/result_surface.h"

#include <math.h>

#include "common/error.h"
#include "geom/surface.h"
#include "trace/result.h"

/* The (u, v) at which a branch starts and, when it has composed pieces,
 * its 3D start; returns 0 for a branch with neither. */
static int branch_start(const pc_branch *b, double uv[2], const double **xyz)
{
    *xyz = NULL;
    if (b->n_pieces > 0) {
        uv[0] = b->pieces[0].uv[0], uv[1] = b->pieces[0].uv[1];
        *xyz = b->pieces[0].ctrl;
        return 1;
    }
    if (b->n_points > 0) {
        uv[0] = b->points[1], uv[1] = b->points[2];
        return 1;
    }
    return 0;
}

projcurve_status pc_result_check_surface(projcurve_context *ctx, const projcurve_result *r,
                                         const projcurve_surface *s)
{
    const double tol = 4.0 * r->stats.tol_distance + 1e-9 * s->size;
    for (size_t k = 0; k < r->n_branches; ++k) {
        double uv[2], x[3];
        const double *start = NULL;
        if (!branch_start(&r->branches[k], uv, &start))
            continue;
        if (projcurve_surface_eval(NULL, s, uv[0], uv[1], 0, x) != PROJCURVE_OK)
            return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                           "branch %zu was not projected onto this surface: it starts at "
                           "(u, v) = (%.9g, %.9g), outside the surface's domain",
                           k, uv[0], uv[1]);
        if (start == NULL)
            continue;
        const double d = sqrt((x[0] - start[0]) * (x[0] - start[0]) +
                              (x[1] - start[1]) * (x[1] - start[1]) +
                              (x[2] - start[2]) * (x[2] - start[2]));
        if (!(d <= tol))
            return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                           "branch %zu was not projected onto this surface: its start is %g "
                           "from S(u, v) there (more than %g)",
                           k, d, tol);
    }
    return PROJCURVE_OK;
}
