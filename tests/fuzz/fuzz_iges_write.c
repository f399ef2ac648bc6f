/* SPDX-License-Identifier: BSD-3-Clause */
/* libFuzzer target: the IGES writer. A surface, a curve and (with a flag)
 * the result of projecting it, from the bytes, are written to a file and
 * read back: the file must read, and its first surface and first curve
 * must be the ones written (fuzz_readback.h). */
#include <stdint.h>
#include <stdio.h>
#include <unistd.h>

#include "fuzz_readback.h"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
    fuzz_written in;
    projcurve_iges_writer *w = NULL;
    if (fuzz_written_make(data, size, &in)) {
        projcurve_context *ctx = in.ctx;
        char path[64];
        snprintf(path, sizeof path, "/tmp/fuzz_iges_write.%ld.igs", (long)getpid());
        if (projcurve_iges_writer_create(ctx, &w) != PROJCURVE_OK ||
            projcurve_iges_writer_add_surface(ctx, w, in.s) != PROJCURVE_OK ||
            projcurve_iges_writer_add_curve(ctx, w, in.c) != PROJCURVE_OK)
            fuzz_finding("adding a valid surface and curve failed", ctx);
        if (in.r != NULL && projcurve_iges_writer_add_result(ctx, w, in.s, in.r) != PROJCURVE_OK)
            fuzz_finding("adding a result failed", ctx);
        if (projcurve_iges_writer_write(ctx, w, path) != PROJCURVE_OK)
            fuzz_finding("writing failed", ctx);
        fuzz_read_back(&in, path);
    }
    projcurve_iges_writer_destroy(w);
    fuzz_written_free(&in);
    return 0;
}
