/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The table of surface projections by kind (faceproj/surface_projection.h).
 */
#include "faceproj/surface_projection.h"

#include "common/error.h"
#include "conical/conical_project.h"
#include "directional/directional_project.h"
#include "ortho/ortho_project.h"

static projcurve_status directional_project(projcurve_context *ctx,
                                            const projcurve_surface *surface,
                                            const projcurve_curve *curve,
                                            const pc_projection_spec *spec, const pc_params *p,
                                            projcurve_result **out)
{
    return pc_directional_project(ctx, surface, curve, spec->vec, p, out);
}

static void directional_projector(pc_projector *proj, pc_projector_storage *st,
                                  const projcurve_surface *surface, const projcurve_curve *curve,
                                  const pc_projection_spec *spec, const pc_params *p)
{
    pc_directional_init(proj, &st->dir_data, &st->dir_cache, surface, curve, spec->vec,
                        p->newton_tol, (int)p->newton_max_iter);
}

/* spec->vec is the eye point */
static projcurve_status conical_project(projcurve_context *ctx, const projcurve_surface *surface,
                                        const projcurve_curve *curve,
                                        const pc_projection_spec *spec, const pc_params *p,
                                        projcurve_result **out)
{
    return pc_conical_project(ctx, surface, curve, spec->vec, p, out);
}

static void conical_projector(pc_projector *proj, pc_projector_storage *st,
                              const projcurve_surface *surface, const projcurve_curve *curve,
                              const pc_projection_spec *spec, const pc_params *p)
{
    pc_conical_init(proj, &st->cone_data, &st->cone_cache, surface, curve, spec->vec,
                    p->newton_tol, (int)p->newton_max_iter);
}

static projcurve_status ortho_project(projcurve_context *ctx, const projcurve_surface *surface,
                                      const projcurve_curve *curve,
                                      const pc_projection_spec *spec, const pc_params *p,
                                      projcurve_result **out)
{
    (void)spec;
    return pc_ortho_project(ctx, surface, curve, p, out);
}

static void ortho_projector(pc_projector *proj, pc_projector_storage *st,
                            const projcurve_surface *surface, const projcurve_curve *curve,
                            const pc_projection_spec *spec, const pc_params *p)
{
    (void)spec;
    pc_ortho_projector_init(proj, &st->ortho_cache, surface, curve, p->newton_tol,
                            (int)p->newton_max_iter);
}

/* Indexed by projcurve_projection_kind; {NULL, NULL}: not wired yet. */
static const pc_surface_projection table[] = {
    [PROJCURVE_PROJECT_DIRECTIONAL] = {directional_project, directional_projector},
    [PROJCURVE_PROJECT_CONICAL] = {conical_project, conical_projector},
    [PROJCURVE_PROJECT_ORTHOGONAL] = {ortho_project, ortho_projector},
};

projcurve_status pc_surface_projection_get(projcurve_context *ctx, projcurve_projection_kind kind,
                                           const pc_surface_projection **out)
{
    const size_t k = (size_t)kind;
    if ((int)kind < 0 || k >= sizeof table / sizeof table[0])
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT, "unknown projection kind %d",
                       (int)kind);
    if (table[k].project == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_UNSUPPORTED,
                       "projection kind %d is not available onto faces and shapes",
                       (int)kind);
    *out = &table[k];
    return PROJCURVE_OK;
}
