/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The box tests of the projections' rays (geom/box_reach.h).
 */
#include "geom/box_reach.h"

#include <math.h>

int pc_swept_box_meets(const double cb[6], pc_vec3 dir, const double fb[6])
{
    const double d[3] = {dir.x, dir.y, dir.z};
    double lo = 0.0, hi = INFINITY;
    for (int i = 0; i < 3; ++i) {
        /* cb + lambda d_i overlaps fb on axis i:
         * fb_lo - cb_hi <= lambda d_i <= fb_hi - cb_lo */
        const double a = fb[i] - cb[i + 3], b = fb[i + 3] - cb[i];
        if (d[i] == 0.0) {
            if (a > 0.0 || b < 0.0)
                return 0;
            continue;
        }
        double l = a / d[i], h = b / d[i];
        if (l > h) {
            const double tmp = l;
            l = h;
            h = tmp;
        }
        lo = fmax(lo, l);
        hi = fmin(hi, h);
    }
    return lo <= hi;
}

int pc_swept_box_test(const void *user, const double box[6])
{
    const pc_swept_box *s = user;
    return pc_swept_box_meets(s->curve_box, s->dir, box);
}

/* Narrows [*lo, *hi] to the mu with c mu <= r; 0 when it becomes empty. */
static int mu_at_most(double c, double r, double *lo, double *hi)
{
    if (c > 0.0)
        *hi = fmin(*hi, r / c);
    else if (c < 0.0)
        *lo = fmax(*lo, r / c);
    else if (r < 0.0)
        return 0;
    return *lo <= *hi;
}

int pc_cone_box_meets(const double cb[6], pc_vec3 eye, const double fb[6])
{
    const double e[3] = {eye.x, eye.y, eye.z};
    double lo = 1.0, hi = INFINITY;
    for (int i = 0; i < 3; ++i) {
        /* the cone's slice at mu spans [e + mu (cb_lo - e), e + mu (cb_hi - e)]
         * on axis i; it overlaps [fb_lo, fb_hi] when
         * mu (cb_lo - e) <= fb_hi - e and mu (e - cb_hi) <= e - fb_lo */
        if (!mu_at_most(cb[i] - e[i], fb[i + 3] - e[i], &lo, &hi) ||
            !mu_at_most(e[i] - cb[i + 3], e[i] - fb[i], &lo, &hi))
            return 0;
    }
    return 1;
}

int pc_cone_box_test(const void *user, const double box[6])
{
    const pc_cone_box *c = user;
    return pc_cone_box_meets(c->curve_box, c->eye, box);
}
