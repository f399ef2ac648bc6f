/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * An independent oracle for the exact projection: dense samples of it, and
 * a point-wise corrector that puts any nearby guess exactly on it.
 *
 * Samples come from the library's line/surface intersection (directional:
 * every hit of the ray P(t) + lambda Dir, lambda > 0) or foot-point finder
 * (orthogonal: every local foot point of P(t)) at equally spaced t — never
 * from the tracer that is being measured. The corrector is Newton's method on
 * the projection equations written out here from the public evaluation
 * functions:
 *   directional  e1.(S - P) = e2.(S - P) = 0, (e1, e2) an orthonormal pair
 *                perpendicular to Dir ([SY13] s3, written as in DESIGN.md);
 *   orthogonal   (S - P).Su = (S - P).Sv = 0 ([PW96] eq. 5-6).
 */
#ifndef PCB_EXACT_H
#define PCB_EXACT_H

#include <stddef.h>

#include "projcurve.h"

typedef struct pcb_exact_point {
    double t, u, v;
    double p[3];
    int primary;  /* part of the set every result must cover (see below) */
} pcb_exact_point;

typedef struct pcb_exact {
    const projcurve_surface *surface;
    const projcurve_curve *curve;
    int orthogonal;
    double dir[3], e1[3], e2[3];  /* unit direction and its orthonormal pair */
    double domain[4];
    double t0, t1, dt;            /* sampled range and spacing */
    double size;                  /* model scale (surface box diagonal) */
    pcb_exact_point *pts;
    size_t n;
} pcb_exact;

/* Samples the exact projection at n_t equally spaced curve parameters.
 * Directional: every hit is primary. Orthogonal: the nearest foot point of
 * each P(t) is primary (the one every orthogonal projector must find); the
 * other foot points are exact too but need not be covered.
 * Returns OK or the library status that stopped it. */
projcurve_status pcb_exact_sample(projcurve_context *ctx, pcb_exact *ex,
                                  const projcurve_surface *surface, const projcurve_curve *curve,
                                  int orthogonal, const double dir[3], size_t n_t);
void pcb_exact_free(pcb_exact *ex);

/* Newton from the guess uv to the exact projection point of P(t) on the
 * surface; on success uv and p (may be NULL) receive it and 1 is returned;
 * 0 when it does not converge or leaves the domain. */
int pcb_exact_correct(const pcb_exact *ex, double t, double uv[2], double p[3]);

/* Distance from x to the exact projection: the nearest sample, then a
 * golden-section search over t around it with corrected points. */
double pcb_exact_distance(const pcb_exact *ex, const double x[3]);

/* Distance from x to the exact points E(t), t in [ta, tb], by golden-section
 * search with points corrected from uv0 (continued along the search);
 * infinity when no E(t) there exists. */
double pcb_exact_distance_window(const pcb_exact *ex, const double x[3], double ta, double tb,
                                 const double uv0[2]);

#endif /* PCB_EXACT_H */
