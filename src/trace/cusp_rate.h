/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * pc_proj_point.cusp_rate for the projectors whose branch is a curve q(t)
 * on S with q' known (directional, conical): the rate at which a cusp of
 * the parametrisation closes in, from S's derivatives alone. It does not
 * depend on how q' was found, so every such projector fills the field the
 * same way and the tracer's cusp rule (tracer.c, cusp_distance and
 * chord_turns_over) applies to all of them alike.
 */
#ifndef PC_TRACE_CUSP_RATE_H
#define PC_TRACE_CUSP_RATE_H

#include <math.h>

#include "common/vec.h"

/* The rate at which a cusp of the parametrisation closes in along the
 * branch (q1 = q'), with s = S, Su, Sv, Suu, Suv, Svv and N = Su x Sv
 * (|N|^2 = area2): the part of d ln |N| / dt = N.N' / |N|^2 that comes
 * from the pure second derivatives, N' ~ Suu u' x Sv + Su x Svv v'. Where
 * Sv vanishes and reverses along a v line (a cusp: Sv ~ (v - v_c) Svv,
 * docs/tracing.md "Pleats"), |N| goes to 0 with it while Dir.N / |N|
 * does not, and this is v' / (v - v_c): what tells the tracer the cusp is
 * near (likewise Su along a u line). At a pole or a collapsed row (a
 * whole u line on one point: Su ~ (v - v_0) Suv, Suu -> 0 with it) the
 * mixed term Suv makes |N| vanish and this rate stays bounded: the branch
 * passes a pole, it ends at a cusp. 0 where N vanishes or the rate is not
 * finite (the projector does not tell). */
static inline double pc_cusp_rate(const pc_vec3 *s, pc_vec3 n, double area2, const double q1[2])
{
    if (!(area2 > 0.0))
        return 0.0;
    const pc_vec3 n_t = vec3_add(vec3_cross(vec3_scale(s[3], q1[0]), s[2]),
                                 vec3_cross(s[1], vec3_scale(s[5], q1[1])));
    const double rate = vec3_dot(n, n_t) / area2;
    return isfinite(rate) ? rate : 0.0;
}

#endif /* PC_TRACE_CUSP_RATE_H */
