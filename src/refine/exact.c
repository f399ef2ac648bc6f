/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Exact points of the projection curve, reached point by point through the
 * projector's corrector ([SY13] s4: "discrete points are sampled ... on
 * q(t)"). The corrector converges from a guess close to the curve; the guess
 * is the linear interpolation, in t, of the two closest known exact points
 * around t: the ends of the segment being refined, or the traced vertices
 * between them. Both are on the curve, so the guess is within the chord
 * deviation of a traced step and Newton stays on this branch.
 */
#include <math.h>

#include "refine/refine_internal.h"

/* A corrected point farther than this many bracket lengths (in u, v) from its
 * guess has left the branch: it is rejected. */
#define PC_EXACT_MAX_JUMP 2.0

/* q(t) by the cubic Hermite interpolant of the exact ends a and b with
 * their derivatives q' ([SY13] s3.2 uses the same Taylor data to predict). */
static void hermite_guess(const pc_rvertex *a, const pc_rvertex *b, double t, double uv[2])
{
    const pc_rvertex *lo = a->t <= b->t ? a : b, *hi = a->t <= b->t ? b : a;
    const double span = hi->t - lo->t;
    if (!(span > 0.0))
        return;
    const double s = (t - lo->t) / span, s2 = s * s, s3 = s2 * s;
    const double h00 = 2.0 * s3 - 3.0 * s2 + 1.0, h10 = s3 - 2.0 * s2 + s;
    const double h01 = -2.0 * s3 + 3.0 * s2, h11 = s3 - s2;
    uv[0] = h00 * lo->u + h10 * span * lo->d[0] + h01 * hi->u + h11 * span * hi->d[0];
    uv[1] = h00 * lo->v + h10 * span * lo->d[1] + h01 * hi->v + h11 * span * hi->d[1];
}

size_t pc_refine_guide_index(const pc_refiner *r, double t)
{
    size_t lo = 0, hi = r->n_guide; /* answer in [lo, hi) */
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (r->guide[mid].t <= t)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

int pc_refine_exact_point(pc_refiner *r, const pc_rvertex *a, const pc_rvertex *b, double t,
                          pc_rvertex *out)
{
    const pc_rvertex *lo = a->t <= b->t ? a : b, *hi = a->t <= b->t ? b : a;
    if (r->n_guide > 0) {
        const size_t k = pc_refine_guide_index(r, t);
        if (r->guide[k].t <= t && r->guide[k].t > lo->t)
            lo = &r->guide[k];
        if (k + 1 < r->n_guide && r->guide[k + 1].t >= t && r->guide[k + 1].t < hi->t)
            hi = &r->guide[k + 1];
    }
    const double span = hi->t - lo->t;
    const double w = span > 0.0 ? (t - lo->t) / span : 0.5;
    double uv[2] = {lo->u + w * (hi->u - lo->u), lo->v + w * (hi->v - lo->v)};
    if (a->has_d && b->has_d) /* the Hermite guess over the segment (pc_rvertex) */
        hermite_guess(a, b, t, uv);
    const double guess[2] = {uv[0], uv[1]};
    if (!r->proj->correct(r->proj, t, uv, NULL))
        return 0;
    if (!isfinite(uv[0]) || !isfinite(uv[1]))
        return 0;
    const double bracket = hypot(hi->u - lo->u, hi->v - lo->v);
    if (hypot(uv[0] - guess[0], uv[1] - guess[1]) > PC_EXACT_MAX_JUMP * bracket + r->min_move)
        return 0;
    out->t = t;
    out->u = uv[0];
    out->v = uv[1];
    out->fixed = 0;
    out->gap = 0;
    out->has_d = 0;
    return 1;
}

pc_vec3 pc_refine_surface_point(pc_refiner *r, double u, double v)
{
    pc_vec3 s;
    pc_nurbs_surface_eval(r->nurbs, u, v, 0, &r->hint_u, &r->hint_v, &s);
    return s;
}
