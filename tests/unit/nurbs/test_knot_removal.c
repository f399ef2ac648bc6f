/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Knot removal (nurbs/knot_removal.c) against knot insertion written here
 * (Boehm's formula, independent of the library): random curves of degrees
 * 3 and 7 in 3D and 4D (homogeneous), knots inserted up to multiplicity
 * p, then removed one copy at a time; each removal must give back the
 * curve before the insertion, pole by pole, to REL of the poles' size,
 * with a residual at rounding. A knot the curve needs (a kink: C0 at a
 * knot of multiplicity p, or C^(p-s) with the jump of a derivative) must
 * leave a residual of the kink's size.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "nurbs/knot_removal.h"

#define MAX_POLES 64
#define MAX_DIM 4
#define MAX_DEG 7
/* Each removal divides by weights of the insertion in (0, 1); over p
 * steps from both ends the rounding grows by at most a few hundred ulps
 * of the poles' size (measured: below 1e-15 at degree 7). */
#define REL 1e-14

typedef struct curve {
    int p, dim;
    size_t n;
    double knots[MAX_POLES + MAX_DEG + 1];
    double poles[MAX_DIM * MAX_POLES];
} curve;

static pc_knot_curve view(curve *c)
{
    const pc_knot_curve v = {c->p, c->dim, c->n, c->knots, c->poles};
    return v;
}

/* Random poles in [-1, 1] (the last coordinate in [0.5, 2] for 4D, a
 * weight) over knots 0 .. spans, simple inside. */
static curve random_curve(pc_test_rng *rng, int p, int dim, size_t spans)
{
    curve c;
    c.p = p;
    c.dim = dim;
    c.n = spans + (size_t)p;
    for (size_t i = 0; i < c.n + (size_t)p + 1; ++i) {
        const double k = (double)i - (double)p;
        c.knots[i] = k < 0 ? 0 : (k > (double)spans ? (double)spans : k);
    }
    for (size_t i = 0; i < c.n; ++i)
        for (int k = 0; k < dim; ++k)
            c.poles[(size_t)dim * i + (size_t)k] =
                dim == 4 && k == 3 ? pc_test_rng_uniform(rng, 0.5, 2.0)
                                   : pc_test_rng_uniform(rng, -1.0, 1.0);
    return c;
}

/* Inserts u once (Boehm; The NURBS Book eq. (5.15)). */
static void insert(curve *c, double u)
{
    const size_t p = (size_t)c->p, dim = (size_t)c->dim;
    size_t k = p; /* span: U[k] <= u < U[k + 1] */
    while (c->knots[k + 1] <= u)
        ++k;
    double q[MAX_DIM * MAX_POLES];
    for (size_t i = 0; i <= c->n; ++i)
        for (size_t d = 0; d < dim; ++d) {
            double v;
            if (i + p <= k)
                v = c->poles[dim * i + d];
            else if (i > k)
                v = c->poles[dim * (i - 1) + d];
            else {
                const double a = (u - c->knots[i]) / (c->knots[i + p] - c->knots[i]);
                v = a * c->poles[dim * i + d] + (1.0 - a) * c->poles[dim * (i - 1) + d];
            }
            q[dim * i + d] = v;
        }
    memmove(c->knots + k + 2, c->knots + k + 1, (c->n + p - k) * sizeof *c->knots);
    c->knots[k + 1] = u;
    c->n += 1;
    memcpy(c->poles, q, dim * c->n * sizeof *q);
}

static size_t last_copy(const curve *c, double u)
{
    size_t r = 0;
    for (size_t i = 0; i < c->n + (size_t)c->p + 1; ++i)
        if (c->knots[i] == u)
            r = i;
    return r;
}

static double pole_distance(const curve *a, const curve *b)
{
    double worst = 0.0;
    for (size_t i = 0; i < (size_t)a->dim * a->n; ++i)
        worst = fmax(worst, fabs(a->poles[i] - b->poles[i]));
    return worst;
}

/* Insert u until its multiplicity is p, then remove the copies one by one:
 * every intermediate curve is the one before the matching insertion. */
static void test_insert_remove(unsigned long long seed, int p, int dim, double u)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, seed);
    curve c = random_curve(&rng, p, dim, 5);
    const int have = u == floor(u); /* a knot already (simple) */
    curve stages[MAX_DEG + 1];
    int n_ins = 0;
    stages[0] = c;
    while (have + n_ins < p) {
        insert(&c, u);
        stages[++n_ins] = c;
    }
    double fresh[MAX_DIM * MAX_DEG];
    for (int k = n_ins; k > 0; --k) {
        pc_knot_curve v = view(&c);
        const size_t r = last_copy(&c, u);
        const double res = pc_knot_removal_solve(&v, r, fresh);
        if (!(res <= REL))
            pc_test_fail_at(__FILE__, __LINE__,
                            "degree %d dim %d u %g: removal %d of %d: residual %.3g", p, dim, u,
                            n_ins - k + 1, n_ins, res);
        pc_knot_removal_apply(&v, r, fresh);
        c.n = v.n_poles;
        CHECK(c.n == stages[k - 1].n);
        const double d = pole_distance(&c, &stages[k - 1]);
        if (!(d <= REL))
            pc_test_fail_at(__FILE__, __LINE__,
                            "degree %d dim %d u %g: after removal %d poles off by %.3g", p, dim,
                            u, n_ins - k + 1, d);
        CHECK(memcmp(c.knots, stages[k - 1].knots, (c.n + (size_t)p + 1) * sizeof(double)) == 0);
    }
    /* the original simple knot of a random curve is needed: C^(p-1) only */
    if (have) {
        pc_knot_curve v = view(&c);
        const double res = pc_knot_removal_solve(&v, last_copy(&c, u), fresh);
        if (!(res > 1e-6))
            pc_test_fail_at(__FILE__, __LINE__, "degree %d dim %d: a needed knot %g: residual %.3g",
                            p, dim, u, res);
    }
}

/* A C0 kink: a knot of multiplicity p with the pole there moved off the
 * line of its neighbours by h; the residual is of the order of h, and
 * removal is refused by any bound below it. */
static void test_kink(int p, int dim)
{
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 99);
    curve c = random_curve(&rng, p, dim, 4);
    for (int k = 1; k < p; ++k)
        insert(&c, 2.0);
    const size_t r = last_copy(&c, 2.0);
    double fresh[MAX_DIM * MAX_DEG];
    pc_knot_curve v = view(&c);
    const double smooth = pc_knot_removal_solve(&v, r, fresh);
    CHECK(smooth <= REL); /* C^(p-1) by construction: one copy can go */
    const size_t joint = r - (size_t)p; /* the pole the curve passes through */
    c.poles[(size_t)dim * joint] += 1e-3;
    const double kinked = pc_knot_removal_solve(&v, r, fresh);
    if (!(kinked > 1e-4 && kinked < 1e-2))
        pc_test_fail_at(__FILE__, __LINE__, "degree %d dim %d kink 1e-3: residual %.3g", p, dim,
                        kinked);
    /* not a removable knot: not interior, or not the last copy */
    CHECK(isinf(pc_knot_removal_solve(&v, r - 1, fresh)));
    CHECK(isinf(pc_knot_removal_solve(&v, (size_t)p, fresh)));
    CHECK(isinf(pc_knot_removal_solve(&v, c.n, fresh)));
}

int main(void)
{
    const int degrees[2] = {3, 7}, dims[2] = {3, 4};
    unsigned long long seed = 1;
    for (int i = 0; i < 2; ++i)
        for (int j = 0; j < 2; ++j) {
            for (int t = 0; t < 5; ++t) {
                test_insert_remove(seed++, degrees[i], dims[j], 0.5 + 0.83 * t);
                test_insert_remove(seed++, degrees[i], dims[j], (double)(1 + t % 4));
            }
            test_kink(degrees[i], dims[j]);
        }
    return pc_test_finish("test_knot_removal");
}
