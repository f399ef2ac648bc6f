/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The directional projector's equations: q' and q'' (DESIGN.md frame form)
 * against central finite differences of the exact projection curve and
 * against the paper's forms ([SY13] eqs. (3.2), (3.3)); the Newton
 * system (3.9) against finite differences; the corrector's convergence.
 */
#include <math.h>
#include <stdio.h>

#include "check.h"
#include "directional/directional.h"
#include "trace_shapes.h"

/* Finite-difference step in t and the tolerances it allows: central
 * differences err by ~h^2 |q'''| (q' and q'') plus ~eps_newton / h and
 * ~eps_newton / h^2 of the corrected points (eps ~ 1e-13 here). */
#define FD_H 1e-4
#define TOL_D1 1e-6
#define TOL_D2 1e-4

static pc_vec3 sub(pc_vec3 a, pc_vec3 b) { return vec3_sub(a, b); }

/* q(t) corrected from a guess. */
static int point_at(const pc_projector *proj, double t, const double guess[2], double uv[2])
{
    uv[0] = guess[0];
    uv[1] = guess[1];
    return proj->correct(proj, t, uv, NULL);
}

/* [SY13] eq. (3.2) and the derivative of (3.2) in t, written out. */
static void paper_derivatives(const projcurve_surface *s, const projcurve_curve *c, pc_vec3 dir,
                              double t, double u, double v, double q1[2], double q2[2],
                              double printed_q2[2])
{
    pc_vec3 sd[6], p[3];
    pc_nurbs_surface_eval(&s->nurbs, u, v, 2, NULL, NULL, sd);
    pc_curve_eval(c, t, 2, NULL, p);
    const pc_vec3 su = sd[1], sv = sd[2];
    const pc_vec3 p1xd = vec3_cross(p[1], dir), p2xd = vec3_cross(p[2], dir);
    const double A = vec3_dot(sv, vec3_cross(su, dir)); /* Sv.(Su x Dir) */
    const double B = vec3_dot(su, vec3_cross(sv, dir)); /* Su.(Sv x Dir) */
    q1[0] = vec3_dot(sv, p1xd) / A;
    q1[1] = vec3_dot(su, p1xd) / B;
    const pc_vec3 su_t = vec3_add(vec3_scale(sd[3], q1[0]), vec3_scale(sd[4], q1[1]));
    const pc_vec3 sv_t = vec3_add(vec3_scale(sd[4], q1[0]), vec3_scale(sd[5], q1[1]));
    /* d/dt of u' A = Sv.(P' x Dir) */
    const double dA = vec3_dot(sv_t, vec3_cross(su, dir)) + vec3_dot(sv, vec3_cross(su_t, dir));
    const double dB = vec3_dot(su_t, vec3_cross(sv, dir)) + vec3_dot(su, vec3_cross(sv_t, dir));
    q2[0] = (vec3_dot(sv, p2xd) + vec3_dot(sv_t, p1xd) - q1[0] * dA) / A;
    q2[1] = (vec3_dot(su, p2xd) + vec3_dot(su_t, p1xd) - q1[1] * dB) / B;
    /* (3.3) as printed: numerator over the derivative of the denominator */
    printed_q2[0] = (vec3_dot(sv, p2xd) + vec3_dot(sv_t, p1xd)) / dA;
    printed_q2[1] = (vec3_dot(su, p2xd) + vec3_dot(su_t, p1xd)) / dB;
}

static double rel(double a, double b)
{
    return fabs(a - b) / fmax(1.0, fmax(fabs(a), fabs(b)));
}

static void test_derivatives(void)
{
    projcurve_surface *s = shape_bumpy(8.0, 777);
    const double pts[18] = {15, 20, 40, 30, 60, 45, 50, 30, 35, 65, 70, 50, 80, 40, 40, 85, 75, 45};
    projcurve_curve *c = shape_bspline_curve(3, 6, pts);
    CHECK(s != NULL && c != NULL);
    const pc_vec3 dir = vec3_normalize(vec3(0.1, -0.2, -1.0));
    pc_projector proj;
    pc_directional_data data;
    pc_directional_cache cache;
    pc_directional_init(&proj, &data, &cache, s, c, dir, 1e-13, 30);
    double worst1 = 0, worst2 = 0, worst_paper1 = 0, worst_paper2 = 0, best_printed = INFINITY;
    double worst_cached = 0;
    for (int k = 1; k <= 9; ++k) {
        const double t = 0.1 * k;
        pc_vec3 p;
        pc_curve_eval(c, t, 0, NULL, &p);
        double guess[2] = {p.x / 100.0, p.y / 100.0}, q[2], qm[2], qp[2];
        CHECK(point_at(&proj, t, guess, q));
        /* derivatives from the evaluation cached by the corrector (moved by
         * its last step, see shift_cache) and from a fresh evaluation */
        pc_proj_point cached, pt;
        CHECK(proj.derivatives(&proj, t, q[0], q[1], &cached));
        cache.surf_valid = 0;
        CHECK(proj.derivatives(&proj, t, q[0], q[1], &pt));
        worst_cached = fmax(worst_cached, fmax(rel(cached.du, pt.du), rel(cached.dv, pt.dv)));
        worst_cached = fmax(worst_cached, fmax(rel(cached.ddu, pt.ddu), rel(cached.ddv, pt.ddv)));
        const double gm[2] = {q[0] - FD_H * pt.du, q[1] - FD_H * pt.dv};
        const double gp[2] = {q[0] + FD_H * pt.du, q[1] + FD_H * pt.dv};
        CHECK(point_at(&proj, t - FD_H, gm, qm));
        CHECK(point_at(&proj, t + FD_H, gp, qp));
        for (int i = 0; i < 2; ++i) {
            const double d1 = (qp[i] - qm[i]) / (2 * FD_H);
            const double d2 = (qp[i] - 2 * q[i] + qm[i]) / (FD_H * FD_H);
            worst1 = fmax(worst1, rel(i ? pt.dv : pt.du, d1));
            worst2 = fmax(worst2, rel(i ? pt.ddv : pt.ddu, d2));
        }
        double a1[2], a2[2], printed[2];
        paper_derivatives(s, c, dir, t, q[0], q[1], a1, a2, printed);
        worst_paper1 = fmax(worst_paper1, fmax(rel(a1[0], pt.du), rel(a1[1], pt.dv)));
        worst_paper2 = fmax(worst_paper2, fmax(rel(a2[0], pt.ddu), rel(a2[1], pt.ddv)));
        best_printed = fmin(best_printed, fmax(rel(printed[0], pt.ddu), rel(printed[1], pt.ddv)));
        /* det: Dir.(Su x Sv) / |Su x Sv| */
        pc_vec3 sd[3];
        pc_nurbs_surface_eval(&s->nurbs, q[0], q[1], 1, NULL, NULL, sd);
        const pc_vec3 n = vec3_cross(sd[1], sd[2]);
        CHECK_NEAR(pt.det, vec3_dot(dir, n) / vec3_norm(n), 1e-14);
        /* |Q'| of eq. (3.6) */
        CHECK_NEAR(pt.speed, vec3_norm(vec3_add(vec3_scale(sd[1], pt.du), vec3_scale(sd[2], pt.dv))),
                   1e-12 * pt.speed);
    }
    printf("q' vs FD %.3g, q'' vs FD %.3g; vs (3.2) %.3g, vs d/dt (3.2) %.3g; "
           "(3.3) as printed off by >= %.3g\n",
           worst1, worst2, worst_paper1, worst_paper2, best_printed);
    printf("cached vs fresh evaluation: %.3g\n", worst_cached);
    /* the corrector's last step moves the point by at most 1e-7 model sizes
     * and keeps S's second derivatives from before it: q'' moves ~1e-7
     * relative per unit of |S'''| / |S''| */
    CHECK(worst_cached <= 1e-6);
    CHECK(worst1 <= TOL_D1);
    CHECK(worst2 <= TOL_D2);
    CHECK(worst_paper1 <= 1e-12);
    CHECK(worst_paper2 <= 1e-10);
    /* A fact worth a check: the printed (3.3) is not the derivative of
     * (3.2) (it divides by the derivative of the denominator). */
    CHECK(best_printed > 1e-3);
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

/* f = r.Su, g = r.Sv with r = (S - p) x Dir (eq. (3.9)): the Jacobian by
 * finite differences against the analytic one, whose cross terms are
 * Su.(Sv x Dir) and Sv.(Su x Dir) (the paper prints Dir x Sv, Dir x Su:
 * the opposite sign). */
static void fg(const projcurve_surface *s, pc_vec3 p, pc_vec3 dir, double u, double v,
               double out[2])
{
    pc_vec3 sd[3];
    pc_nurbs_surface_eval(&s->nurbs, u, v, 1, NULL, NULL, sd);
    const pc_vec3 r = vec3_cross(sub(sd[0], p), dir);
    out[0] = vec3_dot(r, sd[1]);
    out[1] = vec3_dot(r, sd[2]);
}

static void test_newton_system(void)
{
    projcurve_surface *s = shape_bumpy(8.0, 99);
    CHECK(s != NULL);
    const pc_vec3 dir = vec3_normalize(vec3(0.1, -0.2, -1.0));
    const pc_vec3 p = vec3(40, 55, 45);
    const double u = 0.43, v = 0.61, h = 1e-6;
    pc_vec3 sd[6];
    pc_nurbs_surface_eval(&s->nurbs, u, v, 2, NULL, NULL, sd);
    const pc_vec3 r = vec3_cross(sub(sd[0], p), dir);
    const double j_analytic[4] = {
        vec3_dot(sd[3], r), vec3_dot(sd[4], r) + vec3_dot(sd[1], vec3_cross(sd[2], dir)),
        vec3_dot(sd[4], r) + vec3_dot(sd[2], vec3_cross(sd[1], dir)), vec3_dot(sd[5], r)};
    const double j_printed[4] = {
        vec3_dot(sd[3], r), vec3_dot(sd[4], r) + vec3_dot(sd[1], vec3_cross(dir, sd[2])),
        vec3_dot(sd[4], r) + vec3_dot(sd[2], vec3_cross(dir, sd[1])), vec3_dot(sd[5], r)};
    double fp[2], fm[2], j_fd[4];
    fg(s, p, dir, u + h, v, fp);
    fg(s, p, dir, u - h, v, fm);
    j_fd[0] = (fp[0] - fm[0]) / (2 * h);
    j_fd[2] = (fp[1] - fm[1]) / (2 * h);
    fg(s, p, dir, u, v + h, fp);
    fg(s, p, dir, u, v - h, fm);
    j_fd[1] = (fp[0] - fm[0]) / (2 * h);
    j_fd[3] = (fp[1] - fm[1]) / (2 * h);
    double worst = 0, printed = 0, scale = 0;
    for (int k = 0; k < 4; ++k) {
        scale = fmax(scale, fabs(j_fd[k]));
        worst = fmax(worst, fabs(j_fd[k] - j_analytic[k]));
        printed = fmax(printed, fabs(j_fd[k] - j_printed[k]));
    }
    printf("(3.9) Jacobian vs FD: analytic %.3g, as printed %.3g (scale %.3g)\n", worst, printed,
           scale);
    CHECK(worst <= 1e-6 * scale);
    CHECK(printed > 1e-3 * scale);
    projcurve_surface_destroy(s);
}

/* The corrector from a guess 5% of the domain off: converges to the
 * Newton tolerance within a few iterations. */
static void test_corrector(void)
{
    projcurve_surface *s = shape_bumpy(8.0, 4242);
    const double pts[6] = {20, 30, 40, 80, 70, 40};
    projcurve_curve *c = shape_bspline_curve(1, 2, pts);
    CHECK(s != NULL && c != NULL);
    const pc_vec3 dir = vec3(0, 0, -1);
    pc_projector proj;
    pc_directional_data data;
    pc_directional_cache cache;
    pc_directional_init(&proj, &data, &cache, s, c, dir, 1e-12, 20);
    for (int k = 0; k <= 10; ++k) {
        const double t = 0.1 * k;
        pc_vec3 p;
        pc_curve_eval(c, t, 0, NULL, &p);
        double uv[2] = {p.x / 100.0 + 0.05, p.y / 100.0 - 0.05};
        int it = 0;
        CHECK(proj.correct(&proj, t, uv, &it));
        CHECK(it <= 8);
        CHECK(proj.residual(&proj, t, uv[0], uv[1]) <= 1e-12 * s->size);
    }
    projcurve_curve_destroy(c);
    projcurve_surface_destroy(s);
}

int main(void)
{
    test_derivatives();
    test_newton_system();
    test_corrector();
    return pc_test_finish("test_trace_derivatives");
}
