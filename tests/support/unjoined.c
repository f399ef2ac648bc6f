/* SPDX-License-Identifier: BSD-3-Clause */
#include "unjoined.h"

#include "api/project.h"
#include "directional/directional_project.h"
#include "geom/surface.h"
#include "ortho/ortho_project.h"

projcurve_status pc_test_project_unjoined(projcurve_context *ctx, const projcurve_surface *s,
                                          const projcurve_curve *c, const double *dir,
                                          const projcurve_options *o, projcurve_result **out)
{
    pc_params p;
    pc_budget budget;
    pc_vec3 unit = {0.0, 0.0, 0.0};
    projcurve_status st = dir != NULL ? pc_unit_direction(ctx, dir, &unit) : PROJCURVE_OK;
    if (st == PROJCURVE_OK)
        st = pc_projection_params(ctx, o, s->size, &budget, &p);
    if (st != PROJCURVE_OK)
        return st;
    p.join_seams = 0;
    return dir != NULL ? pc_directional_project(ctx, s, c, unit, &p, out)
                       : pc_ortho_project(ctx, s, c, &p, out);
}
