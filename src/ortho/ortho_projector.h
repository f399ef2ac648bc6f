/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The equations of the orthogonal projection onto a parametric surface
 * ([PW96] s4), as a pc_projector for the generic tracing machinery.
 *
 * A foot point q = (u, v) of P(t) solves
 *     F(u, v, t) = [(S - P).Su, (S - P).Sv] = 0            ([PW96] eq. (10))
 * whose Jacobian in (u, v) is the orthogonal projective tensor
 *     K_ij = S_i.S_j + (S - P).S_ij                          (eq. (5), (14))
 * so that K q' = [P'.Su, P'.Sv]                               (eq. (15), (16)).
 * Differentiating K q' = b once more (derivation in docs/orthogonal.md):
 *     K q'' = [S_i.(P'' - C) + 2 A_i.(P' - w) - (S - P).T_i]_i
 * with w = S_k q'^k (velocity of the foot point), A_i = S_ik q'^k,
 * C = S_jk q'^j q'^k and T_i = S_ijk q'^j q'^k (third derivatives of S,
 * evaluated exactly by surface_d3.c).
 * K is singular exactly when P is a principal centre of curvature of S at q
 * (corollary 2.1); the projector reports det K / (|Su| |Sv|)^2, whose sign
 * change the tracer watches.
 */
#ifndef PC_ORTHO_PROJECTOR_H
#define PC_ORTHO_PROJECTOR_H

#include "trace/projector.h"

/* Mutable evaluation state of one projection call (never shared between
 * threads): knot-span hints; P, P', P'' at the last curve parameter asked
 * (the corrector and then the derivatives are asked at the same t, by the
 * tracer and by refine/ alike); and whether a curve callback failed, which
 * the caller turns into PROJCURVE_ERR_CALLBACK after tracing (the
 * projector's functions can only answer "no convergence"). */
typedef struct pc_ortho_cache {
    size_t hint_u, hint_v, hint_t;
    int curve_known;      /* curve_t and curve_p hold a successful evaluation */
    double curve_t;
    pc_vec3 curve_p[3];
    int callback_failed;
} pc_ortho_cache;

/* Fills proj with the orthogonal equations for surface and curve. The
 * Newton tolerance is newton_tol_rel times the surface's model size. The
 * handles and cache must outlive proj; cache is reset here. */
void pc_ortho_projector_init(pc_projector *proj, pc_ortho_cache *cache,
                             const projcurve_surface *surface, const projcurve_curve *curve,
                             double newton_tol_rel, int newton_max_iter);

/* Morse index (ortho/morse_index.h) of the foot point (u, v) of P(t): the
 * number of negative eigenvalues of K. Returns 0 when P cannot be
 * evaluated (a curve callback failed), 1 otherwise. */
int pc_ortho_morse_index(const pc_projector *proj, double t, double u, double v, int *index);

/* q'' from the local data (exposed for tests): s = S and partials up to
 * order 3 (surface_d3.h layout), p = P, P', P'', qd = q', k = K row-major.
 * Returns 0 when K is singular. */
int pc_ortho_second_derivative(const pc_vec3 *s, const pc_vec3 p[3], const double qd[2],
                               const double k[4], double qdd[2]);

#endif /* PC_ORTHO_PROJECTOR_H */
