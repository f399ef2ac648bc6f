/* SPDX-License-Identifier: BSD-3-Clause */
#include "residual.h"
#include "vec3.h"

#include <math.h>

/* A derivative below this fraction of the other marks a collapsed edge
 * (a pole, an apex, a horn's tip), as in the library (ortho/collapsed.h). */
#define CLI_COLLAPSED_RATIO 1e-6

/* Length of the part of d tangent to the plane with normal n. */
static double tangential(const double d[3], const double n[3])
{
    const double nn = dot3(n, n);
    const double dn = dot3(d, n) / nn;
    const double t[3] = {d[0] - dn * n[0], d[1] - dn * n[1], d[2] - dn * n[2]};
    return norm3(t);
}

/* The orthogonal residual: the tangential part of d = S - P. At a point of
 * a collapsed edge Su x Sv is rounding (|Sv| ~ 1e-15 at the horn's tip)
 * and the normal is its limit: with Sv ~ e Suv at a distance e from the
 * edge u = const, Su x Sv ~ e Su x Suv (Suv x Sv for Su ~ 0). Where that
 * limit vanishes too (a cone's apex has no tangent plane) only the regular
 * direction's condition is left: the component of d along it. */
static double orthogonal_residual(const double *s, const double d[3])
{
    const double *su = s + 3, *sv = s + 6, *suv = s + 12;
    const double lu = norm3(su), lv = norm3(sv);
    double n[3];
    if (lv < CLI_COLLAPSED_RATIO * lu || lu < CLI_COLLAPSED_RATIO * lv) {
        const int v_collapsed = lv < lu;
        const double *regular = v_collapsed ? su : sv;
        if (v_collapsed)
            cross3(su, suv, n);
        else
            cross3(suv, sv, n);
        if (norm3(n) > CLI_COLLAPSED_RATIO * norm3(regular) * norm3(suv))
            return tangential(d, n);
        return fabs(dot3(d, regular)) / norm3(regular);
    }
    cross3(su, sv, n);
    if (!(norm3(n) > 0.0))
        return INFINITY;
    return tangential(d, n);
}

/* The length in space of Newton's step -K^-1 F on the foot-point equations
 * F = [d.Su, d.Sv] = 0, K_ij = Si.Sj + d.Sij: the distance from S to the
 * foot point, to first order; INFINITY where K is singular (a centre of
 * curvature, a collapsed edge), where the tangential measure holds. */
static double newton_step_length(const double *s, const double d[3])
{
    const double *su = s + 3, *sv = s + 6, *suu = s + 9, *suv = s + 12, *svv = s + 15;
    const double f0 = dot3(d, su), f1 = dot3(d, sv);
    const double k00 = dot3(su, su) + dot3(d, suu), k01 = dot3(su, sv) + dot3(d, suv);
    const double k11 = dot3(sv, sv) + dot3(d, svv);
    const double det = k00 * k11 - k01 * k01;
    const double scale = fabs(k00) + 2.0 * fabs(k01) + fabs(k11);
    if (!(fabs(det) > 1e-15 * scale * scale))
        return INFINITY;
    const double du = -(k11 * f0 - k01 * f1) / det, dv = -(k00 * f1 - k01 * f0) / det;
    const double step[3] = {su[0] * du + sv[0] * dv, su[1] * du + sv[1] * dv,
                            su[2] * du + sv[2] * dv};
    return norm3(step);
}

/* Parameter nudge, as a fraction of the domain's width, that moves an
 * evaluation off a knot line to the patch on one side of it (S moves by
 * ~1e-12 of the model size). */
#define CLI_SIDE_NUDGE 1e-12

/* The orthogonal residual at (u, v), INFINITY where S cannot be evaluated. */
static double orthogonal_at(projcurve_context *ctx, const projcurve_surface *surface,
                            const double p[3], double u, double v)
{
    double s[18];
    if (projcurve_surface_eval(ctx, surface, u, v, 2, s) != PROJCURVE_OK)
        return INFINITY;
    const double d[3] = {s[0] - p[0], s[1] - p[1], s[2] - p[2]};
    return fmin(orthogonal_residual(s, d), newton_step_length(s, d));
}

double cli_orthogonal_residual(projcurve_context *ctx, const projcurve_surface *surface,
                               const double p[3], double u, double v)
{
    double dom[4];
    projcurve_surface_domain(ctx, surface, dom);
    const double hu = CLI_SIDE_NUDGE * (dom[1] - dom[0]), hv = CLI_SIDE_NUDGE * (dom[3] - dom[2]);
    double r = orthogonal_at(ctx, surface, p, u, v);
    r = fmin(r, orthogonal_at(ctx, surface, p, fmax(dom[0], u - hu), v));
    r = fmin(r, orthogonal_at(ctx, surface, p, fmin(dom[1], u + hu), v));
    r = fmin(r, orthogonal_at(ctx, surface, p, u, fmax(dom[2], v - hv)));
    return fmin(r, orthogonal_at(ctx, surface, p, u, fmin(dom[3], v + hv)));
}
