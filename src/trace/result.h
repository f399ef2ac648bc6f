/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The projection result: branches of traced points, the composed pieces, and
 * statistics. Built by trace/ (points), refine/ and compose/ (pieces), read
 * by api/result.c.
 */
#ifndef PC_TRACE_RESULT_H
#define PC_TRACE_RESULT_H

#include <stddef.h>

#include "common/budget.h"
#include "projcurve.h"

/* A composed piece: Bezier curve of `degree` on S over curve parameters
 * [t0, t1], (u, v) at its ends. Points are Cartesian, weights separate. */
typedef struct pc_piece {
    int degree;
    double t0, t1;
    double uv[4];    /* u(t0), v(t0), u(t1), v(t1) */
    double *ctrl;    /* 3 * (degree + 1) */
    double *weights; /* degree + 1 */
    /* The pcurve: the piece is S(uv(s)), uv(s) the Bezier curve of degree
     * uv_degree (1 or 3) with these (u, v) control points. */
    int uv_degree;
    double uv_ctrl[2 * PROJCURVE_MAX_PCURVE_POINTS];
} pc_piece;

/* A B-spline over the curve parameter: `dim` Cartesian coordinates per
 * pole, n_poles + degree + 1 clamped knots, weights NULL when polynomial.
 * n_poles 0: none. */
typedef struct pc_bspline {
    int degree, dim;
    size_t n_poles;
    double *knots;
    double *poles;
    double *weights;
} pc_bspline;

/* How a branch's compact pcurve was made (fit/). */
typedef enum pc_compact_kind {
    PC_COMPACT_NONE = 0,   /* no compact forms (not composed, or not fitted) */
    PC_COMPACT_FITTED = 1, /* the fitted cubic, checked within eps_D */
    PC_COMPACT_JOINED = 2  /* the fit hit its bound: the pieces' pcurves joined */
} pc_compact_kind;

/* Where a branch's pcurve jumps (seam/): at curve parameter t it crosses
 * the seam of a closed surface or passes a collapsed edge (a pole), and
 * its (u, v) changes by (du, dv) there. */
typedef struct pc_seam_record {
    double t, du, dv;
} pc_seam_record;

typedef struct pc_branch {
    double *points;     /* point_dim doubles per vertex: t, u, v (or t, x, y, z) */
    size_t n_points, cap_points;
    projcurve_branch_start start;
    projcurve_branch_end end;
    pc_piece *pieces;
    size_t n_pieces, cap_pieces;
    /* The compact forms (fit/), over increasing t: the pcurve (dim 2) and
     * the 3D curve (dim 3, n_poles 0 when the fit hit its bound), with the
     * largest distance the fit measured from the exact projection. */
    pc_compact_kind compact;
    pc_bspline compact_pcurve, compact_curve;
    double compact_pcurve_error, compact_curve_error;
    /* The jumps of a branch joined across seams and poles (seam/), in
     * increasing t; the compact pcurve is then unwrapped (seam/seam.h). */
    pc_seam_record *seams;
    size_t n_seams;
} pc_branch;

/* Index j of the segment [t_j, t_j+1] of b holding t (b of (t, u, v)
 * vertices, at least 2, t within its range). */
static inline size_t pc_branch_segment_at(const pc_branch *b, double t)
{
    size_t lo = 0, hi = b->n_points - 1;
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (b->points[3 * mid] <= t)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

typedef struct pc_stats {
    double points, steps, newton_iterations, jumps, pieces;
    double error_sum, error_max; /* estimation error of each corrected step:
                                    [SY13] eq. (3.8) (the projector's
                                    guess_error) */
    double error_count;          /* steps summed into error_sum */
    double tol_distance;
} pc_stats;

struct projcurve_result {
    int point_dim;      /* 3 = (t, u, v); 4 = (t, x, y, z) */
    pc_branch *branches;
    size_t n_branches, cap_branches;
    pc_stats stats;
    /* Branches the verification pass (verify/) dropped because nothing of
     * them could be verified: failures without a branch to show them. */
    size_t failures_dropped;
};

/* Allocation helpers; every function returns OK or NO_MEMORY. */
projcurve_status pc_result_create(projcurve_context *ctx, int point_dim,
                                  projcurve_result **out);
/* Appends an empty branch and returns it through *branch (pointer valid until
 * the next pc_result_add_branch). */
projcurve_status pc_result_add_branch(projcurve_context *ctx, projcurve_result *r,
                                      pc_branch **branch);
projcurve_status pc_branch_add_point(projcurve_context *ctx, pc_branch *b, int point_dim,
                                     const double *point);
/* Inserts a vertex before index `at`. */
projcurve_status pc_branch_insert_point(projcurve_context *ctx, pc_branch *b, int point_dim,
                                        size_t at, const double *point);
/* Appends a piece; ctrl/weights are copied (weights NULL = all 1). */
projcurve_status pc_branch_add_piece(projcurve_context *ctx, pc_branch *b, int degree,
                                     double t0, double t1, const double uv[4],
                                     const double *ctrl, const double *weights);
/* Sets the pcurve of the branch's last piece (pc_branch_add_piece makes it
 * the straight segment between the piece's (u, v) ends): degree 1..3 with
 * degree + 1 (u, v) control points. */
void pc_branch_set_last_pcurve(pc_branch *b, int degree, const double *uv_ctrl);
/* Releases what *s holds and leaves it empty (n_poles 0). */
void pc_bspline_free(pc_bspline *s);
/* Removes every piece of the branch (when recomposing). */
void pc_branch_clear_pieces(pc_branch *b);
/* Removes the branch at index i, keeping the order of the others. */
void pc_result_remove_branch(projcurve_result *r, size_t i);

/* 1 for the statuses with which a projection still returns its result:
 * OK and the partial results of LIMIT_REACHED and CANCELLED. */
static inline int pc_status_keeps_result(projcurve_status st)
{
    return st == PROJCURVE_OK || st == PROJCURVE_ERR_LIMIT_REACHED ||
           st == PROJCURVE_ERR_CANCELLED;
}

/* The end of a projection call with status st: on OK the budget (may be
 * NULL) reports the call complete; with a status that keeps a result, r
 * goes to *out, with any other it is destroyed and *out left untouched.
 * Returns st. */
projcurve_status pc_result_hand_out(projcurve_status st, pc_budget *budget, projcurve_result *r,
                                    projcurve_result **out);

#endif /* PC_TRACE_RESULT_H */
