/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Composed pieces against the surface, through the public API only: every
 * piece of a result, read with projcurve_result_piece, is evaluated by de
 * Casteljau's algorithm in homogeneous coordinates and compared with
 * projcurve_surface_eval at its pcurve (projcurve_result_piece_pcurve, also
 * by de Casteljau) at evenly spaced parameters s in [0, 1]. A piece made by
 * composition lies on S exactly, so the two differ only by rounding.
 */
#ifndef PC_TEST_ON_SURFACE_H
#define PC_TEST_ON_SURFACE_H

#include <stddef.h>

#include "projcurve.h"

typedef struct pc_on_surface_report {
    double worst;             /* largest |piece(s) - S(u(s), v(s))| */
    size_t worst_branch, worst_piece;
    double worst_s;
    double worst_end;         /* pcurve ends against the piece's uv_range */
    size_t pieces;            /* pieces read */
    size_t pcurve_degree[4];  /* pieces by pcurve degree (index 1 and 3) */
    int failures;             /* accessor or evaluation calls that failed */
} pc_on_surface_report;

/* Measures every piece of every branch of r at `samples` + 1 parameters. */
void pc_on_surface_measure(const projcurve_result *r, const projcurve_surface *s, int samples,
                           pc_on_surface_report *out);

/* A composed piece lies on S exactly (compose/: convex combinations of the
 * patch's control points), so it and S at its pcurve differ by the rounding
 * of two evaluations, a few ulps of the coordinates; the test models sit
 * within a few sizes of the origin, so 1e-12 of the size is ~100 ulps (the
 * largest seen is 2e-15 of the size, on degree-30 pieces). */
#define PC_ON_SURFACE_REL 1e-12
#define PC_ON_SURFACE_SAMPLES 99 /* 100 parameters per piece */

/* CHECKs that every piece of r, at 100 parameters, is within
 * PC_ON_SURFACE_REL of the model size of S at its pcurve, that every
 * accessor call succeeds and counts PROJCURVE_STAT_PIECES pieces, that the
 * pcurve ends are the pieces' uv ranges, and that straight mode
 * (pcurve_degree 1) made straight pcurves only; prints the worst piece of
 * a failure. Returns the largest difference relative to the model size. */
double pc_on_surface_check(const char *name, const projcurve_result *r,
                           const projcurve_surface *s, int pcurve_degree);

/* A piece as projcurve_result_piece gives it (degree, Cartesian control
 * points, weights or NULL for a polynomial piece) at s in [0, 1]: de
 * Casteljau in homogeneous coordinates. */
void pc_test_piece_point(int degree, const double *ctrl, const double *weights, double s,
                         double out[3]);

#endif /* PC_TEST_ON_SURFACE_H */
