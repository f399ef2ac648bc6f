/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The distance of a branch's exact point from P(t) (hits.h).
 */
#include "hits/hits.h"

#include <math.h>

projcurve_status pc_hits_distance(const pc_projector *proj, const pc_branch *b, double t,
                                  double uv[2], double *out)
{
    const size_t j = pc_branch_segment_at(b, t);
    const double *a = b->points + 3 * j, *c = a + 3;
    const double w = c[0] > a[0] ? (t - a[0]) / (c[0] - a[0]) : 0.0;
    double guess[2] = {a[1] + w * (c[1] - a[1]), a[2] + w * (c[2] - a[2])};
    uv[0] = guess[0];
    uv[1] = guess[1];
    /* a vertex is exact already; elsewhere the corrector places the point */
    if (t != a[0] && t != c[0] && proj->correct(proj, t, guess, NULL)) {
        uv[0] = guess[0];
        uv[1] = guess[1];
    } else if (t == c[0]) {
        uv[0] = c[1];
        uv[1] = c[2];
    }
    pc_vec3 s, p;
    pc_nurbs_surface_eval(&proj->surface->nurbs, uv[0], uv[1], 0, NULL, NULL, &s);
    const projcurve_status st = pc_curve_eval(proj->curve, t, 0, NULL, &p);
    if (st != PROJCURVE_OK)
        return st;
    *out = vec3_norm(vec3_sub(s, p));
    return PROJCURVE_OK;
}
