/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Where branches of the orthogonal projection are ([PW96] s4.2): every
 * local foot point of P(t) on S, as a pc_seed_finder for the tracing
 * engine. At the start of the curve the foot points are the seeds; in
 * mid-curve, branches are born where P(t) crosses the focal surface (two
 * foot points appear at a centre of curvature) or where a foot point enters
 * through the boundary of S. Neither event has a cheap local test here, so
 * may_jump asks for a full foot-point search at regular intervals of t and
 * whenever a branch has ended since the previous check (a branch ending at
 * a centre of curvature often continues as another one).
 *
 * The engine may call find at a check where may_jump said no (it searches
 * every few checks whatever the finder says, for the sake of the cheap
 * line criteria of the directional kind). A foot-point search costs 0.05 to
 * 10 ms, against ~1 us for a line, so at such a check find answers with no
 * point: nothing new. (It answered with the points of the live branches
 * once, interpolated on their polylines; where the engine's correction of
 * its own copy of such a point moved it by more than ds, the uncorrected
 * point went unmatched and started a branch off the projection: residual
 * 0.068 on linkrods.step surface 11, curve 39.)
 */
#ifndef PC_ORTHO_SEEDS_H
#define PC_ORTHO_SEEDS_H

#include <stddef.h>

#include "trace/trace.h"

typedef struct pc_ortho_finder_state {
    const projcurve_surface *surface;
    const projcurve_curve *curve;
    /* Non-NULL: only the foot points that are local minima of the distance
     * are seeds (PROJCURVE_FOOT_POINTS_MINIMA, ortho_minima.h), their
     * Morse index evaluated with this projector. */
    const pc_projector *minima_of;
    double interval;        /* full search at least every `interval` in t */
    double last_full_t;     /* t of the last check that asked for a search */
    size_t last_active;     /* branches alive at the previous check */
    int started;            /* a check happened since the last reset */
    int skip_due;           /* may_jump said no at skip_t: find answers with nothing */
    double skip_t;
    double *uv;             /* foot-point buffer, 2 doubles per point */
    size_t capacity;        /* points the buffer holds */
    pc_budget *budget;      /* the call's, polled inside each search (NULL: none) */
} pc_ortho_finder_state;

/* Number of full foot-point searches per curve domain in the mid-curve
 * sweep (the brief's "at intervals"): a branch born between two searches
 * is found at the next one and traced back to where it was born; one born
 * and gone between two is missed. 16 missed such branches on the teapot
 * (lid and spout, under 1/16 of the domain long), so surfaces of degree
 * at most PC_ORTHO_DENSE_CHECKS_DEGREE in both directions, where a search
 * costs ~0.1 ms, get PC_ORTHO_DENSE_JUMP_CHECKS. On higher degrees a search
 * costs up to 25 ms (linkrods.step, rational 6 x 10), and 32 searches
 * there took a call past 1 s (docs/orthogonal.md, Seeds). */
#define PC_ORTHO_JUMP_CHECKS 16
#define PC_ORTHO_DENSE_JUMP_CHECKS 32
#define PC_ORTHO_DENSE_CHECKS_DEGREE 3

/* Sets up finder over state for surface and curve; minima_of (may be NULL:
 * every foot point is a seed) as in pc_ortho_finder_state. Release with
 * pc_ortho_finder_free. */
void pc_ortho_finder_init(pc_seed_finder *finder, pc_ortho_finder_state *state,
                          const projcurve_surface *surface, const projcurve_curve *curve,
                          const pc_projector *minima_of);
void pc_ortho_finder_free(pc_ortho_finder_state *state);

#endif /* PC_ORTHO_SEEDS_H */
