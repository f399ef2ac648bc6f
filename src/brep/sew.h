/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Sewing: edges shared by geometry, for faces whose file records no shared
 * edges (IGES 144 trimmed surfaces). Two loop pieces are one edge when
 * their 3D images start, end and pass half way within tol of each other
 * (in the same or the opposite sense); such pieces get one edge id (the
 * smallest of the group) and their senses along it. Pieces of no length in
 * 3D (poles) are left alone. A piece split differently by its two faces
 * (one piece against two) is not matched.
 */
#ifndef PC_BREP_SEW_H
#define PC_BREP_SEW_H

#include <stddef.h>

#include "brep/face.h"

/* Rewrites the edge ids and senses of the pieces of faces[0..n) that
 * match; *shared gets the number of edges used by more than one piece.
 * Statuses: OK, NO_MEMORY. */
projcurve_status pc_sew_faces(projcurve_context *ctx, projcurve_face *const *faces, size_t n,
                              double tol, size_t *shared);

#endif /* PC_BREP_SEW_H */
