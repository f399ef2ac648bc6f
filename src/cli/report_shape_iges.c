/* SPDX-License-Identifier: BSD-3-Clause */
#include "shape_job.h"

/* The surfaces and input curves, as cli_write_iges writes them. */
static int add_inputs(projcurve_context *ctx, projcurve_iges_writer *w, const cli_job *view)
{
    int ok = 1;
    for (size_t s = 0; ok && s < view->n_surfaces; ++s)
        ok = projcurve_iges_writer_add_surface(ctx, w, view->surfaces[s]) == PROJCURVE_OK;
    for (size_t c = 0; ok && c < view->n_curves; ++c) {
        const projcurve_status st = projcurve_iges_writer_add_curve(ctx, w, view->curves[c]);
        ok = st == PROJCURVE_OK || st == PROJCURVE_ERR_WRONG_KIND;
    }
    return ok;
}

static projcurve_status add_shape(projcurve_context *ctx, void *writer,
                                  const projcurve_shape_result *result)
{
    return projcurve_iges_writer_add_shape_result(ctx, writer, result);
}

int cli_write_shape_iges(projcurve_context *ctx, const cli_shape_job *job, const char *path)
{
    projcurve_iges_writer *w = NULL;
    if (projcurve_iges_writer_create(ctx, &w) != PROJCURVE_OK)
        return 0;
    if (job->view.metres_per_unit > 0.0 &&
        projcurve_iges_writer_set_length_unit(NULL, w, job->view.metres_per_unit) != PROJCURVE_OK)
        fprintf(stderr, "projcurve: the input's length unit (%g m) has no IGES units flag; "
                        "the output says millimetres\n",
                job->view.metres_per_unit);
    int ok = add_inputs(ctx, w, &job->view);
    if (ok)
        ok = cli_add_shape_results(ctx, job, path, add_shape, w);
    if (ok)
        ok = projcurve_iges_writer_write(ctx, w, path) == PROJCURVE_OK;
    if (!ok)
        fprintf(stderr, "projcurve: writing %s: %s\n", path, projcurve_context_message(ctx));
    projcurve_iges_writer_destroy(w);
    return ok;
}
