/* SPDX-License-Identifier: BSD-3-Clause */
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
    double *poly;   /* monomial form per span (span_poly.h), or NULL */
} pc_nurbs_curve;

struct pc_nurbs_surface;

/* An evaluator of one degree pair, rationality and derivative order, on
 * spans already found: out as pc_nurbs_surface_eval. */
typedef void (*pc_surface_span_fn)(const struct pc_nurbs_surface *s, double u, double v,
                                   size_t span_u, size_t span_v, pc_vec3 *out);

typedef struct pc_nurbs_surface {
    int deg_u, deg_v;
    size_t n_u, n_v;    /* control net size */
    double *knots_u;    /* n_u + deg_u + 1, clamped */
    double *knots_v;    /* n_v + deg_v + 1, clamped */
    double *cw;         /* 4 * n_u * n_v homogeneous points, u index fastest */
    int rational;
    double domain[4];   /* u0, u1, v0, v1 */
    /* Reciprocal knot differences of every span, precomputed so that the hot
     * evaluation path does no division (pc_knot_inverses); NULL = computed
     * on the fly. */
    double *inv_u, *inv_v;
    /* Monomial coefficients of every span pair (span_poly.h), which the
     * fast evaluators use; NULL = evaluate in B-spline form. */
    double *poly;
    /* Set by pc_nurbs_surface_bind once the fields above are final: the
     * constant-degree evaluator of each derivative order (0, 1, 2) for
     * these degrees and this rationality, or NULL (then the general paths
     * run), so that no call searches for it; and the number of interior
     * spans per parameter unit of a knot vector whose spans are all equal
     * to a quarter of their length (0 otherwise), with which a span is
     * found in O(1) without a hint (pc_knot_uniform_scale). */
    pc_surface_span_fn span_eval[3];
    double span_scale_u, span_scale_v;
} pc_nurbs_surface;

/* Span index k with knots[k] <= t < knots[k+1] inside [degree, n_ctrl - 1]
 * (t = end of domain gives the last non-empty span). `hint` is a previous
 * answer (or any value): sequential calls then cost O(1). */
size_t pc_knot_span(const double *knots, size_t n_ctrl, int degree, double t, size_t hint);

/* spans / (knots[n_ctrl] - knots[degree]) when every span of the domain
 * is within a quarter of that mean length of it (uniform knots, also after
 * rounding), else 0. With it, (t - knots[degree]) * scale is the span
 * index up to one, which pc_knot_span_scaled corrects. */
double pc_knot_uniform_scale(const double *knots, size_t n_ctrl, int degree);

/* pc_knot_span, but with a nonzero scale from pc_knot_uniform_scale it
 * computes the span from t (any t, same answer) instead of trying the hint
 * and searching. */
static inline size_t pc_knot_span_scaled(const double *knots, size_t n_ctrl, int degree,
                                         double t, size_t hint, double scale)
{
    const size_t lo = (size_t)degree, hi = n_ctrl - 1;
    if (scale > 0.0 && t >= knots[lo] && t < knots[n_ctrl]) {
        const double guess = (t - knots[lo]) * scale;
        size_t k = lo + (guess < (double)(hi - lo) ? (size_t)guess : hi - lo);
        /* Now |k - span| <= 1 (the spans are uniform to a quarter); the
         * walks make the answer exact: knots[k] <= t < knots[k + 1]. */
        while (k > lo && t < knots[k])
            --k;
        while (k < hi && !(t < knots[k + 1]))
            ++k;
        return k;
    }
    return pc_knot_span(knots, n_ctrl, degree, t, hint);
}

/* Fills span_eval and span_scale_u/v of a surface whose other fields are
 * set (pc_nurbs_surface_init calls it last). */
void pc_nurbs_surface_bind(pc_nurbs_surface *s);

/* Validates and builds a curve from user arrays (the public creation rules:
 * copies, validates, clamps). */
projcurve_status pc_nurbs_curve_init(projcurve_context *ctx, pc_nurbs_curve *c, int degree,
                                     size_t n_ctrl, const double *ctrl, const double *weights,
                                     const double *knots);
/* The n homogeneous points cw (w x, w y, w z, w) as Cartesian points ctrl
 * (3 n) and weights (n); either output may be NULL. */
void pc_nurbs_points_from_homogeneous(const double *cw, size_t n, double *ctrl,
                                      double *weights);
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

/* ---- Building blocks shared by nurbs/, bezier/ and point/ ---------------- */

/* Largest number of basis functions that are nonzero on one span. */
#define PC_MAX_ORDER (PROJCURVE_MAX_DEGREE + 1)

/* Highest derivative order computed by pc_basis_ders (curves need 3). */
#define PC_MAX_DERIV 3

/* Values and derivatives of the degree + 1 basis functions that are nonzero
 * on one span: d[k][j] = k-th derivative of the j-th function. */
typedef struct pc_basis {
    double d[PC_MAX_DERIV + 1][PC_MAX_ORDER];
} pc_basis;

/* The degree + 1 B-spline basis functions N_{span-degree..span} at t and
 * their derivatives up to order n_deriv (<= PC_MAX_DERIV):
 * out->d[k][j] = d^k N_{span-degree+j} / dt^k. Derivatives above the degree
 * are zero. The NURBS Book, algorithm A2.3. No allocation. */
void pc_basis_ders(const double *knots, size_t span, int degree, double t, int n_deriv,
                   pc_basis *out);

/* Number of reciprocal knot differences per span: degree (degree + 1) / 2. */
static inline size_t pc_knot_inverse_count(int degree)
{
    return (size_t)degree * ((size_t)degree + 1) / 2;
}

/* The table, for spans degree .. n_ctrl - 1 (empty spans hold zeros):
 * span k, level j (1..degree), r (0..j-1) at
 * (k - degree) * pc_knot_inverse_count(degree) + j (j - 1) / 2 + r holds
 * 1 / (knots[k + r + 1] - knots[k + r + 1 - j]). malloc'd; NULL when out of
 * memory (evaluation then divides on the fly). */
double *pc_knot_inverses(const double *knots, size_t n_ctrl, int degree);

/* Point and derivatives (order n_deriv in 0..2, output as
 * pc_nurbs_surface_eval) of the tensor product of a (p+1) x (q+1) block of
 * homogeneous points (row j starts at net + j * stride doubles) with the
 * basis derivative tables bu, bv; rational = 0 skips the division by w
 * (every weight must then be 1). Shared by spline and Bezier patch
 * evaluation. */
void pc_surface_block_eval(const double *net, size_t stride, int p, int q, int n_deriv,
                           const pc_basis *bu, const pc_basis *bv, int rational, pc_vec3 *out);

/* Checks a user knot vector of n_ctrl + degree + 1 values: finite,
 * non-decreasing, no value repeated more than degree + 1 times and a
 * non-empty domain [knots[degree], knots[n_ctrl]]. `name` ("knot vector u")
 * prefixes the message. Statuses: OK, NOT_FINITE, BAD_KNOTS. */
projcurve_status pc_knots_validate(projcurve_context *ctx, const char *name, int degree,
                                   size_t n_ctrl, const double *knots);

/* A batch of splines sharing one knot vector: `rows` splines of n_ctrl
 * control points with `dim` doubles each, stored row after row. A curve is
 * one row of dim 4; a surface is, in u, n_v rows of dim 4 and, in v, one row
 * of dim 4 * n_u (the whole net row is one "point"). */
typedef struct pc_spline_batch {
    int degree;
    size_t n_ctrl;
    size_t dim;
    size_t rows;
    double *knots;  /* n_ctrl + degree + 1, owned (malloc) */
    double *pts;    /* rows * n_ctrl * dim, owned (malloc) */
} pc_spline_batch;

/* Converts the batch in place to clamped knots over the same domain
 * [knots[degree], knots[n_ctrl]] by inserting the domain ends until they have
 * multiplicity degree (Boehm insertion, exact up to rounding) and dropping
 * the control points outside. Knots must have passed pc_knots_validate.
 * Statuses: OK, NO_MEMORY, OVERFLOW. */
projcurve_status pc_spline_batch_clamp(projcurve_context *ctx, pc_spline_batch *b);

/* 1 if the knot vector of n_ctrl + degree + 1 values has degree + 1 equal
 * values at each end. */
int pc_knots_are_clamped(const double *knots, size_t n_ctrl, int degree);

/* Checks that count * size (and count * size * extra) fit in size_t;
 * returns the product or 0 on overflow (count, size > 0). */
size_t pc_size_mul(size_t a, size_t b);

#endif /* PC_NURBS_H */
