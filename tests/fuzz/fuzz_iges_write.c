/* SPDX-License-Identifier: BSD-3-Clause */
/* libFuzzer target: the IGES writer. A surface, a curve and (with a flag)
 * the result of projecting it, from the bytes (fuzz_shapes.h), are written
 * to a file and read back: the file must read, and its first surface and
 * first curve must be the ones written (fuzz_readback.h). */
#include <stdint.h>
#include <stdio.h>
#include <unistd.h>

#include "fuzz_readback.h"
#include "fuzz_shapes.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_bytes b = {data, size, 0};
    projcurve_context *ctx = NULL;
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx) != PROJCURVE_OK)
        return 0;
    projcurve_surface *s = NULL;
    projcurve_curve *c = NULL;
    projcurve_options *o = NULL;
    projcurve_result *r = NULL;
    projcurve_iges_writer *w = NULL;
    projcurve_model *m = NULL;
    double dir[3];
    char path[64];
    snprintf(path, sizeof path, "/tmp/fuzz_iges_write.%ld.igs", (long)getpid());
    if (fuzz_make_surface(ctx, &b, &s) != PROJCURVE_OK || fuzz_make_curve(ctx, &b, &c) != PROJCURVE_OK)
        goto done;
    fuzz_make_direction(&b, dir);
    if (fuzz_make_options(ctx, &b, &o) != PROJCURVE_OK)
        goto done;
    if (fuzz_byte(&b) & 1)
        (void)projcurve_project_directional(ctx, s, c, dir, o, &r);
    if (projcurve_iges_writer_create(ctx, &w) != PROJCURVE_OK ||
        projcurve_iges_writer_add_surface(ctx, w, s) != PROJCURVE_OK ||
        projcurve_iges_writer_add_curve(ctx, w, c) != PROJCURVE_OK)
        fuzz_finding("adding a valid surface and curve failed", ctx);
    if (r != NULL && projcurve_iges_writer_add_result(ctx, w, s, r) != PROJCURVE_OK)
        fuzz_finding("adding a result failed", ctx);
    if (projcurve_iges_writer_write(ctx, w, path) != PROJCURVE_OK)
        fuzz_finding("writing failed", ctx);
    if (projcurve_model_read_file(ctx, path, &m) != PROJCURVE_OK)
        fuzz_finding("the written file does not read", ctx);
    if (projcurve_model_surface_count(m) < 1 || projcurve_model_curve_count(m) < 1)
        fuzz_finding("the file read back lacks the surface or the curve", ctx);
    fuzz_compare_surfaces(ctx, s, projcurve_model_surface(m, 0));
    fuzz_compare_curves(ctx, c, projcurve_model_curve(m, 0));
done:
    remove(path);
    projcurve_model_destroy(m);
    projcurve_iges_writer_destroy(w);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    projcurve_context_destroy(ctx);
    return 0;
}
