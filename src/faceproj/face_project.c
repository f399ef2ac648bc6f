/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * pc_face_project: untrimmed projection, then clipping
 * (faceproj/face_project.h).
 */
#include "faceproj/face_project.h"

#include "brep/face.h"

projcurve_status pc_face_project(projcurve_context *ctx, const projcurve_face *face,
                                 const projcurve_curve *curve, const pc_projection_spec *spec,
                                 const pc_params *p, projcurve_result **out,
                                 pc_branch_trim **trims, size_t *unrefined)
{
    const pc_surface_projection *kind = NULL;
    projcurve_status st = pc_surface_projection_get(ctx, spec->kind, &kind);
    if (st != PROJCURVE_OK)
        return st;
    projcurve_result *untrimmed = NULL;
    st = kind->project(ctx, face->surface, curve, spec, p, &untrimmed);
    if (!pc_status_keeps_result(st))
        return st;
    /* the crossings are solved on the kind's own equations */
    pc_projector proj;
    pc_projector_storage storage;
    kind->projector_init(&proj, &storage, face->surface, curve, spec, p);
    projcurve_result *clipped = NULL;
    const projcurve_status cs = pc_face_clip(ctx, face, &proj, untrimmed, &clipped, trims,
                                             unrefined);
    projcurve_result_destroy(untrimmed);
    if (cs != PROJCURVE_OK)
        return cs;
    *out = clipped;
    return st;
}
