/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Corners of the curve P (its C0 knots, trace/curve_breaks.h): the exact
 * projection is continuous there but turns, like at a crease of S. The
 * tracer puts a vertex exactly on each; the refinement keeps it (a fixed
 * vertex, so no piece straddles the corner) and takes the one-sided
 * tangents there, as at a knot line of S.
 */
#include "refine/refine_internal.h"
#include "trace/curve_breaks.h"

int pc_refine_at_crease(const pc_refiner *r, const pc_rvertex *v)
{
    return pc_refine_on_knot_line(r, v) ||
           pc_curve_break_at(r->proj->curve, v->t, PC_BREAK_ORDER_CORNER);
}

void pc_refine_fix_corners(const pc_refiner *r, pc_vertex_list *list)
{
    for (size_t k = 0; k < list->count; ++k)
        if (pc_curve_break_at(r->proj->curve, list->items[k].t, PC_BREAK_ORDER_CORNER))
            list->items[k].fixed = 1;
}

double pc_refine_corner_left(const pc_refiner *r, double t)
{
    return pc_curve_break_side(r->proj->curve, t, -1, PC_BREAK_ORDER_CORNER);
}
