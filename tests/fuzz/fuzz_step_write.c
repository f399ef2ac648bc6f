/* SPDX-License-Identifier: BSD-3-Clause */
/* libFuzzer target: the STEP writer. A surface, a curve and (with a flag)
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
    projcurve_step_writer *w = NULL;
    if (fuzz_written_make(data, size, &in)) {
        projcurve_context *ctx = in.ctx;
        char path[64];
        snprintf(path, sizeof path, "/tmp/fuzz_step_write.%ld.stp", (long)getpid());
        if (projcurve_step_writer_create(ctx, &w) != PROJCURVE_OK ||
            projcurve_step_writer_add_surface(ctx, w, in.s) != PROJCURVE_OK ||
            projcurve_step_writer_add_curve(ctx, w, in.c) != PROJCURVE_OK)
            fuzz_finding("adding a valid surface and curve failed", ctx);
        /* a branch without compact forms (not composed, or the fit found
         * none) is refused by name: a defined answer, not a finding */
        if (in.r != NULL) {
            const projcurve_status st = projcurve_step_writer_add_result(ctx, w, in.s, in.r);
            if (st != PROJCURVE_OK &&
                (st != PROJCURVE_ERR_INVALID_ARGUMENT || !*projcurve_context_message(ctx)))
                fuzz_finding("adding a result failed", ctx);
        }
        if (projcurve_step_writer_write(ctx, w, path) != PROJCURVE_OK)
            fuzz_finding("writing failed", ctx);
        fuzz_read_back(&in, path);
    }
    projcurve_step_writer_destroy(w);
    fuzz_written_free(&in);
    return 0;
}
