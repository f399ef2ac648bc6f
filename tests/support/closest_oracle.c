/* SPDX-License-Identifier: BSD-3-Clause */
#include "closest_oracle.h"

#include <math.h>
#include <stdlib.h>

#include "geom/curve.h"
#include "geom/surface.h"

static double surface_d2(const projcurve_surface *s, double u, double v, const double *p)
{
    double q[3];
    projcurve_surface_eval(NULL, s, u, v, 0, q);
    return (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) +
           (q[2] - p[2]) * (q[2] - p[2]);
}

/* Pattern search from uv with initial steps hu, hv: a stencil step that
 * gets nearer is taken and the steps grow by half (so that a long curved
 * valley is followed in few iterations), otherwise they are halved, until
 * they reach 1e-15 of the domain (the distance is then flat to rounding)
 * or 5000 iterations; returns the squared distance. */
static double pattern_polish(const projcurve_surface *s, const double *p, const double dom[4],
                             double hu, double hv, double uv[2])
{
    const double stop_u = 1e-15 * (dom[1] - dom[0]), stop_v = 1e-15 * (dom[3] - dom[2]);
    const double max_u = 0.25 * (dom[1] - dom[0]), max_v = 0.25 * (dom[3] - dom[2]);
    double best = surface_d2(s, uv[0], uv[1], p);
    for (int it = 0; it < 5000 && (hu > stop_u || hv > stop_v); ++it) {
        int moved = 0;
        double next[2] = {uv[0], uv[1]};
        for (int a = -1; a <= 1; ++a)
            for (int b = -1; b <= 1; ++b) {
                const double u = fmin(fmax(uv[0] + a * hu, dom[0]), dom[1]);
                const double v = fmin(fmax(uv[1] + b * hv, dom[2]), dom[3]);
                const double d2 = surface_d2(s, u, v, p);
                if (d2 < best) {
                    best = d2;
                    next[0] = u;
                    next[1] = v;
                    moved = 1;
                }
            }
        uv[0] = next[0];
        uv[1] = next[1];
        const double f = moved ? 1.5 : 0.5;
        hu = fmin(hu * f, max_u);
        hv = fmin(hv * f, max_v);
    }
    return best;
}

static int compare_doubles(const void *a, const void *b)
{
    const double x = *(const double *)a, y = *(const double *)b;
    return x < y ? -1 : x > y;
}

/* Sample parameters of one direction: n + 1 uniform values over [lo, hi],
 * and 8 per knot span (its start and eighth points) so that narrow spans
 * (short knot intervals of real data carry whole features) are sampled
 * too; sorted, duplicates removed. Returns the count; *out is malloc'd. */
static size_t sample_params(double lo, double hi, int n, const double *breaks, size_t spans,
                            double **out)
{
    double *t = malloc(((size_t)n + 1 + 8 * spans + 1) * sizeof(double));
    size_t count = 0;
    for (int i = 0; i <= n; ++i)
        t[count++] = lo + (hi - lo) * i / n;
    for (size_t k = 0; k < spans; ++k)
        for (int j = 0; j < 8; ++j)
            t[count++] = breaks[k] + (breaks[k + 1] - breaks[k]) * j / 8.0;
    qsort(t, count, sizeof(double), compare_doubles);
    size_t m = 0;
    for (size_t k = 0; k < count; ++k)
        if (m == 0 || t[k] > t[m - 1])
            t[m++] = t[k];
    *out = t;
    return m;
}

/* Larger gap to the neighbours of sample i: the pattern search's first
 * step from there. */
static double local_step(const double *t, size_t count, size_t i)
{
    const double left = i > 0 ? t[i] - t[i - 1] : 0.0;
    const double right = i + 1 < count ? t[i + 1] - t[i] : 0.0;
    return fmax(left, right);
}

double pc_oracle_surface_closest(const projcurve_surface *s, const double p[3], int n,
                                 double uv[2])
{
    if (n > PC_ORACLE_MAX_GRID)
        n = PC_ORACLE_MAX_GRID;
    double dom[4];
    projcurve_surface_domain(NULL, s, dom);
    double *tu, *tv;
    const size_t nu = sample_params(dom[0], dom[1], n, s->grid.breaks_u, s->grid.spans_u, &tu);
    const size_t nv = sample_params(dom[2], dom[3], n, s->grid.breaks_v, s->grid.spans_v, &tv);
    double *d2 = malloc(nu * nv * sizeof(double));
    for (size_t i = 0; i < nu; ++i)
        for (size_t j = 0; j < nv; ++j)
            d2[i * nv + j] = surface_d2(s, tu[i], tv[j], p);
    double best = INFINITY;
    for (size_t i = 0; i < nu; ++i)
        for (size_t j = 0; j < nv; ++j) {
            const double here = d2[i * nv + j];
            int is_min = 1;
            for (size_t a = i > 0 ? i - 1 : 0; a <= i + 1 && a < nu && is_min; ++a)
                for (size_t b = j > 0 ? j - 1 : 0; b <= j + 1 && b < nv; ++b)
                    if (d2[a * nv + b] < here) {
                        is_min = 0;
                        break;
                    }
            if (!is_min)
                continue;
            double at[2] = {tu[i], tv[j]};
            const double e = pattern_polish(s, p, dom, local_step(tu, nu, i), local_step(tv, nv, j), at);
            if (e < best) {
                best = e;
                uv[0] = at[0];
                uv[1] = at[1];
            }
        }
    free(d2);
    free(tu);
    free(tv);
    return sqrt(best);
}
