/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The writer targets' oracle: a surface and a curve read back from a
 * written file must be the ones written. Curves compare bit for bit (reals
 * are written with 17 significant digits; weights may come back scaled by
 * a common factor); surfaces on a grid with derivatives, bit for bit when
 * polynomial, up to their evaluation's rounding when rational (see
 * fuzz_compare_surfaces). A difference is a finding: a message and abort.
 */
#ifndef PC_FUZZ_READBACK_H
#define PC_FUZZ_READBACK_H

#include "projcurve.h"

/* Prints what (and ctx's message) and aborts: libFuzzer keeps the input. */
void fuzz_finding(const char *what, projcurve_context *ctx);

void fuzz_compare_curves(projcurve_context *ctx, const projcurve_curve *written,
                         const projcurve_curve *read);

void fuzz_compare_surfaces(projcurve_context *ctx, const projcurve_surface *written,
                           const projcurve_surface *read);

#endif /* PC_FUZZ_READBACK_H */
