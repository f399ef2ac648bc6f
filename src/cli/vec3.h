/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The few vector operations of the command's measures (residual.c, run.c),
 * on plain double[3] as the public API gives them.
 */
#ifndef PROJCURVE_CLI_VEC3_H
#define PROJCURVE_CLI_VEC3_H

#include <math.h>

static inline double dot3(const double a[3], const double b[3])
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static inline double norm3(const double v[3])
{
    return sqrt(dot3(v, v));
}

static inline void cross3(const double a[3], const double b[3], double out[3])
{
    out[0] = a[1] * b[2] - a[2] * b[1];
    out[1] = a[2] * b[0] - a[0] * b[2];
    out[2] = a[0] * b[1] - a[1] * b[0];
}

#endif /* PROJCURVE_CLI_VEC3_H */
