/* SPDX-License-Identifier: BSD-3-Clause */
#include <stdlib.h>

#include "cli.h"

int cli_inputs_load(projcurve_context *ctx, const char *const *paths, size_t n, cli_inputs *in)
{
    in->models = calloc(n ? n : 1, sizeof *in->models);
    if (in->models == NULL)
        return cli_usage_error("out of memory");
    size_t n_surfaces = 0, n_curves = 0;
    for (size_t i = 0; i < n; ++i) {
        if (projcurve_model_read_file(ctx, paths[i], &in->models[i]) != PROJCURVE_OK)
            return cli_usage_error("%s", projcurve_context_message(ctx));
        in->n_models = i + 1;
        n_surfaces += projcurve_model_surface_count(in->models[i]);
        n_curves += projcurve_model_curve_count(in->models[i]);
    }
    in->surfaces = calloc(n_surfaces + 1, sizeof *in->surfaces);
    in->curves = calloc(n_curves + 1, sizeof *in->curves);
    if (in->surfaces == NULL || in->curves == NULL)
        return cli_usage_error("out of memory");
    for (size_t i = 0; i < in->n_models; ++i) {
        const projcurve_model *m = in->models[i];
        for (size_t k = 0; k < projcurve_model_surface_count(m); ++k)
            in->surfaces[in->n_surfaces++] = projcurve_model_surface(m, k);
        for (size_t k = 0; k < projcurve_model_curve_count(m); ++k)
            in->curves[in->n_curves++] = projcurve_model_curve(m, k);
    }
    return CLI_EXIT_OK;
}

void cli_inputs_free(cli_inputs *in)
{
    for (size_t i = 0; i < in->n_models; ++i)
        projcurve_model_destroy(in->models[i]);
    free(in->models);
    free((void *)in->surfaces);
    free((void *)in->curves);
    in->models = NULL;
    in->surfaces = NULL;
    in->curves = NULL;
    in->n_models = in->n_surfaces = in->n_curves = 0;
}
