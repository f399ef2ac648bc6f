/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Lists every projection option with its type, bounds and default, as read
 * from the library at run time (projcurve_option_info), and shows how a bad
 * value is reported.
 */
#include <projcurve.h>

#include <stdio.h>

static const struct {
    projcurve_option key;
    const char *name;
} options[] = {
    {PROJCURVE_OPT_TOL_DISTANCE, "TOL_DISTANCE"},
    {PROJCURVE_OPT_TOL_ANGLE_DEG, "TOL_ANGLE_DEG"},
    {PROJCURVE_OPT_NEWTON_TOL, "NEWTON_TOL"},
    {PROJCURVE_OPT_NEWTON_MAX_ITER, "NEWTON_MAX_ITER"},
    {PROJCURVE_OPT_METHOD, "METHOD"},
    {PROJCURVE_OPT_PARAM_STEP, "PARAM_STEP"},
    {PROJCURVE_OPT_ARC_STEP_FRACTION, "ARC_STEP_FRACTION"},
    {PROJCURVE_OPT_MAX_POINTS, "MAX_POINTS"},
    {PROJCURVE_OPT_MAX_PIECES, "MAX_PIECES"},
    {PROJCURVE_OPT_COMPOSE, "COMPOSE"},
    {PROJCURVE_OPT_JUMP_DETECTION, "JUMP_DETECTION"},
};

int main(void)
{
    projcurve_context *ctx = NULL;
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx) != PROJCURVE_OK) {
        fprintf(stderr, "libprojcurve %s is not ABI version %d\n", projcurve_version_string(),
                PROJCURVE_VERSION_MAJOR);
        return 1;
    }
    printf("libprojcurve %s: projection options\n\n", projcurve_version_string());
    printf("%-18s %-8s %12s %12s %12s\n", "option", "type", "min", "max", "default");
    for (size_t i = 0; i < sizeof options / sizeof options[0]; ++i) {
        projcurve_option_type type;
        double lo, hi, def;
        if (projcurve_option_info(ctx, options[i].key, &type, &lo, &hi, &def) != PROJCURVE_OK)
            return 1;
        printf("%-18s %-8s %12g %12g %12g\n", options[i].name,
               type == PROJCURVE_OPTION_DOUBLE ? "double" : "integer", lo, hi, def);
    }

    projcurve_options *opts = NULL;
    if (projcurve_options_create(ctx, &opts) != PROJCURVE_OK)
        return 1;
    const projcurve_status s =
        projcurve_options_set_double(ctx, opts, PROJCURVE_OPT_TOL_ANGLE_DEG, 180.0);
    printf("\nsetting TOL_ANGLE_DEG to 180 -> %s: %s\n", projcurve_status_string(s),
           projcurve_context_message(ctx));
    projcurve_options_destroy(opts);
    projcurve_context_destroy(ctx);
    return s == PROJCURVE_ERR_OUT_OF_RANGE ? 0 : 1;
}
