/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The first-order baseline: the ODE q' = f(t, q) of Wang, Wei & Zhang 2010
 * ([SY13] eq. (3.2), its reference [16]) integrated with the classical
 * fourth-order Runge-Kutta scheme. The corrector that follows is the same
 * Newton as for the second-order tracer, as in [SY13] s5 (Table 1).
 */
#include "trace/tracer.h"

/* f(t, q) = q' at a point that need not lie on the projection curve: the
 * projector's first-derivative formula is defined there too. Its slope()
 * needs first derivatives of S only, as the method of [16]; projectors
 * without one give q' through derivatives(). */
static int slope(const pc_projector *proj, double t, double u, double v, double k[2])
{
    if (proj->slope != NULL)
        return proj->slope(proj, t, u, v, k);
    pc_proj_point p;
    if (!proj->derivatives(proj, t, u, v, &p))
        return 0;
    k[0] = p.du;
    k[1] = p.dv;
    return 1;
}

int pc_predict_rk4(const pc_projector *proj, const pc_proj_point *pt, double h, double uv[2])
{
    const double k1[2] = {pt->du, pt->dv};
    double k2[2], k3[2], k4[2];
    const double half = 0.5 * h;
    if (!slope(proj, pt->t + half, pt->u + half * k1[0], pt->v + half * k1[1], k2) ||
        !slope(proj, pt->t + half, pt->u + half * k2[0], pt->v + half * k2[1], k3) ||
        !slope(proj, pt->t + h, pt->u + h * k3[0], pt->v + h * k3[1], k4))
        return 0;
    uv[0] = pt->u + h / 6.0 * (k1[0] + 2.0 * k2[0] + 2.0 * k3[0] + k4[0]);
    uv[1] = pt->v + h / 6.0 * (k1[1] + 2.0 * k2[1] + 2.0 * k3[1] + k4[1]);
    return 1;
}
