/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Distances of output samples to the model's faces and to the rays
 * (shape_accuracy.h).
 */
#include "shape_accuracy.h"

#include <math.h>

#include "brep/shape.h"

#define RAY_GRID 512         /* t samples of the curve before refining */
#define RAY_GOLDEN_STEPS 80  /* golden-section steps: the bracket shrinks 0.618^80 */

/* Distance of x to the ray (line) of parameter t. */
static double ray_distance_at(const projcurve_curve *c, int conical, const double v[3],
                              const double x[3], double t)
{
    double p[3];
    if (projcurve_curve_eval(NULL, c, t, 0, p) != PROJCURVE_OK)
        return INFINITY;
    double o[3], d[3];
    for (int i = 0; i < 3; ++i) {
        o[i] = conical ? v[i] : p[i];
        d[i] = conical ? p[i] - v[i] : v[i];
    }
    const double dn = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
    const double w[3] = {x[0] - o[0], x[1] - o[1], x[2] - o[2]};
    const double cr[3] = {w[1] * d[2] - w[2] * d[1], w[2] * d[0] - w[0] * d[2],
                          w[0] * d[1] - w[1] * d[0]};
    return sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]) / dn;
}

static double ray_distance(const projcurve_curve *c, int conical, const double v[3],
                           const double x[3])
{
    double t0 = 0, t1 = 1;
    projcurve_curve_domain(NULL, c, &t0, &t1);
    const double h = (t1 - t0) / RAY_GRID;
    int best = 0;
    double best_d = INFINITY;
    for (int i = 0; i <= RAY_GRID; ++i) {
        const double d = ray_distance_at(c, conical, v, x, t0 + h * i);
        if (d < best_d) {
            best_d = d;
            best = i;
        }
    }
    double a = fmax(t0, t0 + h * (best - 1)), b = fmin(t1, t0 + h * (best + 1));
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    double c1 = b - g * (b - a), c2 = a + g * (b - a);
    double f1 = ray_distance_at(c, conical, v, x, c1), f2 = ray_distance_at(c, conical, v, x, c2);
    for (int k = 0; k < RAY_GOLDEN_STEPS; ++k) {
        if (f1 < f2) {
            b = c2;
            c2 = c1;
            f2 = f1;
            c1 = b - g * (b - a);
            f1 = ray_distance_at(c, conical, v, x, c1);
        } else {
            a = c1;
            c1 = c2;
            f1 = f2;
            c2 = a + g * (b - a);
            f2 = ray_distance_at(c, conical, v, x, c2);
        }
    }
    return fmin(best_d, fmin(f1, f2));
}

static int box_holds(const double *box, const double x[3], double slack)
{
    for (int i = 0; i < 3; ++i)
        if (x[i] < box[i] - slack || x[i] > box[i + 3] + slack)
            return 0;
    return 1;
}

/* Distance of x to the nearest face surface among those whose box holds x
 * (within slack); every face when none does. */
static int face_distance(const projcurve_shape *shape, const double x[3], double slack,
                         double *dist)
{
    *dist = INFINITY;
    for (int pass = 0; pass < 2 && !isfinite(*dist); ++pass) {
        for (size_t f = 0; f < shape->n_faces; ++f) {
            if (pass == 0 && !box_holds(shape->boxes + 6 * f, x, slack))
                continue;
            double uv[2], d = INFINITY;
            if (projcurve_surface_closest_point(NULL, projcurve_face_surface(shape->faces[f]), x,
                                                uv, NULL, &d) != PROJCURVE_OK)
                return -1;
            *dist = fmin(*dist, d);
        }
    }
    return 0;
}

int pcb_shape_accuracy_of(const projcurve_shape *shape, const projcurve_curve *curve, int conical,
                          const double vec[3], const double *samples, size_t n,
                          pcb_shape_accuracy *out)
{
    out->face = out->ray = 0.0;
    double lo[3] = {INFINITY, INFINITY, INFINITY}, hi[3] = {-INFINITY, -INFINITY, -INFINITY};
    for (size_t f = 0; f < shape->n_faces; ++f)
        for (int i = 0; i < 3; ++i) {
            lo[i] = fmin(lo[i], shape->boxes[6 * f + i]);
            hi[i] = fmax(hi[i], shape->boxes[6 * f + i + 3]);
        }
    const double size = sqrt((hi[0] - lo[0]) * (hi[0] - lo[0]) + (hi[1] - lo[1]) * (hi[1] - lo[1]) +
                             (hi[2] - lo[2]) * (hi[2] - lo[2]));
    for (size_t i = 0; i < n; ++i) {
        const double *x = samples + 3 * i;
        double d = 0.0;
        if (face_distance(shape, x, 1e-3 * size, &d) != 0)
            return -1;
        out->face = fmax(out->face, d);
        out->ray = fmax(out->ray, ray_distance(curve, conical, vec, x));
    }
    return 0;
}
