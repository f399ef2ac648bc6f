/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Sewing: edges shared by geometry, for faces whose file records no shared
 * edges (IGES 144 trimmed surfaces). Two loop pieces are one edge when
 * their 3D images start, end and pass half way within tol of each other
 * (in the same or the opposite sense); such pieces get one edge id (the
 * smallest of the group) and their senses along it. Pieces of no length in
 * 3D (poles) are left alone. Then an edge split differently by its two
 * faces (one piece against two or more, brep/sew_split.c): each piece
 * still of one use that lies along a longer piece of one use of another
 * face joins that piece's edge. Last, faces that do not meet within the
 * file's resolution (hammer.iges: gaps up to 0.09 at a resolution of
 * 0.001): the pieces still of one use are matched the same way within
 * PC_SEW_GAP_FACTOR times the tolerance, and the widest gap so closed is
 * the tolerance reported.
 */
#ifndef PC_BREP_SEW_H
#define PC_BREP_SEW_H

#include <stddef.h>

#include "brep/face.h"

/* How far beyond the file's resolution two faces' pieces may stay apart
 * and still be sewn: gaps of 100 resolutions are seen in real files, and a
 * piece must still lie along the other over its whole length. */
#define PC_SEW_GAP_FACTOR 100.0

/* Rewrites the edge ids and senses of the pieces of faces[0..n) that
 * match; *shared gets the number of edges used by more than one piece,
 * *used_tol the tolerance they were matched within (tol, or the widest gap
 * closed beyond it). Statuses: OK, NO_MEMORY. */
projcurve_status pc_sew_faces(projcurve_context *ctx, projcurve_face *const *faces, size_t n,
                              double tol, size_t *shared, double *used_tol);

/* The edges split differently by their two faces: a piece B whose edge
 * has one use and whose 3D image lies within tol of a longer piece A of
 * one use of another face (at 5 points along B, each measured to A's image
 * by a bounded golden-section search) takes A's edge id (the smaller of
 * the two ids for the group) and its sense along A. *shared gets the
 * number of longer pieces so shared, *gap the farthest such point from its
 * long piece. Statuses: OK, NO_MEMORY. */
projcurve_status pc_sew_split_pieces(projcurve_context *ctx, projcurve_face *const *faces,
                                     size_t n, double tol, size_t *shared, double *gap);

/* The 3D point of a loop piece at its parameter t, (u, v) clamped to the
 * surface's domain; 0 when the surface cannot be evaluated there. */
int pc_sew_piece_point(const projcurve_face *f, const pc_face_piece *piece, double t,
                       double out[3]);

#endif /* PC_BREP_SEW_H */
