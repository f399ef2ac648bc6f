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

#include <stddef.h>
#include <stdint.h>

#include "projcurve.h"

/* Prints what (and ctx's message) and aborts: libFuzzer keeps the input. */
void fuzz_finding(const char *what, projcurve_context *ctx);

void fuzz_compare_curves(projcurve_context *ctx, const projcurve_curve *written,
                         const projcurve_curve *read);

void fuzz_compare_surfaces(projcurve_context *ctx, const projcurve_surface *written,
                           const projcurve_surface *read);

/* What a writer target writes, from the fuzz bytes (fuzz_shapes.h): a
 * surface, a curve and, with a flag, the result of projecting the curve
 * onto the surface (NULL otherwise or when the projection failed). */
typedef struct fuzz_written {
    projcurve_context *ctx;
    projcurve_surface *s;
    projcurve_curve *c;
    projcurve_result *r;
} fuzz_written;

/* 1 when the bytes give a surface and a curve; release with
 * fuzz_written_free either way. */
int fuzz_written_make(const uint8_t *data, size_t size, fuzz_written *out);
void fuzz_written_free(fuzz_written *w);

/* Reads the file at path back (a finding unless it reads with at least a
 * surface and a curve, the first ones those written), then removes it. */
void fuzz_read_back(const fuzz_written *w, const char *path);

#endif /* PC_FUZZ_READBACK_H */
