/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The equations of the conical (central) projection from an eye point E as
 * a pc_projector. With A(t) = P(t) - E, the ray of P(t) is P + lambda
 * A / |A| (lambda >= 0), and q(t) = (u, v) solves S(q) - E = mu A (mu =
 * 1 + lambda / |A|). At each t, with an orthonormal pair (e1, e2)
 * perpendicular to A(t), Newton solves G(u, v) = [e1.(S - P); e2.(S - P)]
 * = 0; q' and q'' come from differentiating S(q(t)) - E = mu(t) A(t)
 * (docs/conical.md).
 */
#ifndef PC_CONICAL_CONICAL_H
#define PC_CONICAL_CONICAL_H

#include <stddef.h>

#include "geom/curve.h"
#include "geom/surface.h"
#include "trace/projector.h"

/* Evaluation state reused from one call to the next: knot-span hints, the
 * last evaluations and the ray frame at their t. Owned by one projection
 * call (not shared between threads). */
typedef struct pc_conical_cache {
    size_t hint_u, hint_v, hint_t;
    int surf_valid, curve_valid; /* the fields below hold evaluations */
    double t, u, v;
    pc_vec3 surf[6];           /* S, Su, Sv, Suu, Suv, Svv at (u, v) */
    pc_vec3 curve[3];          /* P, P', P'' at t */
    pc_vec3 dir, e1, e2;       /* A / |A| (A = P - E) and the frame (e1, e2, dir) */
    double len;                /* |A| */
    double guess_error;        /* sine of the angle of the last guess */
    int callback_failed;       /* a curve callback failed at some point */
} pc_conical_cache;

typedef struct pc_conical_data {
    pc_vec3 eye;
    pc_conical_cache *cache;
} pc_conical_data;

/* Fills proj for the central projection of curve onto surface from eye.
 * The caller has checked that the curve keeps away from the eye (P(t) = E
 * makes the ray undefined: correct() and derivatives() fail there). data
 * and cache must outlive proj. newton_tol_rel is relative to the surface
 * size, as for the directional projection. */
void pc_conical_init(pc_projector *proj, pc_conical_data *data, pc_conical_cache *cache,
                     const projcurve_surface *surface, const projcurve_curve *curve, pc_vec3 eye,
                     double newton_tol_rel, int newton_max_iter);

/* The unit ray direction (P(t) - E) / |P(t) - E| at curve parameter t
 * into *dir, and P(t) into *p (may be NULL). Returns 0 when the curve
 * callback fails or P(t) = E. */
int pc_conical_ray(const pc_projector *proj, double t, pc_vec3 *p, pc_vec3 *dir);

#endif /* PC_CONICAL_CONICAL_H */
