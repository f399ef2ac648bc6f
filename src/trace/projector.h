/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * What the kind of projection (directional, conical, orthogonal) contributes to the
 * generic machinery: the equations. trace/, refine/ and compose/ only talk to
 * this interface, so the orthogonal projection reuses them unchanged.
 *
 * The projection curve is q(t) = (u(t), v(t)) with F(u, v, t) = 0 (two scalar
 * equations). The implementation provides F's Newton corrector and the
 * derivatives q', q'' for the second-order predictor.
 */
#ifndef PC_TRACE_PROJECTOR_H
#define PC_TRACE_PROJECTOR_H

#include "common/vec.h"
#include "geom/curve.h"
#include "geom/surface.h"

/* A branch ends at a fold when |det| (normalised, see pc_proj_point) falls
 * below this: the Jacobian of F is then singular to ~1e-6 of its scale
 * (directional: Dir within ~1e-6 rad of the tangent plane), q' is not
 * resolved. The tracer ends branches there and the refinement takes the
 * same floor. */
#define PC_PROJECTOR_DET_FOLD 1e-6
/* When the step cannot be made to succeed, a |det| below this says the
 * branch stalled at a fold rather than failed. */
#define PC_PROJECTOR_DET_NEAR_FOLD 1e-2

typedef struct pc_projector pc_projector;

/* Local state at (t, u, v): filled by pc_projector.derivatives. */
typedef struct pc_proj_point {
    double t, u, v;
    double du, dv;     /* q'(t) */
    double ddu, ddv;   /* q''(t) */
    double det;        /* determinant of the Jacobian of F in (u, v), normalised
                          (directional: Dir.(Su x Sv)/|Su x Sv|; orthogonal:
                          det K / (|Su||Sv|)^2); its sign change marks a fold or
                          a centre of curvature */
    pc_vec3 s;         /* S(u, v) */
    pc_vec3 p;         /* P(t) */
    double speed;      /* |Q'(t)| = |Su u' + Sv v'| in model units ([SY13]
                          eq. (3.6)), for the arc-length step (3.7); 0 when
                          unknown (the engine then measures it itself) */
    double cusp_rate;  /* d ln |Su x Sv| / dt along the branch from the pure
                          second derivatives Suu, Svv: negative ahead (t
                          increasing) when a cusp of the parametrisation
                          closes in (a v line folding back on itself,
                          tracer.c cusp_distance); 0 when the projector does
                          not tell */
} pc_proj_point;

/* Starts *out at (t, u, v) with q', q'', det and speed 0: what a
 * projector's derivatives() leaves where it fails (s and p are its to
 * fill). */
static inline void pc_proj_point_start(pc_proj_point *out, double t, double u, double v)
{
    out->t = t;
    out->u = u;
    out->v = v;
    out->du = out->dv = out->ddu = out->ddv = 0.0;
    out->det = 0.0;
    out->speed = 0.0;
    out->cusp_rate = 0.0;
}

struct pc_projector {
    const projcurve_surface *surface;
    const projcurve_curve *curve;
    double model_size;     /* scale for relative tolerances */
    double newton_tol;     /* absolute tolerance (model units) */
    int newton_max_iter;
    /* Newton on F(., ., t) = 0 from the guess uv; uv is updated in place,
     * clamped to the surface domain. Returns 1 on convergence, 0 otherwise;
     * *iterations (may be NULL) gets the iteration count. */
    int (*correct)(const pc_projector *self, double t, double uv[2], int *iterations);
    /* Optional (may be NULL: the engine calls correct(), then
     * derivatives()): the tracer's step in one call. Newton as correct()
     * from the guess uv that the tracer predicted over the curve step h
     * (signed) from its last point, then derivatives() at the point
     * reached into *next. derivatives() right after correct() gives q'' of
     * the corrected point to ~1e-7 relative; here q'' may be less exact,
     * by an amount that moves the next prediction (over a step of the same
     * size) by a small fraction of the correction just made, when that
     * saves an evaluation. Returns 1 when both succeeded, 0 when the
     * correction failed, -1 when it converged but derivatives() failed. */
    int (*advance)(const pc_projector *self, double t, double h, double uv[2], int *iterations,
                   pc_proj_point *next);
    /* q', q'' and det at (t, u, v). Returns 0 when the Jacobian is singular
     * or a callback failed. */
    int (*derivatives)(const pc_projector *self, double t, double u, double v,
                       pc_proj_point *out);
    /* Optional (may be NULL): q' alone at (t, u, v), a point that need not
     * lie on the projection curve, from first derivatives of S only. The
     * RK4 baseline's stages need nothing more; when NULL they call
     * derivatives(). Returns 0 like derivatives(). */
    int (*slope)(const pc_projector *self, double t, double u, double v, double dq[2]);
    /* Residual |F| in model units (distance of S(u, v) from the exact
     * projection condition), for tests and error estimates. */
    double (*residual)(const pc_projector *self, double t, double u, double v);
    const void *data;      /* kind-specific (direction frame, ...) */
    /* Optional (may be NULL): correct() stores here the estimation error of
     * its initial guess, [SY13] eq. (3.8) for the directional kind (the
     * sine of the angle between Dir and S(guess) - P). The engine averages
     * it into the statistics; when NULL it uses residual() / model_size. */
    double *guess_error;
    /* Optional (may be NULL: the fixed pc_trace_config.dir of the run): the
     * unit direction of the ray at the point p (its t, s and p filled), for
     * ray projections whose ray depends on t (central: from the eye
     * through P(t)). The tracer measures lambda = (S - P).ray_dir(p) with
     * it to find where the curve crosses S. */
    pc_vec3 (*ray_dir)(const pc_projector *self, const pc_proj_point *p);
};

#endif /* PC_TRACE_PROJECTOR_H */
