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
 * projection) meets the loop pieces' samples. Then each stretch between
 * two crossings (or a crossing and an end) is sampled on the exact
 * projection and classified against the face: where the side changes from
 * IN to OUT or back between two samples, a crossing the polyline missed
 * lies between them (the polyline's chord on the inside of a loop while
 * the pcurve bulges past it); it is located by bisection on the side and
 * refined by the same Newton (loop_crossing_sides.c). A crossing that
 * neither shows (the branch dipping into a loop and out again between two
 * polyline points and between two samples, less than eps_D deep for a
 * composed branch) is not found.
 */
#ifndef PC_FACEPROJ_LOOP_CROSSING_H
#define PC_FACEPROJ_LOOP_CROSSING_H

#include <stddef.h>

#include "faceproj/loop_samples.h"
#include "trace/projector.h"
#include "trace/result.h"

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
 * v), t monotone) with the loops of s, each refined on proj, sorted by t.
 * seams: the branch's jumps (n_seams records, seam/seam.h), where the
 * polyline runs from one side of the domain to the other: the side search
 * takes no sample there. Statuses: OK, NO_MEMORY. */
projcurve_status pc_loop_crossings(projcurve_context *ctx, const pc_loop_samples *s,
                                   const pc_projector *proj, const double *poly, size_t n,
                                   const pc_seam_record *seams, size_t n_seams,
                                   pc_loop_hits *hits);

/* Newton in (t, tau) on q(t) - c(tau) = 0 from the guess in *h (t, tau,
 * uv, which set), t kept within [t_lo, t_hi]; h holds the last iterate,
 * refined 1 when within PC_CROSSING_TOL. */
void pc_loop_hit_refine(const pc_loop_samples *s, const pc_projector *proj, double t_lo,
                        double t_hi, pc_loop_hit *h);

/* The side-change search of the header comment over the stretches between
 * the crossings hits[from..] (sorted by t; poly, seams as for
 * pc_loop_crossings, poly's vertices the guesses of the corrector):
 * appends each crossing found and refined (unsorted, after the others).
 * Statuses: OK, NO_MEMORY. */
projcurve_status pc_loop_crossings_by_side(projcurve_context *ctx, const pc_loop_samples *s,
                                           const pc_projector *proj, const double *poly, size_t n,
                                           const pc_seam_record *seams, size_t n_seams,
                                           pc_loop_hits *hits, size_t from);

/* The point of the projection at t from the guess uv (updated): 1 when the
 * corrector converged. */
int pc_projection_at(const pc_projector *proj, double t, double uv[2]);

#endif /* PC_FACEPROJ_LOOP_CROSSING_H */
