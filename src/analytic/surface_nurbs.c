/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Analytic surfaces as exact rational NURBS over a parameter box.
 *
 * Cylinders, cones, spheres, tori and surfaces of revolution are one
 * construction: a profile curve in the half-plane of angle 0 (a line, a
 * circular arc, or the swept curve itself) turned about the axis, each of
 * its control points along the rational quadratic arcs of the angle range
 * (The NURBS Book, 8.5: the tensor product of the arc's weights and the
 * profile's is exact because every control point turns on its own circle).
 * A plane is bilinear; an extrusion is the swept curve times a line.
 */
#include <math.h>
#include <string.h>

#include "analytic/analytic.h"
#include "common/error.h"
#include "common/vec.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Angle spans and latitudes may overshoot by this (rounding of 2 pi). */
#define PC_ANGLE_SLACK 1e-12

static projcurve_status no_memory(projcurve_context *ctx)
{
    return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory building an analytic surface");
}

static projcurve_status alloc_net(projcurve_context *ctx, pc_arena *arena, size_t n_u, size_t n_v,
                                  size_t nk_u, size_t nk_v, pc_rational_surface *out)
{
    out->n_u = n_u;
    out->n_v = n_v;
    out->ctrl = pc_arena_calloc(arena, 3 * n_u * n_v, sizeof(double));
    out->weights = pc_arena_calloc(arena, n_u * n_v, sizeof(double));
    out->knots_u = pc_arena_calloc(arena, nk_u, sizeof(double));
    out->knots_v = pc_arena_calloc(arena, nk_v, sizeof(double));
    if (out->ctrl == NULL || out->weights == NULL || out->knots_u == NULL || out->knots_v == NULL)
        return no_memory(ctx);
    return PROJCURVE_OK;
}

static void linear_knots(double *k, double a, double b)
{
    k[0] = k[1] = a;
    k[2] = k[3] = b;
}

static projcurve_status plane_nurbs(projcurve_context *ctx, pc_arena *arena,
                                    const pc_analytic_surface *s, const double box[4],
                                    pc_rational_surface *out)
{
    projcurve_status st = alloc_net(ctx, arena, 2, 2, 4, 4, out);
    if (st != PROJCURVE_OK)
        return st;
    out->deg_u = out->deg_v = 1;
    for (size_t j = 0; j < 2; ++j)
        for (size_t i = 0; i < 2; ++i) {
            pc_analytic_eval(s, box[i], box[2 + j], out->ctrl + 3 * (2 * j + i));
            out->weights[2 * j + i] = 1.0;
        }
    linear_knots(out->knots_u, box[0], box[1]);
    linear_knots(out->knots_v, box[2], box[3]);
    return PROJCURVE_OK;
}

/* The profile, in the half-plane of angle 0 through the frame's x, of an
 * elementary surface of revolution over [v0, v1]. */
static projcurve_status profile_of(projcurve_context *ctx, pc_arena *arena,
                                   const pc_analytic_surface *s, double v0, double v1,
                                   pc_rational_curve *out, pc_angle_map *map_v)
{
    const pc_frame *f = &s->frame;
    double o[3], d[3];
    *map_v = (pc_angle_map){.is_angle = 0};
    switch (s->kind) {
    case PC_ANALYTIC_CYLINDER:
    case PC_ANALYTIC_CONE: {
        const double slope = s->kind == PC_ANALYTIC_CONE ? tan(s->semi_angle) : 0.0;
        for (int k = 0; k < 3; ++k) {
            o[k] = f->origin[k] + s->radius * f->x[k];
            d[k] = slope * f->x[k] + f->z[k];
        }
        return pc_line_segment(ctx, arena, o, d, v0, v1, out);
    }
    case PC_ANALYTIC_SPHERE:
    case PC_ANALYTIC_TORUS: {
        const double centre_r = s->kind == PC_ANALYTIC_TORUS ? s->radius : 0.0;
        const double r = s->kind == PC_ANALYTIC_TORUS ? s->minor_radius : s->radius;
        for (int k = 0; k < 3; ++k)
            o[k] = f->origin[k] + centre_r * f->x[k];
        *map_v = pc_angle_map_make(v0, v1);
        return pc_ellipse_arc(ctx, arena, o, f->x, f->z, r, r, v0, v1, out);
    }
    default: break;
    }
    return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT, "not a surface of revolution");
}

/* The profile turned about (origin, z) over the angles of map_u. */
static projcurve_status revolve(projcurve_context *ctx, pc_arena *arena, const pc_frame *f,
                                const pc_rational_curve *profile, const pc_angle_map *map_u,
                                pc_rational_surface *out)
{
    const size_t n_seg = map_u->n_seg, n_u = 2 * n_seg + 1, n_v = profile->n_ctrl;
    const size_t nk_v = n_v + (size_t)profile->degree + 1;
    projcurve_status st = alloc_net(ctx, arena, n_u, n_v, n_u + 3, nk_v, out);
    if (st != PROJCURVE_OK)
        return st;
    out->deg_u = 2;
    out->deg_v = profile->degree;
    const double step = (map_u->a1 - map_u->a0) / (double)n_seg, w_mid = cos(step / 2.0);
    const pc_vec3 z = vec3_load(f->z), c = vec3_load(f->origin);
    for (size_t j = 0; j < n_v; ++j) {
        const pc_vec3 d = vec3_sub(vec3_load(profile->ctrl + 3 * j), c);
        const double h = vec3_dot(d, z);
        const pc_vec3 r = vec3_axpy(d, -h, z), zr = vec3_cross(z, r), foot = vec3_axpy(c, h, z);
        const double wj = profile->weights ? profile->weights[j] : 1.0;
        for (size_t i = 0; i < n_u; ++i) {
            const size_t seg = i / 2;
            const int middle = (int)(i % 2);
            const double a = (i == n_u - 1) ? map_u->a1
                                            : map_u->a0 + step * (double)seg + (middle ? step / 2.0 : 0.0);
            const double scale = middle ? 1.0 / w_mid : 1.0;
            const pc_vec3 q = vec3_add(foot, vec3_scale(vec3_add(vec3_scale(r, cos(a)),
                                                                 vec3_scale(zr, sin(a))),
                                                        scale));
            vec3_store(q, out->ctrl + 3 * (j * n_u + i));
            out->weights[j * n_u + i] = wj * (middle ? w_mid : 1.0);
        }
    }
    out->knots_u[0] = out->knots_u[1] = out->knots_u[2] = map_u->a0;
    for (size_t k = 1; k < n_seg; ++k)
        out->knots_u[2 * k + 1] = out->knots_u[2 * k + 2] = map_u->a0 + step * (double)k;
    out->knots_u[n_u] = out->knots_u[n_u + 1] = out->knots_u[n_u + 2] = map_u->a1;
    memcpy(out->knots_v, profile->knots, nk_v * sizeof(double));
    return PROJCURVE_OK;
}

static projcurve_status extrude(projcurve_context *ctx, pc_arena *arena,
                                const pc_analytic_surface *s, double v0, double v1,
                                pc_rational_surface *out)
{
    const pc_rational_curve *c = s->curve;
    const size_t n_u = c->n_ctrl, nk_u = n_u + (size_t)c->degree + 1;
    projcurve_status st = alloc_net(ctx, arena, n_u, 2, nk_u, 4, out);
    if (st != PROJCURVE_OK)
        return st;
    out->deg_u = c->degree;
    out->deg_v = 1;
    const double v[2] = {v0, v1};
    for (size_t j = 0; j < 2; ++j)
        for (size_t i = 0; i < n_u; ++i) {
            for (int k = 0; k < 3; ++k)
                out->ctrl[3 * (j * n_u + i) + (size_t)k] = c->ctrl[3 * i + (size_t)k] + v[j] * s->extrusion[k];
            out->weights[j * n_u + i] = c->weights ? c->weights[i] : 1.0;
        }
    memcpy(out->knots_u, c->knots, nk_u * sizeof(double));
    linear_knots(out->knots_v, v0, v1);
    return PROJCURVE_OK;
}

static projcurve_status check_box(projcurve_context *ctx, const pc_analytic_surface *s,
                                  const double box[4])
{
    for (int k = 0; k < 4; ++k)
        if (!isfinite(box[k]))
            return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "a parameter box with a NaN or infinite bound");
    const int curve_dir = s->kind == PC_ANALYTIC_REVOLUTION ? 1 : (s->kind == PC_ANALYTIC_EXTRUSION ? 0 : -1);
    for (int d = 0; d < 2; ++d)
        if (d != curve_dir && !(box[2 * d + 1] > box[2 * d]))
            return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE, "an empty %c range [%g, %g] of a %s",
                           d ? 'v' : 'u', box[2 * d], box[2 * d + 1], pc_analytic_kind_name(s->kind));
    const int angle_u = s->kind != PC_ANALYTIC_PLANE && s->kind != PC_ANALYTIC_EXTRUSION;
    const int angle_v = s->kind == PC_ANALYTIC_SPHERE || s->kind == PC_ANALYTIC_TORUS;
    if ((angle_u && box[1] - box[0] > 2.0 * M_PI + PC_ANGLE_SLACK) ||
        (angle_v && box[3] - box[2] > 2.0 * M_PI + PC_ANGLE_SLACK))
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE, "an angle range of a %s above one turn",
                       pc_analytic_kind_name(s->kind));
    if (s->kind == PC_ANALYTIC_SPHERE &&
        (box[2] < -M_PI / 2.0 - PC_ANGLE_SLACK || box[3] > M_PI / 2.0 + PC_ANGLE_SLACK))
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_RANGE,
                       "sphere latitudes [%g, %g] outside [-pi/2, pi/2]", box[2], box[3]);
    return PROJCURVE_OK;
}

projcurve_status pc_analytic_to_nurbs(projcurve_context *ctx, pc_arena *arena,
                                      const pc_analytic_surface *s, const double box[4],
                                      pc_rational_surface *out, pc_angle_map *map_u,
                                      pc_angle_map *map_v)
{
    PC_REQUIRE(ctx, box, "box");
    PC_REQUIRE(ctx, out, "out");
    projcurve_status st = pc_analytic_check(ctx, s);
    if (st != PROJCURVE_OK || (st = check_box(ctx, s, box)) != PROJCURVE_OK)
        return st;
    pc_angle_map mu = {.is_angle = 0}, mv = {.is_angle = 0};
    switch (s->kind) {
    case PC_ANALYTIC_PLANE: st = plane_nurbs(ctx, arena, s, box, out); break;
    case PC_ANALYTIC_EXTRUSION:
        mu = s->curve_map;
        st = extrude(ctx, arena, s, box[2], box[3], out);
        break;
    case PC_ANALYTIC_REVOLUTION:
        mu = pc_angle_map_make(box[0], box[1]);
        mv = s->curve_map;
        st = revolve(ctx, arena, &s->frame, s->curve, &mu, out);
        break;
    default: {
        pc_rational_curve profile;
        mu = pc_angle_map_make(box[0], box[1]);
        if ((st = profile_of(ctx, arena, s, box[2], box[3], &profile, &mv)) == PROJCURVE_OK)
            st = revolve(ctx, arena, &s->frame, &profile, &mu, out);
        break;
    }
    }
    if (st != PROJCURVE_OK)
        return st;
    if (map_u)
        *map_u = mu;
    if (map_v)
        *map_v = mv;
    return PROJCURVE_OK;
}
