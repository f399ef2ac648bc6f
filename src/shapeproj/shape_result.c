/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Creation and release of shape results (shapeproj/shape_result.h).
 */
#include "shapeproj/shape_result.h"

#include <stdlib.h>
#include <string.h>

#include "common/error.h"

projcurve_status pc_shape_result_create(projcurve_context *ctx, size_t n_parts,
                                        projcurve_shape_result **out)
{
    projcurve_shape_result *r = calloc(1, sizeof *r);
    if (r != NULL)
        r->parts = calloc(n_parts + 1, sizeof *r->parts);
    if (r == NULL || r->parts == NULL) {
        free(r);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a shape result");
    }
    r->n_parts = n_parts;
    *out = r;
    return PROJCURVE_OK;
}

projcurve_status pc_face_part_set_message(projcurve_context *ctx, pc_face_part *part,
                                          const char *message)
{
    const char *m = message ? message : "";
    char *copy = malloc(strlen(m) + 1);
    if (copy == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory for a face message");
    memcpy(copy, m, strlen(m) + 1);
    free(part->message);
    part->message = copy;
    return PROJCURVE_OK;
}

void projcurve_shape_result_destroy(projcurve_shape_result *r)
{
    if (r == NULL)
        return;
    for (size_t i = 0; i < r->n_parts; ++i) {
        projcurve_result_destroy(r->parts[i].result);
        free(r->parts[i].trims);
        free(r->parts[i].message);
    }
    free(r->parts);
    free(r->refs);
    free(r->curves);
    free(r);
}
