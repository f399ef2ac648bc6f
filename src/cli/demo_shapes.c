/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The demo's shapes, built in code so the demo needs no input file.
 */
#include <math.h>

#include "cli.h"

/* [SY13] s5, Example 1 (as in tests/data/cases/song_yong_example1.igs):
 * a degree (5, 1) Bezier sheet spanning z in [-40, 40] near x = -90 and a
 * cubic B-spline in the plane x = 0 with interior knots 0.26 and 0.68.
 * The paper's stated direction (0, 0, -1) misses the sheet; its figure uses
 * (-1, 0, 0), which the demo takes. */
int cli_demo_example1(projcurve_context *ctx, projcurve_surface **s, projcurve_curve **c)
{
    static const double section[6][2] = {{-98.75, 32.5},  {-91.77, 22.86}, {-81.48, 1.23},
                                         {-86.57, -32.46}, {-93.98, -50.36}, {-97.84, -57.27}};
    double net[2 * 6 * 3];
    for (int j = 0; j < 2; ++j)
        for (int i = 0; i < 6; ++i) {
            double *p = net + 3 * (6 * j + i);
            p[0] = section[i][0];
            p[1] = section[i][1];
            p[2] = j ? 40.0 : -40.0;
        }
    static const double ku[] = {0, 0, 0, 0, 0, 0, 1, 1, 1, 1, 1, 1};
    static const double kv[] = {0, 0, 1, 1};
    static const double ctrl[] = {0, -43.75, 3.86,  0, -40.13, -3.86, 0, -23.8, -31.58,
                                  0, -11.87, 33.86, 0, 10.6,   6.4,   0, 16.7,  -2.27};
    static const double knots[] = {0, 0, 0, 0, 0.26, 0.68, 1, 1, 1, 1};
    if (projcurve_surface_create_nurbs(ctx, 5, 1, 6, 2, net, NULL, ku, kv, s) != PROJCURVE_OK)
        return 0;
    if (projcurve_curve_create_nurbs(ctx, 3, 6, ctrl, NULL, knots, c) != PROJCURVE_OK) {
        projcurve_surface_destroy(*s);
        *s = NULL;
        return 0;
    }
    return 1;
}

#define WAVE_NET 7
#define WAVE_SIZE 100.0
#define WAVE_AMPLITUDE 12.0

/* A bicubic 7 x 7 net over [0, 100]^2 with heights
 * 12 sin(0.9 i) cos(0.7 j), and an S-shaped cubic 50 above it. */
int cli_demo_freeform(projcurve_context *ctx, projcurve_surface **s, projcurve_curve **c)
{
    double net[WAVE_NET * WAVE_NET * 3];
    for (int j = 0; j < WAVE_NET; ++j)
        for (int i = 0; i < WAVE_NET; ++i) {
            double *p = net + 3 * (WAVE_NET * j + i);
            p[0] = WAVE_SIZE * i / (WAVE_NET - 1);
            p[1] = WAVE_SIZE * j / (WAVE_NET - 1);
            p[2] = WAVE_AMPLITUDE * sin(0.9 * i) * cos(0.7 * j);
        }
    static const double k[] = {0, 0, 0, 0, 0.25, 0.5, 0.75, 1, 1, 1, 1};
    static const double ctrl[] = {8,  15, 50, 35, 95, 50, 60, 0,
                                  50, 70, 70, 50, 92, 85, 50};
    static const double knots[] = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    if (projcurve_surface_create_nurbs(ctx, 3, 3, WAVE_NET, WAVE_NET, net, NULL, k, k, s) !=
        PROJCURVE_OK)
        return 0;
    if (projcurve_curve_create_nurbs(ctx, 3, 5, ctrl, NULL, knots, c) != PROJCURVE_OK) {
        projcurve_surface_destroy(*s);
        *s = NULL;
        return 0;
    }
    return 1;
}
