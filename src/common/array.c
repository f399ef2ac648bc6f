/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The growth of every growable array (array.h).
 */
#include "common/array.h"

#include <stdint.h>
#include <string.h>

#include "common/error.h"

projcurve_status pc_array_reserve(projcurve_context *ctx, void **items, size_t *capacity,
                                  size_t count, size_t need, size_t elem_size,
                                  size_t min_capacity, int *borrowed, const char *what)
{
    if (need <= *capacity)
        return PROJCURVE_OK;
    size_t cap = *capacity > min_capacity ? *capacity : min_capacity;
    if (cap == 0)
        cap = 1;
    /* doubling is bounded by the bits of size_t: cap only grows, and stops
     * at the first value that holds need or overflows elem_size * cap */
    const size_t max_cap = SIZE_MAX / (elem_size > 0 ? elem_size : 1);
    while (cap < need && cap <= max_cap / 2)
        cap *= 2;
    if (cap < need || cap > max_cap)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "%s of %zu elements of %zu bytes is too large",
                       what, need, elem_size);
    const int is_borrowed = borrowed != NULL && *borrowed;
    void *p = is_borrowed ? malloc(cap * elem_size) : realloc(*items, cap * elem_size);
    if (p == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory growing %s to %zu elements",
                       what, cap);
    if (is_borrowed) {
        if (count > 0)
            memcpy(p, *items, count * elem_size);
        *borrowed = 0;
    }
    *items = p;
    *capacity = cap;
    return PROJCURVE_OK;
}
