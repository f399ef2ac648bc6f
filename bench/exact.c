/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The exact-projection oracle (see exact.h).
 */
#include "exact.h"

#include <math.h>
#include <stdlib.h>

/* Newton stops when the update is below this fraction of the domain size,
 * or the residual below this fraction of the model size. */
#define CORRECT_STEP_TOL 1e-15
#define CORRECT_RESIDUAL_TOL 1e-14
#define CORRECT_MAX_ITER 40
/* A guess may land this far (fraction of the domain) outside and be
 * clamped back; a converged point farther outside is not on the surface. */
#define DOMAIN_SLACK 1e-12
/* Golden-section iterations: 0.618^64 ~ 4e-14 of the bracket (two sample
 * spacings), below 1e-16 of the curve domain. */
#define GOLDEN_ITER 64
/* Hits or foot points kept per curve parameter. */
#define MAX_HITS_PER_T 16

static double dot3(const double *a, const double *b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

static void sub3(const double *a, const double *b, double *r)
{
    r[0] = a[0] - b[0];
    r[1] = a[1] - b[1];
    r[2] = a[2] - b[2];
}

static double dist3(const double *a, const double *b)
{
    double d[3];
    sub3(a, b, d);
    return sqrt(dot3(d, d));
}

static double clampd(double x, double lo, double hi) { return x < lo ? lo : x > hi ? hi : x; }

/* Orthonormal pair perpendicular to the unit vector d. */
static void orthonormal_pair(const double d[3], double e1[3], double e2[3])
{
    const double a[3] = {fabs(d[0]) < 0.9 ? 1.0 : 0.0, fabs(d[0]) < 0.9 ? 0.0 : 1.0, 0.0};
    const double k = dot3(a, d);
    for (int i = 0; i < 3; ++i)
        e1[i] = a[i] - k * d[i];
    const double n = sqrt(dot3(e1, e1));
    for (int i = 0; i < 3; ++i)
        e1[i] /= n;
    e2[0] = d[1] * e1[2] - d[2] * e1[1];
    e2[1] = d[2] * e1[0] - d[0] * e1[2];
    e2[2] = d[0] * e1[1] - d[1] * e1[0];
}

/* Residual F and Jacobian J of the projection equations at (u, v). */
static int equations(const pcb_exact *ex, const double *P, double u, double v, double F[2],
                     double J[4], double S[3])
{
    double d[18];
    if (projcurve_surface_eval(NULL, ex->surface, u, v, ex->orthogonal ? 2 : 1, d) !=
        PROJCURVE_OK)
        return 0;
    const double *Su = d + 3, *Sv = d + 6;
    double r[3];
    sub3(d, P, r);
    S[0] = d[0];
    S[1] = d[1];
    S[2] = d[2];
    if (ex->orthogonal) {
        const double *Suu = d + 9, *Suv = d + 12, *Svv = d + 15;
        F[0] = dot3(r, Su);
        F[1] = dot3(r, Sv);
        J[0] = dot3(Su, Su) + dot3(r, Suu);
        J[1] = J[2] = dot3(Su, Sv) + dot3(r, Suv);
        J[3] = dot3(Sv, Sv) + dot3(r, Svv);
    } else {
        F[0] = dot3(ex->e1, r);
        F[1] = dot3(ex->e2, r);
        J[0] = dot3(ex->e1, Su);
        J[1] = dot3(ex->e1, Sv);
        J[2] = dot3(ex->e2, Su);
        J[3] = dot3(ex->e2, Sv);
    }
    return 1;
}

int pcb_exact_correct(const pcb_exact *ex, double t, double uv[2], double p[3])
{
    double P[3];
    if (projcurve_curve_eval(NULL, ex->curve, t, 0, P) != PROJCURVE_OK)
        return 0;
    const double *dom = ex->domain;
    const double span = fmax(dom[1] - dom[0], dom[3] - dom[2]);
    double u = clampd(uv[0], dom[0], dom[1]), v = clampd(uv[1], dom[2], dom[3]);
    double S[3];
    for (int it = 0; it < CORRECT_MAX_ITER; ++it) {
        double F[2], J[4];
        if (!equations(ex, P, u, v, F, J, S))
            return 0;
        /* Residuals of both kinds are lengths (orthogonal: length^2 / |S_u|). */
        const double scale = ex->orthogonal ? ex->size * ex->size : ex->size;
        const double det = J[0] * J[3] - J[1] * J[2];
        if (!(fabs(det) > 0.0))
            return 0;
        const double du = -(J[3] * F[0] - J[1] * F[1]) / det;
        const double dv = -(J[0] * F[1] - J[2] * F[0]) / det;
        const double nu = u + du, nv = v + dv;
        if (nu < dom[0] - span || nu > dom[1] + span || nv < dom[2] - span || nv > dom[3] + span)
            return 0;
        const int small_step = fabs(du) + fabs(dv) <= CORRECT_STEP_TOL * span;
        const int small_residual = fabs(F[0]) + fabs(F[1]) <= CORRECT_RESIDUAL_TOL * scale;
        if (small_step || small_residual) {
            if (nu < dom[0] - DOMAIN_SLACK * span || nu > dom[1] + DOMAIN_SLACK * span ||
                nv < dom[2] - DOMAIN_SLACK * span || nv > dom[3] + DOMAIN_SLACK * span)
                return 0;
            u = clampd(nu, dom[0], dom[1]);
            v = clampd(nv, dom[2], dom[3]);
            double F2[2], J2[4];
            if (!equations(ex, P, u, v, F2, J2, S))
                return 0;
            if (!ex->orthogonal) {
                double r[3];
                sub3(S, P, r);
                if (dot3(r, ex->dir) <= 0.0)
                    return 0;  /* behind the curve: not on the ray */
            }
            uv[0] = u;
            uv[1] = v;
            if (p) {
                p[0] = S[0];
                p[1] = S[1];
                p[2] = S[2];
            }
            return 1;
        }
        u = clampd(nu, dom[0], dom[1]);
        v = clampd(nv, dom[2], dom[3]);
    }
    return 0;
}

/* Appends one sample; returns 0 on allocation failure. */
static int push_point(pcb_exact *ex, size_t *cap, const pcb_exact_point *pt)
{
    if (ex->n == *cap) {
        const size_t ncap = *cap ? 2 * *cap : 1024;
        pcb_exact_point *np = realloc(ex->pts, ncap * sizeof *np);
        if (!np)
            return 0;
        ex->pts = np;
        *cap = ncap;
    }
    ex->pts[ex->n++] = *pt;
    return 1;
}

/* The exact points of P(t): ray hits or foot points, as (u, v) pairs. */
static projcurve_status points_at(projcurve_context *ctx, const pcb_exact *ex, const double P[3],
                                  double *uv, size_t *count)
{
    if (ex->orthogonal)
        return projcurve_surface_foot_points(ctx, ex->surface, P, MAX_HITS_PER_T, uv, count);
    double hits[3 * MAX_HITS_PER_T];
    const projcurve_status st = projcurve_surface_intersect_line(
        ctx, ex->surface, P, ex->dir, 1, MAX_HITS_PER_T, hits, NULL, count);
    if (st == PROJCURVE_OK)
        for (size_t k = 0; k < *count && k < MAX_HITS_PER_T; ++k) {
            uv[2 * k] = hits[3 * k];
            uv[2 * k + 1] = hits[3 * k + 1];
        }
    return st;
}

projcurve_status pcb_exact_sample(projcurve_context *ctx, pcb_exact *ex,
                                  const projcurve_surface *surface, const projcurve_curve *curve,
                                  int orthogonal, const double dir[3], size_t n_t)
{
    ex->surface = surface;
    ex->curve = curve;
    ex->orthogonal = orthogonal;
    ex->pts = NULL;
    ex->n = 0;
    double box[6];
    projcurve_status st = projcurve_surface_domain(ctx, surface, ex->domain);
    if (st == PROJCURVE_OK)
        st = projcurve_surface_bounds(ctx, surface, box);
    if (st == PROJCURVE_OK)
        st = projcurve_curve_domain(ctx, curve, &ex->t0, &ex->t1);
    if (st != PROJCURVE_OK)
        return st;
    ex->size = sqrt((box[3] - box[0]) * (box[3] - box[0]) + (box[4] - box[1]) * (box[4] - box[1]) +
                    (box[5] - box[2]) * (box[5] - box[2]));
    const double dn = orthogonal ? 1.0 : sqrt(dot3(dir, dir));
    for (int i = 0; i < 3; ++i)
        ex->dir[i] = orthogonal ? (i == 2) : dir[i] / dn;
    orthonormal_pair(ex->dir, ex->e1, ex->e2);
    if (n_t < 2)
        n_t = 2;
    ex->dt = (ex->t1 - ex->t0) / (double)(n_t - 1);
    size_t cap = 0;
    for (size_t i = 0; i < n_t && st == PROJCURVE_OK; ++i) {
        pcb_exact_point pt;
        pt.t = i + 1 == n_t ? ex->t1 : ex->t0 + ex->dt * (double)i;
        double P[3], uv[2 * MAX_HITS_PER_T];
        size_t count = 0;
        st = projcurve_curve_eval(ctx, curve, pt.t, 0, P);
        if (st == PROJCURVE_OK)
            st = points_at(ctx, ex, P, uv, &count);
        for (size_t k = 0; st == PROJCURVE_OK && k < count && k < MAX_HITS_PER_T; ++k) {
            double q[2] = {uv[2 * k], uv[2 * k + 1]};
            if (!pcb_exact_correct(ex, pt.t, q, pt.p))
                continue;  /* a grazing hit Newton cannot sharpen: leave it out */
            pt.u = q[0];
            pt.v = q[1];
            pt.primary = !orthogonal || k == 0;
            if (!push_point(ex, &cap, &pt))
                st = PROJCURVE_ERR_NO_MEMORY;
        }
    }
    if (st != PROJCURVE_OK)
        pcb_exact_free(ex);
    return st;
}

void pcb_exact_free(pcb_exact *ex)
{
    free(ex->pts);
    ex->pts = NULL;
    ex->n = 0;
}

/* |x - E(t)| with E(t) corrected from the guess uv (updated on success);
 * infinity where E(t) does not exist. */
static double distance_at(const pcb_exact *ex, double t, double uv[2], const double x[3])
{
    double q[2] = {uv[0], uv[1]}, p[3];
    if (t < ex->t0 || t > ex->t1 || !pcb_exact_correct(ex, t, q, p))
        return INFINITY;
    uv[0] = q[0];
    uv[1] = q[1];
    return dist3(x, p);
}

double pcb_exact_distance_window(const pcb_exact *ex, const double x[3], double ta, double tb,
                                 const double uv0[2])
{
    const double g = 0.5 * (sqrt(5.0) - 1.0);
    double a = ta, b = tb;
    double uv_c[2] = {uv0[0], uv0[1]}, uv_d[2] = {uv0[0], uv0[1]};
    double c = b - g * (b - a), d = a + g * (b - a);
    double fc = distance_at(ex, c, uv_c, x), fd = distance_at(ex, d, uv_d, x);
    for (int it = 0; it < GOLDEN_ITER; ++it) {
        if (fc < fd) {
            b = d;
            d = c;
            fd = fc;
            uv_d[0] = uv_c[0];
            uv_d[1] = uv_c[1];
            c = b - g * (b - a);
            fc = distance_at(ex, c, uv_c, x);
        } else {
            a = c;
            c = d;
            fc = fd;
            uv_c[0] = uv_d[0];
            uv_c[1] = uv_d[1];
            d = a + g * (b - a);
            fd = distance_at(ex, d, uv_d, x);
        }
    }
    return fmin(fc, fd);
}

double pcb_exact_distance(const pcb_exact *ex, const double x[3])
{
    if (ex->n == 0)
        return INFINITY;
    size_t best = 0;
    double best_d = INFINITY;
    for (size_t i = 0; i < ex->n; ++i) {
        const double d = dist3(x, ex->pts[i].p);
        if (d < best_d) {
            best_d = d;
            best = i;
        }
    }
    /* Refine over one sample spacing either side of the nearest sample. */
    const pcb_exact_point *s = &ex->pts[best];
    const double uv[2] = {s->u, s->v};
    return fmin(best_d, pcb_exact_distance_window(ex, x, s->t - ex->dt, s->t + ex->dt, uv));
}
