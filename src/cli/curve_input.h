/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Curves given on the command line of projcurve project: --line (two end
 * points) and --points FILE (a polyline, or with --interpolate a curve
 * through the points).
 */
#ifndef PC_CLI_CURVE_INPUT_H
#define PC_CLI_CURVE_INPUT_H

#include <stddef.h>

#include "projcurve.h"

/* The largest --points file the command reads, in points. */
#define CLI_MAX_POINTS ((size_t)1 << 20)

/* The straight segment from ends[0..2] to ends[3..5] (degree 1 over
 * [0, 1]). CLI_EXIT_OK, or CLI_EXIT_USAGE after a message (coincident
 * ends, a value the library refuses). */
int cli_curve_from_line(projcurve_context *ctx, const double ends[6], projcurve_curve **out);

/* The curves of --points path (cli_points_read; parameters by chord
 * length over [0, 1]): without interpolate the polyline, one degree-1
 * curve per segment (segment i over [u[i], u[i+1]]: the projection of a
 * corner is a corner, which a tracer cannot follow through, so each
 * segment is projected on its own); with interpolate one B-spline through
 * the points (cli_interpolate: cubic from 4 points, else of degree n - 1).
 * *out (*n_out curves) is the caller's, released by cli_curves_free.
 * CLI_EXIT_OK, or CLI_EXIT_USAGE after a message naming the file and line. */
int cli_curves_from_points(projcurve_context *ctx, const char *path, int interpolate,
                           projcurve_curve ***out, size_t *n_out);
void cli_curves_free(projcurve_curve **curves, size_t n);

/* Reads path: one point per line, three reals separated by spaces, tabs or
 * commas; '#' starts a comment to the end of the line; blank lines are
 * skipped. *xyz (3 * *n doubles) and *lines (the line number of each
 * point) are malloc'ed, the caller frees them. CLI_EXIT_OK, or
 * CLI_EXIT_USAGE after a message "path:line: ...". */
int cli_points_read(const char *path, double **xyz, size_t **lines, size_t *n);

/* Chord-length parameters of the n points, 0 = u[0] < ... < u[n-1] = 1;
 * 0 when two consecutive points coincide (*repeat is then the index of the
 * second) or n < 2. */
int cli_chord_parameters(const double *xyz, size_t n, double *u, size_t *repeat);

/* Global interpolation (Piegl and Tiller, The NURBS Book, s9.2.1): the control points ctrl (3 * n) and
 * knots (n + degree + 1, averaged from u) of the B-spline of the given
 * degree (1 <= degree < n) that passes through xyz[i] at u[i]. The
 * collocation matrix is banded and totally positive, so Gaussian
 * elimination without pivoting is stable (de Boor); 0 when a pivot
 * vanishes (not for strictly increasing u) or memory runs out. */
int cli_interpolate(const double *xyz, const double *u, size_t n, int degree, double *ctrl,
                    double *knots);

#endif /* PC_CLI_CURVE_INPUT_H */
