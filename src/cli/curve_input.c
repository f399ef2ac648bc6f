/* SPDX-License-Identifier: BSD-3-Clause */
#define _POSIX_C_SOURCE 200809L /* getline */

#include <errno.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "cli.h"
#include "curve_input.h"

int cli_curve_from_line(projcurve_context *ctx, const double ends[6], projcurve_curve **out)
{
    static const double knots[4] = {0.0, 0.0, 1.0, 1.0};
    if (ends[0] == ends[3] && ends[1] == ends[4] && ends[2] == ends[5])
        return cli_usage_error("--line: the two end points coincide (%g, %g, %g)", ends[0],
                               ends[1], ends[2]);
    if (projcurve_curve_create_nurbs(ctx, 1, 2, ends, NULL, knots, out) != PROJCURVE_OK)
        return cli_usage_error("--line: %s", projcurve_context_message(ctx));
    return CLI_EXIT_OK;
}

/* Grows the point arrays to hold one more point; 0 when memory runs out. */
static int grow(double **xyz, size_t **lines, size_t *cap, size_t n)
{
    if (n < *cap)
        return 1;
    const size_t want = *cap ? 2 * *cap : 64; /* n < CLI_MAX_POINTS: no overflow */
    double *x = realloc(*xyz, 3 * want * sizeof *x);
    if (x == NULL)
        return 0;
    *xyz = x;
    size_t *l = realloc(*lines, want * sizeof *l);
    if (l == NULL)
        return 0;
    *lines = l;
    *cap = want;
    return 1;
}

/* The numbers of one line (comment cut off) into p; how many were read
 * (at most 4: a fourth means too many), or -1 after a message for a word
 * that is not a finite number. */
static int parse_line(const char *path, size_t line_no, char *text, double p[3])
{
    char *hash = strchr(text, '#');
    if (hash)
        *hash = '\0';
    int count = 0;
    for (char *word = strtok(text, " \t\r\n,"); word; word = strtok(NULL, " \t\r\n,")) {
        if (count == 3)
            return 4;
        char *end = NULL;
        errno = 0;
        const double v = strtod(word, &end);
        if (end == word || *end != '\0' || errno != 0 || !isfinite(v)) {
            cli_usage_error("%s:%zu: '%s' is not a finite number", path, line_no, word);
            return -1;
        }
        p[count++] = v;
    }
    return count;
}

int cli_points_read(const char *path, double **xyz, size_t **lines, size_t *n)
{
    *xyz = NULL;
    *lines = NULL;
    *n = 0;
    FILE *f = fopen(path, "r");
    if (f == NULL)
        return cli_usage_error("--points: cannot open %s: %s", path, strerror(errno));
    char *text = NULL;
    size_t text_cap = 0, cap = 0, line_no = 0;
    int code = CLI_EXIT_OK;
    /* one pass over the file: it ends at end of file or at the first error */
    while (code == CLI_EXIT_OK && getline(&text, &text_cap, f) >= 0) {
        ++line_no;
        double p[3];
        const int got = parse_line(path, line_no, text, p);
        if (got < 0) {
            code = CLI_EXIT_USAGE;
        } else if (got == 0) {
            continue; /* blank or comment */
        } else if (got != 3) {
            code = cli_usage_error("%s:%zu: expected 3 coordinates X Y Z, found %s", path,
                                   line_no, got > 3 ? "more" : got == 1 ? "1" : "2");
        } else if (*n == CLI_MAX_POINTS) {
            code = cli_usage_error("%s:%zu: more than %zu points", path, line_no, CLI_MAX_POINTS);
        } else if (!grow(xyz, lines, &cap, *n)) {
            code = cli_usage_error("%s: out of memory at line %zu", path, line_no);
        } else {
            memcpy(*xyz + 3 * *n, p, sizeof p);
            (*lines)[(*n)++] = line_no;
        }
    }
    if (code == CLI_EXIT_OK && ferror(f))
        code = cli_usage_error("%s: read error after line %zu", path, line_no);
    free(text);
    fclose(f);
    if (code == CLI_EXIT_OK && *n < 2)
        code = cli_usage_error("%s: a curve needs at least 2 points, the file has %zu", path, *n);
    if (code != CLI_EXIT_OK) {
        free(*xyz);
        free(*lines);
        *xyz = NULL;
        *lines = NULL;
        *n = 0;
    }
    return code;
}

int cli_chord_parameters(const double *xyz, size_t n, double *u, size_t *repeat)
{
    if (n < 2)
        return 0;
    u[0] = 0.0;
    for (size_t i = 1; i < n; ++i) {
        const double *a = xyz + 3 * (i - 1), *b = xyz + 3 * i;
        const double d = hypot(hypot(b[0] - a[0], b[1] - a[1]), b[2] - a[2]);
        if (!(d > 0.0)) {
            *repeat = i;
            return 0;
        }
        u[i] = u[i - 1] + d;
    }
    const double total = u[n - 1];
    for (size_t i = 1; i + 1 < n; ++i)
        u[i] /= total;
    u[n - 1] = 1.0;
    /* each chord is > 0, but one far below the total can round to a
     * repeated parameter: that polyline has no usable parametrisation */
    for (size_t i = 1; i < n; ++i)
        if (!(u[i] > u[i - 1])) {
            *repeat = i;
            return 0;
        }
    return 1;
}

/* The segments of the polyline: segment i from point i to point i + 1 over
 * [u[i], u[i+1]], so that t is the polyline's chord-length parameter. */
static int make_segments(projcurve_context *ctx, const char *path, const double *xyz,
                         const double *u, size_t n, projcurve_curve **curves)
{
    for (size_t i = 0; i + 1 < n; ++i) {
        const double knots[4] = {u[i], u[i], u[i + 1], u[i + 1]};
        if (projcurve_curve_create_nurbs(ctx, 1, 2, xyz + 3 * i, NULL, knots, &curves[i]) !=
            PROJCURVE_OK)
            return cli_usage_error("%s: segment %zu: %s", path, i, projcurve_context_message(ctx));
    }
    return CLI_EXIT_OK;
}

static int make_interpolant(projcurve_context *ctx, const char *path, const double *xyz,
                            const double *u, size_t n, projcurve_curve **curve)
{
    const int degree = n >= 4 ? 3 : (int)n - 1;
    double *knots = malloc((n + (size_t)degree + 1) * sizeof *knots);
    double *ctrl = malloc(3 * n * sizeof *ctrl);
    int code = CLI_EXIT_OK;
    if (knots == NULL || ctrl == NULL)
        code = cli_usage_error("%s: out of memory for %zu points", path, n);
    else if (!cli_interpolate(xyz, u, n, degree, ctrl, knots))
        code = cli_usage_error("%s: no curve of degree %d passes through these %zu points", path,
                               degree, n);
    else if (projcurve_curve_create_nurbs(ctx, degree, n, ctrl, NULL, knots, curve) !=
             PROJCURVE_OK)
        code = cli_usage_error("%s: %s", path, projcurve_context_message(ctx));
    free(ctrl);
    free(knots);
    return code;
}

void cli_curves_free(projcurve_curve **curves, size_t n)
{
    for (size_t i = 0; curves && i < n; ++i)
        projcurve_curve_destroy(curves[i]);
    free(curves);
}

int cli_curves_from_points(projcurve_context *ctx, const char *path, int interpolate,
                           projcurve_curve ***out, size_t *n_out)
{
    *out = NULL;
    *n_out = 0;
    double *xyz = NULL;
    size_t *lines = NULL, n = 0;
    int code = cli_points_read(path, &xyz, &lines, &n);
    if (code != CLI_EXIT_OK)
        return code;
    const size_t n_curves = interpolate ? 1 : n - 1;
    double *u = malloc(n * sizeof *u);
    projcurve_curve **curves = calloc(n_curves, sizeof *curves);
    size_t repeat = 0;
    if (u == NULL || curves == NULL)
        code = cli_usage_error("%s: out of memory for %zu points", path, n);
    else if (!cli_chord_parameters(xyz, n, u, &repeat))
        code = cli_usage_error("%s:%zu: the point repeats the one before it (line %zu): "
                               "consecutive points must differ",
                               path, lines[repeat], lines[repeat - 1]);
    else if (interpolate)
        code = make_interpolant(ctx, path, xyz, u, n, &curves[0]);
    else
        code = make_segments(ctx, path, xyz, u, n, curves);
    if (code == CLI_EXIT_OK) {
        *out = curves;
        *n_out = n_curves;
    } else {
        cli_curves_free(curves, n_curves);
    }
    free(u);
    free(lines);
    free(xyz);
    return code;
}
