/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * One Newton step of the tests' own foot-point iterations, through the
 * public API only: the zero of the gradient of |S(u, v) - p|^2 / 2, whose
 * Hessian is K = [Si.Sj + (S - p).Sij]. Each test keeps its own loop (its
 * caps, stopping rule and what it returns).
 */
#ifndef PC_TEST_FOOT_STEP_H
#define PC_TEST_FOOT_STEP_H

#include "projcurve.h"

/* The step (du, dv) from uv towards the foot point of p; e gets S and its
 * derivatives to order 2 at uv (as projcurve_surface_eval writes them).
 * Returns 0 (step untouched) where K is singular. */
int pc_test_foot_step(const projcurve_surface *s, const double p[3], const double uv[2],
                      double step[2], double e[18]);

#endif /* PC_TEST_FOOT_STEP_H */
