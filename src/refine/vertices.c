/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Growable vertex lists of the refinement (common/array.h arrays: a branch
 * of n vertices costs O(log n) allocations, none per vertex), and the
 * output of a vertex under the refinement's limits.
 */
#include "common/array.h"
#include "refine/refine_internal.h"

#define PC_VERTEX_LIST_MIN_CAPACITY 64

projcurve_status pc_vertex_list_push(projcurve_context *ctx, pc_vertex_list *list,
                                     const pc_rvertex *v)
{
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, list, list->count + 1, PC_VERTEX_LIST_MIN_CAPACITY,
                     "a refined polyline");
    if (st != PROJCURVE_OK)
        return st;
    list->items[list->count++] = *v;
    return PROJCURVE_OK;
}

void pc_vertex_list_free(pc_vertex_list *list) { PC_ARRAY_FREE(list); }

projcurve_status pc_refine_output(pc_refiner *r, pc_vertex_list *out, const pc_rvertex *v)
{
    const double at = r->t_range > 0.0 ? (v->t - r->t_lo) / r->t_range : 0.0;
    if (out->count >= r->max_vertices ||
        pc_budget_check(r->budget, r->progress_lo + r->progress_width * at) != PROJCURVE_OK) {
        r->limit_hit = 1;
        return PROJCURVE_ERR_LIMIT_REACHED;
    }
    return pc_vertex_list_push(r->ctx, out, v);
}

projcurve_status pc_refine_output_gap(pc_refiner *r, pc_vertex_list *out, const pc_rvertex *v,
                                      pc_gap_kind kind)
{
    if (out->count > 0)
        out->items[out->count - 1].gap = (int)kind;
    ++r->gaps;
    return pc_refine_output(r, out, v);
}
