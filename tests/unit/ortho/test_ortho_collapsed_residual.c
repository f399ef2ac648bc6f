/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Orthogonal projection next to a collapsed edge: horn.xml (tests/data/real),
 * whose v lines shrink to its tip (|Sv| -> 0 at u = 0), with the curve of
 * test_ortho_real. A branch starts at t = 0.5848 at (u, v) = (3.2e-6,
 * 0.8027), 3.2e-6 from the tip. There the corrector leaves the collapsed
 * parameter alone and accepts the part of S - P across the regular
 * direction up to the error of that direction (times |S - P|); the
 * residual the verification pass measured did not allow it (5.89156e-7
 * against an allowance of 5.89105e-7 and a vertex tolerance of 5.12e-7),
 * so the branch's first piece, [0.5848, 0.6460], was cut off with the foot
 * point at t = 0.62 on it.
 *
 * Checks: no FAILED end on the result; every vertex the corrector accepts
 * passes the projector's residual within the verification's vertex
 * tolerance; and, as an oracle independent of the library's measures,
 * at 9 samples of every piece the exact foot point (this file's own
 * Newton on the squared distance from the pcurve's point) is within eps_D
 * of the piece (dense chords of its Bezier curve).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "foot_step.h"
#include "ortho/ortho_projector.h"
#include "verify/verify_internal.h"

#define PIECE_SAMPLES 9   /* interior samples of each piece */
#define PIECE_CHORDS 256  /* chords of a piece for the point's distance to it */
#define FOOT_REL 1e-12    /* foot-point Newton: converged step, of the size */

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Newton on [(S - p).Su, (S - p).Sv] = 0 (the Hessian of |S - p|^2 / 2)
 * from uv, at most 40 steps; 1 when the last step moved S by less than
 * FOOT_REL of the size. The foot point S(uv) into x. */
static int foot_point(const projcurve_surface *s, const double p[3], double uv[2], double size,
                      double x[3])
{
    double dom[4];
    projcurve_surface_domain(NULL, s, dom);
    for (int it = 0; it < 40; ++it) {
        double e[18], step[2];
        if (!pc_test_foot_step(s, p, uv, step, e))
            return 0;
        const double du = step[0], dv = step[1];
        uv[0] = fmin(dom[1], fmax(dom[0], uv[0] + du));
        uv[1] = fmin(dom[3], fmax(dom[2], uv[1] + dv));
        double move[3];
        for (int i = 0; i < 3; ++i)
            move[i] = du * e[3 + i] + dv * e[6 + i];
        const double zero[3] = {0, 0, 0};
        if (dist3(move, zero) <= FOOT_REL * size) {
            projcurve_surface_eval(NULL, s, uv[0], uv[1], 0, x);
            return 1;
        }
    }
    return 0;
}

/* Rational de Casteljau on the piece's control points at s. */
static void piece_point(int n, const double *ctrl, const double *w, double s, double x[3])
{
    double h[PROJCURVE_MAX_PIECE_POINTS][4];
    for (int i = 0; i <= n; ++i) {
        for (int c = 0; c < 3; ++c)
            h[i][c] = w[i] * ctrl[3 * i + c];
        h[i][3] = w[i];
    }
    for (int level = n; level > 0; --level)
        for (int i = 0; i < level; ++i)
            for (int c = 0; c < 4; ++c)
                h[i][c] = (1.0 - s) * h[i][c] + s * h[i + 1][c];
    for (int c = 0; c < 3; ++c)
        x[c] = h[0][c] / h[0][3];
}

/* Distance of y from the chords of the piece at PIECE_CHORDS parameters:
 * below the true distance by at most a chord's sagitta, (L / 256)^2 / (8 R)
 * for a piece of length L and radius R (~1e-8 of eps_D here). */
static double piece_distance(int n, const double *ctrl, const double *w, const double y[3])
{
    double best = INFINITY, a[3];
    piece_point(n, ctrl, w, 0.0, a);
    for (int k = 1; k <= PIECE_CHORDS; ++k) {
        double b[3], ab[3], ay[3], l2 = 0.0, t = 0.0;
        piece_point(n, ctrl, w, (double)k / PIECE_CHORDS, b);
        for (int c = 0; c < 3; ++c) {
            ab[c] = b[c] - a[c];
            ay[c] = y[c] - a[c];
            l2 += ab[c] * ab[c];
            t += ab[c] * ay[c];
        }
        t = l2 > 0.0 ? fmin(1.0, fmax(0.0, t / l2)) : 0.0;
        const double q[3] = {a[0] + t * ab[0], a[1] + t * ab[1], a[2] + t * ab[2]};
        best = fmin(best, dist3(q, y));
        for (int c = 0; c < 3; ++c)
            a[c] = b[c];
    }
    return best;
}

/* The curve of test_ortho_real: five control points across the box, waving,
 * 5% of the model size above its thinnest side. */
static projcurve_curve *hovering_curve(const projcurve_surface *s, double *size)
{
    double box[6];
    projcurve_surface_bounds(NULL, s, box);
    const double ext[3] = {box[3] - box[0], box[4] - box[1], box[5] - box[2]};
    const int thin = ext[0] <= ext[1] && ext[0] <= ext[2] ? 0 : (ext[1] <= ext[2] ? 1 : 2);
    const int a = (thin + 1) % 3, b = (thin + 2) % 3;
    *size = sqrt(ext[0] * ext[0] + ext[1] * ext[1] + ext[2] * ext[2]);
    double ctrl[15], knots[9] = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    for (int i = 0; i < 5; ++i) {
        ctrl[3 * i + a] = box[a] + (0.25 + 0.125 * i) * ext[a];
        ctrl[3 * i + b] = box[b] + (0.5 + 0.2 * ((i % 2) ? 1.0 : -1.0)) * ext[b];
        ctrl[3 * i + thin] = box[thin + 3] + 0.05 * *size;
    }
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 3, 5, ctrl, NULL, knots, &c));
    return c;
}

static void check_pieces(const projcurve_surface *s, const projcurve_result *r, size_t b,
                         const projcurve_curve *c, double size, double eps_d, double *worst,
                         size_t *unsolved)
{
    size_t n_pieces = 0;
    projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, NULL, &n_pieces);
    for (size_t k = 0; k < n_pieces; ++k) {
        int deg = 0, uv_deg = 0;
        double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS], range[2];
        double uvc[2 * PROJCURVE_MAX_PCURVE_POINTS];
        CHECK_OK(projcurve_result_piece(NULL, r, b, k, &deg, ctrl, w, range, NULL));
        CHECK_OK(projcurve_result_piece_pcurve(NULL, r, b, k, &uv_deg, uvc));
        for (int i = 1; i <= PIECE_SAMPLES; ++i) {
            const double sp = (double)i / (PIECE_SAMPLES + 1);
            double uv[2 * PROJCURVE_MAX_PCURVE_POINTS];
            for (int j = 0; j < 2 * (uv_deg + 1); ++j)
                uv[j] = uvc[j];
            for (int level = uv_deg; level > 0; --level)
                for (int j = 0; j < 2 * level; ++j)
                    uv[j] = (1.0 - sp) * uv[j] + sp * uv[j + 2];
            double p[3], x[3];
            projcurve_curve_eval(NULL, c, range[0] + sp * (range[1] - range[0]), 0, p);
            if (!foot_point(s, p, uv, size, x)) {
                ++*unsolved;
                continue;
            }
            const double d = piece_distance(deg, ctrl, w, x);
            if (d > eps_d)
                printf("  branch %zu piece %zu, t = %.6f: exact point %.3g from the piece\n", b,
                       k, range[0] + sp * (range[1] - range[0]), d);
            *worst = fmax(*worst, d);
        }
    }
}

int main(void)
{
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path("real/horn.xml"), &m) != PROJCURVE_OK)
        pc_test_missing_data("real/horn.xml");
    const projcurve_surface *s = projcurve_model_surface(m, 0);
    double size = 0.0;
    projcurve_curve *c = hovering_curve(s, &size);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal(NULL, s, c, NULL, &r));
    double eps_d = 0.0;
    CHECK_OK(projcurve_result_stat(NULL, r, PROJCURVE_STAT_TOL_DISTANCE, &eps_d));

    pc_projector proj;
    pc_ortho_cache cache;
    pc_ortho_projector_init(&proj, &cache, s, c, 1e-12, 20);
    const double vertex_tol = pc_verify_vertex_tolerance(&proj);
    double worst_res = 0.0, worst_d = 0.0;
    size_t accepted = 0, unsolved = 0;
    for (size_t b = 0; b < projcurve_result_branch_count(r); ++b) {
        size_t n = 0;
        projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, &n, NULL);
        double *pts = malloc(3 * (n ? n : 1) * sizeof *pts);
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, n, pts, &n));
        for (size_t i = 0; i < n; ++i) {
            double uv[2] = {pts[3 * i + 1], pts[3 * i + 2]};
            if (!proj.correct(&proj, pts[3 * i], uv, NULL))
                continue;
            ++accepted;
            worst_res = fmax(worst_res, proj.residual(&proj, pts[3 * i], uv[0], uv[1]));
        }
        free(pts);
        check_pieces(s, r, b, c, size, eps_d, &worst_d, &unsolved);
    }
    printf("horn.xml: %zu branches, %zu failures; %zu vertices accepted by the corrector, "
           "residual <= %.3g (tolerance %.3g); exact points <= %.3g from their "
           "piece (eps_D %.3g), %zu samples without a foot point\n",
           projcurve_result_branch_count(r), projcurve_result_failure_count(r), accepted,
           worst_res, vertex_tol, worst_d, eps_d, unsolved);
    CHECK(projcurve_result_failure_count(r) == 0);
    CHECK(accepted > 0);
    CHECK(worst_res <= vertex_tol);
    CHECK(worst_d <= eps_d);
    CHECK(unsolved == 0);
    projcurve_result_destroy(r);
    projcurve_curve_destroy(c);
    projcurve_model_destroy(m);
    return pc_test_finish("test_ortho_collapsed_residual");
}
