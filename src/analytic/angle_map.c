/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The map between an angle and the parameter of its rational quadratic
 * arcs. A segment of half width h around the middle angle m, with weights
 * 1, cos h, 1, passes through angle m + theta at
 *   tau = (1 + tan(theta / 2) / tan(h / 2)) / 2
 * (the rational quadratic circle is the stereographic parametrisation of
 * the arc, so the half-angle tangent is affine in tau), and back
 *   theta = 2 atan((2 tau - 1) tan(h / 2)).
 * With h <= pi / 4 both are smooth and well conditioned.
 */
#include <math.h>

#include "analytic/analytic.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

/* A quarter turn, so that every middle weight cos(h) >= cos(pi / 4). */
#define PC_ARC_MAX_SEGMENT (M_PI / 2.0)
/* Sweeps this close (relative) to a whole number of quarter turns do not
 * get an extra sliver segment. */
#define PC_ARC_SEGMENT_SLACK 1e-12

pc_angle_map pc_angle_map_make(double a0, double a1)
{
    pc_angle_map m = {.is_angle = 1, .a0 = a0, .a1 = a1, .n_seg = 1};
    const double n = ceil((a1 - a0) / PC_ARC_MAX_SEGMENT - PC_ARC_SEGMENT_SLACK);
    if (n > 1.0 && n < 8.0)
        m.n_seg = (size_t)n;
    else if (n >= 8.0)
        m.n_seg = 4; /* more than one turn: refused by the builders */
    return m;
}

static double segment_start(const pc_angle_map *m, size_t i)
{
    const double step = (m->a1 - m->a0) / (double)m->n_seg;
    return i == m->n_seg ? m->a1 : m->a0 + step * (double)i;
}

static size_t segment_of(const pc_angle_map *m, double a)
{
    const double step = (m->a1 - m->a0) / (double)m->n_seg;
    const double k = floor((a - m->a0) / step);
    if (!(k > 0.0))
        return 0;
    return k >= (double)m->n_seg ? m->n_seg - 1 : (size_t)k;
}

/* a moved by whole turns into [a0, a1], or the nearer end. */
static double into_range(const pc_angle_map *m, double a)
{
    if (a >= m->a0 && a <= m->a1)
        return a;
    double r = fmod(a - m->a0, 2.0 * M_PI);
    if (r < 0.0)
        r += 2.0 * M_PI;
    const double b = m->a0 + r;
    if (b <= m->a1)
        return b;
    return (b - m->a1 <= m->a0 + 2.0 * M_PI - b) ? m->a1 : m->a0;
}

double pc_angle_to_nurbs(const pc_angle_map *m, double a)
{
    if (!m->is_angle)
        return a;
    a = into_range(m, a);
    const size_t i = segment_of(m, a);
    const double s0 = segment_start(m, i), s1 = segment_start(m, i + 1);
    const double h = (s1 - s0) / 2.0, mid = s0 + h;
    const double tau = 0.5 * (1.0 + tan((a - mid) / 2.0) / tan(h / 2.0));
    if (tau <= 0.0)
        return s0;
    if (tau >= 1.0)
        return s1;
    return s0 + tau * (s1 - s0);
}

double pc_nurbs_to_angle(const pc_angle_map *m, double s)
{
    if (!m->is_angle)
        return s;
    if (!(s >= m->a0))
        s = m->a0;
    if (!(s <= m->a1))
        s = m->a1;
    const size_t i = segment_of(m, s);
    const double s0 = segment_start(m, i), s1 = segment_start(m, i + 1);
    const double h = (s1 - s0) / 2.0, mid = s0 + h;
    const double tau = (s - s0) / (s1 - s0);
    return mid + 2.0 * atan((2.0 * tau - 1.0) * tan(h / 2.0));
}
