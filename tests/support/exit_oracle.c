/* SPDX-License-Identifier: BSD-3-Clause */
#include "exit_oracle.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

/* Newton iterations per classification. Quadratic convergence from a point
 * of the projection at a nearby t needs a handful; the rest absorb the
 * bouncing of a clamped iteration whose root is outside. */
#define EXIT_NEWTON_MAX_ITER 40
/* A residual |S - P - lambda Dir| below this fraction of the model size is
 * a point of the projection: three orders above the rounding of S (~1e-16
 * of the size per coordinate over a few dozen flops). */
#define EXIT_ON_CURVE 1e-13
/* A classification may move lambda at most by this fraction of the model
 * size: farther, Newton has jumped to another sheet of S. */
#define EXIT_MAX_LAMBDA_MOVE 0.1
/* Bisection steps: from a bracket of the whole domain down to rounding. */
#define EXIT_MAX_BISECTIONS 200

typedef struct oracle_ctx {
    const projcurve_surface *s;
    const projcurve_curve *c;
    double d[3];
    double dom[4];
    double size;
} oracle_ctx;

static double clamp(double x, double lo, double hi)
{
    return x < lo ? lo : (x > hi ? hi : x);
}

/* Residual S(u, v) - P(t) - lambda d and, with jac, the columns Su, Sv. */
static double residual(const oracle_ctx *o, double t, double u, double v, double lambda,
                       double f[3], double su[3], double sv[3])
{
    double sd[9], p[3];
    projcurve_surface_eval(NULL, o->s, u, v, 1, sd);
    projcurve_curve_eval(NULL, o->c, t, 0, p);
    for (int k = 0; k < 3; ++k) {
        f[k] = sd[k] - p[k] - lambda * o->d[k];
        su[k] = sd[3 + k];
        sv[k] = sd[6 + k];
    }
    return sqrt(f[0] * f[0] + f[1] * f[1] + f[2] * f[2]);
}

static double det3(const double a[3], const double b[3], const double c[3])
{
    return a[0] * (b[1] * c[2] - b[2] * c[1]) - a[1] * (b[0] * c[2] - b[2] * c[0]) +
           a[2] * (b[0] * c[1] - b[1] * c[0]);
}

/* Newton on (u, v, lambda) at fixed t from *p; 1 when it reaches a point of
 * the projection in the domain (then stored in *p). */
static int project_at(const oracle_ctx *o, double t, exit_oracle_point *p)
{
    double u = p->u, v = p->v, lambda = p->lambda;
    for (int it = 0; it < EXIT_NEWTON_MAX_ITER; ++it) {
        double f[3], su[3], sv[3];
        const double r = residual(o, t, u, v, lambda, f, su, sv);
        if (r <= EXIT_ON_CURVE * o->size) {
            if (fabs(lambda - p->lambda) > EXIT_MAX_LAMBDA_MOVE * o->size)
                return 0;
            projcurve_surface_eval(NULL, o->s, u, v, 0, p->x);
            p->t = t;
            p->u = u;
            p->v = v;
            p->lambda = lambda;
            return 1;
        }
        /* J [du dv dl]^T = -f with J = [Su Sv -d] (Cramer) */
        const double nd[3] = {-o->d[0], -o->d[1], -o->d[2]};
        const double nf[3] = {-f[0], -f[1], -f[2]};
        const double det = det3(su, sv, nd);
        if (!(fabs(det) > 0.0))
            return 0;
        u = clamp(u + det3(nf, sv, nd) / det, o->dom[0], o->dom[1]);
        v = clamp(v + det3(su, nf, nd) / det, o->dom[2], o->dom[3]);
        lambda += det3(su, sv, nf) / det;
    }
    return 0;
}

double exit_oracle_margin(const projcurve_surface *s, double u, double v)
{
    double dom[4];
    projcurve_surface_domain(NULL, s, dom);
    const double mu = fmin(u - dom[0], dom[1] - u) / (dom[1] - dom[0]);
    const double mv = fmin(v - dom[2], dom[3] - v) / (dom[3] - dom[2]);
    return fmin(mu, mv);
}

int exit_oracle_crossing(const projcurve_surface *s, const projcurve_curve *c,
                         const double dir[3], double t_in, double u_in, double v_in,
                         double t_out, exit_oracle_point *out)
{
    oracle_ctx o = {s, c, {0, 0, 0}, {0, 0, 0, 0}, 0.0};
    const double dn = sqrt(dir[0] * dir[0] + dir[1] * dir[1] + dir[2] * dir[2]);
    for (int k = 0; k < 3; ++k)
        o.d[k] = dir[k] / dn;
    projcurve_surface_domain(NULL, s, o.dom);
    double box[6];
    projcurve_surface_bounds(NULL, s, box);
    o.size = sqrt((box[3] - box[0]) * (box[3] - box[0]) + (box[4] - box[1]) * (box[4] - box[1]) +
                  (box[5] - box[2]) * (box[5] - box[2]));
    /* lambda of the start: the distance along d from P(t_in) to S(u_in, v_in) */
    double x[3], p[3];
    projcurve_surface_eval(NULL, s, u_in, v_in, 0, x);
    projcurve_curve_eval(NULL, c, t_in, 0, p);
    exit_oracle_point in = {t_in, u_in, v_in,
                            (x[0] - p[0]) * o.d[0] + (x[1] - p[1]) * o.d[1] +
                                (x[2] - p[2]) * o.d[2],
                            {0, 0, 0}};
    if (!project_at(&o, t_in, &in))
        return 0;
    exit_oracle_point probe = in;
    if (project_at(&o, t_out, &probe))
        return 0;
    double t_a = t_in, t_b = t_out;
    for (int k = 0; k < EXIT_MAX_BISECTIONS; ++k) {
        const double mid = 0.5 * (t_a + t_b);
        if (mid == t_a || mid == t_b)
            break;
        probe = in;
        if (project_at(&o, mid, &probe)) {
            in = probe;
            t_a = mid;
        } else {
            t_b = mid;
        }
    }
    *out = in;
    return 1;
}

static double dist3(const double a[3], const double b[3])
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

static double model_size(const projcurve_surface *s)
{
    double box[6];
    projcurve_surface_bounds(NULL, s, box);
    return sqrt((box[3] - box[0]) * (box[3] - box[0]) + (box[4] - box[1]) * (box[4] - box[1]) +
                (box[5] - box[2]) * (box[5] - box[2]));
}

/* One end: vertex e on the boundary, n its neighbour in the branch. */
static void check_end(const projcurve_surface *s, const projcurve_curve *c, const double dir[3],
                      const double *e, const double *n, exit_oracle_report *rep)
{
    double t0, t1;
    projcurve_curve_domain(NULL, c, &t0, &t1);
    const double t_out = clamp(e[0] + (e[0] - n[0]), t0, t1);
    rep->ends++;
    rep->max_margin = fmax(rep->max_margin, exit_oracle_margin(s, e[1], e[2]));
    exit_oracle_point x;
    if (!exit_oracle_crossing(s, c, dir, n[0], n[1], n[2], t_out, &x)) {
        rep->not_found++;
        return;
    }
    /* both ends of the projection line: the point on S and the curve's
     * point (a boundary end off in t alone can keep its point on S when
     * the branch slides along the side) */
    double y[3], pe[3], pc[3];
    projcurve_surface_eval(NULL, s, e[1], e[2], 0, y);
    projcurve_curve_eval(NULL, c, e[0], 0, pe);
    projcurve_curve_eval(NULL, c, x.t, 0, pc);
    const double d = fmax(dist3(x.x, y), dist3(pc, pe));
    rep->max_dist = fmax(rep->max_dist, d / model_size(s));
    rep->max_dt = fmax(rep->max_dt, fabs(x.t - e[0]));
}

void exit_oracle_check_ends(const projcurve_surface *s, const projcurve_curve *c,
                            const double dir[3], const projcurve_result *r,
                            exit_oracle_report *rep)
{
    *rep = (exit_oracle_report){0, 0, 0.0, 0.0, 0.0};
    for (size_t i = 0; i < projcurve_result_branch_count(r); ++i) {
        projcurve_branch_start start;
        projcurve_branch_end end;
        size_t n = 0;
        projcurve_result_branch_info(NULL, r, i, NULL, &start, &end, &n, NULL);
        if (n < 2 || (start != PROJCURVE_START_BOUNDARY && end != PROJCURVE_END_BOUNDARY))
            continue;
        double *p = malloc(3 * n * sizeof *p);
        if (p == NULL) {
            rep->not_found++;
            continue;
        }
        projcurve_result_branch_points(NULL, r, i, n, p, &n);
        if (start == PROJCURVE_START_BOUNDARY)
            check_end(s, c, dir, p, p + 3, rep);
        if (end == PROJCURVE_END_BOUNDARY)
            check_end(s, c, dir, p + 3 * (n - 1), p + 3 * (n - 2), rep);
        free(p);
    }
}

void exit_oracle_print(const char *name, const exit_oracle_report *rep)
{
    printf("%s: %zu boundary ends, %zu without a crossing; off the crossing by %.3g of the "
           "model size (t by %.3g), off the boundary by %.3g\n",
           name, rep->ends, rep->not_found, rep->max_dist, rep->max_dt, rep->max_margin);
}
