#include "closest_oracle.h"

#include <math.h>
#include <stdlib.h>

static double surface_d2(const projcurve_surface *s, double u, double v, const double *p)
{
    double q[3];
    projcurve_surface_eval(NULL, s, u, v, 0, q);
    return (q[0] - p[0]) * (q[0] - p[0]) + (q[1] - p[1]) * (q[1] - p[1]) +
           (q[2] - p[2]) * (q[2] - p[2]);
}

/* Pattern search from uv with initial steps hu, hv, halved whenever no
 * stencil point is nearer, until they reach 1e-15 of the domain (the
 * distance is then flat to rounding); returns the squared distance. */
static double pattern_polish(const projcurve_surface *s, const double *p, const double dom[4],
                             double hu, double hv, double uv[2])
{
    const double stop_u = 1e-15 * (dom[1] - dom[0]), stop_v = 1e-15 * (dom[3] - dom[2]);
    double best = surface_d2(s, uv[0], uv[1], p);
    for (int it = 0; it < 600 && (hu > stop_u || hv > stop_v); ++it) {
        int moved = 0;
        for (int a = -1; a <= 1; ++a)
            for (int b = -1; b <= 1; ++b) {
                const double u = fmin(fmax(uv[0] + a * hu, dom[0]), dom[1]);
                const double v = fmin(fmax(uv[1] + b * hv, dom[2]), dom[3]);
                const double d2 = surface_d2(s, u, v, p);
                if (d2 < best) {
                    best = d2;
                    uv[0] = u;
                    uv[1] = v;
                    moved = 1;
                }
            }
        if (!moved) {
            hu *= 0.5;
            hv *= 0.5;
        }
    }
    return best;
}

double pc_oracle_surface_closest(const projcurve_surface *s, const double p[3], int n,
                                 double uv[2])
{
    if (n > PC_ORACLE_MAX_GRID)
        n = PC_ORACLE_MAX_GRID;
    double dom[4];
    projcurve_surface_domain(NULL, s, dom);
    const size_t side = (size_t)n + 1;
    double *d2 = malloc(side * side * sizeof(double));
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j)
            d2[(size_t)i * side + (size_t)j] = surface_d2(
                s, dom[0] + (dom[1] - dom[0]) * i / n, dom[2] + (dom[3] - dom[2]) * j / n, p);
    const double hu = (dom[1] - dom[0]) / n, hv = (dom[3] - dom[2]) / n;
    double best = INFINITY;
    for (int i = 0; i <= n; ++i)
        for (int j = 0; j <= n; ++j) {
            const double here = d2[(size_t)i * side + (size_t)j];
            int is_min = 1;
            for (int a = -1; a <= 1 && is_min; ++a)
                for (int b = -1; b <= 1; ++b)
                    if (i + a >= 0 && i + a <= n && j + b >= 0 && j + b <= n &&
                        d2[(size_t)(i + a) * side + (size_t)(j + b)] < here) {
                        is_min = 0;
                        break;
                    }
            if (!is_min)
                continue;
            double at[2] = {dom[0] + (dom[1] - dom[0]) * i / n, dom[2] + (dom[3] - dom[2]) * j / n};
            const double e = pattern_polish(s, p, dom, hu, hv, at);
            if (e < best) {
                best = e;
                uv[0] = at[0];
                uv[1] = at[1];
            }
        }
    free(d2);
    return sqrt(best);
}
