/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The projection onto one untrimmed surface, by kind: the call that traces
 * and composes it, and its equations as a pc_projector, which the face
 * clipping uses to locate loop crossings on the exact projection.
 *
 * One table entry per projcurve_projection_kind (directional, conical,
 * orthogonal). A kind whose entry is not filled is refused with
 * PROJCURVE_ERR_UNSUPPORTED by pc_surface_projection_get. Adding a kind is
 * an entry here: a project function of the shape of
 * pc_directional_project, and an init of its projector whose state fits
 * pc_projector_storage.
 */
#ifndef PC_FACEPROJ_SURFACE_PROJECTION_H
#define PC_FACEPROJ_SURFACE_PROJECTION_H

#include "common/params.h"
#include "common/vec.h"
#include "conical/conical.h"
#include "directional/directional.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "ortho/ortho_projector.h"
#include "projcurve.h"
#include "trace/projector.h"

/* What a projection is: its kind and vector (the unit direction, or the
 * eye point; unused for orthogonal). */
typedef struct pc_projection_spec {
    projcurve_projection_kind kind;
    pc_vec3 vec;
} pc_projection_spec;

/* The state behind a projector, for every kind (one is used). */
typedef struct pc_projector_storage {
    pc_directional_data dir_data;
    pc_directional_cache dir_cache;
    pc_conical_data cone_data;
    pc_conical_cache cone_cache;
    pc_ortho_cache ortho_cache;
} pc_projector_storage;

typedef struct pc_surface_projection {
    /* Projects curve onto the untrimmed surface (statuses and *out as
     * pc_directional_project). */
    projcurve_status (*project)(projcurve_context *ctx, const projcurve_surface *surface,
                                const projcurve_curve *curve, const pc_projection_spec *spec,
                                const pc_params *p, projcurve_result **out);
    /* Fills proj with the kind's equations; storage outlives proj. */
    void (*projector_init)(pc_projector *proj, pc_projector_storage *storage,
                           const projcurve_surface *surface, const projcurve_curve *curve,
                           const pc_projection_spec *spec, const pc_params *p);
} pc_surface_projection;

/* The entry of spec->kind in *out. Statuses: OK, INVALID_ARGUMENT (no
 * such kind), UNSUPPORTED (a kind not wired yet). */
projcurve_status pc_surface_projection_get(projcurve_context *ctx, projcurve_projection_kind kind,
                                           const pc_surface_projection **out);

#endif /* PC_FACEPROJ_SURFACE_PROJECTION_H */
