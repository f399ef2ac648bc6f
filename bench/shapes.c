/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Benchmark shapes (see shapes.h).
 */
#include "shapes.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define BICUBIC 3

const double pcb_example1_dir[3] = {-1.0, 0.0, 0.0};

/* Clamped uniform knot vector of `spans` spans over [0, 1]. */
static void uniform_knots(size_t spans, int degree, double *knots)
{
    const size_t n_ctrl = spans + (size_t)degree;
    for (size_t i = 0; i < n_ctrl + (size_t)degree + 1; ++i) {
        const double k = (double)i - (double)degree;
        knots[i] = k <= 0.0 ? 0.0 : k >= (double)spans ? 1.0 : k / (double)spans;
    }
}

int pcb_bumpy_net(size_t spans, double **ctrl_out, double **knots_out)
{
    const size_t n = spans + BICUBIC;
    double *ctrl = malloc(3 * n * n * sizeof *ctrl);
    double *knots = malloc((n + BICUBIC + 1) * sizeof *knots);
    if (!ctrl || !knots) {
        free(ctrl);
        free(knots);
        return -1;
    }
    uniform_knots(spans, BICUBIC, knots);
    for (size_t j = 0; j < n; ++j) {
        for (size_t i = 0; i < n; ++i) {
            double *p = &ctrl[3 * (j * n + i)];
            p[0] = PCB_FIELD_SIZE * (double)i / (double)(n - 1);
            p[1] = PCB_FIELD_SIZE * (double)j / (double)(n - 1);
            /* Incommensurate frequencies: no two spans look alike. */
            p[2] = 6.0 * sin(0.9 * (double)i + 0.3) * cos(0.7 * (double)j) +
                   2.0 * sin(1.7 * (double)(i + 2 * j));
        }
    }
    *ctrl_out = ctrl;
    *knots_out = knots;
    return 0;
}

projcurve_status pcb_make_bumpy_surface(projcurve_context *ctx, size_t spans,
                                        projcurve_surface **out)
{
    double *ctrl, *knots;
    if (pcb_bumpy_net(spans, &ctrl, &knots) != 0)
        return PROJCURVE_ERR_NO_MEMORY;
    const size_t n = spans + BICUBIC;
    const projcurve_status st =
        projcurve_surface_create_nurbs(ctx, BICUBIC, BICUBIC, n, n, ctrl, NULL, knots, knots, out);
    free(ctrl);
    free(knots);
    return st;
}

/*
 * Boehm's single knot insertion: inserts t once into the clamped knot
 * vector `knots` (n_ctrl + degree + 1 entries, room for one more) of a
 * curve with n_ctrl points of `dim` coordinates in `pts` (room for one
 * more). The curve does not change (The NURBS Book, eq. 5.15).
 */
static void insert_knot(double *knots, double *pts, size_t n_ctrl, int degree, size_t dim,
                        double t)
{
    const size_t p = (size_t)degree;
    size_t k = p;
    while (k + 1 < n_ctrl && knots[k + 1] <= t)
        ++k;
    /* Downwards, so that index i still holds P_i when Q_i is formed. */
    for (size_t i = n_ctrl; i > k; --i)
        memcpy(&pts[dim * i], &pts[dim * (i - 1)], dim * sizeof *pts);
    for (size_t i = k; i + p > k; --i) {
        const double a = (t - knots[i]) / (knots[i + p] - knots[i]);
        for (size_t c = 0; c < dim; ++c)
            pts[dim * i + c] = a * pts[dim * i + c] + (1.0 - a) * pts[dim * (i - 1) + c];
    }
    for (size_t i = n_ctrl + p + 1; i > k + 1; --i)
        knots[i] = knots[i - 1];
    knots[k + 1] = t;
}

/* Refines a bicubic Bezier row of 4 points into `spans` uniform spans:
 * out receives spans + 3 points and knots the refined knot vector. */
static void refine_row(const double *row, size_t stride, size_t spans, double *knots,
                       double *work)
{
    static const double bezier_knots[8] = {0, 0, 0, 0, 1, 1, 1, 1};
    memcpy(knots, bezier_knots, sizeof bezier_knots);
    for (size_t i = 0; i < BICUBIC + 1; ++i)
        memcpy(&work[3 * i], &row[3 * i * stride], 3 * sizeof *work);
    for (size_t s = 1; s < spans; ++s)
        insert_knot(knots, work, BICUBIC + s, BICUBIC, 3, (double)s / (double)spans);
}

projcurve_status pcb_make_refined_patch(projcurve_context *ctx, size_t spans,
                                        projcurve_surface **out)
{
    /* A saddle-and-dome Bezier net over the field. */
    static const double heights[4][4] = {
        {0.0, 6.0, 4.0, -2.0},
        {5.0, 12.0, -6.0, 3.0},
        {-3.0, 8.0, 10.0, 4.0},
        {2.0, -4.0, 5.0, 0.0}};
    const size_t n = spans + BICUBIC;
    double bez[4 * 4 * 3];
    for (size_t j = 0; j < 4; ++j)
        for (size_t i = 0; i < 4; ++i) {
            bez[3 * (4 * j + i) + 0] = PCB_FIELD_SIZE * (double)i / 3.0;
            bez[3 * (4 * j + i) + 1] = PCB_FIELD_SIZE * (double)j / 3.0;
            bez[3 * (4 * j + i) + 2] = heights[j][i];
        }
    double *half = malloc(3 * n * 4 * sizeof *half);  /* refined in u: n x 4 */
    double *ctrl = malloc(3 * n * n * sizeof *ctrl);
    double *work = malloc(3 * (n + 1) * sizeof *work);
    double *knots = malloc((n + BICUBIC + 2) * sizeof *knots);
    projcurve_status st = PROJCURVE_ERR_NO_MEMORY;
    if (half && ctrl && work && knots) {
        for (size_t j = 0; j < 4; ++j) {
            refine_row(&bez[3 * 4 * j], 1, spans, knots, work);
            memcpy(&half[3 * n * j], work, 3 * n * sizeof *work);
        }
        for (size_t i = 0; i < n; ++i) {
            refine_row(&half[3 * i], n, spans, knots, work);
            for (size_t j = 0; j < n; ++j)
                memcpy(&ctrl[3 * (j * n + i)], &work[3 * j], 3 * sizeof *work);
        }
        st = projcurve_surface_create_nurbs(ctx, BICUBIC, BICUBIC, n, n, ctrl, NULL, knots,
                                            knots, out);
    }
    free(half);
    free(ctrl);
    free(work);
    free(knots);
    return st;
}

projcurve_status pcb_make_example1(projcurve_context *ctx, projcurve_surface **surface,
                                   projcurve_curve **curve)
{
    /* [SY13] s5: the 6 x 2 net (u fastest: the z = -40 row, then z = 40). */
    static const double xy[6][2] = {{-98.75, 32.50}, {-91.77, 22.86}, {-81.48, 1.23},
                                    {-86.57, -32.46}, {-93.98, -50.36}, {-97.84, -57.27}};
    double net[2 * 6 * 3];
    for (size_t j = 0; j < 2; ++j)
        for (size_t i = 0; i < 6; ++i) {
            net[3 * (6 * j + i) + 0] = xy[i][0];
            net[3 * (6 * j + i) + 1] = xy[i][1];
            net[3 * (6 * j + i) + 2] = j ? 40.0 : -40.0;
        }
    static const double ku[12] = {0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1};
    static const double kv[4] = {0, 0, 1, 1};
    static const double cp[6 * 3] = {0.00, -43.75, 3.86,  0.00, -40.13, -3.86,
                                     0.00, -23.80, -31.58, 0.00, -11.87, 33.86,
                                     0.00, 10.60,  6.40,  0.00, 16.70,  -2.27};
    static const double kc[10] = {0, 0, 0, 0, 0.26, 0.68, 1, 1, 1, 1};
    projcurve_surface *s = NULL;
    projcurve_curve *c = NULL;
    projcurve_status st = projcurve_surface_create_nurbs(ctx, 5, 1, 6, 2, net, NULL, ku, kv, &s);
    if (st == PROJCURVE_OK)
        st = projcurve_curve_create_nurbs(ctx, 3, 6, cp, NULL, kc, &c);
    if (st != PROJCURVE_OK) {
        projcurve_surface_destroy(s);
        return st;
    }
    *surface = s;
    *curve = c;
    return PROJCURVE_OK;
}

/* P(t) = (50 + 40 sin t, 50 + 40 sin(1.3 t + 0.5), z). */
static int lissajous_eval(void *user, double t, double out[9])
{
    const pcb_lissajous *l = user;
    const double a = 1.3 * t + 0.5;
    out[0] = 50.0 + 40.0 * sin(t);
    out[1] = 50.0 + 40.0 * sin(a);
    out[2] = l->z;
    out[3] = 40.0 * cos(t);
    out[4] = 52.0 * cos(a);
    out[5] = 0.0;
    out[6] = -40.0 * sin(t);
    out[7] = -67.6 * sin(a);
    out[8] = 0.0;
    return 0;
}

projcurve_status pcb_make_lissajous(projcurve_context *ctx, const pcb_lissajous *params,
                                    double t_end, projcurve_curve **out)
{
    return projcurve_curve_create_callback(ctx, lissajous_eval, (void *)params, 0.0, t_end, out);
}
