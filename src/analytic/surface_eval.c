/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Points of analytic surfaces from their parameters, and parameters from
 * points: the closed forms of the elementary kinds, and for swept surfaces
 * a bounded search along the swept curve.
 */
#include <math.h>

#include "analytic/analytic.h"
#include "common/vec.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* Samples per knot span of the swept curve before the bracketed search,
 * and the most samples in all. */
#define PC_INVERT_SAMPLES_PER_SPAN 16
#define PC_INVERT_MAX_SAMPLES 4096

typedef struct local {
    double x, y, z; /* coordinates of p - origin in the frame */
} local;

static local to_local(const pc_frame *f, const double p[3])
{
    const pc_vec3 d = vec3_sub(vec3_load(p), vec3_load(f->origin));
    return (local){vec3_dot(d, vec3_load(f->x)), vec3_dot(d, vec3_load(f->y)),
                   vec3_dot(d, vec3_load(f->z))};
}

/* C + a x + b y + c z */
static void from_local(const pc_frame *f, double a, double b, double c, double out[3])
{
    for (int k = 0; k < 3; ++k)
        out[k] = f->origin[k] + a * f->x[k] + b * f->y[k] + c * f->z[k];
}

/* The point turned by angle u about the axis (origin, z). */
static void rotate_about_axis(const pc_frame *f, const double p[3], double u, double out[3])
{
    const pc_vec3 z = vec3_load(f->z);
    const pc_vec3 d = vec3_sub(vec3_load(p), vec3_load(f->origin));
    const double h = vec3_dot(d, z);
    const pc_vec3 r = vec3_axpy(d, -h, z);
    const pc_vec3 q = vec3_add(vec3_axpy(vec3_load(f->origin), h, z),
                               vec3_add(vec3_scale(r, cos(u)), vec3_scale(vec3_cross(z, r), sin(u))));
    vec3_store(q, out);
}

void pc_analytic_eval(const pc_analytic_surface *s, double u, double v, double out[3])
{
    const pc_frame *f = &s->frame;
    switch (s->kind) {
    case PC_ANALYTIC_PLANE: from_local(f, u, v, 0.0, out); return;
    case PC_ANALYTIC_CYLINDER:
        from_local(f, s->radius * cos(u), s->radius * sin(u), v, out);
        return;
    case PC_ANALYTIC_CONE: {
        const double rho = s->radius + v * tan(s->semi_angle);
        from_local(f, rho * cos(u), rho * sin(u), v, out);
        return;
    }
    case PC_ANALYTIC_SPHERE: {
        const double rho = s->radius * cos(v);
        from_local(f, rho * cos(u), rho * sin(u), s->radius * sin(v), out);
        return;
    }
    case PC_ANALYTIC_TORUS: {
        const double rho = s->radius + s->minor_radius * cos(v);
        from_local(f, rho * cos(u), rho * sin(u), s->minor_radius * sin(v), out);
        return;
    }
    case PC_ANALYTIC_REVOLUTION: {
        double k[3];
        pc_rational_curve_eval(s->curve, pc_angle_to_nurbs(&s->curve_map, v), k);
        rotate_about_axis(f, k, u, out);
        return;
    }
    case PC_ANALYTIC_EXTRUSION: {
        double k[3];
        pc_rational_curve_eval(s->curve, pc_angle_to_nurbs(&s->curve_map, u), k);
        for (int i = 0; i < 3; ++i)
            out[i] = k[i] + v * s->extrusion[i];
        return;
    }
    }
}

/* atan2 in [0, 2 pi), 0 where it is not defined. */
static double angle_of(double y, double x)
{
    if (x == 0.0 && y == 0.0)
        return 0.0;
    const double a = atan2(y, x);
    return a < 0.0 ? a + 2.0 * M_PI : a;
}

/* ---- swept curves: the curve parameter nearest to a point ----------------- */

typedef struct sweep_target {
    const pc_analytic_surface *s;
    double p[3];
    local pl; /* revolution: p in the frame */
} sweep_target;

/* The squared distance that the curve parameter t leaves: in the meridian
 * half-plane (radius, height) for a revolution, across the extrusion
 * vector for an extrusion. */
static double sweep_distance2(const sweep_target *g, double t)
{
    double k[3];
    pc_rational_curve_eval(g->s->curve, t, k);
    if (g->s->kind == PC_ANALYTIC_REVOLUTION) {
        const local kl = to_local(&g->s->frame, k);
        const double dr = hypot(kl.x, kl.y) - hypot(g->pl.x, g->pl.y), dh = kl.z - g->pl.z;
        return dr * dr + dh * dh;
    }
    const pc_vec3 e = vec3_load(g->s->extrusion);
    const pc_vec3 d = vec3_sub(vec3_load(g->p), vec3_load(k));
    const pc_vec3 across = vec3_axpy(d, -vec3_dot(d, e) / vec3_dot(e, e), e);
    return vec3_dot(across, across);
}

/* Dense samples, then golden-section search in the bracket around the best
 * one; at most PC_ANALYTIC_INVERT_ITERATIONS steps (then the best point so
 * far is kept: the bracket is then below the resolution of t anyway). */
static double nearest_curve_parameter(const sweep_target *g)
{
    const pc_rational_curve *c = g->s->curve;
    const double t0 = c->knots[c->degree], t1 = c->knots[c->n_ctrl];
    size_t n = (c->n_ctrl - (size_t)c->degree) * PC_INVERT_SAMPLES_PER_SPAN;
    if (n > PC_INVERT_MAX_SAMPLES)
        n = PC_INVERT_MAX_SAMPLES;
    const double dt = (t1 - t0) / (double)n;
    double best_t = t0, best = sweep_distance2(g, t0);
    for (size_t i = 1; i <= n; ++i) {
        const double t = i == n ? t1 : t0 + dt * (double)i;
        const double f = sweep_distance2(g, t);
        if (f < best) {
            best = f;
            best_t = t;
        }
    }
    double a = fmax(t0, best_t - dt), b = fmin(t1, best_t + dt);
    const double phi = 0.5 * (sqrt(5.0) - 1.0);
    double x1 = b - phi * (b - a), x2 = a + phi * (b - a);
    double f1 = sweep_distance2(g, x1), f2 = sweep_distance2(g, x2);
    for (int it = 0; it < PC_ANALYTIC_INVERT_ITERATIONS && x1 < x2; ++it) {
        if (f1 <= f2) {
            b = x2;
            x2 = x1;
            f2 = f1;
            x1 = b - phi * (b - a);
            f1 = sweep_distance2(g, x1);
        } else {
            a = x1;
            x1 = x2;
            f1 = f2;
            x2 = a + phi * (b - a);
            f2 = sweep_distance2(g, x2);
        }
    }
    const double tm = f1 <= f2 ? x1 : x2, fm = fmin(f1, f2);
    return fm < best ? tm : best_t;
}

static void invert_swept(const pc_analytic_surface *s, const double p[3], double *u, double *v)
{
    sweep_target g = {.s = s, .p = {p[0], p[1], p[2]}, .pl = to_local(&s->frame, p)};
    const double t = nearest_curve_parameter(&g);
    const double t_own = pc_nurbs_to_angle(&s->curve_map, t);
    double k[3];
    pc_rational_curve_eval(s->curve, t, k);
    if (s->kind == PC_ANALYTIC_REVOLUTION) {
        const local kl = to_local(&s->frame, k);
        double a = angle_of(g.pl.y, g.pl.x) - angle_of(kl.y, kl.x);
        if (a < 0.0)
            a += 2.0 * M_PI;
        *u = a >= 2.0 * M_PI ? 0.0 : a;
        *v = t_own;
        return;
    }
    const pc_vec3 e = vec3_load(s->extrusion);
    *u = t_own;
    *v = vec3_dot(vec3_sub(vec3_load(p), vec3_load(k)), e) / vec3_dot(e, e);
}

void pc_analytic_invert(const pc_analytic_surface *s, const double p[3], double *u, double *v)
{
    const local l = to_local(&s->frame, p);
    const double rho = hypot(l.x, l.y);
    switch (s->kind) {
    case PC_ANALYTIC_PLANE:
        *u = l.x;
        *v = l.y;
        return;
    case PC_ANALYTIC_CYLINDER:
        *u = angle_of(l.y, l.x);
        *v = l.z;
        return;
    case PC_ANALYTIC_CONE: {
        /* The nearest point of the generator (R + v tan a, v) in the
         * meridian plane through p, on p's side of the axis (signed radius
         * rho) or on the far side (-rho, past the apex, angle u + pi). */
        const double ca = cos(s->semi_angle), sa = sin(s->semi_angle), ta = tan(s->semi_angle);
        const double v1 = (rho - s->radius) * sa * ca + l.z * ca * ca;
        const double v2 = (-rho - s->radius) * sa * ca + l.z * ca * ca;
        const double d1 = hypot(rho - s->radius - v1 * ta, l.z - v1);
        const double d2 = hypot(-rho - s->radius - v2 * ta, l.z - v2);
        const double a = angle_of(l.y, l.x);
        if (d1 <= d2 || rho == 0.0) {
            *u = a;
            *v = v1;
        } else {
            *u = a < M_PI ? a + M_PI : a - M_PI;
            *v = v2;
        }
        return;
    }
    case PC_ANALYTIC_SPHERE:
        *u = angle_of(l.y, l.x);
        *v = (rho == 0.0 && l.z == 0.0) ? 0.0 : atan2(l.z, rho);
        return;
    case PC_ANALYTIC_TORUS:
        *u = angle_of(l.y, l.x);
        *v = angle_of(l.z, rho - s->radius);
        return;
    case PC_ANALYTIC_REVOLUTION:
    case PC_ANALYTIC_EXTRUSION: invert_swept(s, p, u, v); return;
    }
}
