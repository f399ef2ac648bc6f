/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Geometry and options from fuzz bytes, for the pipeline targets: a NURBS
 * surface and curve made through the public creation functions (degrees
 * 1..3, at most 8 x 8 and 8 control points, finite coordinates, knots that
 * may repeat or be unclamped, optional weights), a direction and projection
 * options, all under the library's own work limits. Every byte sequence
 * maps to some input (bytes past the end read as 0), so the fuzzer explores
 * the pipeline, not a parser.
 */
#ifndef PC_FUZZ_SHAPES_H
#define PC_FUZZ_SHAPES_H

#include <stddef.h>
#include <stdint.h>

#include "projcurve.h"

typedef struct fuzz_bytes {
    const uint8_t *data;
    size_t size, at;
} fuzz_bytes;

/* The next byte, 0 past the end. */
uint8_t fuzz_byte(fuzz_bytes *b);

/* The work limit of every projection of the targets, in units of
 * PROJCURVE_OPT_MAX_WORK, and the wall-time backstop in seconds: an
 * input may be slow only up to them (.ci/fuzz.sh's -timeout is far above). */
#define FUZZ_MAX_WORK 20000
#define FUZZ_TIME_LIMIT 2.0

/* A surface / curve from the bytes; a status from creation (which may
 * refuse the input: repeated knots, a degenerate net, ...). */
projcurve_status fuzz_make_surface(projcurve_context *ctx, fuzz_bytes *b,
                                   projcurve_surface **out);
projcurve_status fuzz_make_curve(projcurve_context *ctx, fuzz_bytes *b, projcurve_curve **out);
/* A direction, mostly near -z, sometimes any (zero included). */
void fuzz_make_direction(fuzz_bytes *b, double dir[3]);
/* Options from the bytes with the work limits above. */
projcurve_status fuzz_make_options(projcurve_context *ctx, fuzz_bytes *b,
                                   projcurve_options **out);

/* Reads every part of a result through the accessors (a result of a
 * failed call is NULL and reads as empty); aborts when an accessor fails
 * on an index it was told exists. */
void fuzz_walk_result(projcurve_context *ctx, const projcurve_result *r);

/* Aborts (a finding) unless a failed call left a message. */
void fuzz_require_message(projcurve_context *ctx, projcurve_status st);

#endif /* PC_FUZZ_SHAPES_H */
