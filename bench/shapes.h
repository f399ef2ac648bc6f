/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Surfaces and curves built in code for the benchmarks: known shapes at a
 * chosen number of patches, and the paper's Example 1.
 */
#ifndef PCB_SHAPES_H
#define PCB_SHAPES_H

#include <stddef.h>

#include "projcurve.h"

/* Side of the square that the height-field surfaces below cover: x and y
 * run over [0, PCB_FIELD_SIZE]. */
#define PCB_FIELD_SIZE 100.0

/* The control net of the surface below: (spans + 3)^2 points (u fastest)
 * and the clamped uniform knot vector over [0, 1] used in both directions
 * (spans + 7 knots); the caller frees both. Returns 0 or -1 (no memory). */
int pcb_bumpy_net(size_t spans, double **ctrl, double **knots);

/* A bicubic height field with spans x spans uniform knot spans and bumps
 * of a few units on every span (z in about [-8, 8]). */
projcurve_status pcb_make_bumpy_surface(projcurve_context *ctx, size_t spans,
                                        projcurve_surface **out);

/* One gently curved bicubic Bezier patch, refined exactly by single knot
 * insertions into spans x spans patches: the same shape at any patch
 * count. */
projcurve_status pcb_make_refined_patch(projcurve_context *ctx, size_t spans,
                                        projcurve_surface **out);

/* [SY13] s5, Example 1: the degree 5x1 Bezier sheet and the cubic curve
 * (knots 0.26, 0.68), projected along (-1, 0, 0). */
projcurve_status pcb_make_example1(projcurve_context *ctx, projcurve_surface **surface,
                                   projcurve_curve **curve);
extern const double pcb_example1_dir[3];

/* A planar Lissajous curve at height z over the height fields,
 * P(t) = (50 + 40 sin t, 50 + 40 sin(1.3 t + 0.5), z) for t in [0, t_end]:
 * its length grows linearly with t_end while it stays over the field.
 * The parameter block must outlive the curve. */
typedef struct pcb_lissajous {
    double z;
} pcb_lissajous;
projcurve_status pcb_make_lissajous(projcurve_context *ctx, const pcb_lissajous *params,
                                    double t_end, projcurve_curve **out);

#endif /* PCB_SHAPES_H */
