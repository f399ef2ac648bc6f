/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Example 1 loader (see example1.h).
 */
#include "example1.h"

#include <stdio.h>
#include <string.h>

#include "bench.h"
#include "shapes.h"

int pcb_example1_load(const char *data_dir, pcb_example1 *ex)
{
    memset(ex, 0, sizeof *ex);
    memcpy(ex->dir, pcb_example1_dir, sizeof ex->dir);
    char path[1024];
    snprintf(path, sizeof path, "%s/cases/song_yong_example1.igs", data_dir);
    projcurve_context *ctx = NULL;
    projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx);
    const projcurve_status st = projcurve_model_read_file(ctx, path, &ex->model);
    if (st == PROJCURVE_OK && projcurve_model_surface_count(ex->model) >= 1 &&
        projcurve_model_curve_count(ex->model) >= 1) {
        ex->surface = projcurve_model_surface(ex->model, 0);
        ex->curve = projcurve_model_curve(ex->model, 0);
        ex->source = "IGES";
        projcurve_context_destroy(ctx);
        return 1;
    }
    fprintf(stderr, "example 1: %s: %s %s; using the numbers of [SY13] s5\n", path,
            projcurve_status_string(st), projcurve_context_message(ctx));
    projcurve_context_destroy(ctx);
    projcurve_model_destroy(ex->model);
    ex->model = NULL;
    if (!pcb_ok(NULL, pcb_make_example1(NULL, &ex->own_surface, &ex->own_curve),
                "example 1"))
        return 0;
    ex->surface = ex->own_surface;
    ex->curve = ex->own_curve;
    ex->source = "built-in";
    return 1;
}

void pcb_example1_free(pcb_example1 *ex)
{
    projcurve_model_destroy(ex->model);
    projcurve_surface_destroy(ex->own_surface);
    projcurve_curve_destroy(ex->own_curve);
    memset(ex, 0, sizeof *ex);
}
