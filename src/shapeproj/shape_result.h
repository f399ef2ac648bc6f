/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The result of a projection onto a face or a shape: per projected face,
 * its clipped projcurve_result (faceproj/) with the ends of its branches on
 * the loops; and the connected curves, each an ordered list of (face,
 * branch) references into those results (chain.h).
 */
#ifndef PC_SHAPEPROJ_SHAPE_RESULT_H
#define PC_SHAPEPROJ_SHAPE_RESULT_H

#include <stddef.h>

#include "faceproj/face_clip.h"

typedef struct pc_face_part {
    size_t face;              /* index in the shape (0 for a lone face) */
    const projcurve_face *f;  /* borrowed */
    projcurve_result *result; /* owned; NULL when the projection failed */
    pc_branch_trim *trims;    /* owned; one per branch of result */
    projcurve_status status;
    char *message;            /* owned; "" on OK */
} pc_face_part;

typedef struct pc_piece_ref {
    size_t part, branch;
} pc_piece_ref;

typedef struct pc_connected {
    size_t first, count; /* refs[first .. first + count) */
    int closed;
} pc_connected;

struct projcurve_shape_result {
    pc_face_part *parts;
    size_t n_parts;
    pc_piece_ref *refs;
    size_t n_refs;
    pc_connected *curves;
    size_t n_curves;
    size_t open_ends;
    double chain_tol;
};

/* An empty result with room for n_parts face parts (all zero). Statuses:
 * OK, NO_MEMORY. */
projcurve_status pc_shape_result_create(projcurve_context *ctx, size_t n_parts,
                                        projcurve_shape_result **out);

/* Stores message (copied; NULL is "") as part i's. Statuses: OK, NO_MEMORY. */
projcurve_status pc_face_part_set_message(projcurve_context *ctx, pc_face_part *part,
                                          const char *message);

#endif /* PC_SHAPEPROJ_SHAPE_RESULT_H */
