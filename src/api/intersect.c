/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * projcurve_surface_intersect_line: validation, then pc_intersect_line, then
 * the hits copied out in the public layout.
 */
#include "common/error.h"
#include "geom/surface.h"
#include "intersect/intersect.h"
#include "intersect/ray_patch.h"
#include "projcurve.h"

/* Stack storage of one call: hits, and clipping scratch in doubles (a
 * bicubic patch needs 16 * (4 + 2 * 57) = 1,888). */
#define PC_API_STACK_HITS 16
#define PC_API_STACK_WORK 2048

static projcurve_status check_point(projcurve_context *ctx, const double p[3], const char *what)
{
    for (int k = 0; k < 3; ++k) {
        if (!isfinite(p[k]))
            return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "%s[%d] = %g is not finite", what, k,
                           p[k]);
    }
    return PROJCURVE_OK;
}

PROJCURVE_API projcurve_status projcurve_surface_intersect_line(projcurve_context *ctx,
                                                                const projcurve_surface *surface,
                                                                const double origin[3],
                                                                const double dir[3],
                                                                int ray_only,
                                                                size_t capacity,
                                                                double *hits,
                                                                unsigned *flags,
                                                                size_t *count)
{
    PC_REQUIRE(ctx, surface, "surface");
    PC_REQUIRE(ctx, origin, "origin");
    PC_REQUIRE(ctx, dir, "dir");
    PC_REQUIRE(ctx, count, "count");
    if (capacity > 0 && hits == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NULL_ARGUMENT, "hits is NULL with capacity %zu",
                       capacity);
    projcurve_status st = check_point(ctx, origin, "origin");
    if (st != PROJCURVE_OK)
        return st;
    st = check_point(ctx, dir, "dir");
    if (st != PROJCURVE_OK)
        return st;
    const pc_vec3 d = vec3_load(dir);
    if (!(pc_vec3_length_robust(d) > 0.0))
        return pc_fail(ctx, PROJCURVE_ERR_ZERO_DIRECTION, "dir = (%g, %g, %g) has length 0",
                       dir[0], dir[1], dir[2]);
    /* A call stands alone: stack buffers for the usual hit count and the
     * clipping scratch of bicubic patches, the heap beyond. */
    pc_hit items[PC_API_STACK_HITS];
    double work[PC_API_STACK_WORK];
    pc_hit_list list;
    pc_hit_list_borrow(&list, items, PC_API_STACK_HITS, work, PC_API_STACK_WORK);
    st = pc_intersect_line(ctx, surface, vec3_load(origin), d, ray_only != 0, &list);
    if (st == PROJCURVE_OK) {
        for (size_t k = 0; k < list.count && k < capacity; ++k) {
            hits[3 * k] = list.items[k].u;
            hits[3 * k + 1] = list.items[k].v;
            hits[3 * k + 2] = list.items[k].lambda;
            if (flags != NULL)
                flags[k] = list.items[k].flags & (PROJCURVE_HIT_TANGENT | PROJCURVE_HIT_BOUNDARY);
        }
        *count = list.count;
    }
    pc_hit_list_free(&list);
    return st;
}
