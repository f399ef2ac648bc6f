/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * pc_face_project: untrimmed projection, then clipping, then the compact
 * fits of what was kept (faceproj/face_project.h).
 */
#include "faceproj/face_project.h"

#include <stdlib.h>

#include "brep/face.h"
#include "common/stage_clock.h"
#include "fit/fit.h"
#include "seam/seam.h"

/* 1 when a branch of r may be joined at a seam or pole (seam/): joining
 * is on, the surface is closed in a direction or has an edge collapsed,
 * and a branch enters or leaves through the domain's boundary (a join
 * continues a branch that ends BOUNDARY by one that starts BOUNDARY). */
static int may_join(const projcurve_surface *surface, const pc_params *p,
                    const projcurve_result *r)
{
    if (!p->join_seams)
        return 0;
    int at_boundary = 0;
    for (size_t i = 0; i < r->n_branches && !at_boundary; ++i)
        at_boundary = r->branches[i].start == PROJCURVE_START_BOUNDARY ||
                      r->branches[i].end == PROJCURVE_END_BOUNDARY;
    if (!at_boundary)
        return 0;
    pc_closure cl;
    pc_surface_closure(&surface->nurbs, pc_seam_join_tolerance(p, surface->size), &cl);
    return cl.closed_u || cl.closed_v || cl.collapsed != 0;
}

/* The driver's last two stages on the untrimmed result, in its order: the
 * compact fits, then the seam joins (a joined branch's compact forms are
 * made one from the fits of its two sides, seam/compact.c). */
static projcurve_status fit_and_join(projcurve_context *ctx, const projcurve_face *face,
                                     const projcurve_curve *curve, const pc_projector *proj,
                                     const pc_params *p, projcurve_result *r,
                                     projcurve_status st)
{
    const double since = pc_stage_clock_now(p->stages);
    st = pc_fit_stage(ctx, proj, p, r, st);
    pc_stage_clock_lap(p->stages, PC_STAGE_FITTING, since);
    return pc_seam_stage(ctx, face->surface, curve, p, r, st);
}

projcurve_status pc_face_project(projcurve_context *ctx, const projcurve_face *face,
                                 const projcurve_curve *curve, const pc_projection_spec *spec,
                                 const pc_params *p, projcurve_result **out,
                                 pc_branch_trim **trims, size_t *unrefined)
{
    const pc_surface_projection *kind = NULL;
    projcurve_status st = pc_surface_projection_get(ctx, spec->kind, &kind);
    if (st != PROJCURVE_OK)
        return st;
    /* the compact fits are made after clipping, on the kept stretches
     * only; the driver stops before fitting and joining at seams */
    const int fits = p->compose && p->compact;
    pc_params untrimmed_params = *p;
    if (fits) {
        untrimmed_params.compact = 0;
        untrimmed_params.join_seams = 0;
    }
    projcurve_result *untrimmed = NULL;
    st = kind->project(ctx, face->surface, curve, spec, &untrimmed_params, &untrimmed);
    if (!pc_status_keeps_result(st))
        return st;
    /* the crossings are solved on the kind's own equations */
    pc_projector proj;
    pc_projector_storage storage;
    kind->projector_init(&proj, &storage, face->surface, curve, spec, p);
    int late_fit = fits;
    if (fits && may_join(face->surface, p, untrimmed)) {
        late_fit = 0;
        st = fit_and_join(ctx, face, curve, &proj, p, untrimmed, st);
        if (!pc_status_keeps_result(st)) { /* NO_MEMORY */
            projcurve_result_destroy(untrimmed);
            return st;
        }
    }
    projcurve_result *clipped = NULL;
    const projcurve_status cs = pc_face_clip(ctx, face, &proj, untrimmed, &clipped, trims,
                                             unrefined);
    projcurve_result_destroy(untrimmed);
    if (cs != PROJCURVE_OK)
        return cs;
    if (late_fit) {
        const double since = pc_stage_clock_now(p->stages);
        st = pc_fit_stage(ctx, &proj, p, clipped, st);
        pc_stage_clock_lap(p->stages, PC_STAGE_FITTING, since);
        if (!pc_status_keeps_result(st)) { /* NO_MEMORY */
            projcurve_result_destroy(clipped);
            free(*trims);
            *trims = NULL;
            return st;
        }
    }
    *out = clipped;
    return st;
}
