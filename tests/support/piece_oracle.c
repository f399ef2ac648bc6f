/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Oracles for projection results: see piece_oracle.h. Evaluation goes through
 * the public API only, and pieces are evaluated by Bernstein sums, so nothing
 * here shares code with refine/ or compose/.
 */
#include "piece_oracle.h"

#include <math.h>
#include <string.h>

#define PI 3.14159265358979323846
/* Samples per piece: the deviation of a piece is a smooth bump, so the
 * largest of 9 samples is within 2% of its maximum (a parabola peaking
 * between two samples), well inside the 10% margin a controlled piece keeps;
 * the exact curve is sampled as densely again along the whole branch. */
#define DENSE_PER_PIECE 8
#define DENSE_EXACT 3000
#define ORACLE_MAX_ITER 50

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

static int oracle_correct(const pc_projector *self, double t, double uv[2], int *iterations)
{
    const pc_oracle_dir *d = self->data;
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

static int oracle_derivatives(const pc_projector *self, double t, double u, double v,
                            pc_proj_point *out)
{
    const pc_oracle_dir *d = self->data;
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
    /* Dir.(Su x Sv) / |Su x Sv| (projector.h; e1, e2 orthonormal to Dir) */
    const double area = vec3_norm(vec3_cross(s[1], s[2]));
    out->det = area > 0.0 ? (a * e - b * c) / area : 0.0;
    out->s = s[0];
    out->p = p[0];
    return 1;
}

static double oracle_residual(const pc_projector *self, double t, double u, double v)
{
    const pc_oracle_dir *d = self->data;
    pc_vec3 p[3], s;
    curve_eval(self->curve, t, p);
    surface_eval(self->surface, u, v, 0, &s);
    const pc_vec3 g = vec3_sub(s, p[0]);
    return hypot(vec3_dot(d->e1, g), vec3_dot(d->e2, g));
}

void pc_oracle_projector(const projcurve_surface *s, const projcurve_curve *c, const double dir[3],
                         pc_oracle_dir *d, pc_projector *proj)
{
    d->dir = vec3_normalize(vec3_load(dir));
    vec3_orthonormal_pair(d->dir, &d->e1, &d->e2);
    memset(proj, 0, sizeof *proj);
    proj->surface = s;
    proj->curve = c;
    proj->model_size = s->size;
    proj->newton_tol = 1e-12 * s->size;
    proj->newton_max_iter = 30;
    proj->correct = oracle_correct;
    proj->derivatives = oracle_derivatives;
    proj->residual = oracle_residual;
    proj->data = d;
}

/* Orthogonal projection (DESIGN.md, [PW96] eq. 5-6): F = [(S - P).Su;
 * (S - P).Sv] = 0, K = [g_ij + (S - P).S_ij], q' = K^-1 [P'.Su; P'.Sv]. */
static void ortho_system(const pc_vec3 s[6], pc_vec3 p, double k[4])
{
    const pc_vec3 d = vec3_sub(s[0], p);
    k[0] = vec3_dot(s[1], s[1]) + vec3_dot(d, s[3]);
    k[1] = vec3_dot(s[1], s[2]) + vec3_dot(d, s[4]);
    k[2] = k[1];
    k[3] = vec3_dot(s[2], s[2]) + vec3_dot(d, s[5]);
}

static int ortho_correct(const pc_projector *self, double t, double uv[2], int *iterations)
{
    pc_vec3 p[3];
    curve_eval(self->curve, t, p);
    for (int it = 0; it < self->newton_max_iter; ++it) {
        pc_vec3 s[6];
        surface_eval(self->surface, uv[0], uv[1], 2, s);
        const pc_vec3 d = vec3_sub(s[0], p[0]);
        const double r[2] = {-vec3_dot(d, s[1]), -vec3_dot(d, s[2])};
        if (iterations)
            *iterations = it;
        /* residual in model units: the tangential part of S - P */
        if (hypot(r[0] / vec3_norm(s[1]), r[1] / vec3_norm(s[2])) <= self->newton_tol)
            return 1;
        double k[4], delta[2];
        ortho_system(s, p[0], k);
        if (!mat2_solve(k[0], k[1], k[2], k[3], r, delta))
            return 0;
        uv[0] += delta[0];
        uv[1] += delta[1];
        clamp_domain(self->surface, uv);
    }
    return 0;
}

static int ortho_derivatives(const pc_projector *self, double t, double u, double v,
                             pc_proj_point *out)
{
    pc_vec3 p[3], s[6];
    curve_eval(self->curve, t, p);
    surface_eval(self->surface, u, v, 2, s);
    double k[4], q1[2];
    ortho_system(s, p[0], k);
    const double r[2] = {vec3_dot(p[1], s[1]), vec3_dot(p[1], s[2])};
    if (!mat2_solve(k[0], k[1], k[2], k[3], r, q1))
        return 0;
    memset(out, 0, sizeof *out);
    out->t = t, out->u = u, out->v = v;
    out->du = q1[0], out->dv = q1[1];
    /* det K / (|Su| |Sv|)^2 (projector.h) */
    const double scale = vec3_dot(s[1], s[1]) * vec3_dot(s[2], s[2]);
    out->det = scale > 0.0 ? (k[0] * k[3] - k[1] * k[2]) / scale : 0.0;
    out->s = s[0];
    out->p = p[0];
    return 1;
}

static double ortho_residual(const pc_projector *self, double t, double u, double v)
{
    pc_vec3 p[3], s[3];
    curve_eval(self->curve, t, p);
    surface_eval(self->surface, u, v, 1, s);
    const pc_vec3 d = vec3_sub(s[0], p[0]);
    return hypot(vec3_dot(d, s[1]) / vec3_norm(s[1]), vec3_dot(d, s[2]) / vec3_norm(s[2]));
}

void pc_oracle_projector_orthogonal(const projcurve_surface *s, const projcurve_curve *c,
                                    pc_projector *proj)
{
    memset(proj, 0, sizeof *proj);
    proj->surface = s;
    proj->curve = c;
    proj->model_size = s->size;
    proj->newton_tol = 1e-12 * s->size;
    proj->newton_max_iter = 30;
    proj->correct = ortho_correct;
    proj->derivatives = ortho_derivatives;
    proj->residual = ortho_residual;
}

/* Piece point and derivative at s by Bernstein sums (rational): the power
 * form B_i = C(n,i) s^i (1-s)^(n-i), B_i' = n (B_{i-1}^{n-1} - B_i^{n-1}). */
void pc_oracle_piece_eval(const pc_piece *pc, double s, pc_vec3 *x, pc_vec3 *dx)
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
static double distance_to_exact(pc_oracle_exact_fn exact, const void *user, double ta, double tb,
                                pc_vec3 x, double t)
{
    const double lo = ta < tb ? ta : tb, hi = ta < tb ? tb : ta;
    double best = INFINITY;
    for (int it = 0; it < ORACLE_MAX_ITER; ++it) {
        pc_vec3 q[3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
        exact(user, t, q);
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
        pc_oracle_piece_eval(pc, s, &c, &dc);
        const pc_vec3 d = vec3_sub(c, x);
        const double dist = vec3_norm(d);
        if (dist < best)
            best = dist;
        const double hs = 1e-6;
        pc_oracle_piece_eval(pc, s + hs <= 1.0 ? s + hs : s - hs, &c2, &dc2);
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

pc_oracle_measure pc_oracle_measure_branch(const pc_branch *b, pc_oracle_exact_fn exact,
                                           const void *user, const pc_patch_grid *g)
{
    pc_oracle_measure m = {0, 0, 0, 0, 0};
    const double ta = b->pieces[0].t0, tb = b->pieces[b->n_pieces - 1].t1;
    for (size_t i = 0; i < b->n_pieces; ++i) {
        const pc_piece *pc = &b->pieces[i];
        for (int k = 0; k <= DENSE_PER_PIECE; ++k) {
            const double s = (double)k / DENSE_PER_PIECE;
            pc_vec3 x;
            pc_oracle_piece_eval(pc, s, &x, NULL);
            const double d = distance_to_exact(exact, user, ta, tb, x, pc->t0 + s * (pc->t1 - pc->t0));
            if (d > m.hausdorff)
                m.hausdorff = d;
        }
        pc_vec3 q[3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}}, x0, x1;
        pc_oracle_piece_eval(pc, 0.0, &x0, NULL);
        pc_oracle_piece_eval(pc, 1.0, &x1, NULL);
        exact(user, pc->t0, q);
        m.max_end_err = fmax(m.max_end_err, vec3_dist(q[0], x0));
        exact(user, pc->t1, q);
        m.max_end_err = fmax(m.max_end_err, vec3_dist(q[0], x1));
        if (g != NULL && (!same_cell(g->breaks_u, g->spans_u, pc->uv[0], pc->uv[2]) ||
                          !same_cell(g->breaks_v, g->spans_v, pc->uv[1], pc->uv[3])))
            ++m.off_patch;
        if (i > 0) {
            const pc_piece *pv = &b->pieces[i - 1];
            const int n = pv->degree;
            const pc_vec3 t_end = vec3_sub(vec3_load(pv->ctrl + 3 * n), vec3_load(pv->ctrl + 3 * (n - 1)));
            const pc_vec3 t_start = vec3_sub(vec3_load(pc->ctrl + 3), vec3_load(pc->ctrl));
            m.max_angle = fmax(m.max_angle, angle_deg(t_end, t_start));
            pc_vec3 prev_end;
            pc_oracle_piece_eval(pv, 1.0, &prev_end, NULL);
            m.max_gap = fmax(m.max_gap, vec3_dist(prev_end, x0));
        }
    }
    /* exact -> output: dense samples of the exact curve onto their piece */
    size_t i = 0; /* pieces follow t (either way): walk them along */
    for (int k = 0; k <= DENSE_EXACT; ++k) {
        /* (the last sample is the branch end itself, not a rounding past it:
         * where a branch ends on a pole or a fold, the projection of the
         * curve just beyond is on another sheet, or does not exist) */
        const double t = k == DENSE_EXACT ? tb : ta + (tb - ta) * k / DENSE_EXACT;
        pc_vec3 q[3] = {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}};
        exact(user, t, q);
        while (i + 1 < b->n_pieces && (b->pieces[i].t1 - t) * (tb - ta) < 0.0)
            ++i;
        const pc_piece *pc = &b->pieces[i];
        const double d = distance_to_piece(pc, q[0], (t - pc->t0) / (pc->t1 - pc->t0));
        if (d > m.hausdorff)
            m.hausdorff = d;
    }
    return m;
}


/* The exact projection along a branch: Q(t) from the oracle's corrector
 * seeded by the branch's pcurve, Q'(t) = Su u' + Sv v'. */
typedef struct branch_exact {
    const pc_projector *proj;
    const pc_branch *branch;
    int *failures; /* corrector failures, counted */
    int *singular; /* points with a difference quotient for Q', counted */
    int *loose;    /* points within LOOSE_RESIDUAL_REL only, counted */
} branch_exact;

/* Where the oracle's Newton cannot reach its own tolerance (1e-12 of the
 * model size) — at a fold the projection has a double root and beyond its
 * tip none, at a domain edge the solution may lie outside the domain by a
 * rounding — a point whose residual (distance of S(u, v) from the line
 * P(t) + s Dir, or the tangential part of S - P) is within 1e-9 of the
 * model size is taken. On a fold such a point can lie along the ray up to
 * sqrt(2 r R) from the tip (R the radius of the surface's section, ~ the
 * model size): 4.5e-5 of the size, under 5% of the tightest eps_D this is
 * used with (1e-3 of the size, test_refine_robust). */
#define LOOSE_RESIDUAL_REL 1e-9

static void pcurve_guess(const pc_branch *b, double t, double uv[2])
{
    const double *p = b->points;
    const size_t n = b->n_points;
    const double dir = p[3 * (n - 1)] >= p[0] ? 1.0 : -1.0;
    size_t lo = 0, hi = n - 1; /* bisection for the segment holding t */
    while (hi - lo > 1) {
        const size_t mid = lo + (hi - lo) / 2;
        if (dir * (p[3 * mid] - t) <= 0.0)
            lo = mid;
        else
            hi = mid;
    }
    const double *a = p + 3 * lo, *c = p + 3 * hi;
    const double w = c[0] != a[0] ? (t - a[0]) / (c[0] - a[0]) : 0.0;
    uv[0] = a[1] + w * (c[1] - a[1]);
    uv[1] = a[2] + w * (c[2] - a[2]);
}

/* The exact point at t, from the branch's pcurve; 0 when the corrector fails. */
static int exact_point(const branch_exact *e, double t, double uv[2], pc_vec3 *x)
{
    pcurve_guess(e->branch, t, uv);
    const double guess[2] = {uv[0], uv[1]};
    if (!e->proj->correct(e->proj, t, uv, NULL)) {
        pc_projector loose = *e->proj;
        loose.newton_tol = LOOSE_RESIDUAL_REL * e->proj->model_size;
        uv[0] = guess[0];
        uv[1] = guess[1];
        if (!loose.correct(&loose, t, uv, NULL))
            return 0;
        ++*e->loose;
    }
    double s[3];
    projcurve_surface_eval(NULL, e->proj->surface, uv[0], uv[1], 0, s);
    *x = vec3_load(s);
    return 1;
}

/* Step of the difference quotient for Q' where q' is singular, relative to
 * the branch's t range: Q' only steers the Newton iteration on t (the
 * distances are those of exact points), so its O(step) error is harmless. */
#define SINGULAR_DIFF_REL 1e-7

static void exact_on_branch(const void *user, double t, pc_vec3 q[3])
{
    const branch_exact *e = user;
    double uv[2];
    pc_proj_point pt;
    q[2] = vec3(0.0, 0.0, 0.0);
    if (!exact_point(e, t, uv, &q[0])) {
        ++*e->failures;
        q[0] = vec3(NAN, NAN, NAN);
        return;
    }
    if (e->proj->derivatives(e->proj, t, uv[0], uv[1], &pt)) {
        double s[9];
        projcurve_surface_eval(NULL, e->proj->surface, uv[0], uv[1], 1, s);
        q[1] = vec3_add(vec3_scale(vec3_load(s + 3), pt.du), vec3_scale(vec3_load(s + 6), pt.dv));
        return;
    }
    /* q' is singular (on a collapsed edge, where Su = 0, the projection's
     * Jacobian is singular though the point is well defined): Q' as the
     * difference quotient of exact points inside the branch */
    const pc_branch *b = e->branch;
    const double first = b->points[0], last = b->points[3 * (b->n_points - 1)];
    const double lo = fmin(first, last), hi = fmax(first, last);
    const double h = SINGULAR_DIFF_REL * (hi - lo);
    const double ta = fmax(lo, t - h), tb = fmin(hi, t + h);
    double uv_a[2], uv_b[2];
    pc_vec3 xa, xb;
    if (!(tb > ta) || !exact_point(e, ta, uv_a, &xa) || !exact_point(e, tb, uv_b, &xb)) {
        ++*e->failures;
        q[0] = vec3(NAN, NAN, NAN);
        return;
    }
    ++*e->singular;
    q[1] = vec3_scale(vec3_sub(xb, xa), 1.0 / (tb - ta));
}

void pc_oracle_measure_result(const projcurve_result *r, const pc_projector *proj,
                              const pc_patch_grid *grid, pc_oracle_summary *out)
{
    memset(out, 0, sizeof *out);
    for (size_t i = 0; i < r->n_branches; ++i) {
        const pc_branch *b = &r->branches[i];
        if (b->n_pieces == 0) {
            ++out->branches_without_pieces;
            continue;
        }
        const branch_exact e = {proj, b, &out->failures, &out->singular_points,
                                &out->loose_points};
        const pc_oracle_measure m = pc_oracle_measure_branch(b, exact_on_branch, &e, grid);
        out->worst.hausdorff = fmax(out->worst.hausdorff, m.hausdorff);
        out->worst.max_angle = fmax(out->worst.max_angle, m.max_angle);
        out->worst.max_gap = fmax(out->worst.max_gap, m.max_gap);
        out->worst.max_end_err = fmax(out->worst.max_end_err, m.max_end_err);
        out->worst.off_patch += m.off_patch;
        out->pieces += b->n_pieces;
    }
}
