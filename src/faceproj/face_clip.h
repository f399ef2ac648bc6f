/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A projection onto a face's untrimmed surface clipped to the face's loops.
 *
 * Each branch is cut at its loop crossings (loop_crossing.h) into
 * stretches; a stretch is kept when the exact projection at its middle is
 * inside the face or on a loop (projcurve_face_classify), dropped when
 * outside. A kept stretch becomes a branch whose ends at a crossing start
 * with PROJCURVE_START_TRIM / end with PROJCURVE_END_TRIM; an end of the
 * untrimmed branch that lies on a loop (within the face's tolerance: the
 * projection left the surface through a side of the domain that is a loop
 * of the face) is a TRIM end too. The kept branch carries the traced
 * points inside the stretch plus the exact crossings, its composed pieces
 * cut there (piece_cut.h) and its compact forms restricted to its t range.
 */
#ifndef PC_FACEPROJ_FACE_CLIP_H
#define PC_FACEPROJ_FACE_CLIP_H

#include "faceproj/loop_samples.h"
#include "trace/projector.h"
#include "trace/result.h"

/* An end of a clipped branch: where it lies on the face's loops. */
typedef struct pc_trim_end {
    int on_loop;        /* 1: on loop piece (loop, piece) at tau */
    size_t loop, piece;
    double tau;
    long edge;          /* that piece's edge id, -1 when none */
    double t, uv[2];    /* the end */
} pc_trim_end;

typedef struct pc_branch_trim {
    pc_trim_end start, end; /* in the branch's own order */
} pc_branch_trim;

/* The clipped result of `untrimmed` (a parametric result onto face's
 * surface, made with the projection that proj solves) in *out and, per
 * branch of it, its ends in *trims (malloc'd, *out's branch count
 * entries; NULL for none). *unrefined counts the crossings Newton did not
 * bring within PC_CROSSING_TOL (kept at their best iterate). Statuses: OK,
 * NO_MEMORY; nothing is set on failure. */
projcurve_status pc_face_clip(projcurve_context *ctx, const projcurve_face *face,
                              const pc_projector *proj, const projcurve_result *untrimmed,
                              projcurve_result **out, pc_branch_trim **trims, size_t *unrefined);

#endif /* PC_FACEPROJ_FACE_CLIP_H */
