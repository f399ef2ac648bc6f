/* SPDX-License-Identifier: BSD-3-Clause */
#include "foot_step.h"

int pc_test_foot_step(const projcurve_surface *s, const double p[3], const double uv[2],
                      double step[2], double e[18])
{
    double d[3], f[2] = {0, 0}, k[3] = {0, 0, 0};
    projcurve_surface_eval(NULL, s, uv[0], uv[1], 2, e);
    for (int i = 0; i < 3; ++i) {
        d[i] = e[i] - p[i];
        f[0] += d[i] * e[3 + i];
        f[1] += d[i] * e[6 + i];
    }
    for (int i = 0; i < 3; ++i) {
        k[0] += e[3 + i] * e[3 + i] + d[i] * e[9 + i];
        k[1] += e[3 + i] * e[6 + i] + d[i] * e[12 + i];
        k[2] += e[6 + i] * e[6 + i] + d[i] * e[15 + i];
    }
    const double det = k[0] * k[2] - k[1] * k[1];
    if (!(det != 0.0))
        return 0;
    step[0] = -(k[2] * f[0] - k[1] * f[1]) / det;
    step[1] = -(k[0] * f[1] - k[1] * f[0]) / det;
    return 1;
}
