/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Checks shared by the conical tests (header-only: each test program
 * includes it once). Independent of the library's own measures: a result
 * is read through the public accessors, its pieces evaluated by de
 * Casteljau (pc_test_piece_point), rays handled in closed form.
 */
#ifndef PC_TEST_CONICAL_CHECK_H
#define PC_TEST_CONICAL_CHECK_H

#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "on_surface.h"
#include "projcurve.h"

/* Samples of each piece for the distance of a point to a result. */
#define CONICAL_PIECE_SAMPLES 256

static inline double cc_dist(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Distance from x to the segment [a, b]. */
static inline double cc_segment_dist(const double x[3], const double a[3], const double b[3])
{
    double ab[3], ax[3], len2 = 0.0, dot = 0.0;
    for (int i = 0; i < 3; ++i) {
        ab[i] = b[i] - a[i];
        ax[i] = x[i] - a[i];
        len2 += ab[i] * ab[i];
        dot += ab[i] * ax[i];
    }
    const double s = len2 > 0.0 ? fmin(fmax(dot / len2, 0.0), 1.0) : 0.0;
    const double y[3] = {a[0] + s * ab[0], a[1] + s * ab[1], a[2] + s * ab[2]};
    return cc_dist(x, y);
}

/* The composed pieces of r sampled once: each the polyline of its
 * CONICAL_PIECE_SAMPLES + 1 samples (its sub-chords' sagitta is far below
 * the tolerances the tests compare with), with the box of its samples. */
typedef struct cc_pieces {
    double *x;      /* 3 (CONICAL_PIECE_SAMPLES + 1) per piece */
    double *box;    /* 6 per piece */
    size_t n;
} cc_pieces;

static inline void cc_pieces_free(cc_pieces *p)
{
    free(p->x);
    free(p->box);
    p->x = p->box = NULL;
    p->n = 0;
}

/* Returns 0 when memory ran out. */
static inline int cc_pieces_sample(const projcurve_result *r, cc_pieces *out)
{
    const size_t per = CONICAL_PIECE_SAMPLES + 1;
    size_t total = 0;
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        size_t n_pieces = 0;
        projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, NULL, &n_pieces);
        total += n_pieces;
    }
    out->n = 0;
    out->x = malloc((total + 1) * per * 3 * sizeof *out->x);
    out->box = malloc((total + 1) * 6 * sizeof *out->box);
    if (out->x == NULL || out->box == NULL) {
        cc_pieces_free(out);
        return 0;
    }
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        size_t n_pieces = 0;
        projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, NULL, &n_pieces);
        for (size_t k = 0; k < n_pieces; ++k) {
            int degree = 0;
            double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS];
            projcurve_result_piece(NULL, r, b, k, &degree, ctrl, w, NULL, NULL);
            double *x = out->x + 3 * per * out->n, *box = out->box + 6 * out->n;
            for (int i = 0; i < 3; ++i) {
                box[i] = INFINITY;
                box[i + 3] = -INFINITY;
            }
            for (size_t j = 0; j < per; ++j) {
                pc_test_piece_point(degree, ctrl, w, (double)j / CONICAL_PIECE_SAMPLES,
                                    x + 3 * j);
                for (int i = 0; i < 3; ++i) {
                    box[i] = fmin(box[i], x[3 * j + i]);
                    box[i + 3] = fmax(box[i + 3], x[3 * j + i]);
                }
            }
            out->n++;
        }
    }
    return 1;
}

/* Distance from x to the sampled pieces (INFINITY without pieces). */
static inline double cc_pieces_dist(const cc_pieces *p, const double x[3])
{
    const size_t per = CONICAL_PIECE_SAMPLES + 1;
    double best = INFINITY;
    for (size_t k = 0; k < p->n; ++k) {
        const double *box = p->box + 6 * k;
        double gap2 = 0.0;
        for (int i = 0; i < 3; ++i) {
            const double g = fmax(fmax(box[i] - x[i], x[i] - box[i + 3]), 0.0);
            gap2 += g * g;
        }
        if (gap2 >= best * best)
            continue;
        const double *y = p->x + 3 * per * k;
        for (size_t j = 1; j < per; ++j)
            best = fmin(best, cc_segment_dist(x, y + 3 * (j - 1), y + 3 * j));
    }
    return best;
}

/* For every traced vertex (t, u, v) of r: the distance of S(u, v) from
 * the line through eye and P(t), and lambda = (S - P).(P - E) / |P - E|.
 * Returns the largest distance; *min_lambda gets the smallest lambda. */
static inline double cc_vertex_ray_residual(const projcurve_result *r, const projcurve_surface *s,
                                     const projcurve_curve *c, const double eye[3],
                                     double *min_lambda)
{
    double worst = 0.0;
    *min_lambda = INFINITY;
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        size_t n = 0;
        projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, &n, NULL);
        double *pts = malloc(3 * (n + 1) * sizeof *pts);
        if (pts == NULL)
            return INFINITY;
        projcurve_result_branch_points(NULL, r, b, n, pts, &n);
        for (size_t k = 0; k < n; ++k) {
            double x[3], p[3];
            projcurve_surface_eval(NULL, s, pts[3 * k + 1], pts[3 * k + 2], 0, x);
            projcurve_curve_eval(NULL, c, pts[3 * k], 0, p);
            double d[3], len = 0.0, lambda = 0.0;
            for (int i = 0; i < 3; ++i) {
                d[i] = p[i] - eye[i];
                len += d[i] * d[i];
            }
            len = sqrt(len);
            for (int i = 0; i < 3; ++i) {
                d[i] /= len;
                lambda += (x[i] - p[i]) * d[i];
            }
            const double foot[3] = {p[0] + lambda * d[0], p[1] + lambda * d[1],
                                    p[2] + lambda * d[2]};
            worst = fmax(worst, cc_dist(x, foot));
            *min_lambda = fmin(*min_lambda, lambda);
        }
        free(pts);
    }
    return worst;
}

/* Options with eps_D = tol (and defaults otherwise); NULL on failure. */
static inline projcurve_options *cc_options(double tol)
{
    projcurve_options *o = NULL;
    if (projcurve_options_create(NULL, &o) != PROJCURVE_OK)
        return NULL;
    projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, tol);
    return o;
}

#endif /* PC_TEST_CONICAL_CHECK_H */
