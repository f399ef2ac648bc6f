/* SPDX-License-Identifier: BSD-3-Clause */
#include "io/io_geom.h"

#include <math.h>
#include <string.h>

#include "common/error.h"

/* Splitting into Bezier segments inserts knots one by one (each insertion
 * moves the points after it): curves whose splitting would cost more point
 * moves than this are refused rather than joined slowly. */
#define PC_IO_MAX_JOIN_WORK 100000000.0

void pc_io_affine_identity(pc_io_affine *a)
{
    memset(a->m, 0, sizeof a->m);
    a->m[0] = a->m[5] = a->m[10] = 1.0;
}

pc_io_affine pc_io_affine_compose(const pc_io_affine *outer, const pc_io_affine *inner)
{
    pc_io_affine r;
    for (int i = 0; i < 3; ++i) {
        const double *o = outer->m + 4 * i;
        for (int j = 0; j < 4; ++j) {
            double s = (j == 3) ? o[3] : 0.0;
            for (int k = 0; k < 3; ++k)
                s += o[k] * inner->m[4 * k + j];
            r.m[4 * i + j] = s;
        }
    }
    return r;
}

void pc_io_affine_apply(const pc_io_affine *a, const double p[3], double out[3])
{
    double r[3];
    for (int i = 0; i < 3; ++i)
        r[i] = a->m[4 * i] * p[0] + a->m[4 * i + 1] * p[1] + a->m[4 * i + 2] * p[2] + a->m[4 * i + 3];
    memcpy(out, r, sizeof r);
}

void pc_io_affine_points(const pc_io_affine *a, double *ctrl, size_t n_points)
{
    for (size_t i = 0; i < n_points; ++i)
        pc_io_affine_apply(a, ctrl + 3 * i, ctrl + 3 * i);
}

void pc_io_curve_domain(const pc_io_curve *c, double *t0, double *t1)
{
    *t0 = c->knots[c->degree];
    *t1 = c->knots[c->n_ctrl];
}

static void *arena_doubles(pc_arena *arena, size_t n)
{
    return pc_arena_calloc(arena, n, sizeof(double));
}

static projcurve_status no_memory(projcurve_context *ctx)
{
    return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory while converting geometry");
}

projcurve_status pc_io_line_curve(projcurve_context *ctx, pc_arena *arena, const double p0[3],
                                  const double p1[3], pc_io_curve *out)
{
    double *ctrl = arena_doubles(arena, 6);
    double *knots = arena_doubles(arena, 4);
    if (ctrl == NULL || knots == NULL)
        return no_memory(ctx);
    memcpy(ctrl, p0, 3 * sizeof(double));
    memcpy(ctrl + 3, p1, 3 * sizeof(double));
    const double dx = p1[0] - p0[0], dy = p1[1] - p0[1], dz = p1[2] - p0[2];
    const double len = sqrt(dx * dx + dy * dy + dz * dz);
    knots[2] = knots[3] = (len > 0.0 && isfinite(len)) ? len : 1.0;
    *out = (pc_io_curve){.degree = 1, .n_ctrl = 2, .ctrl = ctrl, .weights = NULL, .knots = knots};
    return PROJCURVE_OK;
}

projcurve_status pc_io_arc_curve(projcurve_context *ctx, pc_arena *arena,
                                 const double centre[3], const double x_axis[3],
                                 const double y_axis[3], double radius, double a0, double a1,
                                 pc_io_curve *out)
{
    return pc_ellipse_arc(ctx, arena, centre, x_axis, y_axis, radius, radius, a0, a1, out);
}

/* ---- homogeneous working copies ---------------------------------------- */

typedef struct hcurve {
    int p;
    size_t n;       /* control points */
    size_t cap;     /* capacity in points (knots: cap + p + 1) */
    double *pw;     /* 4 * cap */
    double *u;      /* cap + p + 1 */
} hcurve;

static projcurve_status hcurve_from(projcurve_context *ctx, pc_arena *arena, const pc_io_curve *c,
                                    size_t extra, hcurve *h)
{
    h->p = c->degree;
    h->n = c->n_ctrl;
    h->cap = c->n_ctrl + extra;
    h->pw = arena_doubles(arena, 4 * h->cap);
    h->u = arena_doubles(arena, h->cap + (size_t)c->degree + 1);
    if (h->pw == NULL || h->u == NULL)
        return no_memory(ctx);
    for (size_t i = 0; i < c->n_ctrl; ++i) {
        const double w = c->weights ? c->weights[i] : 1.0;
        for (int k = 0; k < 3; ++k)
            h->pw[4 * i + (size_t)k] = w * c->ctrl[3 * i + (size_t)k];
        h->pw[4 * i + 3] = w;
    }
    memcpy(h->u, c->knots, (c->n_ctrl + (size_t)c->degree + 1) * sizeof(double));
    return PROJCURVE_OK;
}

static size_t knot_multiplicity(const hcurve *h, double t)
{
    size_t s = 0;
    for (size_t i = 0; i < h->n + (size_t)h->p + 1; ++i)
        s += (h->u[i] == t);
    return s;
}

/* Boehm's insertion of t (U[p] <= t <= U[n]) once; needs cap > n.
 * Q[i] = P[i] (i <= k-p), a_i P[i] + (1 - a_i) P[i-1] (k-p < i <= k),
 * P[i-1] (i > k), a_i = (t - U[i]) / (U[i+p] - U[i]). */
static void hcurve_insert(hcurve *h, double t)
{
    const size_t p = (size_t)h->p;
    size_t k = p;
    for (size_t i = p; i < h->n; ++i)
        if (h->u[i] < h->u[i + 1] && h->u[i] <= t)
            k = i;
    double old[4 * (PROJCURVE_MAX_DEGREE + 1)];
    double alpha[PROJCURVE_MAX_DEGREE + 1];
    memcpy(old, h->pw + 4 * (k - p), 4 * (p + 1) * sizeof(double));
    for (size_t i = k - p + 1; i <= k; ++i)
        alpha[i - (k - p)] = (t - h->u[i]) / (h->u[i + p] - h->u[i]);
    memmove(h->pw + 4 * (k + 1), h->pw + 4 * k, 4 * (h->n - k) * sizeof(double));
    memmove(h->u + k + 2, h->u + k + 1, (h->n + p - k) * sizeof(double));
    for (size_t i = k - p + 1; i <= k; ++i) {
        const size_t j = i - (k - p);
        for (size_t c = 0; c < 4; ++c)
            h->pw[4 * i + c] = alpha[j] * old[4 * j + c] + (1.0 - alpha[j]) * old[4 * (j - 1) + c];
    }
    h->u[k + 1] = t;
    h->n += 1;
}

static size_t last_knot_index(const hcurve *h, double t)
{
    size_t k = 0;
    for (size_t i = 0; i < h->n + (size_t)h->p + 1; ++i)
        if (h->u[i] == t)
            k = i;
    return k;
}

static size_t first_knot_index(const hcurve *h, double t)
{
    for (size_t i = 0; i < h->n + (size_t)h->p + 1; ++i)
        if (h->u[i] == t)
            return i;
    return 0;
}

/* Inserts a and b to multiplicity p and keeps the part between them (the
 * points P[k-p .. m-1] where U[k] is the last a and U[m] the first b), so
 * that the result is clamped over [a, b]. extra is spare capacity kept for
 * later insertions. */
static projcurve_status hcurve_restrict(projcurve_context *ctx, pc_arena *arena,
                                        const pc_io_curve *c, double a, double b, size_t extra,
                                        hcurve *out)
{
    const size_t p = (size_t)c->degree;
    hcurve h;
    projcurve_status st = hcurve_from(ctx, arena, c, 2 * p, &h);
    if (st != PROJCURVE_OK)
        return st;
    for (size_t r = knot_multiplicity(&h, a); r < p; ++r)
        hcurve_insert(&h, a);
    for (size_t r = knot_multiplicity(&h, b); r < p; ++r)
        hcurve_insert(&h, b);
    const size_t k = last_knot_index(&h, a);
    const size_t m = first_knot_index(&h, b);
    if (m <= k || k < p)
        return pc_fail(ctx, PROJCURVE_ERR_BAD_KNOTS, "cannot restrict a curve to [%.17g, %.17g]", a, b);
    out->p = (int)p;
    out->n = m - k + p;
    out->cap = out->n + extra;
    out->pw = arena_doubles(arena, 4 * out->cap);
    out->u = arena_doubles(arena, out->cap + p + 1);
    if (out->pw == NULL || out->u == NULL)
        return no_memory(ctx);
    memcpy(out->pw, h.pw + 4 * (k - p), 4 * out->n * sizeof(double));
    size_t q = 0;
    for (size_t i = 0; i <= p; ++i)
        out->u[q++] = a;
    for (size_t i = k + 1; i < m; ++i)
        out->u[q++] = h.u[i];
    for (size_t i = 0; i <= p; ++i)
        out->u[q++] = b;
    return PROJCURVE_OK;
}

static projcurve_status hcurve_to_io(projcurve_context *ctx, pc_arena *arena, const hcurve *h,
                                     pc_io_curve *out)
{
    double *ctrl = arena_doubles(arena, 3 * h->n);
    double *w = arena_doubles(arena, h->n);
    double *knots = arena_doubles(arena, h->n + (size_t)h->p + 1);
    if (ctrl == NULL || w == NULL || knots == NULL)
        return no_memory(ctx);
    int rational = 0;
    for (size_t i = 0; i < h->n; ++i) {
        w[i] = h->pw[4 * i + 3];
        for (size_t k = 0; k < 3; ++k)
            ctrl[3 * i + k] = h->pw[4 * i + k] / w[i];
        rational |= (w[i] != 1.0); /* kept even when equal: rows of a net need them */
    }
    memcpy(knots, h->u, (h->n + (size_t)h->p + 1) * sizeof(double));
    *out = (pc_io_curve){.degree = h->p, .n_ctrl = h->n, .ctrl = ctrl,
                         .weights = rational ? w : NULL, .knots = knots};
    return PROJCURVE_OK;
}

projcurve_status pc_io_curve_restrict(projcurve_context *ctx, pc_arena *arena,
                                      const pc_io_curve *c, double a, double b,
                                      pc_io_curve *out)
{
    double t0, t1;
    pc_io_curve_domain(c, &t0, &t1);
    if (!(a < b) || a < t0 || b > t1)
        return pc_fail(ctx, PROJCURVE_ERR_OUT_OF_DOMAIN,
                       "range [%.17g, %.17g] is not inside the curve domain [%.17g, %.17g]", a, b,
                       t0, t1);
    hcurve h;
    projcurve_status st = hcurve_restrict(ctx, arena, c, a, b, 0, &h);
    return st != PROJCURVE_OK ? st : hcurve_to_io(ctx, arena, &h, out);
}

/* Raises a Bezier segment (4D points) from degree p to p + 1 in place; the
 * buffer holds p + 2 points. */
static void bezier_elevate(double *pw, int p)
{
    const double n1 = (double)(p + 1);
    double prev[4];
    memcpy(prev, pw, sizeof prev);
    for (int i = 1; i <= p; ++i) {
        double cur[4];
        memcpy(cur, pw + 4 * i, sizeof cur);
        const double a = (double)i / n1;
        for (int c = 0; c < 4; ++c)
            pw[4 * i + c] = a * prev[c] + (1.0 - a) * cur[c];
        memcpy(prev, cur, sizeof prev);
    }
    memcpy(pw + 4 * (p + 1), prev, sizeof prev);
}

/* Splits c (clamped over its domain) into Bezier segments by inserting
 * every interior knot to multiplicity p. */
static projcurve_status hcurve_bezier(projcurve_context *ctx, pc_arena *arena,
                                      const pc_io_curve *c, hcurve *h)
{
    double t0, t1;
    pc_io_curve_domain(c, &t0, &t1);
    const size_t p = (size_t)c->degree;
    size_t n_interior = 0;
    for (size_t i = p + 1; i < c->n_ctrl; ++i)
        n_interior += (c->knots[i] > t0 && c->knots[i] < t1 && c->knots[i] != c->knots[i - 1]);
    const double inserts = (double)n_interior * (double)p;
    if (inserts * ((double)c->n_ctrl + inserts) > PC_IO_MAX_JOIN_WORK)
        return pc_fail(ctx, PROJCURVE_ERR_UNSUPPORTED,
                       "a curve with %zu interior knots of degree %zu is too large to join",
                       n_interior, p);
    projcurve_status st = hcurve_restrict(ctx, arena, c, t0, t1, n_interior * p, h);
    if (st != PROJCURVE_OK)
        return st;
    for (size_t i = p + 1; i < h->n; ++i) {
        const double t = h->u[i];
        if (t > t0 && t < t1 && t != h->u[i - 1])
            for (size_t r = knot_multiplicity(h, t); r < p; ++r)
                hcurve_insert(h, t);
    }
    return PROJCURVE_OK;
}

/* Appends the Bezier segments of h (raised to degree o->p) to o, whose
 * first q points and kq knots are filled; *t is the running parameter. A
 * part after the first must start where the previous one ended. */
static projcurve_status append_part(projcurve_context *ctx, const hcurve *h, size_t index,
                                    double gap_tol, hcurve *o, size_t *q, size_t *kq, double *t)
{
    const size_t p = (size_t)h->p, P = (size_t)o->p;
    double scale = 1.0;
    if (*q > 0) {
        const double *end = o->pw + 4 * (*q - 1), *start = h->pw;
        double gap = 0.0;
        for (size_t c = 0; c < 3; ++c) {
            const double d = end[c] / end[3] - start[c] / start[3];
            gap += d * d;
        }
        if (!(sqrt(gap) <= gap_tol))
            return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                           "part %zu does not start where part %zu ends (gap %g)", index + 1,
                           index, sqrt(gap));
        /* Scaling a rational part's weights leaves it unchanged and makes
         * the homogeneous points agree at the join. */
        scale = end[3] / start[3];
    }
    double seg[4 * (PROJCURVE_MAX_DEGREE + 1)];
    for (size_t s = 0; s + 1 < h->n; s += p) {
        memcpy(seg, h->pw + 4 * s, 4 * (p + 1) * sizeof(double));
        for (int e = (int)p; e < o->p; ++e)
            bezier_elevate(seg, e);
        for (size_t j = (*q == 0) ? 0 : 1; j <= P; ++j) { /* a join shares its point */
            for (size_t c = 0; c < 4; ++c)
                o->pw[4 * *q + c] = seg[4 * j + c] * scale;
            ++*q;
        }
        *t += h->u[s + p + 1] - h->u[s + p];
        for (size_t k = 0; k < P; ++k)
            o->u[(*kq)++] = *t;
    }
    return PROJCURVE_OK;
}

projcurve_status pc_io_curve_join(projcurve_context *ctx, pc_arena *arena,
                                  const pc_io_curve *parts, size_t n_parts, double gap_tol,
                                  pc_io_curve *out)
{
    if (n_parts == 0)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT, "no curves to join");
    if (n_parts == 1) {
        double t0, t1;
        pc_io_curve_domain(&parts[0], &t0, &t1);
        return pc_io_curve_restrict(ctx, arena, &parts[0], t0, t1, out);
    }
    int deg = 1;
    for (size_t i = 0; i < n_parts; ++i)
        deg = parts[i].degree > deg ? parts[i].degree : deg;
    hcurve *bz = pc_arena_calloc(arena, n_parts, sizeof *bz);
    if (bz == NULL)
        return no_memory(ctx);
    size_t n_seg = 0;
    for (size_t i = 0; i < n_parts; ++i) {
        projcurve_status st = hcurve_bezier(ctx, arena, &parts[i], &bz[i]);
        if (st != PROJCURVE_OK)
            return st;
        n_seg += (bz[i].n - 1) / (size_t)bz[i].p;
    }
    /* Output: n_seg * deg + 1 points; knots t0 (deg + 1 times), each join
     * deg times, the end once more. */
    hcurve o = {.p = deg, .n = n_seg * (size_t)deg + 1};
    o.cap = o.n;
    o.pw = arena_doubles(arena, 4 * o.n);
    o.u = arena_doubles(arena, o.n + (size_t)deg + 1);
    if (o.pw == NULL || o.u == NULL)
        return no_memory(ctx);
    double t = bz[0].u[0];
    size_t q = 0, kq = 0;
    for (size_t k = 0; k <= (size_t)deg; ++k)
        o.u[kq++] = t;
    for (size_t i = 0; i < n_parts; ++i) {
        projcurve_status st = append_part(ctx, &bz[i], i, gap_tol, &o, &q, &kq, &t);
        if (st != PROJCURVE_OK)
            return st;
    }
    o.u[kq] = t;
    return hcurve_to_io(ctx, arena, &o, out);
}

/* Restricts the u direction of a net (rows of n_u points, u fastest) to
 * [a, b]: each row is a curve with the same knots, so each gets the same
 * insertions and the rows stay a net. */
static projcurve_status restrict_rows(projcurve_context *ctx, pc_arena *arena, int degree,
                                      size_t n_u, size_t n_v, const double *ctrl,
                                      const double *weights, const double *knots, double a,
                                      double b, pc_io_curve *rows_out, size_t *n_u_out)
{
    for (size_t j = 0; j < n_v; ++j) {
        const pc_io_curve row = {.degree = degree, .n_ctrl = n_u, .ctrl = (double *)ctrl + 3 * j * n_u,
                                 .weights = weights ? (double *)weights + j * n_u : NULL,
                                 .knots = (double *)knots};
        projcurve_status st = pc_io_curve_restrict(ctx, arena, &row, a, b, &rows_out[j]);
        if (st != PROJCURVE_OK)
            return st;
    }
    *n_u_out = rows_out[0].n_ctrl;
    return PROJCURVE_OK;
}

/* Copies the restricted rows back into one net; weights stay or become all
 * ones when the rows came back polynomial. */
static projcurve_status gather_rows(projcurve_context *ctx, pc_arena *arena,
                                    const pc_io_curve *rows, size_t n_u, size_t n_v,
                                    double **ctrl, double **weights)
{
    *ctrl = arena_doubles(arena, 3 * n_u * n_v);
    *weights = arena_doubles(arena, n_u * n_v);
    if (*ctrl == NULL || *weights == NULL)
        return no_memory(ctx);
    for (size_t j = 0; j < n_v; ++j) {
        memcpy(*ctrl + 3 * j * n_u, rows[j].ctrl, 3 * n_u * sizeof(double));
        for (size_t i = 0; i < n_u; ++i)
            (*weights)[j * n_u + i] = rows[j].weights ? rows[j].weights[i] : 1.0;
    }
    return PROJCURVE_OK;
}

/* The transpose of a net (v becomes the fast index). */
static projcurve_status transpose(projcurve_context *ctx, pc_arena *arena, size_t n_u, size_t n_v,
                                  const double *ctrl, const double *weights, double **t_ctrl,
                                  double **t_weights)
{
    *t_ctrl = arena_doubles(arena, 3 * n_u * n_v);
    *t_weights = weights ? arena_doubles(arena, n_u * n_v) : NULL;
    if (*t_ctrl == NULL || (weights && *t_weights == NULL))
        return no_memory(ctx);
    for (size_t j = 0; j < n_v; ++j)
        for (size_t i = 0; i < n_u; ++i) {
            memcpy(*t_ctrl + 3 * (i * n_v + j), ctrl + 3 * (j * n_u + i), 3 * sizeof(double));
            if (weights)
                (*t_weights)[i * n_v + j] = weights[j * n_u + i];
        }
    return PROJCURVE_OK;
}

/* [a, b] clamped to the knot domain, or 0 when nothing is to be cut. */
static int cut_range(const double *knots, int degree, size_t n, double *a, double *b)
{
    const double t0 = knots[degree], t1 = knots[n];
    for (size_t i = 0; i + 1 < n + (size_t)degree + 1; ++i)
        if (!(knots[i] <= knots[i + 1]))
            return 0; /* creation reports the bad knots */
    *a = *a > t0 ? *a : t0;
    *b = *b < t1 ? *b : t1;
    return *a < *b && (*a > t0 || *b < t1);
}

projcurve_status pc_io_surface_restrict(projcurve_context *ctx, pc_arena *arena,
                                        const pc_io_surface *s, double u0, double u1, double v0,
                                        double v1, pc_io_surface *out)
{
    pc_io_surface r = *s;
    projcurve_status st = PROJCURVE_OK;
    if (cut_range(s->knots_u, s->deg_u, s->n_u, &u0, &u1)) {
        pc_io_curve *rows = pc_arena_calloc(arena, r.n_v, sizeof *rows);
        if (rows == NULL)
            return no_memory(ctx);
        size_t n_u = 0;
        if ((st = restrict_rows(ctx, arena, r.deg_u, r.n_u, r.n_v, r.ctrl, r.weights, r.knots_u,
                                u0, u1, rows, &n_u)) != PROJCURVE_OK ||
            (st = gather_rows(ctx, arena, rows, n_u, r.n_v, &r.ctrl, &r.weights)) != PROJCURVE_OK)
            return st;
        r.n_u = n_u;
        r.knots_u = rows[0].knots;
    }
    if (cut_range(s->knots_v, s->deg_v, s->n_v, &v0, &v1)) {
        double *tc, *tw;
        if ((st = transpose(ctx, arena, r.n_u, r.n_v, r.ctrl, r.weights, &tc, &tw)) != PROJCURVE_OK)
            return st;
        pc_io_curve *cols = pc_arena_calloc(arena, r.n_u, sizeof *cols);
        if (cols == NULL)
            return no_memory(ctx);
        size_t n_v = 0;
        double *cc, *cw;
        if ((st = restrict_rows(ctx, arena, r.deg_v, r.n_v, r.n_u, tc, tw, r.knots_v, v0, v1,
                                cols, &n_v)) != PROJCURVE_OK ||
            (st = gather_rows(ctx, arena, cols, n_v, r.n_u, &cc, &cw)) != PROJCURVE_OK ||
            (st = transpose(ctx, arena, n_v, r.n_u, cc, cw, &r.ctrl, &r.weights)) != PROJCURVE_OK)
            return st;
        r.n_v = n_v;
        r.knots_v = cols[0].knots;
    }
    *out = r;
    return PROJCURVE_OK;
}
