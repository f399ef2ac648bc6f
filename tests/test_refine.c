/*
 * Tolerance control and composition (refine/): the composed pieces must be
 * within eps_D of the exact projection (3D Hausdorff distance), meet at
 * joints within eps_T, each lie in one Bezier patch, and the piece limit and
 * bad tolerances must give clear statuses.
 *
 * Oracles, independent of the refinement code:
 *  - a bicubic height field whose (x, y) map is the identity up to scale
 *    (control points at the Greville abscissae), projected along -z: the
 *    exact projection of P(t) = (x(t), y(t), h) is S(x(t)/X, y(t)/Y);
 *  - a half cylinder as an exact rational NURBS, projected along -z: the
 *    exact projection is (x, y, sqrt(R^2 - x^2)).
 * The distance is measured both ways on dense samples: each output sample is
 * projected onto the exact curve by its own Newton iteration on t, and each
 * exact sample onto its piece by Newton on s.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "api/handles.h"
#include "check.h"
#include "refine/refine.h"
#include "trace/projector.h"
#include "trace/result.h"

#define PI 3.14159265358979323846
#define DENSE_PER_PIECE 16
#define DENSE_EXACT 4000
#define ORACLE_MAX_ITER 50

/* ------------------------------------------------------------------------ */
/* A directional projector written for this test (DESIGN.md, "Numerics").   */
/* ------------------------------------------------------------------------ */

typedef struct test_dir {
    pc_vec3 dir, e1, e2;
} test_dir;

static void surface_eval(const projcurve_surface *s, double u, double v, int n, pc_vec3 *out)
{
    double buf[18];
    projcurve_surface_eval(NULL, s, u, v, n, buf);
    for (int k = 0; k < (n == 0 ? 1 : n == 1 ? 3 : 6); ++k)
        out[k] = vec3_load(buf + 3 * k);
}

static void curve_eval(const projcurve_curve *c, double t, pc_vec3 out[3])
{
    double buf[9];
    projcurve_curve_eval(NULL, c, t, 2, buf);
    for (int k = 0; k < 3; ++k)
        out[k] = vec3_load(buf + 3 * k);
}

static void clamp_domain(const projcurve_surface *s, double uv[2])
{
    double d[4];
    projcurve_surface_domain(NULL, s, d);
    uv[0] = uv[0] < d[0] ? d[0] : (uv[0] > d[1] ? d[1] : uv[0]);
    uv[1] = uv[1] < d[2] ? d[2] : (uv[1] > d[3] ? d[3] : uv[1]);
}

static int test_correct(const pc_projector *self, double t, double uv[2], int *iterations)
{
    const test_dir *d = self->data;
    pc_vec3 p[3];
    curve_eval(self->curve, t, p);
    for (int it = 0; it < self->newton_max_iter; ++it) {
        pc_vec3 s[3];
        surface_eval(self->surface, uv[0], uv[1], 1, s);
        const pc_vec3 g = vec3_sub(s[0], p[0]);
        const double r[2] = {-vec3_dot(d->e1, g), -vec3_dot(d->e2, g)};
        if (iterations)
            *iterations = it;
        if (hypot(r[0], r[1]) <= self->newton_tol)
            return 1;
        double delta[2];
        if (!mat2_solve(vec3_dot(d->e1, s[1]), vec3_dot(d->e1, s[2]), vec3_dot(d->e2, s[1]),
                        vec3_dot(d->e2, s[2]), r, delta))
            return 0;
        uv[0] += delta[0];
        uv[1] += delta[1];
        clamp_domain(self->surface, uv);
    }
    return 0;
}

static int test_derivatives(const pc_projector *self, double t, double u, double v,
                            pc_proj_point *out)
{
    const test_dir *d = self->data;
    pc_vec3 p[3], s[6];
    curve_eval(self->curve, t, p);
    surface_eval(self->surface, u, v, 2, s);
    const double a = vec3_dot(d->e1, s[1]), b = vec3_dot(d->e1, s[2]);
    const double c = vec3_dot(d->e2, s[1]), e = vec3_dot(d->e2, s[2]);
    const double r1[2] = {vec3_dot(d->e1, p[1]), vec3_dot(d->e2, p[1])};
    double q1[2], q2[2];
    if (!mat2_solve(a, b, c, e, r1, q1))
        return 0;
    const pc_vec3 curv = vec3_add(vec3_add(vec3_scale(s[3], q1[0] * q1[0]),
                                           vec3_scale(s[4], 2.0 * q1[0] * q1[1])),
                                  vec3_scale(s[5], q1[1] * q1[1]));
    const double r2[2] = {vec3_dot(d->e1, vec3_sub(p[2], curv)),
                          vec3_dot(d->e2, vec3_sub(p[2], curv))};
    if (!mat2_solve(a, b, c, e, r2, q2))
        return 0;
    memset(out, 0, sizeof *out);
    out->t = t, out->u = u, out->v = v;
    out->du = q1[0], out->dv = q1[1], out->ddu = q2[0], out->ddv = q2[1];
    out->s = s[0];
    out->p = p[0];
    return 1;
}

static double test_residual(const pc_projector *self, double t, double u, double v)
{
    const test_dir *d = self->data;
    pc_vec3 p[3], s;
    curve_eval(self->curve, t, p);
    surface_eval(self->surface, u, v, 0, &s);
    const pc_vec3 g = vec3_sub(s, p[0]);
    return hypot(vec3_dot(d->e1, g), vec3_dot(d->e2, g));
}

static void make_projector(const projcurve_surface *s, const projcurve_curve *c, test_dir *d,
                           pc_projector *proj)
{
    d->dir = vec3(0.0, 0.0, -1.0);
    vec3_orthonormal_pair(d->dir, &d->e1, &d->e2);
    memset(proj, 0, sizeof *proj);
    proj->surface = s;
    proj->curve = c;
    proj->model_size = s->size;
    proj->newton_tol = 1e-12 * s->size;
    proj->newton_max_iter = 30;
    proj->correct = test_correct;
    proj->derivatives = test_derivatives;
    proj->residual = test_residual;
    proj->data = d;
}

/* ------------------------------------------------------------------------ */
/* Test shapes with their exact projections.                               */
/* ------------------------------------------------------------------------ */

typedef struct shape {
    const char *name;
    projcurve_surface *surface;
    projcurve_curve *curve;
    double t0, t1;
    /* exact projection Q(t) and its first two derivatives */
    void (*exact)(const struct shape *sh, double t, pc_vec3 q[3]);
    /* exact (u, v) at t, for the traced polyline given to the refinement */
    void (*exact_uv)(const struct shape *sh, double t, double uv[2]);
} shape;

/* Height field: x = 10 u, y = 8 v, z = h(u, v); the curve flies at z = 20. */
#define HF_X 10.0
#define HF_Y 8.0

static void hf_curve_xy(double t, double xy[2], double d1[2], double d2[2])
{
    /* x from 0.3 to 9.7, y a wave across most of the v range */
    const double w = 3.0 * PI;
    xy[0] = 0.3 + 9.4 * t;
    xy[1] = 4.0 + 3.2 * sin(w * t);
    d1[0] = 9.4;
    d1[1] = 3.2 * w * cos(w * t);
    d2[0] = 0.0;
    d2[1] = -3.2 * w * w * sin(w * t);
}

static int hf_curve_fn(void *user, double t, double out[9])
{
    (void)user;
    double xy[2], d1[2], d2[2];
    hf_curve_xy(t, xy, d1, d2);
    const double v[9] = {xy[0], xy[1], 20.0, d1[0], d1[1], 0.0, d2[0], d2[1], 0.0};
    memcpy(out, v, sizeof v);
    return 0;
}

static void hf_exact_uv(const shape *sh, double t, double uv[2])
{
    (void)sh;
    double xy[2], d1[2], d2[2];
    hf_curve_xy(t, xy, d1, d2);
    uv[0] = xy[0] / HF_X;
    uv[1] = xy[1] / HF_Y;
}

static void hf_exact(const shape *sh, double t, pc_vec3 q[3])
{
    double xy[2], d1[2], d2[2];
    hf_curve_xy(t, xy, d1, d2);
    const double u1 = d1[0] / HF_X, v1 = d1[1] / HF_Y, u2 = d2[0] / HF_X, v2 = d2[1] / HF_Y;
    pc_vec3 s[6];
    surface_eval(sh->surface, xy[0] / HF_X, xy[1] / HF_Y, 2, s);
    q[0] = s[0];
    q[1] = vec3_add(vec3_scale(s[1], u1), vec3_scale(s[2], v1));
    q[2] = vec3_add(vec3_add(vec3_scale(s[3], u1 * u1), vec3_scale(s[4], 2.0 * u1 * v1)),
                    vec3_add(vec3_scale(s[5], v1 * v1),
                             vec3_add(vec3_scale(s[1], u2), vec3_scale(s[2], v2))));
}

/* Clamped uniform knots of a degree-p spline with n control points on [0,1]. */
static void uniform_knots(int p, int n, double *knots)
{
    for (int k = 0; k < n + p + 1; ++k) {
        const int inner = k - p;
        const int spans = n - p;
        knots[k] = inner <= 0 ? 0.0 : (inner >= spans ? 1.0 : (double)inner / spans);
    }
}

static double greville(const double *knots, int p, int i)
{
    double s = 0.0;
    for (int k = 1; k <= p; ++k)
        s += knots[i + k];
    return s / p;
}

static int make_height_field(shape *sh)
{
    enum { P = 3, NU = 9, NV = 7 };
    double ku[NU + P + 1], kv[NV + P + 1], ctrl[3 * NU * NV];
    uniform_knots(P, NU, ku);
    uniform_knots(P, NV, kv);
    pc_test_rng rng;
    pc_test_rng_seed(&rng, 6101);
    for (int j = 0; j < NV; ++j)
        for (int i = 0; i < NU; ++i) {
            double *c = ctrl + 3 * (j * NU + i);
            c[0] = HF_X * greville(ku, P, i);
            c[1] = HF_Y * greville(kv, P, j);
            c[2] = pc_test_rng_uniform(&rng, -1.5, 1.5);
        }
    memset(sh, 0, sizeof *sh);
    sh->name = "bicubic height field";
    sh->t0 = 0.0;
    sh->t1 = 1.0;
    sh->exact = hf_exact;
    sh->exact_uv = hf_exact_uv;
    if (projcurve_surface_create_nurbs(NULL, P, P, NU, NV, ctrl, NULL, ku, kv, &sh->surface) !=
        PROJCURVE_OK)
        return 0;
    return projcurve_curve_create_callback(NULL, hf_curve_fn, NULL, 0.0, 1.0, &sh->curve) ==
           PROJCURVE_OK;
}

/* Half cylinder x^2 + z^2 = R^2, z >= 0, y in [-5, 5]: two rational quadratic
 * arcs in u (double knot at 1/2), linear in v with two spans. */
#define CYL_R 4.0

static void cyl_curve(double t, double out[9])
{
    const double w = 2.0 * PI;
    const double v[9] = {3.5 * sin(w * t), -4.5 + 9.0 * t, 10.0,
                         3.5 * w * cos(w * t), 9.0, 0.0,
                         -3.5 * w * w * sin(w * t), 0.0, 0.0};
    memcpy(out, v, sizeof v);
}

static int cyl_curve_fn(void *user, double t, double out[9])
{
    (void)user;
    cyl_curve(t, out);
    return 0;
}

static void cyl_exact(const shape *sh, double t, pc_vec3 q[3])
{
    (void)sh;
    double c[9];
    cyl_curve(t, c);
    const double x = c[0], x1 = c[3], x2 = c[6];
    const double z = sqrt(CYL_R * CYL_R - x * x);
    const double z1 = -x * x1 / z;
    const double z2 = -(x1 * x1 + x * x2 + z1 * z1) / z;
    q[0] = vec3(x, c[1], z);
    q[1] = vec3(x1, c[4], z1);
    q[2] = vec3(x2, c[7], z2);
}

/* u of a point at angle a (from +x towards +z) on the rational arcs: on each
 * quarter arc with weights (1, sqrt(1/2), 1), tan(a'/2) = s / ((1 - s) sqrt2 + s)
 * inverted; an initial guess for the test projector's Newton. */
static void cyl_exact_uv(const shape *sh, double t, double uv[2])
{
    double c[9];
    cyl_curve(t, c);
    const double a = atan2(sqrt(CYL_R * CYL_R - c[0] * c[0]), c[0]);
    const double local = a <= PI / 2 ? a : a - PI / 2;
    const double k = tan(local / 2) * sqrt(2.0);
    const double s = k / (1.0 + k - tan(local / 2));
    uv[0] = a <= PI / 2 ? 0.5 * s : 0.5 + 0.5 * s;
    uv[1] = (c[1] + 5.0) / 10.0;
    pc_projector proj;
    test_dir d;
    make_projector(sh->surface, sh->curve, &d, &proj);
    test_correct(&proj, t, uv, NULL);
}

static int make_cylinder(shape *sh)
{
    const double h = sqrt(0.5);
    const double arc[5][2] = {{CYL_R, 0}, {CYL_R, CYL_R}, {0, CYL_R}, {-CYL_R, CYL_R}, {-CYL_R, 0}};
    const double warc[5] = {1, h, 1, h, 1};
    const double ys[3] = {-5.0, 0.0, 5.0};
    double ctrl[3 * 15], weights[15];
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 5; ++i) {
            double *c = ctrl + 3 * (j * 5 + i);
            c[0] = arc[i][0];
            c[1] = ys[j];
            c[2] = arc[i][1];
            weights[j * 5 + i] = warc[i];
        }
    const double ku[8] = {0, 0, 0, 0.5, 0.5, 1, 1, 1}, kv[5] = {0, 0, 0.5, 1, 1};
    memset(sh, 0, sizeof *sh);
    sh->name = "rational half cylinder";
    sh->t0 = 0.0;
    sh->t1 = 1.0;
    sh->exact = cyl_exact;
    sh->exact_uv = cyl_exact_uv;
    if (projcurve_surface_create_nurbs(NULL, 2, 1, 5, 3, ctrl, weights, ku, kv, &sh->surface) !=
        PROJCURVE_OK)
        return 0;
    return projcurve_curve_create_callback(NULL, cyl_curve_fn, NULL, 0.0, 1.0, &sh->curve) ==
           PROJCURVE_OK;
}

static void free_shape(shape *sh)
{
    projcurve_surface_destroy(sh->surface);
    projcurve_curve_destroy(sh->curve);
}

/* A result with one branch: the exact projection at n_points even t over
 * [ta, tb] (in that order: tb < ta gives a descending branch). */
static projcurve_result *traced_result(const shape *sh, double ta, double tb, int n_points)
{
    projcurve_result *r = NULL;
    pc_branch *b = NULL;
    if (pc_result_create(NULL, 3, &r) != PROJCURVE_OK)
        return NULL;
    if (pc_result_add_branch(NULL, r, &b) != PROJCURVE_OK) {
        projcurve_result_destroy(r);
        return NULL;
    }
    for (int k = 0; k < n_points; ++k) {
        const double t = ta + (tb - ta) * k / (n_points - 1);
        double p[3] = {t, 0, 0};
        sh->exact_uv(sh, t, p + 1);
        pc_branch_add_point(NULL, b, 3, p);
    }
    b->start = PROJCURVE_START_CURVE_START;
    b->end = PROJCURVE_END_CURVE_END;
    return r;
}

/* ------------------------------------------------------------------------ */
/* Independent measurements on the output.                                  */
/* ------------------------------------------------------------------------ */

/* Piece point and derivative at s by Bernstein sums (rational): the power
 * form B_i = C(n,i) s^i (1-s)^(n-i), B_i' = n (B_{i-1}^{n-1} - B_i^{n-1}). */
static void piece_eval(const pc_piece *pc, double s, pc_vec3 *x, pc_vec3 *dx)
{
    const int n = pc->degree;
    double sp[2 * PROJCURVE_MAX_DEGREE + 2], rp[2 * PROJCURVE_MAX_DEGREE + 2];
    sp[0] = rp[0] = 1.0;
    for (int i = 1; i <= n; ++i) {
        sp[i] = sp[i - 1] * s;
        rp[i] = rp[i - 1] * (1.0 - s);
    }
    double h[4] = {0, 0, 0, 0}, dh[4] = {0, 0, 0, 0};
    double binom = 1.0, binom1 = 1.0; /* C(n, i) and C(n-1, i) */
    for (int i = 0; i <= n; ++i) {
        if (i > 0) {
            binom = binom * (n - i + 1) / i;
            binom1 = i <= n - 1 ? binom1 * (n - i) / i : 0.0;
        }
        const double b = binom * sp[i] * rp[n - i];
        const double lower_prev = i > 0 ? (binom * i / n) * sp[i - 1] * rp[n - i] : 0.0;
        const double lower_here = i < n ? binom1 * sp[i] * rp[n - 1 - i] : 0.0;
        const double db = n * (lower_prev - lower_here);
        const double w = pc->weights[i];
        for (int c = 0; c < 3; ++c) {
            h[c] += b * w * pc->ctrl[3 * i + c];
            dh[c] += db * w * pc->ctrl[3 * i + c];
        }
        h[3] += b * w;
        dh[3] += db * w;
    }
    *x = vec3(h[0] / h[3], h[1] / h[3], h[2] / h[3]);
    if (dx)
        *dx = vec3_scale(vec3_axpy(vec3(dh[0], dh[1], dh[2]), -dh[3], *x), 1.0 / h[3]);
}

/* Distance from x to the exact projection near t (Newton on t, clamped). */
static double distance_to_exact(const shape *sh, double ta, double tb, pc_vec3 x, double t)
{
    const double lo = ta < tb ? ta : tb, hi = ta < tb ? tb : ta;
    double best = INFINITY;
    for (int it = 0; it < ORACLE_MAX_ITER; ++it) {
        pc_vec3 q[3];
        sh->exact(sh, t, q);
        const pc_vec3 d = vec3_sub(q[0], x);
        const double dist = vec3_norm(d);
        if (dist < best)
            best = dist;
        const double f = vec3_dot(d, q[1]);
        double fp = vec3_dot(q[1], q[1]) + vec3_dot(d, q[2]);
        if (!(fp > 0.0))
            fp = vec3_dot(q[1], q[1]);
        double next = t - f / fp;
        next = next < lo ? lo : (next > hi ? hi : next);
        if (fabs(next - t) < 1e-15)
            break;
        t = next;
    }
    return best;
}

/* Distance from x to the piece (Newton on s from s0; derivative by the
 * analytic Bernstein derivative, second order by a difference quotient). */
static double distance_to_piece(const pc_piece *pc, pc_vec3 x, double s)
{
    double best = INFINITY;
    for (int it = 0; it < ORACLE_MAX_ITER; ++it) {
        pc_vec3 c, dc, c2, dc2;
        piece_eval(pc, s, &c, &dc);
        const pc_vec3 d = vec3_sub(c, x);
        const double dist = vec3_norm(d);
        if (dist < best)
            best = dist;
        const double hs = 1e-6;
        piece_eval(pc, s + hs <= 1.0 ? s + hs : s - hs, &c2, &dc2);
        const pc_vec3 ddc = vec3_scale(vec3_sub(dc2, dc), s + hs <= 1.0 ? 1.0 / hs : -1.0 / hs);
        double fp = vec3_dot(dc, dc) + vec3_dot(d, ddc);
        if (!(fp > 0.0))
            fp = vec3_dot(dc, dc);
        double next = s - vec3_dot(d, dc) / fp;
        next = next < 0.0 ? 0.0 : (next > 1.0 ? 1.0 : next);
        if (fabs(next - s) < 1e-14)
            break;
        s = next;
    }
    return best;
}

typedef struct measure {
    double hausdorff;   /* max of both one-sided distances */
    double max_angle;   /* largest joint angle, degrees */
    double max_gap;     /* largest distance between joined piece ends */
    double max_end_err; /* piece ends vs the exact projection */
    int off_patch;      /* pieces whose (u, v) range spans two patches */
} measure;

static double angle_deg(pc_vec3 a, pc_vec3 b)
{
    const double c = vec3_dot(a, b) / (vec3_norm(a) * vec3_norm(b));
    return acos(c > 1.0 ? 1.0 : (c < -1.0 ? -1.0 : c)) * 180.0 / PI;
}

static int same_cell(const double *breaks, size_t n, double a, double b)
{
    for (size_t k = 1; k < n; ++k) /* an inner break strictly between a and b */
        if ((breaks[k] - a) * (breaks[k] - b) < 0.0)
            return 0;
    return 1;
}

static measure measure_branch(const shape *sh, const pc_branch *b)
{
    measure m = {0, 0, 0, 0, 0};
    const double ta = b->pieces[0].t0, tb = b->pieces[b->n_pieces - 1].t1;
    const pc_patch_grid *g = &sh->surface->grid;
    for (size_t i = 0; i < b->n_pieces; ++i) {
        const pc_piece *pc = &b->pieces[i];
        for (int k = 0; k <= DENSE_PER_PIECE; ++k) {
            const double s = (double)k / DENSE_PER_PIECE;
            pc_vec3 x;
            piece_eval(pc, s, &x, NULL);
            const double d = distance_to_exact(sh, ta, tb, x, pc->t0 + s * (pc->t1 - pc->t0));
            if (d > m.hausdorff)
                m.hausdorff = d;
        }
        pc_vec3 q[3], x0, x1;
        piece_eval(pc, 0.0, &x0, NULL);
        piece_eval(pc, 1.0, &x1, NULL);
        sh->exact(sh, pc->t0, q);
        m.max_end_err = fmax(m.max_end_err, vec3_dist(q[0], x0));
        sh->exact(sh, pc->t1, q);
        m.max_end_err = fmax(m.max_end_err, vec3_dist(q[0], x1));
        if (!same_cell(g->breaks_u, g->spans_u, pc->uv[0], pc->uv[2]) ||
            !same_cell(g->breaks_v, g->spans_v, pc->uv[1], pc->uv[3]))
            ++m.off_patch;
        if (i > 0) {
            const pc_piece *pv = &b->pieces[i - 1];
            const int n = pv->degree;
            const pc_vec3 t_end = vec3_sub(vec3_load(pv->ctrl + 3 * n), vec3_load(pv->ctrl + 3 * (n - 1)));
            const pc_vec3 t_start = vec3_sub(vec3_load(pc->ctrl + 3), vec3_load(pc->ctrl));
            m.max_angle = fmax(m.max_angle, angle_deg(t_end, t_start));
            pc_vec3 prev_end;
            piece_eval(pv, 1.0, &prev_end, NULL);
            m.max_gap = fmax(m.max_gap, vec3_dist(prev_end, x0));
        }
    }
    /* exact -> output: dense samples of the exact curve onto their piece */
    size_t i = 0; /* pieces follow t (either way): walk them along */
    for (int k = 0; k <= DENSE_EXACT; ++k) {
        const double t = ta + (tb - ta) * k / DENSE_EXACT;
        pc_vec3 q[3];
        sh->exact(sh, t, q);
        while (i + 1 < b->n_pieces && (b->pieces[i].t1 - t) * (tb - ta) < 0.0)
            ++i;
        const pc_piece *pc = &b->pieces[i];
        const double d = distance_to_piece(pc, q[0], (t - pc->t0) / (pc->t1 - pc->t0));
        if (d > m.hausdorff)
            m.hausdorff = d;
    }
    return m;
}

/* ------------------------------------------------------------------------ */
/* Tests                                                                    */
/* ------------------------------------------------------------------------ */

static void test_tolerances(shape *sh)
{
    static const double rel_eps[] = {1e-2, 1e-3, 1e-4, 1e-5, 1e-6};
    static const double angles[] = {10.0, 1.0};
    pc_projector proj;
    test_dir d;
    make_projector(sh->surface, sh->curve, &d, &proj);
    const double size = sh->surface->size;
    for (size_t a = 0; a < sizeof angles / sizeof angles[0]; ++a) {
        for (size_t e = 0; e < sizeof rel_eps / sizeof rel_eps[0]; ++e) {
            struct projcurve_options o;
            pc_options_defaults(&o);
            o.tol_distance = rel_eps[e] * size;
            o.tol_angle_deg = angles[a];
            projcurve_result *r = traced_result(sh, sh->t0, sh->t1, 41);
            CHECK(r != NULL);
            if (r == NULL)
                return;
            CHECK_OK(pc_refine_and_compose(NULL, &proj, &o, r));
            const pc_branch *b = &r->branches[0];
            CHECK(b->n_pieces > 0);
            if (b->n_pieces > 0) {
                const measure m = measure_branch(sh, b);
                printf("%s: eps_D %.0e, eps_T %4.1f deg: %4zu pieces, Hausdorff %.3e (%.2f eps), "
                       "max joint %.3f deg\n",
                       sh->name, rel_eps[e], angles[a], b->n_pieces, m.hausdorff / size,
                       m.hausdorff / o.tol_distance, m.max_angle);
                CHECK(m.hausdorff <= o.tol_distance);
                CHECK(m.max_angle <= angles[a] * (1.0 + 1e-9));
                CHECK(m.max_gap <= 1e-12 * size);
                CHECK(m.max_end_err <= 1e-9 * size);
                CHECK(m.off_patch == 0);
                CHECK_NEAR(b->pieces[0].t0, sh->t0, 1e-15);
                CHECK_NEAR(b->pieces[b->n_pieces - 1].t1, sh->t1, 1e-15);
                /* the branch's points are the pieces' pcurve */
                CHECK(b->n_points == b->n_pieces + 1);
            }
            CHECK_NEAR(r->stats.tol_distance, o.tol_distance, 0.0);
            CHECK_NEAR(r->stats.pieces, (double)b->n_pieces, 0.0);
            projcurve_result_destroy(r);
        }
    }
}

/* A branch stored with decreasing t gives pieces in that order, same accuracy. */
static void test_descending(shape *sh)
{
    pc_projector proj;
    test_dir d;
    make_projector(sh->surface, sh->curve, &d, &proj);
    struct projcurve_options o;
    pc_options_defaults(&o);
    o.tol_distance = 1e-4 * sh->surface->size;
    projcurve_result *r = traced_result(sh, sh->t1, sh->t0, 30);
    CHECK_OK(pc_refine_and_compose(NULL, &proj, &o, r));
    const pc_branch *b = &r->branches[0];
    CHECK(b->n_pieces > 0);
    if (b->n_pieces > 0) {
        CHECK_NEAR(b->pieces[0].t0, sh->t1, 0.0);
        CHECK_NEAR(b->pieces[b->n_pieces - 1].t1, sh->t0, 0.0);
        CHECK(b->pieces[0].t1 < b->pieces[0].t0);
        const measure m = measure_branch(sh, b);
        CHECK(m.hausdorff <= o.tol_distance);
        CHECK(m.max_angle <= o.tol_angle_deg * (1.0 + 1e-9));
    }
    projcurve_result_destroy(r);
}

/* Automatic eps_D = 1e-4 of the model size; NULL options = defaults. */
static void test_automatic_tolerance(shape *sh)
{
    pc_projector proj;
    test_dir d;
    make_projector(sh->surface, sh->curve, &d, &proj);
    projcurve_result *r = traced_result(sh, sh->t0, sh->t1, 20);
    CHECK_OK(pc_refine_and_compose(NULL, &proj, NULL, r));
    CHECK_NEAR(r->stats.tol_distance, 1e-4 * sh->surface->size, 1e-18);
    if (r->branches[0].n_pieces > 0) {
        const measure m = measure_branch(sh, &r->branches[0]);
        CHECK(m.hausdorff <= r->stats.tol_distance);
    }
    projcurve_result_destroy(r);
}

static void test_bad_tolerances(shape *sh)
{
    pc_projector proj;
    test_dir d;
    make_projector(sh->surface, sh->curve, &d, &proj);
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    static const struct {
        double dist, angle;
        long long pieces;
        projcurve_status expect;
    } cases[] = {
        {-1e-3, 1.0, 100, PROJCURVE_ERR_OUT_OF_RANGE},
        {NAN, 1.0, 100, PROJCURVE_ERR_NOT_FINITE},
        {INFINITY, 1.0, 100, PROJCURVE_ERR_NOT_FINITE},
        {1e-3, 0.0, 100, PROJCURVE_ERR_OUT_OF_RANGE},
        {1e-3, -5.0, 100, PROJCURVE_ERR_OUT_OF_RANGE},
        {1e-3, 90.5, 100, PROJCURVE_ERR_OUT_OF_RANGE},
        {1e-3, NAN, 100, PROJCURVE_ERR_NOT_FINITE},
        {1e-3, 1.0, 0, PROJCURVE_ERR_OUT_OF_RANGE},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        struct projcurve_options o;
        pc_options_defaults(&o);
        o.tol_distance = cases[k].dist;
        o.tol_angle_deg = cases[k].angle;
        o.max_pieces = cases[k].pieces;
        projcurve_result *r = traced_result(sh, sh->t0, sh->t1, 10);
        CHECK_STATUS(pc_refine_and_compose(ctx, &proj, &o, r), cases[k].expect);
        CHECK(strlen(projcurve_context_message(ctx)) > 0);
        CHECK(r->branches[0].n_pieces == 0);
        CHECK(r->branches[0].n_points == 10); /* untouched */
        projcurve_result_destroy(r);
    }
    /* the bounds themselves are accepted */
    struct projcurve_options o;
    pc_options_defaults(&o);
    o.tol_angle_deg = 90.0;
    o.tol_distance = 1e-2 * sh->surface->size;
    projcurve_result *r = traced_result(sh, sh->t0, sh->t1, 10);
    CHECK_OK(pc_refine_and_compose(ctx, &proj, &o, r));
    projcurve_result_destroy(r);
    CHECK_STATUS(pc_refine_and_compose(ctx, NULL, &o, NULL), PROJCURVE_ERR_NULL_ARGUMENT);
    projcurve_context_destroy(ctx);
}

/* A tolerance that needs more pieces than allowed: LIMIT_REACHED, the branch
 * ends with END_LIMIT, and the pieces kept are a valid prefix. A second
 * branch after the limit gets no pieces and is marked too. */
static void test_piece_limit(shape *sh)
{
    pc_projector proj;
    test_dir d;
    make_projector(sh->surface, sh->curve, &d, &proj);
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    struct projcurve_options o;
    pc_options_defaults(&o);
    o.tol_distance = 1e-6 * sh->surface->size;
    o.max_pieces = 7;
    projcurve_result *r = traced_result(sh, sh->t0, 0.5 * (sh->t0 + sh->t1), 20);
    pc_branch *second = NULL;
    CHECK_OK(pc_result_add_branch(NULL, r, &second));
    for (int k = 0; k < 10; ++k) {
        const double t = 0.5 * (sh->t0 + sh->t1) + k * 0.05 * (sh->t1 - sh->t0);
        double p[3] = {t, 0, 0};
        sh->exact_uv(sh, t, p + 1);
        pc_branch_add_point(NULL, second, 3, p);
    }
    CHECK_STATUS(pc_refine_and_compose(ctx, &proj, &o, r), PROJCURVE_ERR_LIMIT_REACHED);
    CHECK(strstr(projcurve_context_message(ctx), "limit") != NULL);
    const pc_branch *b = &r->branches[0];
    CHECK(b->end == PROJCURVE_END_LIMIT);
    CHECK(b->n_pieces == 7);
    CHECK(b->n_points == b->n_pieces + 1);
    CHECK_NEAR(b->pieces[0].t0, sh->t0, 0.0);
    for (size_t i = 1; i < b->n_pieces; ++i)
        CHECK_NEAR(b->pieces[i].t0, b->pieces[i - 1].t1, 0.0);
    CHECK(r->branches[1].n_pieces == 0);
    CHECK(r->branches[1].end == PROJCURVE_END_LIMIT);
    CHECK_NEAR(r->stats.pieces, 7.0, 0.0);
    projcurve_result_destroy(r);
    projcurve_context_destroy(ctx);
}

static int failing_correct(const pc_projector *self, double t, double uv[2], int *iterations)
{
    (void)self, (void)t, (void)uv;
    if (iterations)
        *iterations = 0;
    return 0;
}

/* A corrector that never converges: the refinement must still end, keep the
 * traced vertices and compose pieces that lie on S and join. */
static void test_failing_corrector(shape *sh)
{
    pc_projector proj;
    test_dir d;
    make_projector(sh->surface, sh->curve, &d, &proj);
    proj.correct = failing_correct;
    projcurve_result *r = traced_result(sh, sh->t0, sh->t1, 15);
    CHECK_OK(pc_refine_and_compose(NULL, &proj, NULL, r));
    const pc_branch *b = &r->branches[0];
    CHECK(b->n_pieces >= 14);
    for (size_t i = 1; i < b->n_pieces; ++i)
        CHECK_NEAR(b->pieces[i].t0, b->pieces[i - 1].t1, 0.0);
    const measure m = measure_branch(sh, b);
    CHECK(m.off_patch == 0);
    CHECK(m.max_gap <= 1e-12 * sh->surface->size);
    projcurve_result_destroy(r);
}

/* Degenerate branches: one point (left alone), repeated parameters (the
 * repeats are dropped), and a result of 3D points (not refinable). */
static void test_degenerate_branches(shape *sh)
{
    pc_projector proj;
    test_dir d;
    make_projector(sh->surface, sh->curve, &d, &proj);
    projcurve_result *r = traced_result(sh, sh->t0, sh->t1, 12);
    pc_branch *single = NULL, *repeated = NULL;
    CHECK_OK(pc_result_add_branch(NULL, r, &single));
    double p[3] = {0.3, 0, 0};
    sh->exact_uv(sh, 0.3, p + 1);
    CHECK_OK(pc_branch_add_point(NULL, single, 3, p));
    CHECK_OK(pc_result_add_branch(NULL, r, &repeated));
    for (int k = 0; k < 6; ++k) {
        double q[3] = {0.4 + 0.02 * (k / 2), 0, 0};
        sh->exact_uv(sh, q[0], q + 1);
        CHECK_OK(pc_branch_add_point(NULL, repeated, 3, q));
    }
    CHECK_OK(pc_refine_and_compose(NULL, &proj, NULL, r));
    CHECK(r->branches[0].n_pieces > 0);
    CHECK(r->branches[1].n_pieces == 0 && r->branches[1].n_points == 1);
    CHECK(r->branches[2].n_pieces > 0);
    for (size_t i = 0; i < r->branches[2].n_pieces; ++i)
        CHECK(r->branches[2].pieces[i].t1 > r->branches[2].pieces[i].t0);
    projcurve_result_destroy(r);

    projcurve_result *r4 = NULL;
    CHECK_OK(pc_result_create(NULL, 4, &r4));
    CHECK_STATUS(pc_refine_and_compose(NULL, &proj, NULL, r4), PROJCURVE_ERR_INVALID_ARGUMENT);
    projcurve_result_destroy(r4);
}

int main(void)
{
    shape shapes[2];
    if (!make_height_field(&shapes[0]) || !make_cylinder(&shapes[1]))
        pc_test_skip("surface or curve creation is not available");
    for (int k = 0; k < 2; ++k) {
        test_tolerances(&shapes[k]);
        test_descending(&shapes[k]);
        test_automatic_tolerance(&shapes[k]);
    }
    test_bad_tolerances(&shapes[0]);
    test_piece_limit(&shapes[0]);
    test_failing_corrector(&shapes[0]);
    test_failing_corrector(&shapes[1]);
    test_degenerate_branches(&shapes[0]);
    for (int k = 0; k < 2; ++k)
        free_shape(&shapes[k]);
    return pc_test_finish("test_refine");
}
