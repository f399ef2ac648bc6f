/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The face pieces of a shape result as tracks for the nearest-hit
 * selection (shapeproj/shape_hits.h), each with its face's equations, and
 * the rebuilding of the parts from the kept spans of them.
 */
#ifndef PC_SHAPEPROJ_HITS_PART_H
#define PC_SHAPEPROJ_HITS_PART_H

#include "common/params.h"
#include "faceproj/surface_projection.h"
#include "shapeproj/shape_result.h"

/* One face piece: branch `branch` of part `part`. */
typedef struct pc_track {
    size_t part, branch;
    const pc_branch *b;
    const pc_projector *proj;  /* its face's equations */
    double lo, hi;             /* its t range */
    double jump_u, jump_v;     /* half the surface's domain: a wider segment is a seam jump */
    int whole;                 /* fewer than 2 points: kept whole, occludes nothing */
} pc_track;

typedef struct pc_track_set {
    pc_track *tracks;          /* by part, then branch */
    size_t n_tracks;
    pc_projector *projs;       /* one per part */
    pc_projector_storage *storage;
} pc_track_set;

/* The tracks of r's parts. Statuses: OK, NO_MEMORY, and those of
 * pc_surface_projection_get. */
projcurve_status pc_track_set_build(projcurve_context *ctx, const projcurve_shape_result *r,
                                    const projcurve_curve *curve,
                                    const pc_projection_spec *spec, const pc_params *p,
                                    pc_track_set *out);
void pc_track_set_free(pc_track_set *set);

/* The distance |S(q(t)) - P(t)| of track k at t in its range, from the
 * exact point there (the corrector from the polyline's point; the
 * polyline's own point where it does not converge), (u, v) into uv.
 * Statuses: OK, CALLBACK. */
projcurve_status pc_track_distance(const pc_track *k, double t, double uv[2], double *out);

/* A kept span [s, e] of a track. */
typedef struct pc_span {
    size_t track;
    double s, e;
} pc_span;

typedef struct pc_span_list {
    pc_span *items;
    size_t count, capacity;
} pc_span_list;

/* Appends [s, e] of track unless it is no longer than min_len. Statuses:
 * OK, NO_MEMORY. */
projcurve_status pc_span_push(projcurve_context *ctx, pc_span_list *l, size_t track, double s,
                              double e, double min_len);

/* Replaces each part's result and trims by its kept spans (spans in track
 * order). Statuses: OK, NO_MEMORY, CALLBACK; on failure r is unchanged. */
projcurve_status pc_parts_rebuild(projcurve_context *ctx, projcurve_shape_result *r,
                                  const pc_track_set *set, const pc_span_list *spans);

#endif /* PC_SHAPEPROJ_HITS_PART_H */
