/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * A composed branch as the fitting sees it: its pieces in increasing curve
 * parameter t, and exact points of the projection at any t of its range,
 * reached by the projector's corrector from the pieces' pcurves (which lie
 * within eps_D of the projection, so Newton starts beside its root).
 */
#ifndef PC_FIT_BRANCH_VIEW_H
#define PC_FIT_BRANCH_VIEW_H

#include <stddef.h>

#include "common/budget.h"
#include "trace/projector.h"
#include "trace/result.h"

/* An exact point of the projection: t, q(t) = (u, v), S(q(t)) and the
 * partials Su, Sv there (with which the fit measures a pcurve near q(t)
 * to first order while it places knots; its check evaluates S). */
typedef struct pc_fit_sample {
    double t, uv[2], x[3], su[3], sv[3];
} pc_fit_sample;

typedef struct pc_fit_branch {
    const pc_projector *proj;
    const pc_nurbs_surface *surface;
    const pc_branch *b;
    int reversed;      /* the pieces run with t decreasing */
    double t_lo, t_hi; /* the branch's range, t_lo < t_hi */
    double min_move;   /* (u, v) slack of the corrector's sanity check */
    pc_budget *budget; /* polled once per corrected point; may be NULL */
    size_t hint_u, hint_v;
    size_t corrections; /* corrector calls made (for the statistics) */
    double progress;    /* how far the fitting stage is, for the budget */
} pc_fit_branch;

/* Sets up the view; 0 when the branch has no pieces or they do not follow
 * one another in t (then it has no compact forms). */
int pc_fit_branch_init(pc_fit_branch *fb, const pc_projector *proj, const pc_branch *b,
                       pc_budget *budget);

/* The k-th piece in increasing t, and its t range. */
const pc_piece *pc_fit_piece(const pc_fit_branch *fb, size_t k);
void pc_fit_piece_range(const pc_piece *p, double *lo, double *hi);
/* The (u, v) of piece p's pcurve at t (inside its range). */
void pc_fit_piece_uv(const pc_piece *p, double t, double uv[2]);

/* S(u, v) into x[3]. */
void pc_fit_surface_point(pc_fit_branch *fb, const double uv[2], double x[3]);
/* The sample at (t, uv): S and its partials there. */
void pc_fit_sample_at(pc_fit_branch *fb, double t, const double uv[2], pc_fit_sample *out);

/* The exact point at t (clamped to the branch's range): the corrector from
 * the pieces' pcurve at t. Returns 1 on success; 0 when the corrector does
 * not converge, moves farther than the piece is long (another branch), or
 * the budget has stopped the call. */
int pc_fit_exact(pc_fit_branch *fb, double t, pc_fit_sample *out);

/* The piece ends are exact vertices of the projection: sample of the end
 * at the low (hi = 0) or high (hi = 1) t of piece k. */
void pc_fit_piece_end(pc_fit_branch *fb, size_t k, int hi, pc_fit_sample *out);

#endif /* PC_FIT_BRANCH_VIEW_H */
