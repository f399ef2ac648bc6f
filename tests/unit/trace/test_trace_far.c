/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Translation invariance of the directional projection (issue 14, defect 8).
 * The same bumpy bicubic sheet (150 units across, folded to a tilted Dir)
 * and curve, translated by 0, 1e3, 1e6 and 1e8 along (1, 1, 1): the
 * translated results must be the translated result. Before the Newton
 * tolerance was floored by the rounding of the coordinates, 1e6 gave
 * branches ending FAILED and holes in t, and 1e8 more branches.
 *
 * Checks, against the run at the origin:
 *   - the same number of branches, with the same t ranges (to 1e-6 of the
 *     curve's domain: the ranges end at folds and boundary exits located
 *     to ~1e-12, far finer);
 *   - every traced vertex, evaluated on the untranslated surface and curve
 *     (the same (u, v) and t), lies on the ray of P(t) within FAR_TOL and
 *     in front of it: an oracle independent of the translated run's own
 *     residual.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "trace_shapes.h"

#define NET 8
/* The translated run's corrector works to 16 ulps of the coordinates
 * (PC_ROUNDING_ULPS); evaluating its (u, v) on the translated surface and
 * subtracting the offset adds a few more. 64 ulps of |offset| plus 1e-11 of
 * the model size (the run at the origin) bounds both. */
#define FAR_ULPS 64.0

static projcurve_surface *bumpy_at(double offset)
{
    unsigned long long state = 12345;
    double ctrl[3 * NET * NET];
    for (int j = 0; j < NET; ++j)
        for (int i = 0; i < NET; ++i) {
            state = state * 6364136223846793005ULL + 1442695040888963407ULL;
            const double h = ((double)(state >> 11) / 9007199254740992.0 - 0.5) * 100.0;
            ctrl[3 * (j * NET + i) + 0] = offset + 100.0 * i / (NET - 1);
            ctrl[3 * (j * NET + i) + 1] = offset + 100.0 * j / (NET - 1);
            ctrl[3 * (j * NET + i) + 2] = offset + h;
        }
    const double k[12] = {0, 0, 0, 0, 0.2, 0.4, 0.6, 0.8, 1, 1, 1, 1};
    projcurve_surface *s = NULL;
    projcurve_surface_create_nurbs(NULL, 3, 3, NET, NET, ctrl, NULL, k, k, &s);
    return s;
}

static projcurve_curve *curve_at(double offset)
{
    const double base[15] = {5, 10, 30, 30, 80, 30, 50, 20, 30, 75, 85, 30, 95, 40, 30};
    double pts[15];
    for (int i = 0; i < 15; ++i)
        pts[i] = base[i] + offset;
    return shape_bspline_curve(3, 5, pts);
}

typedef struct run_result {
    size_t n;
    double (*range)[2];
} run_result;

static int by_range(const void *a, const void *b)
{
    const double *x = a, *y = b;
    if (x[0] != y[0])
        return x[0] < y[0] ? -1 : 1;
    return (x[1] > y[1]) - (x[1] < y[1]);
}

/* Projects the translated pair; checks its vertices on the untranslated
 * pair (s0, c0); returns the sorted t ranges. */
static run_result run(double offset, const projcurve_surface *s0, const projcurve_curve *c0,
                      const double dir[3], int compose, int pcurve_degree)
{
    run_result out = {0, NULL};
    projcurve_surface *s = bumpy_at(offset);
    projcurve_curve *c = curve_at(offset);
    projcurve_options *o = NULL;
    projcurve_options_create(NULL, &o);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, compose);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_PCURVE_DEGREE, pcurve_degree);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, dir, o, &r));
    out.n = projcurve_result_branch_count(r);
    out.range = calloc(out.n ? out.n : 1, sizeof *out.range);
    const double size = 150.0;
    const double tol = FAR_ULPS * 2.220446049250313e-16 * fabs(offset) + 1e-11 * size;
    const double dn = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    double worst = 0.0;
    size_t failed = 0, behind = 0;
    for (size_t b = 0; b < out.n; ++b) {
        size_t np = 0;
        projcurve_branch_end end;
        projcurve_result_branch_info(NULL, r, b, out.range[b], NULL, &end, &np, NULL);
        failed += end == PROJCURVE_END_FAILED;
        double *p = malloc(3 * np * sizeof *p);
        size_t got = 0;
        projcurve_result_branch_points(NULL, r, b, np, p, &got);
        for (size_t k = 0; k < got; ++k) {
            double q[3], x[3];
            projcurve_surface_eval(NULL, s0, p[3 * k + 1], p[3 * k + 2], 0, q);
            projcurve_curve_eval(NULL, c0, p[3 * k], 0, x);
            const double d[3] = {q[0] - x[0], q[1] - x[1], q[2] - x[2]};
            const double cr[3] = {d[1] * dir[2] - d[2] * dir[1], d[2] * dir[0] - d[0] * dir[2],
                                  d[0] * dir[1] - d[1] * dir[0]};
            worst = fmax(worst, sqrt(cr[0] * cr[0] + cr[1] * cr[1] + cr[2] * cr[2]) / dn);
            behind += (d[0] * dir[0] + d[1] * dir[1] + d[2] * dir[2]) / dn < -tol;
        }
        free(p);
    }
    printf("offset %g%s: %zu branches, %zu failed, worst distance to the ray %.3g (tol %.3g)\n",
           offset, !compose ? "" : pcurve_degree == 3 ? " (composed, cubic pcurves)" : " (composed)",
           out.n, failed, worst, tol);
    CHECK(failed == 0);
    CHECK(behind == 0);
    CHECK(worst <= tol);
    qsort(out.range, out.n, sizeof *out.range, by_range);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
    return out;
}

int main(void)
{
    const double dir[3] = {1.0, 0.4, -1.0};
    projcurve_surface *s0 = bumpy_at(0.0);
    projcurve_curve *c0 = curve_at(0.0);
    CHECK(s0 != NULL && c0 != NULL);
    /* traced only, composed, composed with cubic pcurves (beside the
     * sheet's folds at 1e8 the cubic march once handed the straight one
     * stretches whose last piece missed the angle bound: 181 FAILED ends) */
    for (int variant = 0; variant < 3; ++variant) {
        const int compose = variant > 0, degree = variant == 2 ? 3 : 1;
        const run_result base = run(0.0, s0, c0, dir, compose, degree);
        /* the sheet folds to this Dir and the curve passes through it:
         * several branches, some ending where the curve meets S */
        CHECK(base.n >= 3);
        const double offsets[3] = {1e3, 1e6, 1e8};
        for (int k = 0; k < 3; ++k) {
            const run_result far = run(offsets[k], s0, c0, dir, compose, degree);
            CHECK(far.n == base.n);
            for (size_t b = 0; b < base.n && far.n > 0; ++b) {
                /* the far branch with the nearest range (two may start
                 * together) */
                size_t best = 0;
                double gap = INFINITY;
                for (size_t i = 0; i < far.n; ++i) {
                    const double g = fabs(far.range[i][0] - base.range[b][0]) +
                                     fabs(far.range[i][1] - base.range[b][1]);
                    if (g < gap) {
                        gap = g;
                        best = i;
                    }
                }
                CHECK_NEAR(far.range[best][0], base.range[b][0], 1e-6);
                CHECK_NEAR(far.range[best][1], base.range[b][1], 1e-6);
            }
            free(far.range);
        }
        free(base.range);
    }
    projcurve_curve_destroy(c0);
    projcurve_surface_destroy(s0);
    return pc_test_finish("test_trace_far");
}
