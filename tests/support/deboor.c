#include "deboor.h"

#include <stdlib.h>

#define DEBOOR_MAX_ORDER (PROJCURVE_MAX_DEGREE + 1)

/* Span k with knots[k] <= t < knots[k+1] within [p, n - 1], by a plain scan
 * (deliberately unlike the library's search); t = knots[n] uses the last
 * non-empty span. */
static size_t find_span(const double *knots, size_t n, int p, double t)
{
    size_t k = (size_t)p;
    for (size_t i = (size_t)p; i < n; ++i)
        if (knots[i] <= t && knots[i] < knots[i + 1])
            k = i;
    return k;
}

/* de Boor on homogeneous 4-vectors. */
static void deboor4(const double *knots, size_t n, int p, const double *hw, double t,
                    double out[4])
{
    const size_t k = find_span(knots, n, p, t);
    double d[DEBOOR_MAX_ORDER][4];
    for (size_t j = 0; j <= (size_t)p; ++j)
        for (int m = 0; m < 4; ++m)
            d[j][m] = hw[4 * (k - (size_t)p + j) + (size_t)m];
    for (size_t r = 1; r <= (size_t)p; ++r)
        for (size_t j = (size_t)p; j >= r; --j) {
            const size_t i = j + k - (size_t)p;
            const double alpha = (t - knots[i]) / (knots[i + (size_t)p + 1 - r] - knots[i]);
            for (int m = 0; m < 4; ++m)
                d[j][m] = (1.0 - alpha) * d[j - 1][m] + alpha * d[j][m];
        }
    for (int m = 0; m < 4; ++m)
        out[m] = d[p][m];
}

static void homogeneous(const double *ctrl, const double *weights, size_t i, double hw[4])
{
    const double w = weights != NULL ? weights[i] : 1.0;
    hw[0] = w * ctrl[3 * i];
    hw[1] = w * ctrl[3 * i + 1];
    hw[2] = w * ctrl[3 * i + 2];
    hw[3] = w;
}

void pc_deboor_curve(const pc_shape_curve *c, double t, double out[3])
{
    double *hw = malloc(4 * c->n_ctrl * sizeof(double));
    for (size_t i = 0; i < c->n_ctrl; ++i)
        homogeneous(c->ctrl, c->weights, i, hw + 4 * i);
    double r[4];
    deboor4(c->knots, c->n_ctrl, c->degree, hw, t, r);
    for (int m = 0; m < 3; ++m)
        out[m] = r[m] / r[3];
    free(hw);
}

void pc_deboor_surface(const pc_shape_surface *s, double u, double v, double out[3])
{
    double *row = malloc(4 * s->n_u * sizeof(double));
    double *col = malloc(4 * s->n_v * sizeof(double));
    for (size_t j = 0; j < s->n_v; ++j) {
        for (size_t i = 0; i < s->n_u; ++i)
            homogeneous(s->ctrl, s->weights, j * s->n_u + i, row + 4 * i);
        deboor4(s->knots_u, s->n_u, s->deg_u, row, u, col + 4 * j);
    }
    double r[4];
    deboor4(s->knots_v, s->n_v, s->deg_v, col, v, r);
    for (int m = 0; m < 3; ++m)
        out[m] = r[m] / r[3];
    free(row);
    free(col);
}
