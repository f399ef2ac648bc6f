/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The face pieces of a connected curve (projcurve_shape_result) as the
 * members the IGES and STEP writers put into one composite curve: each
 * piece's 3D curve (the compact one, or its composed pieces joined), the
 * sense in which the chain runs along it and its ends in chain order.
 */
#ifndef PC_API_SHAPE_MEMBER_H
#define PC_API_SHAPE_MEMBER_H

#include <stddef.h>

#include "projcurve.h"

typedef struct pc_shape_member {
    projcurve_curve *curve; /* the piece's 3D curve, parametrised by t increasing (owned) */
    int forward;            /* 1: the chain runs along it with t increasing */
    double first[3];        /* its point where the chain enters it */
    double last[3];         /* its point where the chain leaves it */
} pc_shape_member;

/* The 3D curve of a composed branch: the compact one (fit/), or where
 * there is none (its fit hit its bound, or no compact forms) the pieces
 * joined (projcurve_result_branch_curve). Statuses: those of the two. */
projcurve_status pc_branch_curve3d(projcurve_context *ctx, const projcurve_result *r,
                                   size_t branch, int compact, projcurve_curve **c);

/* Piece `piece` of connected curve `curve` of r as a member. Statuses: OK,
 * INDEX, INVALID_ARGUMENT (the piece was not composed: no 3D curve, the
 * message says why), OUT_OF_RANGE (a sliver: its t range too narrow for a
 * curve), NO_MEMORY. On failure m holds nothing to free. */
projcurve_status pc_shape_member_get(projcurve_context *ctx, const projcurve_shape_result *r,
                                     size_t curve, size_t piece, pc_shape_member *m);
void pc_shape_member_free(pc_shape_member *m);

/* Whether the chain runs on from a to b without a gap: a's last point and
 * b's first within tol (the result's chaining tolerance). */
int pc_shape_members_meet(const pc_shape_member *a, const pc_shape_member *b, double tol);

#endif /* PC_API_SHAPE_MEMBER_H */
