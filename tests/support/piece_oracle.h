/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Test oracles for projection results, independent of the library's
 * refinement code:
 *  - a directional projector written from DESIGN.md's equations (Newton on
 *    [e1.(S - P); e2.(S - P)] = 0 through the public evaluation API), and an
 *    orthogonal one (Newton on [(S - P).Su; (S - P).Sv] = 0);
 *  - measurements of a branch's composed pieces against an exact projection
 *    curve given point by point: the Hausdorff distance both ways on dense
 *    samples (each output sample projected onto the exact curve by Newton on
 *    t, each exact sample onto its piece by Newton on s), joint angles, gaps,
 *    piece ends and whether each piece stays in one patch.
 */
#ifndef PC_TEST_PIECE_ORACLE_H
#define PC_TEST_PIECE_ORACLE_H

#include "geom/curve.h"
#include "geom/surface.h"
#include "trace/projector.h"
#include "trace/result.h"

typedef struct pc_oracle_dir {
    pc_vec3 dir, e1, e2;
} pc_oracle_dir;

/* A directional projector along dir (need not be unit) for surface and curve;
 * d must outlive proj. */
void pc_oracle_projector(const projcurve_surface *s, const projcurve_curve *c, const double dir[3],
                         pc_oracle_dir *d, pc_projector *proj);

/* An orthogonal projector (foot points of P(t) on S; only q' is given). */
void pc_oracle_projector_orthogonal(const projcurve_surface *s, const projcurve_curve *c,
                                    pc_projector *proj);

/* The exact projection curve at t: q[0] = Q(t), q[1] = Q'(t), q[2] = Q''(t)
 * (q[2] may be left zero: Newton then runs as Gauss-Newton). */
typedef void (*pc_oracle_exact_fn)(const void *user, double t, pc_vec3 q[3]);

typedef struct pc_oracle_measure {
    double hausdorff;   /* max of both one-sided distances */
    double max_angle;   /* largest joint angle, degrees */
    double max_gap;     /* largest distance between joined piece ends */
    double max_end_err; /* piece ends vs the exact projection */
    int off_patch;      /* pieces whose (u, v) range spans two patches */
} pc_oracle_measure;

/* Measures branch b (with pieces) against exact over its pieces' t range.
 * grid may be NULL (then off_patch is not checked). */
pc_oracle_measure pc_oracle_measure_branch(const pc_branch *b, pc_oracle_exact_fn exact,
                                           const void *user, const pc_patch_grid *grid);

/* Every branch of a result measured against the projection that the oracle
 * projector proj defines: the exact point at t is proj's own Newton solution
 * started from the branch's pcurve, Q' = Su u' + Sv v' from its q'.
 * `worst` holds the largest of each measure over the branches (off_patch:
 * their sum); failures counts exact points the oracle could not compute;
 * singular_points those where q' is singular (a collapsed edge of S, where
 * Su = 0) and Q' is a difference quotient of exact points instead;
 * loose_points those where the oracle's Newton reached only 1e-9 of the
 * model size (next to folds and domain edges, see piece_oracle.c). */
typedef struct pc_oracle_summary {
    pc_oracle_measure worst;
    size_t pieces;
    int failures;
    int singular_points;
    int loose_points;
    int branches_without_pieces;
} pc_oracle_summary;

void pc_oracle_measure_result(const projcurve_result *r, const pc_projector *proj,
                              const pc_patch_grid *grid, pc_oracle_summary *out);

/* Point (and derivative, dx may be NULL) of a piece at s by Bernstein sums. */
void pc_oracle_piece_eval(const pc_piece *pc, double s, pc_vec3 *x, pc_vec3 *dx);

#endif /* PC_TEST_PIECE_ORACLE_H */
