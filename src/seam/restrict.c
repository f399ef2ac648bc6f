/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The seam records of a part of a branch (seam/seam.h,
 * pc_seam_restrict_records).
 */
#include <stdlib.h>

#include "common/error.h"
#include "seam/seam.h"

projcurve_status pc_seam_restrict_records(projcurve_context *ctx, const pc_branch *src,
                                          double a, double b, pc_branch *dst)
{
    size_t n = 0;
    for (size_t k = 0; k < src->n_seams; ++k)
        n += src->seams[k].t > a && src->seams[k].t < b;
    pc_seam_record *seams = NULL;
    if (n > 0) {
        seams = malloc(n * sizeof *seams);
        if (seams == NULL)
            return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY,
                           "out of memory for the seams of a face piece");
        size_t m = 0;
        for (size_t k = 0; k < src->n_seams; ++k)
            if (src->seams[k].t > a && src->seams[k].t < b)
                seams[m++] = src->seams[k];
    }
    free(dst->seams);
    dst->seams = seams;
    dst->n_seams = n;
    /* the jumps before the part: its unwrapped pcurve starts in the domain */
    double shift[2];
    pc_seam_unwrap_shift(src, a, shift);
    pc_bspline *q = &dst->compact_pcurve;
    if (q->dim >= 2 && (shift[0] != 0.0 || shift[1] != 0.0))
        for (size_t i = 0; i < q->n_poles; ++i) {
            q->poles[i * (size_t)q->dim] += shift[0];
            q->poles[i * (size_t)q->dim + 1] += shift[1];
        }
    return PROJCURVE_OK;
}
