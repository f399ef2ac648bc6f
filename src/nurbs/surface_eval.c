/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Surface point and partial derivatives up to order 2: the hot path of
 * tracing and of point projection.
 *
 * For degrees up to PC_SMALL_DEGREE the evaluator uses eight-wide basis
 * tables (basis_small.h) and is written once as an always-inlined function
 * of (p, q, n_deriv, rational). It is instantiated with constants for the
 * common degree pairs at every derivative order, where the compiler unrolls
 * it completely and keeps it in registers; other small degrees use an
 * instance with the degrees read at run time (its basis still specialised
 * per degree). Degrees above 7 go to surface_eval_large.c. No allocation.
 */
#include "nurbs/basis_small.h"
#include "nurbs/nurbs.h"
#include "nurbs/span_poly.h"
#include "nurbs/surface_block.h"
#include "nurbs/surface_eval_large.h"

static double clamp_to(double x, double lo, double hi)
{
    if (!(x >= lo))
        return lo; /* also maps NaN to lo: callers validate, the hot path never traps */
    return x > hi ? hi : x;
}

/* The span's row of the surface's reciprocal knot table, or NULL. */
static inline const double *span_inverses(const double *table, size_t span, int degree)
{
    return table != NULL ? table + (span - (size_t)degree) * pc_knot_inverse_count(degree)
                         : NULL;
}

/* One evaluation in monomial form with the spans found and (u, v) inside
 * the domain (s->poly != NULL). */
static PC_ALWAYS_INLINE void eval_poly(const pc_nurbs_surface *s, double u, double v,
                                       size_t span_u, size_t span_v, int p, int q,
                                       int n_deriv, int rational, pc_vec3 *out)
{
    const size_t index = (span_v - (size_t)q) * (s->n_u - (size_t)p) + (span_u - (size_t)p);
    double a[PC_D_COUNT][4];
    pc_span_poly_eval(s->poly + index * pc_span_poly_len(p, q), p, q, n_deriv,
                      u - s->knots_u[span_u], v - s->knots_v[span_v], a);
    pc_block_finish(a, n_deriv, rational, out);
}

/* Constant-degree instances: polynomial and rational, orders 0, 1, 2. */
#define PC_EVAL_INSTANCE(P, Q, RATIONAL, N)                                                  \
    PC_HOT_CLONES static void eval_##P##Q##_##RATIONAL##_##N(                                \
        const pc_nurbs_surface *s, double u, double v, size_t su, size_t sv, pc_vec3 *out)   \
    {                                                                                        \
        eval_poly(s, u, v, su, sv, P, Q, N, RATIONAL, out);                                  \
    }
#define PC_EVAL_DEGREES(P, Q)                                                                \
    PC_EVAL_INSTANCE(P, Q, 0, 0)                                                             \
    PC_EVAL_INSTANCE(P, Q, 0, 1)                                                             \
    PC_EVAL_INSTANCE(P, Q, 0, 2)                                                             \
    PC_EVAL_INSTANCE(P, Q, 1, 0)                                                             \
    PC_EVAL_INSTANCE(P, Q, 1, 1)                                                             \
    PC_EVAL_INSTANCE(P, Q, 1, 2)
#define PC_EVAL_TABLE(P, Q)                                                                  \
    {P, Q,                                                                                   \
     {{eval_##P##Q##_0_0, eval_##P##Q##_0_1, eval_##P##Q##_0_2},                             \
      {eval_##P##Q##_1_0, eval_##P##Q##_1_1, eval_##P##Q##_1_2}}}

/* Bicubic and biquadratic are the usual CAD surfaces; bilinear and
 * cubic x linear (ruled and extruded), degree 5 x 5 and the seed paper's
 * 5 x 1 sheet ([SY13], Example 1) come with the test cases. */
PC_EVAL_DEGREES(3, 3)
PC_EVAL_DEGREES(2, 2)
PC_EVAL_DEGREES(1, 1)
PC_EVAL_DEGREES(3, 1)
PC_EVAL_DEGREES(1, 3)
PC_EVAL_DEGREES(5, 5)
PC_EVAL_DEGREES(5, 1)

typedef struct eval_instances {
    int p, q;
    pc_surface_span_fn fn[2][3]; /* [rational][n_deriv] */
} eval_instances;

static const eval_instances k_instances[] = {
    PC_EVAL_TABLE(3, 3), PC_EVAL_TABLE(2, 2), PC_EVAL_TABLE(1, 1), PC_EVAL_TABLE(3, 1),
    PC_EVAL_TABLE(1, 3), PC_EVAL_TABLE(5, 5), PC_EVAL_TABLE(5, 1),
};

/* Basis of a run-time degree <= PC_SMALL_DEGREE through an instance of
 * constant degree (the derivatives up to 2 always: cheaper than loops). */
static PC_ALWAYS_INLINE void small_basis_any(const double *knots, size_t span, int p, double t,
                                             const double *inv, pc_small_basis *out)
{
    switch (p) {
    case 1: pc_small_basis_ders(knots, span, 1, t, 2, inv, out); break;
    case 2: pc_small_basis_ders(knots, span, 2, t, 2, inv, out); break;
    case 3: pc_small_basis_ders(knots, span, 3, t, 2, inv, out); break;
    case 4: pc_small_basis_ders(knots, span, 4, t, 2, inv, out); break;
    case 5: pc_small_basis_ders(knots, span, 5, t, 2, inv, out); break;
    case 6: pc_small_basis_ders(knots, span, 6, t, 2, inv, out); break;
    default: pc_small_basis_ders(knots, span, PC_SMALL_DEGREE, t, 2, inv, out); break;
    }
}

/* Any pair of degrees up to PC_SMALL_DEGREE. */
PC_HOT_CLONES static void eval_small_any(const pc_nurbs_surface *s, double u, double v,
                                         size_t span_u, size_t span_v, int n_deriv,
                                         pc_vec3 *out)
{
    const int p = s->deg_u, q = s->deg_v;
    double local_u[PC_SMALL_INVERSES], local_v[PC_SMALL_INVERSES];
    const double *inv_u =
        pc_small_inverses(s->knots_u, span_u, p, span_inverses(s->inv_u, span_u, p), local_u);
    const double *inv_v =
        pc_small_inverses(s->knots_v, span_v, q, span_inverses(s->inv_v, span_v, q), local_v);
    pc_small_basis bu, bv;
    small_basis_any(s->knots_u, span_u, p, u, inv_u, &bu);
    small_basis_any(s->knots_v, span_v, q, v, inv_v, &bv);
    const size_t first = (span_v - (size_t)q) * s->n_u + (span_u - (size_t)p);
    double a[PC_D_COUNT][4];
    pc_block_contract(s->cw + 4 * first, 4 * s->n_u, p, q, 2, bu.d[0], bv.d[0],
                      PC_SMALL_ORDER, a);
    pc_block_finish(a, n_deriv, s->rational, out);
}

void pc_nurbs_surface_bind(pc_nurbs_surface *s)
{
    for (int d = 0; d < 3; ++d)
        s->span_eval[d] = NULL;
    if (s->poly != NULL) {
        const size_t n_instances = sizeof k_instances / sizeof k_instances[0];
        for (size_t k = 0; k < n_instances; ++k)
            if (k_instances[k].p == s->deg_u && k_instances[k].q == s->deg_v)
                for (int d = 0; d < 3; ++d)
                    s->span_eval[d] = k_instances[k].fn[s->rational != 0][d];
    }
    s->span_scale_u = pc_knot_uniform_scale(s->knots_u, s->n_u, s->deg_u);
    s->span_scale_v = pc_knot_uniform_scale(s->knots_v, s->n_v, s->deg_v);
}

void pc_nurbs_surface_eval(const pc_nurbs_surface *s, double u, double v, int n_deriv,
                           size_t *hint_u, size_t *hint_v, pc_vec3 *out)
{
    u = clamp_to(u, s->domain[0], s->domain[1]);
    v = clamp_to(v, s->domain[2], s->domain[3]);
    n_deriv = n_deriv < 0 ? 0 : (n_deriv > 2 ? 2 : n_deriv);
    const int p = s->deg_u, q = s->deg_v;
    const size_t span_u = pc_knot_span_scaled(s->knots_u, s->n_u, p, u, hint_u ? *hint_u : 0,
                                              s->span_scale_u);
    const size_t span_v = pc_knot_span_scaled(s->knots_v, s->n_v, q, v, hint_v ? *hint_v : 0,
                                              s->span_scale_v);
    if (hint_u != NULL)
        *hint_u = span_u;
    if (hint_v != NULL)
        *hint_v = span_v;
    const pc_surface_span_fn fn = s->span_eval[n_deriv];
    if (fn != NULL)
        fn(s, u, v, span_u, span_v, out);
    else if (p <= PC_SMALL_DEGREE && q <= PC_SMALL_DEGREE)
        eval_small_any(s, u, v, span_u, span_v, n_deriv, out);
    else
        pc_surface_eval_large(s, u, v, span_u, span_v, n_deriv, out);
}
