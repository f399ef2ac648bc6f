/*
 * Surface point and partial derivatives up to order 2: the hot path of
 * tracing. Basis functions and their derivatives in u and v, then a tensor
 * contraction row by row; rational surfaces are evaluated in homogeneous
 * coordinates and divided with the quotient rule.
 *
 * Speed: the work is a few dozen multiply-adds, so loop overhead and
 * divisions would dominate a generic loop. The evaluator is therefore
 * written once as an always-inlined function of (p, q, n_deriv, rational)
 * and instantiated with constants for the common cases (bicubic and
 * biquadratic, polynomial and rational, second derivatives), where the
 * compiler unrolls it completely; other degrees use the generic instance.
 * No allocation, fixed-size stack tables.
 */
#include "nurbs/basis_impl.h"
#include "nurbs/nurbs.h"

/* Homogeneous derivatives A_{kl} = d^{k+l} (w S) / du^k dv^l, 4 doubles each,
 * in the output order S, Su, Sv, Suu, Suv, Svv. */
enum { D00, D10, D01, D20, D11, D02, D_COUNT };

static double clamp_to(double x, double lo, double hi)
{
    if (!(x >= lo))
        return lo; /* also maps NaN to lo: callers validate, the hot path never traps */
    return x > hi ? hi : x;
}

/* Contracts the (p+1) x (q+1) homogeneous net block at `net` (row stride
 * `stride` doubles) with the basis derivatives. Only the first `dims`
 * coordinates are summed (3 for polynomial surfaces: w is 1). */
static PC_ALWAYS_INLINE void contract(const double *net, size_t stride, int p, int q,
                                      int n_deriv, int dims, const pc_basis *basis_u,
                                      const pc_basis *basis_v, double a[D_COUNT][4])
{
    const double(*bu)[PC_MAX_ORDER] = basis_u->d;
    const double(*bv)[PC_MAX_ORDER] = basis_v->d;
    for (int d = 0; d < D_COUNT; ++d)
        a[d][0] = a[d][1] = a[d][2] = a[d][3] = 0.0;
    PC_UNROLL
    for (int j = 0; j <= q; ++j) {
        const double *row = net + (size_t)j * stride;
        double r0[4] = {0, 0, 0, 0}, r1[4] = {0, 0, 0, 0}, r2[4] = {0, 0, 0, 0};
        PC_UNROLL
        for (int i = 0; i <= p; ++i) {
            const double *pt = row + 4 * i;
            for (int m = 0; m < dims; ++m) {
                r0[m] += bu[0][i] * pt[m];
                if (n_deriv >= 1)
                    r1[m] += bu[1][i] * pt[m];
                if (n_deriv >= 2)
                    r2[m] += bu[2][i] * pt[m];
            }
        }
        for (int m = 0; m < dims; ++m) {
            a[D00][m] += bv[0][j] * r0[m];
            if (n_deriv >= 1) {
                a[D10][m] += bv[0][j] * r1[m];
                a[D01][m] += bv[1][j] * r0[m];
            }
            if (n_deriv >= 2) {
                a[D20][m] += bv[0][j] * r2[m];
                a[D11][m] += bv[1][j] * r1[m];
                a[D02][m] += bv[2][j] * r0[m];
            }
        }
    }
}

static pc_vec3 xyz(const double h[4]) { return vec3(h[0], h[1], h[2]); }

/* Quotient rule for S = A / w (The NURBS Book, eq. 4.20). */
static PC_ALWAYS_INLINE void divide_by_weight(double a[D_COUNT][4], int n_deriv, pc_vec3 *out)
{
    const double inv_w = 1.0 / a[D00][3];
    const pc_vec3 s = vec3_scale(xyz(a[D00]), inv_w);
    out[0] = s;
    if (n_deriv < 1)
        return;
    const double wu = a[D10][3], wv = a[D01][3];
    const pc_vec3 su = vec3_scale(vec3_axpy(xyz(a[D10]), -wu, s), inv_w);
    const pc_vec3 sv = vec3_scale(vec3_axpy(xyz(a[D01]), -wv, s), inv_w);
    out[1] = su;
    out[2] = sv;
    if (n_deriv < 2)
        return;
    const pc_vec3 suu = vec3_axpy(vec3_axpy(xyz(a[D20]), -2.0 * wu, su), -a[D20][3], s);
    const pc_vec3 suv =
        vec3_axpy(vec3_axpy(vec3_axpy(xyz(a[D11]), -wu, sv), -wv, su), -a[D11][3], s);
    const pc_vec3 svv = vec3_axpy(vec3_axpy(xyz(a[D02]), -2.0 * wv, sv), -a[D02][3], s);
    out[3] = vec3_scale(suu, inv_w);
    out[4] = vec3_scale(suv, inv_w);
    out[5] = vec3_scale(svv, inv_w);
}

static PC_ALWAYS_INLINE void block_eval(const double *net, size_t stride, int p, int q,
                                        int n_deriv, const pc_basis *bu, const pc_basis *bv,
                                        int rational, pc_vec3 *out)
{
    double a[D_COUNT][4];
    contract(net, stride, p, q, n_deriv, 4, bu, bv, a);
    if (rational) {
        divide_by_weight(a, n_deriv, out);
        return;
    }
    const int count = n_deriv == 0 ? 1 : (n_deriv == 1 ? 3 : 6);
    for (int d = 0; d < count; ++d)
        out[d] = xyz(a[d]);
}

void pc_surface_block_eval(const double *net, size_t stride, int p, int q, int n_deriv,
                           const pc_basis *bu, const pc_basis *bv, int rational, pc_vec3 *out)
{
    block_eval(net, stride, p, q, n_deriv, bu, bv, rational, out);
}

/* One instance of the evaluator: spans known, (u, v) inside the domain. */
static PC_ALWAYS_INLINE void eval_at_span(const pc_nurbs_surface *s, double u, double v,
                                          size_t span_u, size_t span_v, int p, int q,
                                          int n_deriv, int rational, pc_vec3 *out)
{
    pc_basis bu, bv;
    const double *inv_u =
        s->inv_u != NULL ? s->inv_u + (span_u - (size_t)p) * pc_knot_inverse_count(p) : NULL;
    const double *inv_v =
        s->inv_v != NULL ? s->inv_v + (span_v - (size_t)q) * pc_knot_inverse_count(q) : NULL;
    pc_basis_ders_inline(s->knots_u, span_u, p, u, n_deriv, &bu, inv_u);
    pc_basis_ders_inline(s->knots_v, span_v, q, v, n_deriv, &bv, inv_v);
    const size_t first = (span_v - (size_t)q) * s->n_u + (span_u - (size_t)p);
    block_eval(s->cw + 4 * first, 4 * s->n_u, p, q, n_deriv, &bu, &bv, rational, out);
}

static void eval_generic(const pc_nurbs_surface *s, double u, double v, size_t su, size_t sv,
                         int n_deriv, pc_vec3 *out)
{
    eval_at_span(s, u, v, su, sv, s->deg_u, s->deg_v, n_deriv, s->rational, out);
}

/* Constant-degree instances with second derivatives (what tracing asks). */
#define PC_EVAL_INSTANCE(name, P, Q, RATIONAL)                                                \
    static void name(const pc_nurbs_surface *s, double u, double v, size_t su, size_t sv,     \
                     pc_vec3 *out)                                                            \
    {                                                                                         \
        eval_at_span(s, u, v, su, sv, P, Q, 2, RATIONAL, out);                                \
    }
PC_EVAL_INSTANCE(eval_33_poly, 3, 3, 0)
PC_EVAL_INSTANCE(eval_33_rational, 3, 3, 1)
PC_EVAL_INSTANCE(eval_22_poly, 2, 2, 0)
PC_EVAL_INSTANCE(eval_22_rational, 2, 2, 1)

void pc_nurbs_surface_eval(const pc_nurbs_surface *s, double u, double v, int n_deriv,
                           size_t *hint_u, size_t *hint_v, pc_vec3 *out)
{
    u = clamp_to(u, s->domain[0], s->domain[1]);
    v = clamp_to(v, s->domain[2], s->domain[3]);
    n_deriv = n_deriv < 0 ? 0 : (n_deriv > 2 ? 2 : n_deriv);
    const int p = s->deg_u, q = s->deg_v;
    const size_t span_u = pc_knot_span(s->knots_u, s->n_u, p, u, hint_u ? *hint_u : 0);
    const size_t span_v = pc_knot_span(s->knots_v, s->n_v, q, v, hint_v ? *hint_v : 0);
    if (hint_u != NULL)
        *hint_u = span_u;
    if (hint_v != NULL)
        *hint_v = span_v;
    if (n_deriv == 2 && p == q && (p == 3 || p == 2)) {
        if (p == 3)
            (s->rational ? eval_33_rational : eval_33_poly)(s, u, v, span_u, span_v, out);
        else
            (s->rational ? eval_22_rational : eval_22_poly)(s, u, v, span_u, span_v, out);
        return;
    }
    eval_generic(s, u, v, span_u, span_v, n_deriv, out);
}
