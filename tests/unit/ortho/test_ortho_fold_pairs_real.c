/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Folds in pairs: linkrods.step curve 74 leaves the edge of surface 1 (a
 * fillet of degree 6 x 10 whose v knots are all C0) and passes, at
 * t ~ 0.75, about one radius of curvature from it: the foot points race
 * across the fillet, and at each v knot two centres of curvature come
 * 1e-3 apart in t (a minimum dies at one just after another is born at the
 * other). Three branches of minima, 0.065, 0.02 and 0.14 long in t, lie
 * between two foot-point searches of the sweep (0.17 apart). The tracer
 * once stepped 0.06 in t from the third straight onto the first, across
 * both pairs; the refinement could not verify that segment, and the
 * result said FAILED with the second branch and half the first missing:
 * the foot points of P(0.75653) 418 eps_D from every piece (the real-data
 * sweep, case #2667). Surface 5 and curve 76 are its mirror image (t and v
 * reversed). On surface 9, curve 38 the sweep found only the branch after
 * a fold pair at t ~ 2.6608; its backward trace stalled there and the
 * minima before it (t from 2.641) were missing with no failure reported
 * (the foot of P(2.65072) 707 eps_D from the result, case #1387).
 *
 * Oracles, independent of the tracer: the sweep's verifier
 * (support/sweep_verify.c: every piece sample within eps_D of an exact foot
 * point, every local minimum of the distance found by its mesh and Newton
 * within eps_D of a piece) at 32 t over the curve, and a brute force over
 * the fold region: at 111 t (1e-3 apart), the local minima in v of the
 * distance from P(t) to S (for each of 401 v, the minimum over u by a scan
 * and golden section) polished by Newton, each to lie within eps_D of a piece unless
 * it is on the edge of the domain (not a foot point) or its t lies in a
 * stretch the result reports as not followed (beside a FAILED end or
 * start, at most 0.02 long in t). Last, the verifier's own brute force
 * where S folds (check_verifier_on_fold).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "ray_oracle.h"
#include "sweep_verify.h"

#define BRUTE_T 110
#define BRUTE_V 400
#define BRUTE_U 40
/* A stretch beside a FAILED end may be this long in t: the part of a
 * branch between the step that went across a fold pair and the fold (on
 * surface 5, a branch started beside a fold stepped back across the pair
 * from its seed: 0.011 of it is reported as not followed). */
#define MAX_GAP_T 0.02

typedef struct foot_case {
    size_t surface, curve;
    double t_lo, t_hi; /* the fold region */
} foot_case;

static double d2(const projcurve_surface *s, double u, double v, const double p[3])
{
    double f[3];
    projcurve_surface_eval(NULL, s, u, v, 0, f);
    return (f[0] - p[0]) * (f[0] - p[0]) + (f[1] - p[1]) * (f[1] - p[1]) +
           (f[2] - p[2]) * (f[2] - p[2]);
}

/* min over u of |S(u, v) - p|^2 (scan, then golden section); *u_at gets u. */
static double min_over_u(const projcurve_surface *s, const double dom[4], double v,
                         const double p[3], double *u_at)
{
    double bu = dom[0], bd = HUGE_VAL;
    for (int k = 0; k <= BRUTE_U; ++k) {
        const double u = dom[0] + (dom[1] - dom[0]) * k / BRUTE_U, d = d2(s, u, v, p);
        if (d < bd)
            bd = d, bu = u;
    }
    const double w = (dom[1] - dom[0]) / BRUTE_U, g = 0.5 * (sqrt(5.0) - 1.0);
    double a = fmax(dom[0], bu - w), b = fmin(dom[1], bu + w);
    for (int k = 0; k < 30; ++k) {
        const double c = b - g * (b - a), d = a + g * (b - a);
        if (d2(s, c, v, p) <= d2(s, d, v, p))
            b = d;
        else
            a = c;
    }
    *u_at = 0.5 * (a + b);
    return d2(s, *u_at, v, p);
}

/* Newton on (S - p).Su = (S - p).Sv = 0 from (u, v): 1 when it converges
 * inside the domain to a local minimum. */
static int polish(const projcurve_surface *s, const double dom[4], const double p[3], double uv[2])
{
    for (int it = 0; it < 50; ++it) {
        double f[18];
        if (projcurve_surface_eval(NULL, s, uv[0], uv[1], 2, f) != PROJCURVE_OK)
            return 0;
        double w[3], g0 = 0, g1 = 0, a = 0, b = 0, d = 0;
        for (int c = 0; c < 3; ++c)
            w[c] = f[c] - p[c];
        for (int c = 0; c < 3; ++c) {
            g0 += w[c] * f[3 + c], g1 += w[c] * f[6 + c];
            a += f[3 + c] * f[3 + c] + w[c] * f[9 + c];
            b += f[3 + c] * f[6 + c] + w[c] * f[12 + c];
            d += f[6 + c] * f[6 + c] + w[c] * f[15 + c];
        }
        const double det = a * d - b * b;
        if (!(det > 0.0 && a > 0.0))
            return 0;
        const double du = -(d * g0 - b * g1) / det, dv = -(a * g1 - b * g0) / det;
        uv[0] += du, uv[1] += dv;
        if (uv[0] < dom[0] || uv[0] > dom[1] || uv[1] < dom[2] || uv[1] > dom[3])
            return 0;
        if (fabs(du) < 1e-14 && fabs(dv) < 1e-14)
            return 1;
    }
    return 0;
}

/* Distance from x to the rational piece (deg, ctrl, w) at s (de Casteljau
 * on the homogeneous points). */
static double piece_point_distance(int deg, const double *ctrl, const double *w, double s,
                                   const double x[3])
{
    double h[4 * PROJCURVE_MAX_PIECE_POINTS];
    for (int j = 0; j <= deg; ++j) {
        for (int c = 0; c < 3; ++c)
            h[4 * j + c] = ctrl[3 * j + c] * w[j];
        h[4 * j + 3] = w[j];
    }
    for (int q = 1; q <= deg; ++q)
        for (int j = 0; j <= deg - q; ++j)
            for (int c = 0; c < 4; ++c)
                h[4 * j + c] = (1 - s) * h[4 * j + c] + s * h[4 * (j + 1) + c];
    double dd = 0.0;
    for (int c = 0; c < 3; ++c)
        dd += (h[c] / h[3] - x[c]) * (h[c] / h[3] - x[c]);
    return sqrt(dd);
}

/* Distance from x to the result's pieces: 64 samples a piece, the nearest
 * polished by golden section over the two sample intervals beside it (a
 * long piece's samples lie farther apart than eps_D). */
static double piece_distance(const projcurve_result *r, const double x[3])
{
    double best = HUGE_VAL;
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        size_t n = 0;
        projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, NULL, &n);
        for (size_t k = 0; k < n; ++k) {
            int deg = 0;
            double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS];
            projcurve_result_piece(NULL, r, b, k, &deg, ctrl, w, NULL, NULL);
            double bs = 0.0, bd = HUGE_VAL;
            for (int i = 0; i <= 64; ++i) {
                const double d = piece_point_distance(deg, ctrl, w, i / 64.0, x);
                if (d < bd)
                    bd = d, bs = i / 64.0;
            }
            const double g = 0.5 * (sqrt(5.0) - 1.0);
            double lo = fmax(0.0, bs - 1.0 / 64), hi = fmin(1.0, bs + 1.0 / 64);
            for (int it = 0; it < 40; ++it) {
                const double c = hi - g * (hi - lo), d = lo + g * (hi - lo);
                if (piece_point_distance(deg, ctrl, w, c, x) <=
                    piece_point_distance(deg, ctrl, w, d, x))
                    hi = d;
                else
                    lo = c;
            }
            bd = fmin(bd, piece_point_distance(deg, ctrl, w, 0.5 * (lo + hi), x));
            best = fmin(best, bd);
        }
    }
    return best;
}

/* 1 when t lies within MAX_GAP_T beside a FAILED end or start. */
static int beside_failure(const projcurve_result *r, double t)
{
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        double tr[2];
        projcurve_branch_start st;
        projcurve_branch_end en;
        projcurve_result_branch_info(NULL, r, b, tr, &st, &en, NULL, NULL);
        if ((en == PROJCURVE_END_FAILED && t >= tr[1] && t <= tr[1] + MAX_GAP_T) ||
            (st == PROJCURVE_START_FAILED && t <= tr[0] && t >= tr[0] - MAX_GAP_T))
            return 1;
    }
    return 0;
}

static void check_case(const projcurve_model *m, const foot_case *fc)
{
    const projcurve_surface *s = projcurve_model_surface(m, fc->surface);
    const projcurve_curve *c = projcurve_model_curve(m, fc->curve);
    double dom[4], box[6], eps_d = 0.0;
    projcurve_surface_domain(NULL, s, dom);
    projcurve_surface_bounds(NULL, s, box);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, NULL, &r));
    projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &eps_d);
    printf("surface %zu, curve %zu: %zu branches, %zu failures\n", fc->surface, fc->curve,
           projcurve_result_branch_count(r), projcurve_result_failure_count(r));

    size_t su = 1, sv = 1;
    projcurve_surface_info(NULL, s, NULL, NULL, NULL, NULL, &su, &sv, NULL);
    pc_oracle_mesh mesh;
    CHECK(pc_oracle_mesh_build(&mesh, pc_sweep_surface_eval, (void *)s, dom,
                               pc_sweep_mesh_cells(su), pc_sweep_mesh_cells(sv)));
    double diag = 0.0;
    for (int k = 0; k < 3; ++k)
        diag += (box[k + 3] - box[k]) * (box[k + 3] - box[k]);
    const pc_sweep_input in = {s, c, 1, {0, 0, 0}, &mesh, eps_d, sqrt(diag), 2.0 * eps_d, 32,
                               40000};
    pc_sweep_report rep;
    pc_sweep_verify(&in, r, &rep);
    printf("  sweep verifier: %zu samples (far %zu, off %zu); %zu foot points, %zu missed "
           "(t %g, %.3g eps_D)\n",
           rep.samples, rep.far_from_exact, rep.off_projection, rep.oracle_points, rep.missed,
           rep.missed_t, rep.worst_missed);
    CHECK(rep.oracle_points > 0);
    CHECK(rep.missed == 0);
    CHECK(rep.far_from_exact == 0 && rep.off_projection == 0);
    CHECK(rep.failed_ends <= projcurve_result_failure_count(r));

    /* the brute force over the fold region */
    double *dv = malloc(sizeof *dv * (BRUTE_V + 1)), *uu = malloc(sizeof *uu * (BRUTE_V + 1));
    size_t feet = 0, missed = 0, excused = 0;
    double worst = 0.0, worst_t = NAN;
    for (int i = 0; i <= BRUTE_T; ++i) {
        const double t = fc->t_lo + (fc->t_hi - fc->t_lo) * i / BRUTE_T;
        double p[3];
        projcurve_curve_eval(NULL, c, t, 0, p);
        for (int j = 0; j <= BRUTE_V; ++j)
            dv[j] = min_over_u(s, dom, dom[2] + (dom[3] - dom[2]) * j / BRUTE_V, p, &uu[j]);
        for (int j = 1; j < BRUTE_V; ++j) {
            if (!(dv[j] <= dv[j - 1] && dv[j] <= dv[j + 1]))
                continue;
            double uv[2] = {uu[j], dom[2] + (dom[3] - dom[2]) * j / BRUTE_V};
            if (!polish(s, dom, p, uv))
                continue; /* on the edge, or no minimum near */
            double x[3];
            projcurve_surface_eval(NULL, s, uv[0], uv[1], 0, x);
            ++feet;
            const double d = piece_distance(r, x);
            if (d <= eps_d * (1.0 + 1e-3))
                continue;
            if (beside_failure(r, t)) {
                ++excused;
                continue;
            }
            ++missed;
            if (d > worst)
                worst = d, worst_t = t;
        }
    }
    printf("  brute force over t in [%g, %g]: %zu foot points, %zu missed (worst %.3g eps_D at "
           "t %g), %zu beside a reported failure\n",
           fc->t_lo, fc->t_hi, feet, missed, worst / eps_d, worst_t, excused);
    CHECK(feet > BRUTE_T / 2);
    CHECK(missed == 0);
    free(dv);
    free(uu);
    pc_oracle_mesh_free(&mesh);
    projcurve_result_destroy(r);
}

/* The verifier itself where S folds onto itself: surface 11 of
 * linkrods.step is a tube whose v lines reverse within 1e-3 of v. Its
 * scans of t flagged 1 to 5 samples of curve 3's projection at 1.1 to 5.1
 * eps_D; by its brute force (dense_nearest_foot) each lies within eps_D
 * of an exact foot point: no sample is off. */
static void check_verifier_on_fold(const projcurve_model *m)
{
    const projcurve_surface *s = projcurve_model_surface(m, 11);
    const projcurve_curve *c = projcurve_model_curve(m, 3);
    double dom[4], box[6], eps_d = 0.0;
    projcurve_surface_domain(NULL, s, dom);
    projcurve_surface_bounds(NULL, s, box);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, NULL, &r));
    projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &eps_d);
    size_t su = 1, sv = 1;
    projcurve_surface_info(NULL, s, NULL, NULL, NULL, NULL, &su, &sv, NULL);
    pc_oracle_mesh mesh;
    CHECK(pc_oracle_mesh_build(&mesh, pc_sweep_surface_eval, (void *)s, dom,
                               pc_sweep_mesh_cells(su), pc_sweep_mesh_cells(sv)));
    double diag = 0.0;
    for (int k = 0; k < 3; ++k)
        diag += (box[k + 3] - box[k]) * (box[k + 3] - box[k]);
    const pc_sweep_input in = {s, c, 1, {0, 0, 0}, &mesh, eps_d, sqrt(diag), 2.0 * eps_d, 32,
                               40000};
    pc_sweep_report rep;
    pc_sweep_verify(&in, r, &rep);
    printf("surface 11, curve 3: %zu samples, far %zu, off %zu, worst %.3g eps_D\n",
           rep.samples, rep.far_from_exact, rep.off_projection, rep.worst_exact);
    CHECK(rep.samples > 1000);
    CHECK(rep.far_from_exact == 0 && rep.off_projection == 0);
    CHECK(rep.worst_exact <= 1.0 + 1e-3);
    pc_oracle_mesh_free(&mesh);
    projcurve_result_destroy(r);
}

int main(void)
{
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/linkrods.step"), &m) !=
        PROJCURVE_OK)
        pc_test_missing_data("real/linkrods.step");
    /* Surface 9 / curve 38: a minimum born at the boundary at t ~ 2.641,
     * a fold pair at t ~ 2.6608; the sweep found only the branch after the
     * pair, whose backward trace stalled there, and the feet before it
     * (P(2.65072): 707 eps_D from the result) were missed with no failure
     * reported. */
    const foot_case cases[] = {
        {1, 74, 0.69, 0.80}, {5, 76, -0.80, -0.69}, {9, 38, 2.635, 2.675}};
    /* the sanitizer and coverage builds check the first case only */
    const int n = PC_TEST_SLOWDOWN > 1 ? 1 : 3;
    for (int k = 0; k < n; ++k)
        check_case(m, &cases[k]);
    check_verifier_on_fold(m);
    projcurve_model_destroy(m);
    return pc_test_finish("test_ortho_fold_pairs_real");
}
