/* SPDX-License-Identifier: BSD-3-Clause */
#include <string.h>
#include <strings.h>

#include "cli.h"

int cli_is_step_path(const char *path)
{
    const char *dot = strrchr(path, '.');
    return dot != NULL && (strcasecmp(dot, ".step") == 0 || strcasecmp(dot, ".stp") == 0);
}

/* As cli_write_iges: every surface, every NURBS curve, then each pair's
 * branches as SURFACE_CURVEs of their compact forms, in the input's unit.
 * A result with a branch that has no compact forms (not composed) is left
 * out with a message. */
int cli_write_step(projcurve_context *ctx, const cli_job *job, const char *path)
{
    projcurve_step_writer *w = NULL;
    if (projcurve_step_writer_create(ctx, &w) != PROJCURVE_OK)
        return 0;
    int ok = 1;
    if (job->metres_per_unit > 0.0)
        ok = projcurve_step_writer_set_length_unit(ctx, w, job->metres_per_unit) == PROJCURVE_OK;
    for (size_t s = 0; ok && s < job->n_surfaces; ++s)
        ok = projcurve_step_writer_add_surface(ctx, w, job->surfaces[s]) == PROJCURVE_OK;
    for (size_t c = 0; ok && c < job->n_curves; ++c) {
        const projcurve_status st = projcurve_step_writer_add_curve(ctx, w, job->curves[c]);
        ok = st == PROJCURVE_OK || st == PROJCURVE_ERR_WRONG_KIND;
    }
    for (size_t i = 0; ok && i < job->n_pairs; ++i) {
        const cli_pair *p = &job->pairs[i];
        if (p->result == NULL || projcurve_result_branch_count(p->result) == 0)
            continue;
        const projcurve_status st =
            projcurve_step_writer_add_result(ctx, w, job->surfaces[p->surface], p->result);
        if (st == PROJCURVE_ERR_INVALID_ARGUMENT)
            fprintf(stderr, "projcurve: %s: the branches of pair %zu are not written: %s\n",
                    path, i, projcurve_context_message(ctx));
        else
            ok = st == PROJCURVE_OK;
    }
    if (ok)
        ok = projcurve_step_writer_write(ctx, w, path) == PROJCURVE_OK;
    if (!ok)
        fprintf(stderr, "projcurve: writing %s: %s\n", path, projcurve_context_message(ctx));
    projcurve_step_writer_destroy(w);
    return ok;
}
