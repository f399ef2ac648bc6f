/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Frames and the validation of analytic surface descriptions.
 */
#include <math.h>
#include <string.h>

#include "analytic/analytic.h"
#include "common/error.h"
#include "common/vec.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* A reference direction whose part perpendicular to the axis is shorter
 * than this (relative) is taken as parallel to it: the frame's x would
 * carry the rounding of the subtraction in its leading digits. */
#define PC_FRAME_PARALLEL_REL 1e-10

static int finite3(const double *p)
{
    return isfinite(p[0]) && isfinite(p[1]) && isfinite(p[2]);
}

projcurve_status pc_frame_make(projcurve_context *ctx, const double origin[3],
                               const double axis[3], const double ref[3], pc_frame *out)
{
    PC_REQUIRE(ctx, origin, "origin");
    PC_REQUIRE(ctx, axis, "axis");
    if (!finite3(origin) || !finite3(axis) || (ref != NULL && !finite3(ref)))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "a frame with a NaN or infinite value");
    const pc_vec3 a = vec3_load(axis);
    const double la = vec3_norm(a);
    if (!(la > 0.0) || !isfinite(la))
        return pc_fail(ctx, PROJCURVE_ERR_ZERO_DIRECTION, "a frame axis of length zero");
    const pc_vec3 z = vec3_scale(a, 1.0 / la);
    pc_vec3 r;
    if (ref != NULL) {
        r = vec3_load(ref);
        const double lr = vec3_norm(r);
        if (!(lr > 0.0) || !isfinite(lr))
            return pc_fail(ctx, PROJCURVE_ERR_ZERO_DIRECTION,
                           "a frame reference direction of length zero");
        r = vec3_scale(r, 1.0 / lr);
    } else {
        r = fabs(z.x) <= fabs(z.y) ? vec3(1.0, 0.0, 0.0) : vec3(0.0, 1.0, 0.0);
    }
    const pc_vec3 xp = vec3_axpy(r, -vec3_dot(r, z), z);
    const double lx = vec3_norm(xp);
    if (!(lx > PC_FRAME_PARALLEL_REL))
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "a frame reference direction (%g, %g, %g) parallel to its axis (%g, %g, %g)",
                       r.x, r.y, r.z, z.x, z.y, z.z);
    const pc_vec3 x = vec3_scale(xp, 1.0 / lx);
    const pc_vec3 y = vec3_cross(z, x);
    memcpy(out->origin, origin, 3 * sizeof(double));
    vec3_store(x, out->x);
    vec3_store(y, out->y);
    vec3_store(z, out->z);
    return PROJCURVE_OK;
}

const char *pc_analytic_kind_name(pc_analytic_kind kind)
{
    switch (kind) {
    case PC_ANALYTIC_PLANE: return "plane";
    case PC_ANALYTIC_CYLINDER: return "cylinder";
    case PC_ANALYTIC_CONE: return "cone";
    case PC_ANALYTIC_SPHERE: return "sphere";
    case PC_ANALYTIC_TORUS: return "torus";
    case PC_ANALYTIC_REVOLUTION: return "revolution";
    case PC_ANALYTIC_EXTRUSION: return "extrusion";
    }
    return "unknown";
}

static projcurve_status check_curve(projcurve_context *ctx, const pc_rational_curve *c)
{
    if (c == NULL || c->ctrl == NULL || c->knots == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NULL_ARGUMENT, "a swept surface without its curve");
    if (c->degree < 1 || c->degree > PROJCURVE_MAX_DEGREE || c->n_ctrl < (size_t)c->degree + 1)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "a swept curve of degree %d with %zu control points", c->degree, c->n_ctrl);
    for (size_t i = 0; i < c->n_ctrl; ++i)
        if (!finite3(c->ctrl + 3 * i) || (c->weights && !(c->weights[i] > 0.0 && isfinite(c->weights[i]))))
            return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE,
                           "swept curve control point %zu is not finite or has a weight <= 0", i);
    const size_t nk = c->n_ctrl + (size_t)c->degree + 1;
    for (size_t i = 0; i + 1 < nk; ++i)
        if (!(c->knots[i] <= c->knots[i + 1]) || !isfinite(c->knots[i + 1]))
            return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                           "swept curve knots decrease at index %zu", i + 1);
    if (!(c->knots[c->degree] < c->knots[c->n_ctrl]))
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT, "a swept curve with an empty domain");
    return PROJCURVE_OK;
}

static projcurve_status positive(projcurve_context *ctx, double r, const char *what)
{
    if (!isfinite(r))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "%s is not finite", what);
    if (!(r > 0.0))
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT, "%s %g is not positive", what, r);
    return PROJCURVE_OK;
}

projcurve_status pc_analytic_check(projcurve_context *ctx, const pc_analytic_surface *s)
{
    PC_REQUIRE(ctx, s, "surface");
    const pc_frame *f = &s->frame;
    if (!finite3(f->origin) || !finite3(f->x) || !finite3(f->y) || !finite3(f->z))
        return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "a %s frame with a NaN or infinite value",
                       pc_analytic_kind_name(s->kind));
    projcurve_status st = PROJCURVE_OK;
    switch (s->kind) {
    case PC_ANALYTIC_PLANE: break;
    case PC_ANALYTIC_CYLINDER:
    case PC_ANALYTIC_SPHERE: st = positive(ctx, s->radius, "radius"); break;
    case PC_ANALYTIC_CONE:
        if (!isfinite(s->radius) || !isfinite(s->semi_angle))
            return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "a cone with a NaN or infinite value");
        if (!(s->radius >= 0.0))
            return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT, "cone radius %g is negative",
                           s->radius);
        if (!(fabs(s->semi_angle) < M_PI / 2.0) || s->semi_angle == 0.0)
            return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                           "cone semi-angle %g rad is not in (-pi/2, pi/2) \\ {0}", s->semi_angle);
        break;
    case PC_ANALYTIC_TORUS:
        if ((st = positive(ctx, s->radius, "torus major radius")) != PROJCURVE_OK ||
            (st = positive(ctx, s->minor_radius, "torus minor radius")) != PROJCURVE_OK)
            return st;
        if (s->minor_radius > s->radius)
            return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                           "torus minor radius %g exceeds its major radius %g (a spindle torus)",
                           s->minor_radius, s->radius);
        break;
    case PC_ANALYTIC_REVOLUTION: st = check_curve(ctx, s->curve); break;
    case PC_ANALYTIC_EXTRUSION:
        if (!finite3(s->extrusion))
            return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "an extrusion vector is not finite");
        if (!(vec3_norm(vec3_load(s->extrusion)) > 0.0))
            return pc_fail(ctx, PROJCURVE_ERR_ZERO_DIRECTION, "an extrusion vector of length zero");
        st = check_curve(ctx, s->curve);
        break;
    default:
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT, "unknown analytic kind %d",
                       (int)s->kind);
    }
    return st;
}

void pc_analytic_natural_box(const pc_analytic_surface *s, double box[4], int bounded[2])
{
    bounded[0] = bounded[1] = 0;
    switch (s->kind) {
    case PC_ANALYTIC_PLANE: return;
    case PC_ANALYTIC_CYLINDER:
    case PC_ANALYTIC_CONE:
    case PC_ANALYTIC_REVOLUTION:
        box[0] = 0.0;
        box[1] = 2.0 * M_PI;
        bounded[0] = 1;
        break;
    case PC_ANALYTIC_SPHERE:
        box[0] = 0.0;
        box[1] = 2.0 * M_PI;
        box[2] = -M_PI / 2.0;
        box[3] = M_PI / 2.0;
        bounded[0] = bounded[1] = 1;
        return;
    case PC_ANALYTIC_TORUS:
        box[0] = box[2] = 0.0;
        box[1] = box[3] = 2.0 * M_PI;
        bounded[0] = bounded[1] = 1;
        return;
    case PC_ANALYTIC_EXTRUSION: break;
    }
    if (s->curve != NULL && (s->kind == PC_ANALYTIC_REVOLUTION || s->kind == PC_ANALYTIC_EXTRUSION)) {
        const int k = s->kind == PC_ANALYTIC_REVOLUTION ? 2 : 0;
        box[k] = pc_nurbs_to_angle(&s->curve_map, s->curve->knots[s->curve->degree]);
        box[k + 1] = pc_nurbs_to_angle(&s->curve_map, s->curve->knots[s->curve->n_ctrl]);
        bounded[k / 2] = 1;
    }
}

int pc_analytic_box_covering(const pc_analytic_surface *s, const double *points, size_t n,
                             double box[4])
{
    int bounded[2];
    pc_analytic_natural_box(s, box, bounded);
    for (int dir = 0; dir < 2; ++dir) {
        if (bounded[dir])
            continue;
        if (n == 0)
            return 0;
        double lo = HUGE_VAL, hi = -HUGE_VAL;
        for (size_t i = 0; i < n; ++i) {
            double uv[2];
            pc_analytic_invert(s, points + 3 * i, &uv[0], &uv[1]);
            lo = fmin(lo, uv[dir]);
            hi = fmax(hi, uv[dir]);
        }
        const double scale = fmax(fmax(fabs(lo), fabs(hi)), s->radius);
        double pad = PC_ANALYTIC_BOX_MARGIN_REL * (hi - lo) + PC_ANALYTIC_BOX_MARGIN_ABS_REL * scale;
        if (!(pad > 0.0))
            pad = 1.0;
        box[2 * dir] = lo - pad;
        box[2 * dir + 1] = hi + pad;
    }
    return 1;
}
