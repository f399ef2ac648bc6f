/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A face: a surface and its trimming loops in (u, v).
 *
 * One outer loop (the natural boundary of the surface's domain when none is
 * given) and any number of holes, each a closed chain of 2D NURBS pieces;
 * each piece knows the 3D edge it lies on (an id of the model, -1 when it
 * has none) and its senses. Loops are flattened once, at creation, into
 * polygons within flat_err of the pieces (curve2.h), oriented outer
 * counter-clockwise and holes clockwise whatever the file said, so that the
 * face is where the winding number is not 0 (classify.h).
 *
 * The face borrows its surface: the surface must outlive it. The face is
 * immutable after creation and safe to read from many threads.
 */
#ifndef PC_BREP_FACE_H
#define PC_BREP_FACE_H

#include <stddef.h>

#include "brep/classify.h"
#include "brep/curve2.h"
#include "projcurve.h"

#define PC_PIECE_SEAM 1u       /* its edge appears twice in the loop */
#define PC_PIECE_DEGENERATE 2u /* its edge is a point in 3D (a pole) */
#define PC_PIECE_NATURAL 4u    /* a side of the domain, no edge of the file */

/* Flattening error as a fraction of the ON tolerance: ON is decided within
 * tol of the polygon, so within tol +- flat_err of the loop. */
#define PC_FACE_FLATTEN_FRACTION 0.25
#define PC_FACE_KIND_TEXT 24

typedef struct pc_face_piece {
    pc_curve2 curve;
    long edge;      /* the model's id of its 3D edge, -1 when none */
    int sense;      /* +1: the loop runs along the curve, -1: against it */
    int edge_sense; /* +1: the curve runs along its edge, -1: against it */
    unsigned flags; /* PC_PIECE_* */
} pc_face_piece;

typedef struct pc_face_loop {
    pc_face_piece *pieces;
    size_t n_pieces;
    int outer;
    double *poly; /* flattened, outer CCW / holes CW */
    size_t n_poly;
} pc_face_loop;

struct projcurve_face {
    const projcurve_surface *surface; /* borrowed */
    double domain[4];
    int same_sense;  /* +1: the face's normal is Su x Sv, -1: the opposite */
    int periodic[2]; /* the surface closes on itself across u, across v */
    pc_face_loop *loops;
    size_t n_loops;  /* loops[0] is the outer loop */
    double tol_uv, tol_model, flat_err;
    double box_uv[4];
    double box[6];   /* 3D: the surface's control-net box, which holds the face */
    pc_classifier cls;
    long id;         /* the file's entity of the face, -1 for a caller's face */
    char kind[PC_FACE_KIND_TEXT]; /* "bspline", ... as read from the file */
};

/* A piece as given to pc_face_build. */
typedef struct pc_piece_input {
    int degree;
    size_t n_ctrl;
    const double *ctrl, *weights, *knots;
    long edge;
    int sense, edge_sense;
    unsigned flags;
} pc_piece_input;

typedef struct pc_loop_input {
    const pc_piece_input *pieces;
    size_t n_pieces;
    int outer;
} pc_loop_input;

typedef struct pc_face_params {
    double tol_uv;    /* ON tolerance in (u, v), > 0 */
    double tol_model; /* the model's precision, for periodicity */
    double close_tol; /* the most a loop's pieces may miss each other in (u, v) */
    int same_sense;
    /* 1: no loop is marked outer, the file does not say which is (STEP
     * FACE_BOUND only): the one of largest area is the outer loop. */
    int pick_outer;
    long id;
    const char *kind;
    const char *what; /* names the face in messages */
} pc_face_params;

/* Builds a face. Loops: at most one outer (none: the natural boundary);
 * every loop closed within close_tol; every hole inside the outer loop.
 * Statuses: OK, NULL_ARGUMENT, INVALID_ARGUMENT (open loop, two outer
 * loops, a hole outside, a loop of no area), the piece statuses of
 * pc_curve2_init, LIMIT_REACHED, NO_MEMORY; messages name the face, loop
 * and piece. */
projcurve_status pc_face_build(projcurve_context *ctx, const projcurve_surface *surface,
                               const pc_loop_input *loops, size_t n_loops,
                               const pc_face_params *params, projcurve_face **out);
void pc_face_free(projcurve_face *face);

/* The ON tolerance in (u, v) that keeps within tol_model in 3D: tol_model
 * over the largest |Su|, |Sv| of a 17 x 17 sample of the domain (a sample,
 * not a bound: stated as such in docs/brep.md). */
double pc_face_uv_tolerance(const projcurve_surface *surface, double tol_model);

/* Start and end of a piece in the loop's direction. */
void pc_piece_ends(const pc_face_piece *p, double start[2], double end[2]);

#endif /* PC_BREP_FACE_H */
