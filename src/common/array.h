/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The growable array of the library, as libgit2's git_array_t: any struct
 * with fields `items` (a typed pointer), `count` and `capacity` (size_t) is
 * one, grown by PC_ARRAY_RESERVE and released by PC_ARRAY_FREE; arrays
 * whose fields are named otherwise call pc_array_reserve themselves.
 *
 * One policy for every array: the capacity grows geometrically (doubling
 * from the array's minimum), elem_size * capacity is checked against
 * SIZE_MAX before any allocation, and running out of memory, or of
 * size_t, is PROJCURVE_ERR_NO_MEMORY with a message naming the array; the
 * array is then unchanged. Growth costs O(log n) allocations for n
 * elements, none per element.
 */
#ifndef PC_COMMON_ARRAY_H
#define PC_COMMON_ARRAY_H

#include <stddef.h>
#include <stdlib.h>

#include "projcurve.h"

/* Room for at least `need` elements of elem_size bytes in the storage
 * *items of *capacity elements, count of them in use: the capacity doubles
 * from max(*capacity, min_capacity) until it holds need. When *borrowed
 * (borrowed may be NULL: owned) the storage is the caller's, never
 * reallocated nor freed: the count elements are copied to new storage and
 * *borrowed is cleared. Statuses: OK; NO_MEMORY (recorded in ctx, naming
 * `what`) with *items, *capacity and *borrowed unchanged. */
projcurve_status pc_array_reserve(projcurve_context *ctx, void **items, size_t *capacity,
                                  size_t count, size_t need, size_t elem_size,
                                  size_t min_capacity, int *borrowed, const char *what);

/* Room for `need` elements in the array *(a) (a struct with items, count,
 * capacity; a is evaluated more than once); st (a projcurve_status
 * lvalue) gets the status of pc_array_reserve. */
#define PC_ARRAY_RESERVE(st, ctx, a, need, min_capacity, what)                              \
    do {                                                                                    \
        void *pc_array_items_ = (a)->items;                                                 \
        (st) = pc_array_reserve((ctx), &pc_array_items_, &(a)->capacity, (a)->count, (need), \
                                sizeof *(a)->items, (min_capacity), NULL, (what));          \
        (a)->items = pc_array_items_;                                                       \
    } while (0)

/* Releases the storage of the array *(a) and empties it. */
#define PC_ARRAY_FREE(a)                                                                    \
    do {                                                                                    \
        free((a)->items);                                                                   \
        (a)->items = NULL;                                                                  \
        (a)->count = (a)->capacity = 0;                                                     \
    } while (0)

#endif /* PC_COMMON_ARRAY_H */
