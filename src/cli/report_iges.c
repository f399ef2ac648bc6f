/* SPDX-License-Identifier: BSD-3-Clause */
#include "cli.h"

/* Every surface that has a result, then each pair's branches (3D curve,
 * pcurve and curve on surface); surfaces without branches are written too
 * so the file shows the whole input. */
int cli_write_iges(projcurve_context *ctx, const cli_job *job, const char *path)
{
    projcurve_iges_writer *w = NULL;
    if (projcurve_iges_writer_create(ctx, &w) != PROJCURVE_OK)
        return 0;
    int ok = 1;
    /* a unit IGES has no flag for (a STEP file's own conversion) stays
     * millimetres: the coordinates are written as read either way */
    if (job->metres_per_unit > 0.0 &&
        projcurve_iges_writer_set_length_unit(NULL, w, job->metres_per_unit) != PROJCURVE_OK)
        fprintf(stderr, "projcurve: the input's length unit (%g m) has no IGES units flag; "
                        "the output says millimetres\n",
                job->metres_per_unit);
    for (size_t s = 0; ok && s < job->n_surfaces; ++s)
        ok = projcurve_iges_writer_add_surface(ctx, w, job->surfaces[s]) == PROJCURVE_OK;
    for (size_t c = 0; ok && c < job->n_curves; ++c) {
        const projcurve_status st = projcurve_iges_writer_add_curve(ctx, w, job->curves[c]);
        ok = st == PROJCURVE_OK || st == PROJCURVE_ERR_WRONG_KIND;
    }
    for (size_t i = 0; ok && i < job->n_pairs; ++i) {
        const cli_pair *p = &job->pairs[i];
        if (p->result != NULL && projcurve_result_branch_count(p->result) > 0)
            ok = projcurve_iges_writer_add_result(ctx, w, job->surfaces[p->surface], p->result) ==
                 PROJCURVE_OK;
    }
    if (ok)
        ok = projcurve_iges_writer_write(ctx, w, path) == PROJCURVE_OK;
    if (!ok)
        fprintf(stderr, "projcurve: writing %s: %s\n", path, projcurve_context_message(ctx));
    projcurve_iges_writer_destroy(w);
    return ok;
}
