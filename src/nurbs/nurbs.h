/*
 * NURBS curves and surfaces: storage and evaluation with derivatives.
 *
 * Control points are stored in homogeneous form (w x, w y, w z, w) so that a
 * rational and a polynomial spline share one evaluation path; `rational` is 0
 * when every weight is 1, which lets evaluation skip the quotient rule.
 * Knot vectors are always clamped here (the creation functions convert
 * unclamped input exactly by knot insertion).
 */
#ifndef PC_NURBS_H
#define PC_NURBS_H

#include <stddef.h>

#include "common/vec.h"
#include "projcurve.h"

typedef struct pc_nurbs_curve {
    int degree;
    size_t n_ctrl;  /* control points */
    double *knots;  /* n_ctrl + degree + 1, clamped */
    double *cw;     /* 4 * n_ctrl homogeneous control points */
    int rational;
    double t0, t1;  /* domain = [knots[degree], knots[n_ctrl]] */
} pc_nurbs_curve;

typedef struct pc_nurbs_surface {
    int deg_u, deg_v;
    size_t n_u, n_v;    /* control net size */
    double *knots_u;    /* n_u + deg_u + 1, clamped */
    double *knots_v;    /* n_v + deg_v + 1, clamped */
    double *cw;         /* 4 * n_u * n_v homogeneous points, u index fastest */
    int rational;
    double domain[4];   /* u0, u1, v0, v1 */
} pc_nurbs_surface;

/* Span index k with knots[k] <= t < knots[k+1] inside [degree, n_ctrl - 1]
 * (t = end of domain gives the last non-empty span). `hint` is a previous
 * answer (or any value): sequential calls then cost O(1). */
size_t pc_knot_span(const double *knots, size_t n_ctrl, int degree, double t, size_t hint);

/* Validates and builds a curve from user arrays (the public creation rules:
 * copies, validates, clamps). */
projcurve_status pc_nurbs_curve_init(projcurve_context *ctx, pc_nurbs_curve *c, int degree,
                                     size_t n_ctrl, const double *ctrl, const double *weights,
                                     const double *knots);
void pc_nurbs_curve_free(pc_nurbs_curve *c);

projcurve_status pc_nurbs_surface_init(projcurve_context *ctx, pc_nurbs_surface *s,
                                       int deg_u, int deg_v, size_t n_u, size_t n_v,
                                       const double *ctrl, const double *weights,
                                       const double *knots_u, const double *knots_v);
void pc_nurbs_surface_free(pc_nurbs_surface *s);

/* Curve point and derivatives up to order n_deriv (<= 3) at t (clamped to the
 * domain): out[0..n_deriv]. No allocation. */
void pc_nurbs_curve_eval(const pc_nurbs_curve *c, double t, int n_deriv, size_t *hint,
                         pc_vec3 *out);

/* Surface point and derivatives up to total order n_deriv (<= 2) at (u, v)
 * (clamped to the domain): out = S, Su, Sv, Suu, Suv, Svv (first 1, 3 or 6
 * entries). hint_u/hint_v may be NULL. No allocation; this is the hot path
 * of tracing. */
void pc_nurbs_surface_eval(const pc_nurbs_surface *s, double u, double v, int n_deriv,
                           size_t *hint_u, size_t *hint_v, pc_vec3 *out);

#endif /* PC_NURBS_H */
