/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Samples of a face's loop pieces, with their parameters: the first guess
 * of where a branch's pcurve crosses a loop (loop_crossing.h) and of which
 * loop piece a point on a loop lies on. The face's own flattened polygons
 * (brep/face.h) keep no piece parameters, hence this table.
 */
#ifndef PC_FACEPROJ_LOOP_SAMPLES_H
#define PC_FACEPROJ_LOOP_SAMPLES_H

#include <stddef.h>

#include "brep/face.h"

/* Samples per knot span of a loop piece (at least this many per piece). */
#define PC_LOOP_SAMPLES_PER_SPAN 16
/* Samples of one face at most: beyond it a piece keeps its spans' ends. */
#define PC_LOOP_MAX_SAMPLES ((size_t)1 << 20)

typedef struct pc_loop_sample {
    double tau, uv[2];
} pc_loop_sample;

/* The samples of one loop piece, tau increasing, and their box. */
typedef struct pc_piece_samples {
    size_t loop, piece;
    size_t first, count;
    double box[4]; /* u0, u1, v0, v1 */
} pc_piece_samples;

typedef struct pc_loop_samples {
    const projcurve_face *face;
    pc_piece_samples *pieces;
    size_t n_pieces;
    pc_loop_sample *items;
    size_t count, capacity;
} pc_loop_samples;

/* Samples every piece of every loop of face. Statuses: OK, NO_MEMORY. */
projcurve_status pc_loop_samples_build(projcurve_context *ctx, const projcurve_face *face,
                                       pc_loop_samples *out);
void pc_loop_samples_free(pc_loop_samples *s);

/* The loop piece nearest to uv (by its samples, then a local search of
 * tau): index into s->pieces in *which and its parameter in *tau. Returns
 * the distance in (u, v); +inf when the face has no pieces. */
double pc_loop_samples_nearest(const pc_loop_samples *s, const double uv[2], size_t *which,
                               double *tau);

/* c(tau) and c'(tau) of loop piece `which` (c' by central differences of
 * the rational curve: a guide for Newton, not its target). */
void pc_loop_piece_eval(const pc_loop_samples *s, size_t which, double tau, double c[2],
                        double dc[2]);

#endif /* PC_FACEPROJ_LOOP_SAMPLES_H */
