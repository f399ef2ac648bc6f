/* SPDX-License-Identifier: BSD-3-Clause */
#include "brep/curve2.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "common/array.h"
#include "common/error.h"

projcurve_status pc_curve2_init(projcurve_context *ctx, pc_curve2 *c, int degree, size_t n_ctrl,
                                const double *ctrl, const double *weights, const double *knots,
                                const char *what)
{
    memset(c, 0, sizeof *c);
    if (ctrl == NULL || knots == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NULL_ARGUMENT, "%s: %s is NULL", what,
                       ctrl == NULL ? "ctrl" : "knots");
    if (degree < 1 || degree > PROJCURVE_MAX_DEGREE)
        return pc_fail(ctx, PROJCURVE_ERR_BAD_DEGREE, "%s: degree %d is outside [1, %d]", what,
                       degree, PROJCURVE_MAX_DEGREE);
    if (n_ctrl <= (size_t)degree || n_ctrl > PC_CURVE2_MAX_POINTS)
        return pc_fail(ctx, PROJCURVE_ERR_BAD_COUNT,
                       "%s: %zu control points for degree %d (need %d to %zu)", what, n_ctrl,
                       degree, degree + 1, PC_CURVE2_MAX_POINTS);
    const size_t n_knots = n_ctrl + (size_t)degree + 1;
    for (size_t i = 0; i < n_knots; ++i) {
        if (!isfinite(knots[i]))
            return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "%s: knot %zu is not finite", what, i);
        if (i > 0 && knots[i] < knots[i - 1])
            return pc_fail(ctx, PROJCURVE_ERR_BAD_KNOTS, "%s: knot vector decreases at index %zu",
                           what, i);
    }
    if (!(knots[n_ctrl] > knots[degree]))
        return pc_fail(ctx, PROJCURVE_ERR_BAD_KNOTS, "%s: the domain [%g, %g] is empty", what,
                       knots[degree], knots[n_ctrl]);
    for (size_t i = 0; i < 2 * n_ctrl; ++i)
        if (!isfinite(ctrl[i]))
            return pc_fail(ctx, PROJCURVE_ERR_NOT_FINITE, "%s: control point %zu is not finite",
                           what, i / 2);
    for (size_t i = 0; weights != NULL && i < n_ctrl; ++i)
        if (!(weights[i] > 0.0) || !isfinite(weights[i]))
            return pc_fail(ctx, PROJCURVE_ERR_BAD_WEIGHT, "%s: weight %zu is %g (must be > 0)",
                           what, i, weights[i]);
    c->ctrl = malloc(2 * n_ctrl * sizeof *c->ctrl);
    c->knots = malloc(n_knots * sizeof *c->knots);
    c->weights = weights ? malloc(n_ctrl * sizeof *c->weights) : NULL;
    if (c->ctrl == NULL || c->knots == NULL || (weights && c->weights == NULL)) {
        pc_curve2_free(c);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "%s: out of memory", what);
    }
    memcpy(c->ctrl, ctrl, 2 * n_ctrl * sizeof *c->ctrl);
    memcpy(c->knots, knots, n_knots * sizeof *c->knots);
    if (weights)
        memcpy(c->weights, weights, n_ctrl * sizeof *c->weights);
    c->degree = degree;
    c->n_ctrl = n_ctrl;
    return PROJCURVE_OK;
}

void pc_curve2_free(pc_curve2 *c)
{
    free(c->ctrl);
    free(c->knots);
    free(c->weights);
    memset(c, 0, sizeof *c);
}

void pc_curve2_domain(const pc_curve2 *c, double *t0, double *t1)
{
    *t0 = c->knots[c->degree];
    *t1 = c->knots[c->n_ctrl];
}

/* The span k in [p, n - 1] with U[k] <= t, U[k] < U[k + 1], largest such. */
static size_t find_span(const double *u, size_t p, size_t n, double t)
{
    size_t k = p;
    for (size_t i = p; i < n; ++i)
        if (u[i] < u[i + 1] && u[i] <= t)
            k = i;
    return k;
}

void pc_curve2_eval(const pc_curve2 *c, double t, double out[2])
{
    const size_t p = (size_t)c->degree;
    double t0, t1;
    pc_curve2_domain(c, &t0, &t1);
    t = fmin(fmax(t, t0), t1);
    const size_t k = find_span(c->knots, p, c->n_ctrl, t);
    double h[3 * (PROJCURVE_MAX_DEGREE + 1)];
    for (size_t j = 0; j <= p; ++j) {
        const size_t i = k - p + j;
        const double w = c->weights ? c->weights[i] : 1.0;
        h[3 * j] = w * c->ctrl[2 * i];
        h[3 * j + 1] = w * c->ctrl[2 * i + 1];
        h[3 * j + 2] = w;
    }
    /* de Boor, homogeneous */
    for (size_t r = 1; r <= p; ++r)
        for (size_t j = p; j >= r; --j) {
            const size_t i = k - p + j;
            const double den = c->knots[i + p - r + 1] - c->knots[i];
            const double a = den > 0.0 ? (t - c->knots[i]) / den : 0.0;
            for (int d = 0; d < 3; ++d)
                h[3 * j + d] = (1.0 - a) * h[3 * (j - 1) + d] + a * h[3 * j + d];
        }
    out[0] = h[3 * p] / h[3 * p + 2];
    out[1] = h[3 * p + 1] / h[3 * p + 2];
}

projcurve_status pc_polyline2_push(projcurve_context *ctx, pc_polyline2 *line, double x, double y)
{
    void *xy = line->xy;
    const projcurve_status st =
        pc_array_reserve(ctx, &xy, &line->capacity, line->count, line->count + 1,
                         2 * sizeof *line->xy, 64, NULL, "flattened loop points");
    line->xy = xy;
    if (st != PROJCURVE_OK)
        return st;
    line->xy[2 * line->count] = x;
    line->xy[2 * line->count + 1] = y;
    ++line->count;
    return PROJCURVE_OK;
}

void pc_polyline2_free(pc_polyline2 *line)
{
    free(line->xy);
    memset(line, 0, sizeof *line);
}

/* The homogeneous B-spline (3 doubles a point) being cut into Bezier
 * segments by knot insertion. */
typedef struct hspline {
    size_t p, n;
    double *h, *u;
    size_t cap_h, cap_u; /* points of h, knots of u */
} hspline;

/* Room in s for one more point and its knot. Statuses: OK, NO_MEMORY. */
static projcurve_status reserve_knot(projcurve_context *ctx, hspline *s)
{
    void *h = s->h, *u = s->u;
    projcurve_status st = pc_array_reserve(ctx, &h, &s->cap_h, s->n, s->n + 1,
                                           3 * sizeof *s->h, 8, NULL, "knot-inserted points");
    s->h = h;
    if (st == PROJCURVE_OK)
        st = pc_array_reserve(ctx, &u, &s->cap_u, s->n + s->p + 1, s->n + s->p + 2,
                              sizeof *s->u, 8, NULL, "knot-inserted knots");
    s->u = u;
    return st;
}

/* Boehm's insertion of t (inside the domain) once. Statuses: OK, NO_MEMORY. */
static projcurve_status insert_knot(projcurve_context *ctx, hspline *s, double t)
{
    const projcurve_status st = reserve_knot(ctx, s);
    if (st != PROJCURVE_OK)
        return st;
    const size_t p = s->p, k = find_span(s->u, p, s->n, t);
    for (size_t i = s->n; i > k; --i) /* Q[i] = P[i-1] for i >= k + 1 */
        memcpy(s->h + 3 * i, s->h + 3 * (i - 1), 3 * sizeof *s->h);
    for (size_t i = k; i >= k - p + 1; --i) {
        const double a = (t - s->u[i]) / (s->u[i + p] - s->u[i]);
        for (int d = 0; d < 3; ++d)
            s->h[3 * i + d] = (1.0 - a) * s->h[3 * (i - 1) + d] + a * s->h[3 * i + d];
        if (i == 0)
            break;
    }
    memmove(s->u + k + 2, s->u + k + 1, (s->n + p - k) * sizeof *s->u);
    s->u[k + 1] = t;
    ++s->n;
    return PROJCURVE_OK;
}

static size_t multiplicity(const hspline *s, double t)
{
    size_t m = 0;
    for (size_t i = 0; i < s->n + s->p + 1; ++i)
        m += s->u[i] == t;
    return m;
}

static double point_segment_distance2(const double p[2], const double a[2], const double b[2])
{
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double len2 = dx * dx + dy * dy;
    double s = len2 > 0.0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2 : 0.0;
    s = s < 0.0 ? 0.0 : (s > 1.0 ? 1.0 : s);
    const double ex = p[0] - a[0] - s * dx, ey = p[1] - a[1] - s * dy;
    return ex * ex + ey * ey;
}

typedef struct flattener {
    projcurve_context *ctx;
    pc_polyline2 *line;
    double err;
    size_t p;
    const char *what;
    size_t limit;
} flattener;

/* Emits the start of the Bezier segment b (homogeneous) and its inner
 * vertices; halves it until its control polygon is within err of its chord. */
static projcurve_status flatten_bezier(flattener *fl, const double *b, int depth)
{
    const size_t p = fl->p;
    const double a[2] = {b[0] / b[2], b[1] / b[2]};
    const double z[2] = {b[3 * p] / b[3 * p + 2], b[3 * p + 1] / b[3 * p + 2]};
    int flat = 1;
    for (size_t j = 1; j < p && flat; ++j) {
        const double q[2] = {b[3 * j] / b[3 * j + 2], b[3 * j + 1] / b[3 * j + 2]};
        flat = point_segment_distance2(q, a, z) <= fl->err * fl->err;
    }
    if (flat)
        return fl->line->count >= fl->limit
                   ? pc_fail(fl->ctx, PROJCURVE_ERR_LIMIT_REACHED,
                             "%s: more than %zu points to flatten it within %g", fl->what,
                             PC_CURVE2_MAX_POINTS, fl->err)
                   : pc_polyline2_push(fl->ctx, fl->line, a[0], a[1]);
    if (depth >= PC_CURVE2_MAX_DEPTH)
        return pc_fail(fl->ctx, PROJCURVE_ERR_LIMIT_REACHED,
                       "%s: a segment is not within %g of its chord after %d halvings", fl->what,
                       fl->err, PC_CURVE2_MAX_DEPTH);
    double left[3 * (PROJCURVE_MAX_DEGREE + 1)], right[3 * (PROJCURVE_MAX_DEGREE + 1)];
    double work[3 * (PROJCURVE_MAX_DEGREE + 1)];
    memcpy(work, b, 3 * (p + 1) * sizeof *work);
    for (size_t r = 0; r <= p; ++r) { /* de Casteljau at 1/2 */
        memcpy(left + 3 * r, work, 3 * sizeof *work);
        memcpy(right + 3 * (p - r), work + 3 * (p - r), 3 * sizeof *work);
        for (size_t j = 0; j + r < p; ++j)
            for (int d = 0; d < 3; ++d)
                work[3 * j + d] = 0.5 * (work[3 * j + d] + work[3 * (j + 1) + d]);
    }
    projcurve_status st = flatten_bezier(fl, left, depth + 1);
    return st != PROJCURVE_OK ? st : flatten_bezier(fl, right, depth + 1);
}

projcurve_status pc_curve2_flatten(projcurve_context *ctx, const pc_curve2 *c, double err,
                                   pc_polyline2 *line, const char *what)
{
    const size_t p = (size_t)c->degree, n = c->n_ctrl;
    hspline s = {.p = p, .n = n, .cap_h = n, .cap_u = n + p + 1};
    s.h = malloc(3 * n * sizeof *s.h);
    s.u = malloc((n + p + 1) * sizeof *s.u);
    projcurve_status st = PROJCURVE_OK;
    if (s.h == NULL || s.u == NULL)
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "%s: out of memory", what);
    for (size_t i = 0; st == PROJCURVE_OK && i < n; ++i) {
        const double w = c->weights ? c->weights[i] : 1.0;
        s.h[3 * i] = w * c->ctrl[2 * i];
        s.h[3 * i + 1] = w * c->ctrl[2 * i + 1];
        s.h[3 * i + 2] = w;
    }
    if (st == PROJCURVE_OK)
        memcpy(s.u, c->knots, (n + p + 1) * sizeof *s.u);
    double t0, t1;
    pc_curve2_domain(c, &t0, &t1);
    /* Every distinct knot of the domain to multiplicity p: the segments are
     * then consecutive groups of p + 1 points. */
    for (size_t i = p; st == PROJCURVE_OK && i <= s.n; ++i) {
        const double t = s.u[i];
        if (t < t0 || t > t1 || (i > p && t == s.u[i - 1]))
            continue;
        while (st == PROJCURVE_OK && multiplicity(&s, t) < p)
            st = insert_knot(ctx, &s, t);
    }
    flattener fl = {.ctx = ctx, .line = line, .err = err, .p = p, .what = what,
                    .limit = line->count + PC_CURVE2_MAX_POINTS};
    for (size_t k = p; st == PROJCURVE_OK && k < s.n; ++k)
        if (s.u[k] < s.u[k + 1] && s.u[k] >= t0 && s.u[k + 1] <= t1)
            st = flatten_bezier(&fl, s.h + 3 * (k - p), 0);
    free(s.h);
    free(s.u);
    return st;
}
