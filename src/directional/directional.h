/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The equations of the directional projection ([SY13] s3.2-s3.3) as a
 * pc_projector. With an orthonormal pair (e1, e2) perpendicular to Dir, the
 * projection q(t) = (u, v) solves G(u, v, t) = [e1.(S - P); e2.(S - P)] = 0
 * (equivalent to the paper's (3.1)/(3.9); see docs/tracing.md).
 */
#ifndef PC_DIRECTIONAL_DIRECTIONAL_H
#define PC_DIRECTIONAL_DIRECTIONAL_H

#include <stddef.h>

#include "geom/curve.h"
#include "geom/surface.h"
#include "nurbs/span_bound_table.h"
#include "trace/projector.h"

/* Evaluation state reused from one call to the next: knot-span hints and the
 * last evaluation, so that derivatives() right after a converged correct()
 * at the same point costs no new evaluation. Owned by one projection call
 * (not shared between threads). */
typedef struct pc_directional_cache {
    size_t hint_u, hint_v, hint_t;
    int surf_valid, curve_valid; /* the fields below hold evaluations */
    double t, u, v;
    pc_vec3 surf[6];           /* S, Su, Sv, Suu, Suv, Svv at (u, v) */
    pc_vec3 curve[3];          /* P, P', P'' at t */
    double frame_d1[2], frame_d2[2]; /* [e1.P'; e2.P'], [e1.P''; e2.P''] */
    size_t span_u, span_v;     /* knot span of the evaluation in surf */
    /* Derivative bounds of the spans visited; bound_state -1 = none
     * (rational surface); bound is the entry of the span of the cached
     * evaluation, after span_bound(). */
    int bound_state;
    const pc_span_bound_entry *bound;
    pc_span_bound_table bounds;
    double guess_error;        /* [SY13] eq. (3.8) of the last guess */
    int callback_failed;       /* a curve callback failed at some point */
} pc_directional_cache;

typedef struct pc_directional_data {
    pc_vec3 dir, e1, e2;       /* unit Dir and the frame (e1, e2, Dir) */
    pc_directional_cache *cache;
} pc_directional_data;

/* Fills proj for the projection of curve onto surface along unit_dir (unit
 * length, checked by the caller). data and cache must outlive proj.
 * newton_tol_rel is relative to the surface size ([SY13] s3.3 eps1, eps2). */
void pc_directional_init(pc_projector *proj, pc_directional_data *data,
                         pc_directional_cache *cache, const projcurve_surface *surface,
                         const projcurve_curve *curve, pc_vec3 unit_dir,
                         double newton_tol_rel, int newton_max_iter);

/* Gives the cache storage for its span-bound table: `slots` zero-filled
 * entries (pc_span_bound_table_slots), outliving the projector; without
 * it the table keeps one span. */
void pc_directional_use_bound_table(pc_directional_cache *cache, pc_span_bound_entry *storage,
                                    size_t slots);

#endif /* PC_DIRECTIONAL_DIRECTIONAL_H */
