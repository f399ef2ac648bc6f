/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Corners of the curve P (its C0 knots, trace/curve_breaks.h): the exact
 * projection is continuous there but turns, like at a crease of S. The
 * tracer puts a vertex exactly on each; the refinement keeps it (a fixed
 * vertex, so no piece straddles the corner) and takes the one-sided
 * tangents there, as at a knot line of S.
 *
 * A knot of multiplicity = degree is only C0 by its multiplicity: the
 * rational quadratic circle of a CAD edge has such a knot at every
 * quarter, where P' keeps its direction (G1). There the projection does
 * not turn, and a fixed vertex or one-sided tangents would only change
 * the refinement's runs; such a knot is no corner.
 */
#include <math.h>

#include "refine/refine_internal.h"
#include "trace/curve_breaks.h"

/* One-sided directions of P' closer than this (rad) are one direction:
 * far below any eps_T, far above the rounding of the evaluation. */
#define PC_CORNER_MIN_TURN 1e-9

/* 1 when t is a C0 knot of P at which P' turns. */
static int is_corner(const pc_refiner *r, double t)
{
    const projcurve_curve *c = r->proj->curve;
    if (!pc_curve_break_at(c, t, PC_BREAK_ORDER_CORNER))
        return 0;
    pc_vec3 left[2], right[2];
    if (pc_curve_eval(c, nextafter(t, -INFINITY), 1, NULL, left) != PROJCURVE_OK ||
        pc_curve_eval(c, nextafter(t, INFINITY), 1, NULL, right) != PROJCURVE_OK)
        return 1;
    const double turn = atan2(vec3_norm(vec3_cross(left[1], right[1])),
                              vec3_dot(left[1], right[1]));
    return !(turn <= PC_CORNER_MIN_TURN); /* NaN (a zero P') counts as a corner */
}

int pc_refine_at_crease(const pc_refiner *r, const pc_rvertex *v)
{
    return pc_refine_on_knot_line(r, v) || is_corner(r, v->t);
}

void pc_refine_fix_corners(const pc_refiner *r, pc_vertex_list *list)
{
    for (size_t k = 0; k < list->count; ++k)
        if (is_corner(r, list->items[k].t))
            list->items[k].fixed = 1;
}

double pc_refine_corner_left(const pc_refiner *r, double t)
{
    return is_corner(r, t) ? nextafter(t, -INFINITY) : t;
}
