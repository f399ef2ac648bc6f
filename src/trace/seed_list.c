/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The growable seed list of trace.h.
 */
#include <stdint.h>
#include <stdlib.h>

#include "common/error.h"
#include "trace/trace.h"

projcurve_status pc_seed_list_push(projcurve_context *ctx, pc_seed_list *list, double t,
                                   double u, double v)
{
    if (list->count == list->capacity) {
        const size_t cap = list->capacity ? 2 * list->capacity : 8;
        if (cap > SIZE_MAX / sizeof *list->items)
            return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "seed list size overflows");
        pc_seed *p = realloc(list->items, cap * sizeof *p);
        if (p == NULL)
            return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory growing a seed list");
        list->items = p;
        list->capacity = cap;
    }
    list->items[list->count++] = (pc_seed){t, u, v};
    return PROJCURVE_OK;
}

void pc_seed_list_free(pc_seed_list *list)
{
    free(list->items);
    list->items = NULL;
    list->count = list->capacity = 0;
}
