/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The join reduction of a composed curve (exact/join_removal.c): a
 * random Bezier curve of degree 6 cut into three parts by knots of
 * multiplicity 6 (inserted here by Boehm's formula) is one polynomial,
 * so its joins may lose copies; the same with a kink at the second join
 * (its pole moved: C0 there) must keep that join whole; a join not marked
 * smooth is left alone. In every case the reduced curve must stay within
 * the bound of the original at dense samples (de Boor on the raw arrays,
 * tests/support/deboor.c).
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "deboor.h"
#include "exact/exact.h"

#define P 6
#define N_MAX (P + 1 + 2 * P)
#define SAMPLES 1000

typedef struct curve {
    size_t n;
    double knots[N_MAX + P + 1];
    double poles[3 * N_MAX];
} curve;

/* Inserts u once (Boehm; The NURBS Book eq. (5.15)). */
static void insert(curve *c, double u)
{
    size_t k = P;
    while (c->knots[k + 1] <= u)
        ++k;
    double q[3 * N_MAX];
    for (size_t i = 0; i <= c->n; ++i)
        for (size_t d = 0; d < 3; ++d) {
            double v;
            if (i + P <= k)
                v = c->poles[3 * i + d];
            else if (i > k)
                v = c->poles[3 * (i - 1) + d];
            else {
                const double a = (u - c->knots[i]) / (c->knots[i + P] - c->knots[i]);
                v = a * c->poles[3 * i + d] + (1.0 - a) * c->poles[3 * (i - 1) + d];
            }
            q[3 * i + d] = v;
        }
    memmove(c->knots + k + 2, c->knots + k + 1, (c->n + P - k) * sizeof *c->knots);
    c->knots[k + 1] = u;
    c->n += 1;
    memcpy(c->poles, q, 3 * c->n * sizeof *q);
}

static curve three_parts(unsigned long long seed)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, seed);
    curve c;
    c.n = P + 1;
    for (size_t i = 0; i < 2 * (P + 1); ++i)
        c.knots[i] = i <= P ? 0.0 : 1.0;
    for (size_t i = 0; i < 3 * c.n; ++i)
        c.poles[i] = pc_test_rng_uniform(&rng, -1.0, 1.0);
    for (int k = 0; k < P; ++k) {
        insert(&c, 0.3);
        insert(&c, 0.6);
    }
    return c;
}

static int multiplicity(const curve *c, double u)
{
    int m = 0;
    for (size_t i = 0; i < c->n + P + 1; ++i)
        m += c->knots[i] == u;
    return m;
}

static double distance(curve *a, curve *b)
{
    pc_shape_curve sa = {P, a->n, a->poles, NULL, a->knots};
    pc_shape_curve sb = {P, b->n, b->poles, NULL, b->knots};
    double worst = 0.0;
    for (int i = 0; i <= SAMPLES; ++i) {
        double x[3], y[3];
        const double t = (double)i / SAMPLES;
        pc_deboor_curve(&sa, t, x);
        pc_deboor_curve(&sb, t, y);
        worst = fmax(worst, sqrt((x[0] - y[0]) * (x[0] - y[0]) + (x[1] - y[1]) * (x[1] - y[1]) +
                                 (x[2] - y[2]) * (x[2] - y[2])));
    }
    return worst;
}

/* Reduces a copy of c with the given flags; returns the reduced curve. */
static curve reduce(const curve *c, unsigned char s0, unsigned char s1, double tol, size_t *removed)
{
    curve r = *c;
    pc_knot_curve v = {P, 3, r.n, r.knots, r.poles};
    unsigned char smooth[2] = {s0, s1};
    double scratch[2 * 3 + 1];
    *removed = pc_exact_reduce_joins(&v, smooth, 3, tol, scratch);
    CHECK(v.n_poles + *removed == c->n);
    r.n = v.n_poles;
    return r;
}

int main(void)
{
    const double tol = 256.0 * DBL_EPSILON; /* poles in [-1, 1] */
    for (unsigned long long seed = 1; seed <= 5; ++seed) {
        curve c = three_parts(seed);
        size_t removed = 0;
        /* one polynomial: every copy goes, the curve is its Bezier form
         * again (each residual a difference of rounded poles of O(1):
         * measured below 1.4e-15 in all, well within 256 ulps) */
        curve r = reduce(&c, 1, 1, tol, &removed);
        printf("seed %llu: %zu copies removed, curve moved by %.3g\n", seed, removed,
               distance(&c, &r));
        CHECK(removed == 2 * P);
        CHECK(distance(&c, &r) <= tol);
        /* a kink of 1e-3 at 0.6: that join is needed, whole */
        curve k = c;
        k.poles[3 * (2 * P) + 1] += 1e-3;
        r = reduce(&k, 1, 1, tol, &removed);
        CHECK(multiplicity(&r, 0.6) == P);
        CHECK(multiplicity(&r, 0.3) <= P - 3);
        CHECK(distance(&k, &r) <= tol);
        /* not marked smooth: left alone */
        r = reduce(&c, 0, 1, tol, &removed);
        CHECK(multiplicity(&r, 0.3) == P && multiplicity(&r, 0.6) <= P - 3);
        CHECK(distance(&c, &r) <= tol);
        /* no bound: nothing removed */
        r = reduce(&c, 1, 1, 0.0, &removed);
        CHECK(removed == 0);
    }
    return pc_test_finish("test_exact_join_removal");
}
