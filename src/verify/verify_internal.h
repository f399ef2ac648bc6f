/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The checks of one branch (verify_piece.c), used by the driver verify.c.
 */
#ifndef PC_VERIFY_INTERNAL_H
#define PC_VERIFY_INTERNAL_H

#include "common/budget.h"
#include "trace/projector.h"
#include "trace/result.h"

typedef struct pc_verifier {
    const pc_projector *proj;
    double eps_d;      /* the bound of (b) and (c), model units */
    double vertex_tol; /* the bound of (a), model units */
    double domain_tol; /* how far (u, v) may be outside the domain (rounding) */
    double min_move;   /* (u, v) distance that counts as none */
    size_t samples;    /* interior samples of the piece just checked */
    double worst_vertex, worst_piece; /* largest residual and distance met */
    pc_budget *budget; /* polled once per item checked; NULL: none */
} pc_verifier;

/* The vertex tolerance of (a) for the projector: see verify_piece.c. */
double pc_verify_vertex_tolerance(const pc_projector *proj);

/* (a) for the vertex (t, u, v). Returns 1 when it passes. */
int pc_verify_vertex(pc_verifier *v, double t, double u, double w);
/* (a) for the vertex (t, u, w) of pieces whose other ends are toward[0]
 * and toward[1] ((u, v) pairs; either may be NULL): where the residual at
 * (u, w) fails, it is measured one ulp towards each piece. Returns 1 when
 * it passes. */
int pc_verify_vertex_of_pieces(pc_verifier *v, double t, double u, double w,
                               const double *const toward[2]);

/* (b) and (c) for piece p of a branch; prev is the piece before it in the
 * branch (NULL for the first). Returns 1 when it passes. */
int pc_verify_piece(pc_verifier *v, const pc_piece *p, const pc_piece *prev);

#endif /* PC_VERIFY_INTERNAL_H */
