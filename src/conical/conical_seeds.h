/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The seed finder of the conical projection: the points of the projection
 * at P(t) are the hits of the ray P(t) + lambda Dir(t) (lambda >= 0,
 * Dir(t) = (P(t) - E) / |P(t) - E|) with S. The jump criteria of [SY13]
 * s3.4 are the directional ones (directional/jump_detect.c), asked with
 * the ray of each check; the arc-length estimate likewise.
 */
#ifndef PC_CONICAL_CONICAL_SEEDS_H
#define PC_CONICAL_CONICAL_SEEDS_H

#include "directional/line_seeds.h"
#include "intersect/intersect.h"
#include "trace/trace.h"

typedef struct pc_cone_finder {
    pc_seed_finder base;       /* base.state points to this struct */
    const pc_projector *proj;  /* conical: surface, curve, the corrector, the rays */
    pc_vec3 eye;
    pc_hit_list hits;          /* scratch of find() */
    /* The control-polygon criteria and their state, on the ray of the
     * current check (its dir is set before each use; it reads only the
     * surface and the curve of proj). */
    pc_line_finder line;
    /* Some patch's control-net box (padded) contains the eye: seen from
     * there its polygon does not map to a convex set of directions, so a
     * ray that meets that box always asks for a full search. */
    int eye_in_some_box;
} pc_cone_finder;

/* Sets up the finder (no allocation until used). proj must be conical. */
void pc_cone_finder_init(pc_cone_finder *f, const pc_projector *proj, pc_vec3 eye);
void pc_cone_finder_free(pc_cone_finder *f);

/* The bounds of the curve's pieces and with them the finder's
 * step_may_skip, from the eye (as pc_line_finder_bound_curve). Statuses:
 * OK, NO_MEMORY, OVERFLOW. */
projcurve_status pc_cone_finder_bound_curve(projcurve_context *ctx, pc_cone_finder *f);

/* The projection's arc length estimated as for the directional projection
 * ([SY13] s3.3: the curve's polyline projected along its rays onto the
 * patches' control polygons); 0 when no sample meets them. */
double pc_conical_length_estimate(pc_cone_finder *f);

#endif /* PC_CONICAL_CONICAL_SEEDS_H */
