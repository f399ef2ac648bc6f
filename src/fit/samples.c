/* SPDX-License-Identifier: BSD-3-Clause */
#include "fit/samples.h"

#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"

projcurve_status pc_fit_samples_push(projcurve_context *ctx, pc_fit_samples *s,
                                     const pc_fit_sample *x)
{
    projcurve_status st;
    PC_ARRAY_RESERVE(st, ctx, s, s->count + 1, 64, "fit samples");
    if (st != PROJCURVE_OK)
        return st;
    if (s->count > 0 && x->t < s->items[s->count - 1].t)
        s->unsorted = 1;
    s->items[s->count++] = *x;
    return PROJCURVE_OK;
}

static int by_t(const void *a, const void *b)
{
    const double x = ((const pc_fit_sample *)a)->t, y = ((const pc_fit_sample *)b)->t;
    return (x > y) - (x < y);
}

/* Sorts the samples appended since the last sort and merges them into
 * the sorted ones (O(n) for a few appended, where a full sort of every
 * round's samples was a tenth of a fit). Without memory for the merge,
 * a full sort. */
void pc_fit_samples_sort(pc_fit_samples *s)
{
    if (s->unsorted) {
        const size_t head = s->sorted < s->count ? s->sorted : 0, tail = s->count - head;
        pc_fit_sample *merged = head > 0 ? malloc(s->count * sizeof *merged) : NULL;
        if (merged == NULL) {
            qsort(s->items, s->count, sizeof *s->items, by_t);
        } else {
            qsort(s->items + head, tail, sizeof *s->items, by_t);
            size_t i = 0, j = head, k = 0;
            while (i < head || j < s->count)
                merged[k++] = (j >= s->count || (i < head && s->items[i].t <= s->items[j].t))
                                  ? s->items[i++]
                                  : s->items[j++];
            memcpy(s->items, merged, s->count * sizeof *merged);
            free(merged);
        }
    }
    s->unsorted = 0;
    s->sorted = s->count;
}

void pc_fit_samples_free(pc_fit_samples *s)
{
    PC_ARRAY_FREE(s);
    s->unsorted = 0;
    s->sorted = 0;
}

projcurve_status pc_fit_samples_from_pieces(projcurve_context *ctx, pc_fit_branch *fb,
                                            int inner, pc_fit_samples *s, int *complete)
{
    *complete = 1;
    projcurve_status st = PROJCURVE_OK;
    const size_t n = fb->b->n_pieces;
    for (size_t k = 0; st == PROJCURVE_OK && k < n; ++k) {
        pc_fit_sample x;
        pc_fit_piece_end(fb, k, 0, &x);
        st = pc_fit_samples_push(ctx, s, &x);
        double lo, hi;
        pc_fit_piece_range(pc_fit_piece(fb, k), &lo, &hi);
        for (int i = 1; st == PROJCURVE_OK && i <= inner; ++i) {
            if (!pc_fit_exact(fb, lo + (hi - lo) * i / (inner + 1), &x)) {
                *complete = 0;
                return PROJCURVE_OK;
            }
            st = pc_fit_samples_push(ctx, s, &x);
        }
        if (st == PROJCURVE_OK && k + 1 == n) {
            pc_fit_piece_end(fb, k, 1, &x);
            st = pc_fit_samples_push(ctx, s, &x);
        }
    }
    return st;
}
