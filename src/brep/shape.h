/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A shape: a set of faces of a model and the edges they share (which
 * piece of which face runs along which edge, and in which sense), with the
 * 3D box of every face and a BVH over them (shape_bvh.h; shapes of real
 * models have tens to a * few hundred faces).
 *
 * Faces are borrowed from the model that holds the shape.
 */
#ifndef PC_BREP_SHAPE_H
#define PC_BREP_SHAPE_H

#include <stddef.h>

#include "brep/face.h"
#include "brep/shape_bvh.h"
#include "projcurve.h"

typedef struct pc_edge_use {
    size_t face; /* index into the shape's faces */
    size_t loop, piece;
    int sense;   /* the piece's edge_sense x sense: +1 the loop runs along the edge */
} pc_edge_use;

typedef struct pc_shape_edge {
    long id;
    size_t first_use, n_uses;
} pc_shape_edge;

struct projcurve_shape {
    projcurve_shape_kind kind;
    const projcurve_face **faces;
    size_t *face_index; /* the model's index of each face */
    size_t n_faces;
    double *boxes;      /* 6 per face */
    pc_shape_edge *edges; /* sorted by id */
    size_t n_edges;
    pc_edge_use *uses;
    size_t n_uses;
    double sew_tol;     /* the tolerance edges were matched with, 0 when read */
    long id;            /* the file's entity, -1 when none */
    pc_face_bvh bvh;    /* over boxes (shape_bvh.h) */
};

/* Builds a shape over faces[0..n) (model indices index[0..n)), grouping
 * the pieces by edge id. Statuses: OK, NO_MEMORY. */
projcurve_status pc_shape_build(projcurve_context *ctx, projcurve_shape_kind kind, long id,
                                const projcurve_face *const *faces, const size_t *index, size_t n,
                                projcurve_shape **out);
void pc_shape_free(projcurve_shape *shape);

#endif /* PC_BREP_SHAPE_H */
