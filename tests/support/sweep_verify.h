/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * An independent verifier of one projection result, for the real-data
 * sweep (tests/realdata/test_realdata_sweep.c). It uses the public API only and
 * none of the library's own error measures:
 *
 *  - soundness: every piece of every branch is sampled; each sample X must
 *    lie on S (the piece against S at its pcurve), and some curve point
 *    P(t*) must project onto it: X - P(t*) parallel to Dir with
 *    (X - P(t*)).Dir >= -eps_D (directional; the ray passing within
 *    eps_D of X), or parallel to the normal of S at X (orthogonal); and X
 *    must be within eps_D of the exact projection curve: of the exact point
 *    of P(t*), or else of the nearest exact point over t around t* or over
 *    the piece's t range (where S folds, the normal names a wrong t*), each
 *    found by the test's own Newton iteration from X (ray_oracle.h's polish
 *    for the ray; a Newton on (S - P).Su = (S - P).Sv = 0 for the foot,
 *    a descent on the distance where it fails);
 *  - completeness: at evenly spaced t, the brute-force ray hits
 *    (directional, ray_oracle.h's mesh) or the local minima of the distance
 *    from P(t) to S (orthogonal, the same mesh's points refined by Newton)
 *    must each lie within eps_D of some returned piece;
 *    a hit where the curve runs along Dir (its image a point of S, not a
 *    curve) is counted apart, for the caller to require a reported failure;
 *  - signals: a branch with no pieces, a branch that ends FAILED.
 *
 * Documented exclusions, counted but not failed: samples and hits where
 * Dir is within PC_VERIFY_GRAZING_DEG of the tangent plane (there the
 * exact point along the surface is ill-conditioned, ~eps_D / sin(angle)),
 * samples at a collapsed edge (no normal), ray hits closer to the curve than
 * in->lambda_min (a curve lying on S: whether its own points count is the
 * library's decision), and feet that are not local minima of the distance.
 */
#ifndef PC_TEST_SWEEP_VERIFY_H
#define PC_TEST_SWEEP_VERIFY_H

#include <stddef.h>

#include "projcurve.h"
#include "ray_oracle.h"

/* Angle between Dir and the tangent plane below which a point is grazing. */
#define PC_VERIFY_GRAZING_DEG 2.0

typedef struct pc_sweep_input {
    const projcurve_surface *surface;
    const projcurve_curve *curve;
    int orthogonal;
    double dir[3];               /* directional only */
    const pc_oracle_mesh *mesh;  /* of the surface (ray_oracle.h) */
    double eps_d;                /* the distance tolerance of the call */
    double size;                 /* the surface's size: its box diagonal */
    double lambda_min;           /* ray hits nearer than this are not required */
    int completeness_samples;    /* t values of the completeness check */
    size_t max_piece_samples;    /* work bound of the soundness check */
} pc_sweep_input;

typedef struct pc_sweep_report {
    size_t branches, pieces, samples;
    size_t pieces_skipped;       /* not sampled: beyond max_piece_samples */
    /* soundness */
    size_t off_surface;          /* piece and S at its pcurve differ */
    size_t off_projection;       /* no t* projects onto the sample */
    size_t behind;               /* the only t* lie behind the curve */
    size_t far_from_exact;       /* too far from the exact point of t* */
    size_t grazing_samples, pole_samples; /* excluded, see above */
    double worst_off_surface, worst_residual, worst_exact; /* in units of eps_d */
    double wrong_t;              /* t of the first wrong sample, NaN if none */
    double wrong_gap, wrong_lambda; /* its distance to the nearest ray or
                                     * normal line (any t), and lambda there */
    /* completeness */
    size_t oracle_points, missed, grazing_points;
    /* hits not covered where the curve runs along Dir (the rays of the
     * neighbouring samples are its ray to eps_D): the curve's image is a
     * point of S, which the library does not return as a branch but counts
     * as a failure (projcurve.h, projcurve_project_directional); the
     * caller requires that failure (not counted in missed) */
    size_t point_image_points;
    double missed_t;             /* t of the first missed point, NaN if none */
    double worst_missed;         /* its distance to the pieces / eps_d */
    /* signals */
    size_t zero_piece_branches, failed_ends;
    int accessor_failures;       /* result accessors that failed */
} pc_sweep_report;

void pc_sweep_verify(const pc_sweep_input *in, const projcurve_result *r,
                      pc_sweep_report *rep);

/* The oracle mesh's evaluator (pc_oracle_mesh_build) for the surface
 * `user` (a const projcurve_surface *): projcurve_surface_eval, NaN where
 * it fails. */
void pc_sweep_surface_eval(void *user, double u, double v, int n_deriv, double out[9]);
/* The sweep's mesh cells per side of a surface with `spans` knot spans
 * that way: 8 a span, 48 to 256 (the ray oracle's chord error is then
 * ~1e-4 of the size on the real surfaces). */
int pc_sweep_mesh_cells(size_t spans);

#endif /* PC_TEST_SWEEP_VERIFY_H */
