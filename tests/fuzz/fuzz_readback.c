/* SPDX-License-Identifier: BSD-3-Clause */
#include "fuzz_readback.h"

#include "fuzz_shapes.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

void fuzz_finding(const char *what, projcurve_context *ctx)
{
    fprintf(stderr, "fuzz finding: %s (%s)\n", what, projcurve_context_message(ctx));
    abort();
}

/* The stored data of a NURBS curve, malloc'd (NULL without memory). */
typedef struct curve_data {
    int degree;
    size_t n, n_knots;
    double *ctrl, *weights, *knots;
} curve_data;

static int read_curve(projcurve_context *ctx, const projcurve_curve *c, curve_data *d)
{
    memset(d, 0, sizeof *d);
    if (projcurve_curve_nurbs_info(ctx, c, &d->degree, &d->n, &d->n_knots, NULL) != PROJCURVE_OK)
        return 0;
    d->ctrl = malloc(3 * d->n * sizeof(double));
    d->weights = malloc(d->n * sizeof(double));
    d->knots = malloc(d->n_knots * sizeof(double));
    return d->ctrl && d->weights && d->knots &&
           projcurve_curve_nurbs_data(ctx, c, d->ctrl, d->weights, d->knots) == PROJCURVE_OK;
}

static void free_curve(curve_data *d)
{
    free(d->ctrl);
    free(d->weights);
    free(d->knots);
}

/* Weights that differ by a common factor give the same curve (the writer
 * writes equal weights as a polynomial curve). */
static int proportional(const double *a, const double *b, size_t n)
{
    for (size_t i = 0; i < n; ++i)
        if (fabs(a[i] * b[0] - b[i] * a[0]) > 4 * DBL_EPSILON * fabs(a[i] * b[0]))
            return 0;
    return 1;
}

void fuzz_compare_curves(projcurve_context *ctx, const projcurve_curve *a,
                           const projcurve_curve *b)
{
    curve_data x, y;
    if (read_curve(ctx, a, &x) && read_curve(ctx, b, &y)) {
        if (x.degree != y.degree || x.n != y.n || x.n_knots != y.n_knots ||
            memcmp(x.ctrl, y.ctrl, 3 * x.n * sizeof(double)) != 0 ||
            !proportional(x.weights, y.weights, x.n) ||
            memcmp(x.knots, y.knots, x.n_knots * sizeof(double)) != 0) {
            fprintf(stderr, "written: degree %d, %zu points, %zu knots; read: %d, %zu, %zu\n",
                    x.degree, x.n, x.n_knots, y.degree, y.n, y.n_knots);
            for (size_t i = 0; i < x.n_knots && i < y.n_knots; ++i)
                fprintf(stderr, "knot %zu: %.17g %.17g\n", i, x.knots[i], y.knots[i]);
            for (size_t i = 0; i < x.n && i < y.n; ++i)
                fprintf(stderr, "point %zu: %.17g %.17g %.17g w %.17g | %.17g %.17g %.17g w %.17g\n",
                        i, x.ctrl[3 * i], x.ctrl[3 * i + 1], x.ctrl[3 * i + 2], x.weights[i],
                        y.ctrl[3 * i], y.ctrl[3 * i + 1], y.ctrl[3 * i + 2], y.weights[i]);
            fuzz_finding("the curve read back differs from the curve written", ctx);
        }
    }
    free_curve(&x);
    free_curve(&y);
}

/* What bounds the rounding of a surface's evaluation: its NURBS data. */
typedef struct surface_net {
    int du, dv, rational;
    size_t nu, nv;
    double *ctrl, *w, *ku, *kv;
} surface_net;

static void free_net(surface_net *n)
{
    free(n->ctrl);
    free(n->w);
    free(n->ku);
    free(n->kv);
}

static void read_net(projcurve_context *ctx, const projcurve_surface *s, surface_net *n)
{
    size_t su, sv;
    memset(n, 0, sizeof *n);
    if (projcurve_surface_info(ctx, s, &n->du, &n->dv, &n->nu, &n->nv, &su, &sv, &n->rational) !=
        PROJCURVE_OK)
        fuzz_finding("surface_info failed", ctx);
    const size_t count = n->nu * n->nv;
    n->ctrl = malloc(3 * count * sizeof *n->ctrl);
    n->w = malloc(count * sizeof *n->w);
    n->ku = malloc((n->nu + (size_t)n->du + 1) * sizeof *n->ku);
    n->kv = malloc((n->nv + (size_t)n->dv + 1) * sizeof *n->kv);
    if (!n->ctrl || !n->w || !n->ku || !n->kv ||
        projcurve_surface_nurbs_data(ctx, s, n->ctrl, n->w, n->ku, n->kv) != PROJCURVE_OK)
        fuzz_finding("surface_nurbs_data failed", ctx);
}

/* max w / min w of a rational net (1 for a polynomial one): the rounding
 * of its evaluation with derivatives grows with it (up to its square in
 * the second derivatives, through w'' / w). */
static double weight_spread(const surface_net *n)
{
    if (!n->rational)
        return 1.0;
    double lo = INFINITY, hi = 0.0;
    for (size_t i = 0; i < n->nu * n->nv; ++i) {
        lo = fmin(lo, fabs(n->w[i]));
        hi = fmax(hi, fabs(n->w[i]));
    }
    return lo > 0.0 && hi >= lo ? hi / lo : 1.0;
}

static double largest_point(const surface_net *n)
{
    double m = 0.0;
    for (size_t i = 0; i < 3 * n->nu * n->nv; ++i)
        m = fmax(m, fabs(n->ctrl[i]));
    return m;
}

/* Width of the non-empty knot span that evaluates x (the last one at the
 * end of the domain). */
static double span_width(const double *k, size_t n_points, int degree, double x)
{
    double width = k[n_points] - k[degree];
    for (size_t j = (size_t)degree; j < n_points; ++j)
        if (k[j + 1] > k[j] && (x < k[j + 1] || j + 1 == n_points))
            return k[j + 1] - k[j];
    return width;
}

/* Surfaces are compared on a grid with derivatives. A non-rational surface
 * reads back bit for bit; a rational one may come back with its weights
 * scaled by a common factor (all equal: as a polynomial surface), the same
 * surface evaluated with other rounding. A derivative of order (a, b) is a
 * sum of control points times basis derivatives of size up to
 * (2 p / h_u)^a (2 q / h_v)^b, h the width of the knot span evaluated: its
 * rounding is relative to those terms, not to the result, which on a
 * narrow span or a nearly flat net is their small difference. 1e-12 of
 * the terms covers the division by w of a few of them, times the square
 * of the weights' spread (a net with weights far apart rounds its second
 * derivatives that much more). */
void fuzz_compare_surfaces(projcurve_context *ctx, const projcurve_surface *a,
                             const projcurve_surface *b)
{
    double da[4], db[4];
    if (projcurve_surface_domain(ctx, a, da) != PROJCURVE_OK ||
        projcurve_surface_domain(ctx, b, db) != PROJCURVE_OK)
        fuzz_finding("a surface domain cannot be read", ctx);
    if (memcmp(da, db, sizeof da) != 0)
        fuzz_finding("the surface read back has another domain", ctx);
    surface_net na, nb;
    read_net(ctx, a, &na);
    read_net(ctx, b, &nb);
    const int exact = !na.rational && !nb.rational;
    const double spread = fmax(weight_spread(&na), weight_spread(&nb));
    const double rel = 1e-12 * spread * spread, size = largest_point(&na);
    static const int order_u[6] = {0, 1, 0, 2, 1, 0}, order_v[6] = {0, 0, 1, 0, 1, 2};
    for (int i = 0; i <= 4; ++i)
        for (int j = 0; j <= 4; ++j) {
            const double u = da[0] + (da[1] - da[0]) * i / 4.0, v = da[2] + (da[3] - da[2]) * j / 4.0;
            const double gu = 2.0 * na.du / span_width(na.ku, na.nu, na.du, u);
            const double gv = 2.0 * na.dv / span_width(na.kv, na.nv, na.dv, v);
            double pa[18], pb[18];
            if (projcurve_surface_eval(ctx, a, u, v, 2, pa) != PROJCURVE_OK ||
                projcurve_surface_eval(ctx, b, u, v, 2, pb) != PROJCURVE_OK)
                fuzz_finding("a surface cannot be evaluated in its domain", ctx);
            for (int k = 0; k < 18; ++k) {
                const double terms = size * pow(gu, order_u[k / 3]) * pow(gv, order_v[k / 3]);
                if (exact ? pa[k] != pb[k] : !(fabs(pa[k] - pb[k]) <= rel * terms)) {
                    fprintf(stderr, "(%.17g, %.17g) value %d: %.17g written, %.17g read\n", u, v,
                            k, pa[k], pb[k]);
                    fuzz_finding("the surface read back evaluates differently", ctx);
                }
            }
        }
    free_net(&na);
    free_net(&nb);
}


int fuzz_written_make(const uint8_t *data, size_t size, fuzz_written *out)
{
    memset(out, 0, sizeof *out);
    if (projcurve_context_create(PROJCURVE_VERSION_MAJOR, &out->ctx) != PROJCURVE_OK)
        return 0;
    fuzz_bytes b = {data, size, 0};
    projcurve_options *o = NULL;
    double dir[3];
    if (fuzz_make_surface(out->ctx, &b, &out->s) != PROJCURVE_OK ||
        fuzz_make_curve(out->ctx, &b, &out->c) != PROJCURVE_OK)
        return 0;
    fuzz_make_direction(&b, dir);
    if (fuzz_make_options(out->ctx, &b, &o) != PROJCURVE_OK)
        return 0;
    if (fuzz_byte(&b) & 1)
        (void)projcurve_project_directional(out->ctx, out->s, out->c, dir, o, &out->r);
    projcurve_options_destroy(o);
    return 1;
}

void fuzz_written_free(fuzz_written *w)
{
    projcurve_result_destroy(w->r);
    projcurve_curve_destroy(w->c);
    projcurve_surface_destroy(w->s);
    projcurve_context_destroy(w->ctx);
}

void fuzz_read_back(const fuzz_written *w, const char *path)
{
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(w->ctx, path, &m) != PROJCURVE_OK)
        fuzz_finding("the written file does not read", w->ctx);
    if (projcurve_model_surface_count(m) < 1 || projcurve_model_curve_count(m) < 1)
        fuzz_finding("the file read back lacks the surface or the curve", w->ctx);
    fuzz_compare_surfaces(w->ctx, w->s, projcurve_model_surface(m, 0));
    fuzz_compare_curves(w->ctx, w->c, projcurve_model_curve(m, 0));
    projcurve_model_destroy(m);
    remove(path);
}
