/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The rounding floor of a projection's tolerances (precision.h).
 */
#include "trace/precision.h"

#include <float.h>
#include <math.h>

/* Samples of the curve for its magnitude. */
#define PC_ROUNDING_SAMPLES 16

static double max_abs3(pc_vec3 p)
{
    return fmax(fabs(p.x), fmax(fabs(p.y), fabs(p.z)));
}

double pc_pair_rounding(const projcurve_surface *surface, const projcurve_curve *curve)
{
    double m = 0.0;
    for (int k = 0; k < 6; ++k)
        if (isfinite(surface->box[k]))
            m = fmax(m, fabs(surface->box[k]));
    size_t hint = 0;
    for (int i = 0; curve != NULL && i <= PC_ROUNDING_SAMPLES; ++i) {
        const double t = curve->t0 + (curve->t1 - curve->t0) * (double)i / PC_ROUNDING_SAMPLES;
        pc_vec3 p;
        if (pc_curve_eval(curve, t, 0, &hint, &p) == PROJCURVE_OK && vec3_is_finite(p))
            m = fmax(m, max_abs3(p));
    }
    return PC_ROUNDING_ULPS * DBL_EPSILON * m;
}
