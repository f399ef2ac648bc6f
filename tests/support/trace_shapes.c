/* SPDX-License-Identifier: BSD-3-Clause */
#include "trace_shapes.h"

#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "shapes.h"

/* Largest control net built here. */
#define SHAPE_MAX_CTRL 64

projcurve_curve *shape_bspline_curve(int degree, size_t n, const double *pts)
{
    double knots[SHAPE_MAX_CTRL + 32];
    if (n > SHAPE_MAX_CTRL || (size_t)degree >= n)
        return NULL;
    const size_t spans = n - (size_t)degree;
    for (size_t i = 0; i < n + (size_t)degree + 1; ++i) {
        const double k = (double)i - (double)degree;
        knots[i] = k < 0.0 ? 0.0 : (k > (double)spans ? 1.0 : k / (double)spans);
    }
    projcurve_curve *c = NULL;
    projcurve_curve_create_nurbs(NULL, degree, n, pts, NULL, knots, &c);
    return c;
}

projcurve_surface *shape_plane(const double o[3], const double a[3], const double b[3])
{
    double ctrl[12];
    for (int k = 0; k < 3; ++k) {
        ctrl[k] = o[k];
        ctrl[3 + k] = o[k] + a[k];
        ctrl[6 + k] = o[k] + b[k];
        ctrl[9 + k] = o[k] + a[k] + b[k];
    }
    const double knots[4] = {0, 0, 1, 1};
    projcurve_surface *s = NULL;
    projcurve_surface_create_nurbs(NULL, 1, 1, 2, 2, ctrl, NULL, knots, knots, &s);
    return s;
}

projcurve_surface *shape_half_cylinder(double r, double len)
{
    const double h = sqrt(0.5);
    const double prof[5][3] = {{r, 0, 0}, {r, 0, r}, {0, 0, r}, {-r, 0, r}, {-r, 0, 0}};
    const double pw[5] = {1, h, 1, h, 1};
    double ctrl[30], w[10];
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 5; ++i) {
            ctrl[3 * (j * 5 + i) + 0] = prof[i][0];
            ctrl[3 * (j * 5 + i) + 1] = j * len;
            ctrl[3 * (j * 5 + i) + 2] = prof[i][2];
            w[j * 5 + i] = pw[i];
        }
    const double ku[8] = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
    const double kv[4] = {0, 0, 1, 1};
    projcurve_surface *s = NULL;
    projcurve_surface_create_nurbs(NULL, 2, 1, 5, 2, ctrl, w, ku, kv, &s);
    return s;
}

projcurve_surface *shape_sphere(double r)
{
    const double centre[3] = {0, 0, 0};
    pc_shape_surface arrays = pc_shape_sphere(centre, r);
    projcurve_surface *s = pc_shape_surface_create(&arrays);
    pc_shape_surface_free(&arrays);
    return s;
}

projcurve_surface *shape_example1_surface(void)
{
    /* [SY13] s5: P_i0 at z = -40, P_i1 at z = 40 */
    const double xy[6][2] = {{-98.75, 32.50}, {-91.77, 22.86}, {-81.48, 1.23},
                             {-86.57, -32.46}, {-93.98, -50.36}, {-97.84, -57.27}};
    double ctrl[36];
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 6; ++i) {
            ctrl[3 * (j * 6 + i) + 0] = xy[i][0];
            ctrl[3 * (j * 6 + i) + 1] = xy[i][1];
            ctrl[3 * (j * 6 + i) + 2] = j == 0 ? -40.0 : 40.0;
        }
    const double ku[12] = {0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1};
    const double kv[4] = {0, 0, 1, 1};
    projcurve_surface *s = NULL;
    projcurve_surface_create_nurbs(NULL, 5, 1, 6, 2, ctrl, NULL, ku, kv, &s);
    return s;
}

projcurve_curve *shape_example1_curve(void)
{
    const double pts[18] = {0.00, -43.75, 3.86,  0.00, -40.13, -3.86, 0.00, -23.80, -31.58,
                            0.00, -11.87, 33.86, 0.00, 10.60,  6.40,  0.00, 16.70,  -2.27};
    const double knots[10] = {0, 0, 0, 0, 0.26, 0.68, 1, 1, 1, 1};
    projcurve_curve *c = NULL;
    projcurve_curve_create_nurbs(NULL, 3, 6, pts, NULL, knots, &c);
    return c;
}

projcurve_surface *shape_c_fold(void)
{
    /* quadratic profile in the xz-plane */
    const double px[7] = {0, 50, 100, 115, 100, 60, 20};
    const double pz[7] = {0, 0, 0, 10, 20, 20, 20};
    double ctrl[3 * 14];
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 7; ++i) {
            ctrl[3 * (j * 7 + i) + 0] = px[i];
            ctrl[3 * (j * 7 + i) + 1] = 100.0 * j;
            ctrl[3 * (j * 7 + i) + 2] = pz[i];
        }
    const double ku[10] = {0, 0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1, 1};
    const double kv[4] = {0, 0, 1, 1};
    projcurve_surface *s = NULL;
    projcurve_surface_create_nurbs(NULL, 2, 1, 7, 2, ctrl, NULL, ku, kv, &s);
    return s;
}

projcurve_surface *shape_z_fold(void)
{
    /* quadratic profile in the xz-plane: three layers joined by two bends */
    const double px[11] = {20, 60, 100, 115, 100, 60, 10, -5, 10, 40, 70};
    const double pz[11] = {0, 0, 0, 10, 20, 20, 20, 30, 40, 40, 40};
    double ctrl[3 * 22];
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 11; ++i) {
            ctrl[3 * (j * 11 + i) + 0] = px[i];
            ctrl[3 * (j * 11 + i) + 1] = 100.0 * j;
            ctrl[3 * (j * 11 + i) + 2] = pz[i];
        }
    double ku[14];
    for (int i = 0; i < 14; ++i) {
        const double k = (double)(i - 2);
        ku[i] = k < 0 ? 0.0 : (k > 9 ? 1.0 : k / 9.0);
    }
    const double kv[4] = {0, 0, 1, 1};
    projcurve_surface *s = NULL;
    projcurve_surface_create_nurbs(NULL, 2, 1, 11, 2, ctrl, NULL, ku, kv, &s);
    return s;
}

projcurve_surface *shape_bumpy(double amp, unsigned long long seed)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, seed);
    double ctrl[3 * 64];
    for (int j = 0; j < 8; ++j)
        for (int i = 0; i < 8; ++i) {
            ctrl[3 * (j * 8 + i) + 0] = 100.0 * i / 7.0;
            ctrl[3 * (j * 8 + i) + 1] = 100.0 * j / 7.0;
            ctrl[3 * (j * 8 + i) + 2] = pc_test_rng_uniform(&rng, -amp, amp);
        }
    const double k[12] = {0, 0, 0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1, 1, 1};
    projcurve_surface *s = NULL;
    projcurve_surface_create_nurbs(NULL, 3, 3, 8, 8, ctrl, NULL, k, k, &s);
    return s;
}

projcurve_surface *shape_pinched_sheet(void)
{
    /* rows along v: y, z and whether the row is the collapsed one */
    const double ry[5] = {0, 25, 50, 75, 100}, rz[5] = {0, 5, 10, 5, 0};
    const double cx[4] = {0, 100.0 / 3.0, 200.0 / 3.0, 100};
    double ctrl[3 * 20];
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 4; ++i) {
            double *p = ctrl + 3 * (4 * j + i);
            p[0] = j == 2 ? 50.0 : cx[i];
            p[1] = ry[j];
            p[2] = rz[j];
        }
    const double ku[7] = {0, 0, 0, 0.5, 1, 1, 1};
    const double kv[8] = {0, 0, 0, 0.5, 0.5, 1, 1, 1};
    projcurve_surface *s = NULL;
    projcurve_surface_create_nurbs(NULL, 2, 2, 4, 5, ctrl, NULL, ku, kv, &s);
    return s;
}
