/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Parameter text of the entities the writer emits: 126 (B-spline curve) and
 * 128 (B-spline surface), from the clamped homogeneous storage of
 * nurbs/nurbs.h. Reals are written with 17 significant digits, which
 * round-trips every double exactly (io/text_buf.h).
 */
#include "io/iges_write.h"

void pc_iges_param_real(pc_text_buf *b, double v)
{
    pc_text_buf_real(b, v);
    pc_text_buf_append(b, ",", 1);
}

void pc_iges_param_int(pc_text_buf *b, long long v)
{
    pc_text_buf_printf(b, "%lld,", v);
}

void pc_iges_param_end(pc_text_buf *b)
{
    if (!b->failed && b->len > 0 && b->text[b->len - 1] == ',')
        b->text[b->len - 1] = ';';
}

static void reals(pc_text_buf *b, const double *v, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        pc_iges_param_real(b, v[i]);
}

/* Weights (4th homogeneous coordinate) and Cartesian points of n points. */
static void weights_and_points(pc_text_buf *b, const double *cw, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        pc_iges_param_real(b, cw[4 * i + 3]);
    for (size_t i = 0; i < n; ++i)
        for (size_t k = 0; k < 3; ++k)
            pc_iges_param_real(b, cw[4 * i + k] / cw[4 * i + 3]);
}

void pc_iges_format_surface(pc_text_buf *b, const pc_nurbs_surface *s)
{
    /* K1, K2, M1, M2, PROP1..5 (closed u, closed v, polynomial, periodic u, v) */
    pc_iges_param_int(b, (long long)s->n_u - 1);
    pc_iges_param_int(b, (long long)s->n_v - 1);
    pc_iges_param_int(b, s->deg_u);
    pc_iges_param_int(b, s->deg_v);
    pc_iges_param_int(b, 0);
    pc_iges_param_int(b, 0);
    pc_iges_param_int(b, s->rational ? 0 : 1);
    pc_iges_param_int(b, 0);
    pc_iges_param_int(b, 0);
    reals(b, s->knots_u, s->n_u + (size_t)s->deg_u + 1);
    reals(b, s->knots_v, s->n_v + (size_t)s->deg_v + 1);
    weights_and_points(b, s->cw, s->n_u * s->n_v);
    reals(b, s->domain, 4);
    pc_iges_param_end(b);
}

static void curve_tail(pc_text_buf *b, double t0, double t1, int planar_z)
{
    pc_iges_param_real(b, t0);
    pc_iges_param_real(b, t1);
    /* Unit normal of the plane for planar curves, else zeros. */
    pc_iges_param_real(b, 0.0);
    pc_iges_param_real(b, 0.0);
    pc_iges_param_real(b, planar_z ? 1.0 : 0.0);
    pc_iges_param_end(b);
}

void pc_iges_format_curve(pc_text_buf *b, const pc_nurbs_curve *c, int planar_z)
{
    /* K, M, PROP1..4 (planar, closed, polynomial, periodic) */
    pc_iges_param_int(b, (long long)c->n_ctrl - 1);
    pc_iges_param_int(b, c->degree);
    pc_iges_param_int(b, planar_z ? 1 : 0);
    pc_iges_param_int(b, 0);
    pc_iges_param_int(b, c->rational ? 0 : 1);
    pc_iges_param_int(b, 0);
    reals(b, c->knots, c->n_ctrl + (size_t)c->degree + 1);
    weights_and_points(b, c->cw, c->n_ctrl);
    curve_tail(b, c->t0, c->t1, planar_z);
}

void pc_iges_format_polyline(pc_text_buf *b, const double *xyz, const double *t, size_t n,
                             int planar_z)
{
    pc_iges_param_int(b, (long long)n - 1);
    pc_iges_param_int(b, 1);
    pc_iges_param_int(b, planar_z ? 1 : 0);
    pc_iges_param_int(b, 0);
    pc_iges_param_int(b, 1);
    pc_iges_param_int(b, 0);
    pc_iges_param_real(b, t[0]);
    reals(b, t, n);
    pc_iges_param_real(b, t[n - 1]);
    for (size_t i = 0; i < n; ++i)
        pc_iges_param_real(b, 1.0);
    reals(b, xyz, 3 * n);
    curve_tail(b, t[0], t[n - 1], planar_z);
}

/* The curve run backwards, parametrised by s = a + b - t over the same
 * interval [a, b] (a, b the clamped knot vector's ends): knots mirrored and
 * taken in reverse, the points (and weights) in reverse order. */
void pc_iges_format_curve_reversed(pc_text_buf *b, const pc_nurbs_curve *c, int planar_z)
{
    const size_t n = c->n_ctrl, n_knots = n + (size_t)c->degree + 1;
    const double lo = c->knots[0], hi = c->knots[n_knots - 1];
    pc_iges_param_int(b, (long long)n - 1);
    pc_iges_param_int(b, c->degree);
    pc_iges_param_int(b, planar_z ? 1 : 0);
    pc_iges_param_int(b, 0);
    pc_iges_param_int(b, c->rational ? 0 : 1);
    pc_iges_param_int(b, 0);
    for (size_t i = n_knots; i-- > 0;)
        pc_iges_param_real(b, lo + hi - c->knots[i]);
    for (size_t i = n; i-- > 0;)
        pc_iges_param_real(b, c->cw[4 * i + 3]);
    for (size_t i = n; i-- > 0;)
        for (size_t k = 0; k < 3; ++k)
            pc_iges_param_real(b, c->cw[4 * i + k] / c->cw[4 * i + 3]);
    curve_tail(b, lo + hi - c->t1, lo + hi - c->t0, planar_z);
}

void pc_iges_format_composite(pc_text_buf *b, const size_t *members, size_t n)
{
    pc_iges_param_int(b, (long long)n);
    for (size_t i = 0; i < n; ++i)
        pc_iges_param_int(b, (long long)members[i]);
    pc_iges_param_end(b);
}
