/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The growable seed list of trace.h (a common/array.h array).
 */
#include "common/array.h"
#include "trace/trace.h"

#define PC_SEED_LIST_MIN_CAPACITY 8

projcurve_status pc_seed_list_push(projcurve_context *ctx, pc_seed_list *list, double t,
                                   double u, double v)
{
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, list, list->count + 1, PC_SEED_LIST_MIN_CAPACITY, "a seed list");
    if (st != PROJCURVE_OK)
        return st;
    list->items[list->count++] = (pc_seed){t, u, v};
    return PROJCURVE_OK;
}

void pc_seed_list_free(pc_seed_list *list) { PC_ARRAY_FREE(list); }
