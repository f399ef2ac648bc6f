/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The cubic refit of a sampled curve (fit/resampled.h) against curves
 * known in closed form:
 *   - a half circle (x, y) = (cos t, sin t) sampled at 257 points, tol
 *     1e-7: a fit of 67 poles, within tol of the circle at 20,001
 *     parameters (ten times denser than the points it was checked at), its
 *     end poles the end samples bit for bit;
 *   - a C1 curve whose second derivative jumps at t = 0.3 (y = 0, then
 *     (t - 0.3)^2): named as a break, each side is a polynomial of degree
 *     2 and the fit is exact with one span a side (7 poles, to 1e-11: the
 *     ridge of fit/lsq.h pulls at 1e-12); not named, it needs many more;
 *   - a kink (y = |t - 0.5|) with no break named: no fit within 1e-9 (the
 *     caller keeps its polyline);
 *   - a coordinate constant over the samples stays exactly constant;
 *   - more breaks than PC_FIT_RESAMPLED_MAX_BREAKS, too few samples: no fit.
 */
#include <math.h>
#include <stdlib.h>

#include "check.h"
#include "fit/resampled.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define N 256
#define DENSE 20000

typedef void (*curve_fn)(double t, double out[2]);

static void half_circle(double t, double out[2])
{
    out[0] = cos(t);
    out[1] = sin(t);
}

static void c1_at_03(double t, double out[2])
{
    out[0] = t;
    out[1] = t > 0.3 ? (t - 0.3) * (t - 0.3) : 0.0;
}

static void kink_at_05(double t, double out[2])
{
    out[0] = t;
    out[1] = fabs(t - 0.5);
}

static void on_seam(double t, double out[2])
{
    out[0] = t * t;
    out[1] = 6.283185307179586;
}

static void exact_of(const void *user, double t, double *out)
{
    const curve_fn *f = user;
    (*f)(t, out);
}

typedef struct fitted {
    double poles[2 * PC_FIT_RESAMPLED_POLES], knots[PC_FIT_RESAMPLED_POLES + 4];
    double samples[2 * (N + 1)];
    size_t n_poles;
} fitted;

static void fit(curve_fn f, double t0, double t1, const double *breaks, size_t n_breaks,
                double tol, size_t n, fitted *out)
{
    for (size_t i = 0; i <= n; ++i)
        f(i == n ? t1 : t0 + (t1 - t0) * (double)i / (double)n, out->samples + 2 * i);
    const pc_fit_resampled_input in = {.dim = 2, .samples = out->samples, .n = n, .t0 = t0,
                                       .t1 = t1, .breaks = breaks, .n_breaks = n_breaks,
                                       .exact = exact_of, .user = &f, .tol = tol};
    CHECK_OK(pc_fit_resampled_cubic(NULL, &in, out->poles, out->knots, &out->n_poles));
}

/* The clamped cubic of `fitted` at t (de Boor). */
static void eval(const fitted *c, double t, double out[2])
{
    size_t span = 3;
    while (span + 1 < c->n_poles && t >= c->knots[span + 1])
        ++span;
    double d[4][2];
    for (int j = 0; j < 4; ++j)
        for (int k = 0; k < 2; ++k)
            d[j][k] = c->poles[2 * (span - 3 + (size_t)j) + (size_t)k];
    for (int r = 1; r <= 3; ++r)
        for (int j = 3; j >= r; --j) {
            const size_t i = span - 3 + (size_t)j;
            const double den = c->knots[i + 4 - (size_t)r] - c->knots[i];
            const double a = den > 0.0 ? (t - c->knots[i]) / den : 0.0;
            for (int k = 0; k < 2; ++k)
                d[j][k] = (1.0 - a) * d[j - 1][k] + a * d[j][k];
        }
    out[0] = d[3][0];
    out[1] = d[3][1];
}

static double worst_error(const fitted *c, curve_fn f, double t0, double t1)
{
    double worst = 0.0;
    for (int i = 0; i <= DENSE; ++i) {
        const double t = t0 + (t1 - t0) * i / DENSE;
        double q[2], x[2];
        eval(c, t, q);
        f(t, x);
        worst = fmax(worst, hypot(q[0] - x[0], q[1] - x[1]));
    }
    return worst;
}

int main(void)
{
    static fitted c;
    /* the half circle */
    fit(half_circle, 0.0, M_PI, NULL, 0, 1e-7, N, &c);
    /* a cubic over h = pi / 32 is off by ~h^4 / 384 = 2e-7: 64 spans */
    CHECK(c.n_poles > 0 && c.n_poles <= 67);
    CHECK(worst_error(&c, half_circle, 0.0, M_PI) <= 1e-7);
    CHECK(c.poles[0] == c.samples[0] && c.poles[1] == c.samples[1]);
    CHECK(c.poles[2 * c.n_poles - 2] == c.samples[2 * N] &&
          c.poles[2 * c.n_poles - 1] == c.samples[2 * N + 1]);
    /* the C1 curve with and without its break */
    const double brk = 0.3;
    fit(c1_at_03, 0.0, 1.0, &brk, 1, 1e-9, N, &c);
    CHECK(c.n_poles == 7);
    CHECK(worst_error(&c, c1_at_03, 0.0, 1.0) <= 1e-11);
    fit(c1_at_03, 0.0, 1.0, NULL, 0, 1e-9, N, &c);
    CHECK(c.n_poles == 0 || c.n_poles > 30);
    /* the kink */
    fit(kink_at_05, 0.0, 1.0, NULL, 0, 1e-9, N, &c);
    CHECK(c.n_poles == 0);
    /* along a seam */
    fit(on_seam, 0.0, 1.0, NULL, 0, 1e-9, N, &c);
    CHECK(c.n_poles > 0);
    int off_seam = 0;
    for (size_t j = 0; j < c.n_poles; ++j)
        off_seam += c.poles[2 * j + 1] != 6.283185307179586;
    CHECK(off_seam == 0);
    /* no fit: too many breaks, too few samples */
    double many[PC_FIT_RESAMPLED_MAX_BREAKS + 1];
    for (size_t i = 0; i <= PC_FIT_RESAMPLED_MAX_BREAKS; ++i)
        many[i] = ((double)i + 1.0) / (PC_FIT_RESAMPLED_MAX_BREAKS + 2.0);
    fit(half_circle, 0.0, 1.0, many, PC_FIT_RESAMPLED_MAX_BREAKS + 1, 1e-3, N, &c);
    CHECK(c.n_poles == 0);
    fit(half_circle, 0.0, 1.0, NULL, 0, 1e-3, 3, &c);
    CHECK(c.n_poles == 0);
    return pc_test_finish("test_fit_resampled");
}
