/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The orthogonal residual the command reports for a traced point: how far
 * S(u, v) is from being a foot point of p, in model units. Public API only,
 * so that a test can link it alone (tests/unit/ortho/test_ortho_singular.c).
 */
#ifndef PROJCURVE_CLI_RESIDUAL_H
#define PROJCURVE_CLI_RESIDUAL_H

#include "projcurve.h"

/* The smaller of two distances, at (u, v) and just beside it on either
 * side in u and in v (a crease of a C0 surface has the derivatives of one
 * patch on the knot line); INFINITY where S cannot be evaluated:
 * - backward: the tangential part of S - p, the distance from p to the
 *   normal line at S (with the limit normal at a collapsed edge);
 * - forward: the length in space of the Newton step -K^-1 F, the distance
 *   from S(u, v) to the exact foot point to first order. It stays right
 *   where the parametrisation is singular (Su nearly parallel to Sv), where
 *   the normal Su x Sv, and the backward measure with it, is rounding. */
double cli_orthogonal_residual(projcurve_context *ctx, const projcurve_surface *surface,
                               const double p[3], double u, double v);

#endif /* PROJCURVE_CLI_RESIDUAL_H */
