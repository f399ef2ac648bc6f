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
    unsigned long long search_cost; /* most budget units one search took so far */
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
 * sweep, at least: a branch born between two searches is found at the next
 * one and traced back to where it was born, but a branch born and gone
 * between two searches is missed. */
#define PC_ORTHO_JUMP_CHECKS 16
/* ... and at most, where searches are cheap. The sweep searches as often
 * as PC_ORTHO_SEARCH_WORK units of work allow at the cost of the dearest
 * search so far, a unit being a sub-patch examined (the budget's unit of a
 * foot-point search) weighed by the size of the control net, (p + 1)
 * (q + 1), doubled when S is rational: the count depends only on the
 * inputs, so the result does too. On the teapot's bicubic one-patch
 * surfaces a search examines ~40 sub-patches (640 units) and the sweep
 * searches 256 times (a branch of minima living 0.05 of the domain, from
 * the boundary to a centre of curvature, fell between two of 16); on the
 * degree 6 x 10 rational surfaces of linkrods.step one examines 1,000 to
 * 11,000 (1 to 10 ms; 160,000 units and more) and the sweep keeps its 16
 * (counted in sub-patches alone, surface 14 had 125 searches and its
 * slowest call took 0.56 s instead of 0.12 s). */
#define PC_ORTHO_JUMP_CHECKS_MAX 256
#define PC_ORTHO_SEARCH_WORK 1048576ull

/* Sets up finder over state for surface and curve; minima_of (may be NULL:
 * every foot point is a seed) as in pc_ortho_finder_state. Release with
 * pc_ortho_finder_free. */
void pc_ortho_finder_init(pc_seed_finder *finder, pc_ortho_finder_state *state,
                          const projcurve_surface *surface, const projcurve_curve *curve,
                          const pc_projector *minima_of);
void pc_ortho_finder_free(pc_ortho_finder_state *state);

#endif /* PC_ORTHO_SEEDS_H */
