/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A program that uses the installed libprojcurve the way an application
 * would: only <projcurve.h>, linked against the installed library. It checks
 * that header and library agree and that an error comes back with a message.
 */
#include <projcurve.h>

#include <stdio.h>
#include <string.h>

int main(void)
{
    if (projcurve_version_number() != PROJCURVE_VERSION_NUMBER) {
        fprintf(stderr, "header %s but library %s\n", PROJCURVE_VERSION_STRING,
                projcurve_version_string());
        return 1;
    }
    projcurve_context *ctx = NULL;
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx) != PROJCURVE_OK)
        return 1;
    projcurve_options *opts = NULL;
    int ok = projcurve_options_create(ctx, &opts) == PROJCURVE_OK;
    const projcurve_status s =
        projcurve_options_set_double(ctx, opts, PROJCURVE_OPT_TOL_ANGLE_DEG, 120.0);
    ok = ok && s == PROJCURVE_ERR_OUT_OF_RANGE &&
         strstr(projcurve_context_message(ctx), "TOL_ANGLE_DEG") != NULL;
    printf("C consumer: libprojcurve %s, bad option -> %s: %s\n", projcurve_version_string(),
           projcurve_status_string(s), projcurve_context_message(ctx));
    projcurve_options_destroy(opts);
    projcurve_context_destroy(ctx);
    return ok ? 0 : 1;
}
