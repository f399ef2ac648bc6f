/* SPDX-License-Identifier: BSD-3-Clause */
#include "brep/loop_overlap.h"

#include <stdlib.h>

#include "common/error.h"

/* Twice the signed area of (a, b, c): > 0 when c is left of a -> b. */
static double orient(const double *a, const double *b, const double *c)
{
    return (b[0] - a[0]) * (c[1] - a[1]) - (b[1] - a[1]) * (c[0] - a[0]);
}

/* Segments s = (ax, ay, bx, by) and t crossing properly. */
static int cross(const double *s, const double *t)
{
    const double o1 = orient(s, s + 2, t), o2 = orient(s, s + 2, t + 2);
    const double o3 = orient(t, t + 2, s), o4 = orient(t, t + 2, s + 2);
    return ((o1 > 0.0 && o2 < 0.0) || (o1 < 0.0 && o2 > 0.0)) &&
           ((o3 > 0.0 && o4 < 0.0) || (o3 < 0.0 && o4 > 0.0));
}

/* The loop of segment i: the classifier's segments are the loops' in order,
 * n_poly each; first[l] is loop l's first segment (first[n_loops] = all). */
static size_t loop_of(const size_t *first, size_t n_loops, size_t i)
{
    size_t lo = 0, hi = n_loops; /* first[lo] <= i < first[hi] */
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (first[mid] <= i)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* A crossing of two loops, or of a loop with itself, within one grid cell: any two crossing segments
 * share a cell (each is listed in every cell its box meets, and they meet
 * at a point of both). The work is the cells' pairs: a few segments a cell
 * by the grid's sizing (classify.h). */
static projcurve_status check_crossings(projcurve_context *ctx, const projcurve_face *f,
                                        const size_t *first, const char *what)
{
    const pc_classifier *c = &f->cls;
    const size_t n_cells = c->nx * c->ny;
    for (size_t cell = 0; cell < n_cells; ++cell)
        for (size_t p = c->cell_start[cell]; p < c->cell_start[cell + 1]; ++p)
            for (size_t q = p + 1; q < c->cell_start[cell + 1]; ++q) {
                const size_t i = c->cell_seg[p], j = c->cell_seg[q];
                /* consecutive segments share an end, where orient is 0:
                 * never a proper crossing */
                if (!cross(c->seg + 4 * i, c->seg + 4 * j))
                    continue;
                const size_t li = loop_of(first, f->n_loops, i), lj = loop_of(first, f->n_loops, j);
                const double *s = c->seg + 4 * i;
                if (li == lj)
                    return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                                   "%s: loop %zu crosses itself (near (%.9g, %.9g))", what, li,
                                   s[0], s[1]);
                return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                               "%s: loops %zu and %zu cross (near (%.9g, %.9g))", what,
                               li < lj ? li : lj, li < lj ? lj : li, s[0], s[1]);
            }
    return PROJCURVE_OK;
}

/* Each hole inside the outer loop and no other hole: with no crossings,
 * its first point tells for all of it. */
static projcurve_status check_nesting(projcurve_context *ctx, const projcurve_face *f,
                                      const size_t *first, const char *what)
{
    const pc_classifier *c = &f->cls;
    for (size_t l = 1; l < f->n_loops; ++l) {
        const double *p = f->loops[l].poly;
        const int w = pc_winding_brute(c->seg, first[l], p[0], p[1]) +
                      pc_winding_brute(c->seg + 4 * first[l + 1], c->n_seg - first[l + 1], p[0],
                                       p[1]);
        if (w == 0)
            return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                           "%s: loop %zu (a hole) is not inside the outer loop alone: its point "
                           "(%.9g, %.9g) is outside the outer loop or inside another hole",
                           what, l, p[0], p[1]);
    }
    return PROJCURVE_OK;
}

projcurve_status pc_face_check_loops_apart(projcurve_context *ctx, const projcurve_face *f,
                                           const char *what)
{
    size_t *first = malloc((f->n_loops + 1) * sizeof *first);
    if (first == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory checking a face's loops");
    first[0] = 0;
    for (size_t l = 0; l < f->n_loops; ++l)
        first[l + 1] = first[l] + f->loops[l].n_poly;
    projcurve_status st = first[f->n_loops] == f->cls.n_seg
                              ? check_crossings(ctx, f, first, what)
                              : pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                                        "%s: the classifier does not hold the loops", what);
    if (st == PROJCURVE_OK)
        st = check_nesting(ctx, f, first, what);
    free(first);
    return st;
}
