/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Where a branch of a projection crosses the loops of a face: located on
 * the exact projection q(t), the root of q(t) - c(tau) = 0 for a loop
 * piece c, by Newton in (t, tau) with q(t) from the projector's corrector
 * and q'(t) from its derivatives; converged when S(q(t)) and S(c(tau))
 * agree to PC_CROSSING_TOL of the model size.
 *
 * Crossings are first guessed where the branch's polyline (its traced
 * points, or its composed pieces' pcurves, all exact points of the
 * projection) meets the loop pieces' samples: a crossing that neither
 * polyline shows (the branch dipping into a loop and out again between two
 * of its points, less than eps_D deep for a composed branch) is not found.
 */
#ifndef PC_FACEPROJ_LOOP_CROSSING_H
#define PC_FACEPROJ_LOOP_CROSSING_H

#include <stddef.h>

#include "faceproj/loop_samples.h"
#include "trace/projector.h"

/* The crossing's accuracy in 3D, relative to the model size. */
#define PC_CROSSING_TOL 1e-10
/* Newton iterations per crossing; a crossing not met within them keeps its
 * best iterate and is flagged (refined 0). */
#define PC_CROSSING_MAX_ITER 40

typedef struct pc_loop_hit {
    double t, tau, uv[2];
    size_t which; /* index into the samples' pieces */
    int refined;  /* 1: within PC_CROSSING_TOL */
} pc_loop_hit;

typedef struct pc_loop_hits {
    pc_loop_hit *items;
    size_t count, capacity;
} pc_loop_hits;

/* Appends to hits the crossings of the polyline poly (n vertices of (t, u,
 * v), t monotone) with the loops of s, each
 * refined on proj, sorted by t. Statuses: OK, NO_MEMORY. */
projcurve_status pc_loop_crossings(projcurve_context *ctx, const pc_loop_samples *s,
                                   const pc_projector *proj, const double *poly, size_t n,
                                   pc_loop_hits *hits);

/* The point of the projection at t from the guess uv (updated): 1 when the
 * corrector converged. */
int pc_projection_at(const pc_projector *proj, double t, double uv[2]);

#endif /* PC_FACEPROJ_LOOP_CROSSING_H */
