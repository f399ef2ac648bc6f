/* SPDX-License-Identifier: BSD-3-Clause */
/* libFuzzer target: the projection pipeline. A surface, a curve, a
 * direction and options come from the bytes (fuzz_shapes.h); the curve is
 * projected directionally and orthogonally under the library's work limit
 * (FUZZ_MAX_WORK, FUZZ_TIME_LIMIT) and every part of each result is read
 * back. Each call must return a status (with a message when it fails),
 * never crash, leak, hang or run past the limits. */
#include <stdint.h>
#include <stdlib.h>

#include "fuzz_shapes.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

static void project(projcurve_context *ctx, const projcurve_surface *s, const projcurve_curve *c,
                    const double dir[3], const projcurve_options *o, int orthogonal)
{
    projcurve_result *r = NULL;
    projcurve_context_clear(ctx);
    const projcurve_status st = orthogonal ? projcurve_project_orthogonal(ctx, s, c, o, &r)
                                           : projcurve_project_directional(ctx, s, c, dir, o, &r);
    fuzz_require_message(ctx, st);
    /* only OK and the partial results of a limit or a cancel carry one */
    if (r != NULL && st != PROJCURVE_OK && st != PROJCURVE_ERR_LIMIT_REACHED &&
        st != PROJCURVE_ERR_CANCELLED)
        abort();
    fuzz_walk_result(ctx, r);
    projcurve_result_destroy(r);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_bytes b = {data, size, 0};
    projcurve_context *ctx = NULL;
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx) != PROJCURVE_OK)
        return 0;
    projcurve_surface *s = NULL;
    projcurve_curve *c = NULL;
    projcurve_options *o = NULL;
    double dir[3];
    projcurve_status st = fuzz_make_surface(ctx, &b, &s);
    fuzz_require_message(ctx, st);
    if (st == PROJCURVE_OK) {
        st = fuzz_make_curve(ctx, &b, &c);
        fuzz_require_message(ctx, st);
    }
    fuzz_make_direction(&b, dir);
    if (st == PROJCURVE_OK)
        st = fuzz_make_options(ctx, &b, &o);
    if (st == PROJCURVE_OK) {
        const uint8_t kinds = fuzz_byte(&b);
        if ((kinds & 3) != 2)
            project(ctx, s, c, dir, o, 0);
        if ((kinds & 3) != 1)
            project(ctx, s, c, dir, o, 1);
    }
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    projcurve_context_destroy(ctx);
    return 0;
}
