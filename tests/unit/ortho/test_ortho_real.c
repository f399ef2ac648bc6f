/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Orthogonal projection onto real CAD surfaces (tests/data/real): a
 * wavy cubic curve hovering a little above the surface (along its thinnest
 * axis) is projected; every traced vertex must be a foot point, and every
 * interior local minimum of the distance from P(t), found independently by
 * a dense grid and Newton at sample values of t, must lie on a branch.
 */
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#include "check.h"
#include "on_surface.h"

#define GRID 100          /* brute-force grid per direction */
#define T_SAMPLES 25      /* values of t checked against the brute force */
#define RESIDUAL_REL 1e-9 /* foot-point condition, relative to the model size */
#define MATCH_REL 1e-3    /* a brute-force foot point on a branch, relative */

/* Tangential distance |F^T g^-1 F|^(1/2) of S(u, v) - p, and the Newton step. */
static double foot_step(const projcurve_surface *s, const double p[3], const double uv[2],
                        double step[2])
{
    double e[18];
    projcurve_surface_eval(NULL, s, uv[0], uv[1], 2, e);
    double d[3], f[2] = {0, 0}, k[3] = {0, 0, 0}, g[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        d[i] = e[i] - p[i];
        f[0] += d[i] * e[3 + i];
        f[1] += d[i] * e[6 + i];
        g[0] += e[3 + i] * e[3 + i];
        g[1] += e[3 + i] * e[6 + i];
        g[2] += e[6 + i] * e[6 + i];
        k[0] += d[i] * e[9 + i];
        k[1] += d[i] * e[12 + i];
        k[2] += d[i] * e[15 + i];
    }
    const double a = g[0] + k[0], b = g[1] + k[1], c = g[2] + k[2];
    const double det = a * c - b * b, dg = g[0] * g[2] - g[1] * g[1];
    step[0] = det != 0.0 ? -(c * f[0] - b * f[1]) / det : 0.0;
    step[1] = det != 0.0 ? -(a * f[1] - b * f[0]) / det : 0.0;
    const double x0 = (g[2] * f[0] - g[1] * f[1]) / dg, x1 = (g[0] * f[1] - g[1] * f[0]) / dg;
    return sqrt(fmax(0.0, f[0] * x0 + f[1] * x1));
}

/* The resolution of foot_step's residual: Su and Sv carry an absolute
 * rounding of a few DBL_EPSILON of the model size whatever their length, so
 * the tangential part of S - p is known to |S - p| times that over the
 * shorter of them. Negligible at regular points (~1e-14 |S - p|); near a
 * collapsed edge (the horn's tip, where |Sv| -> 0) it is what limits every
 * measure of the foot-point condition, this one and the library's. */
static double residual_floor(const projcurve_surface *s, const double p[3], const double uv[2],
                             double size)
{
    double e[9];
    projcurve_surface_eval(NULL, s, uv[0], uv[1], 1, e);
    const double d = sqrt((e[0] - p[0]) * (e[0] - p[0]) + (e[1] - p[1]) * (e[1] - p[1]) +
                          (e[2] - p[2]) * (e[2] - p[2]));
    const double su = sqrt(e[3] * e[3] + e[4] * e[4] + e[5] * e[5]);
    const double sv = sqrt(e[6] * e[6] + e[7] * e[7] + e[8] * e[8]);
    return d * 16.0 * DBL_EPSILON * size / fmin(su, sv);
}

static void point_at(const projcurve_surface *s, double u, double v, double x[3])
{
    projcurve_surface_eval(NULL, s, u, v, 0, x);
}

static double dist3(const double *a, const double *b)
{
    return sqrt((a[0] - b[0]) * (a[0] - b[0]) + (a[1] - b[1]) * (a[1] - b[1]) +
                (a[2] - b[2]) * (a[2] - b[2]));
}

/* Distance from q to the segment x y. */
static double segment_distance(const double x[3], const double y[3], const double q[3])
{
    double ab[3], aq[3], l2 = 0.0, w = 0.0;
    for (int k = 0; k < 3; ++k) {
        ab[k] = y[k] - x[k];
        aq[k] = q[k] - x[k];
        l2 += ab[k] * ab[k];
        w += ab[k] * aq[k];
    }
    w = l2 > 0.0 ? fmin(1.0, fmax(0.0, w / l2)) : 0.0;
    const double c[3] = {x[0] + w * ab[0], x[1] + w * ab[1], x[2] + w * ab[2]};
    return dist3(c, q);
}

/* Distance from q to the composed pieces of branch b whose t-range comes
 * within T_WINDOW of t (the exact foot point of P(t) lies on the branch,
 * not necessarily at the piece's matching t), each sampled at
 * PIECE_SAMPLES + 1 points joined by chords (a piece's chords are far
 * within MATCH_REL of it: pieces are short against the curvature radii
 * here, and straight or cubic pcurves alike); INFINITY when no piece is
 * near t. */
#define T_WINDOW 0.02
#define PIECE_SAMPLES 32
static double branch_distance(const projcurve_result *r, size_t b, double t, const double q[3])
{
    double best = INFINITY;
    size_t n_pieces = 0;
    projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, NULL, &n_pieces);
    for (size_t k = 0; k < n_pieces; ++k) {
        int degree = 0;
        double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS], range[2];
        CHECK_OK(projcurve_result_piece(NULL, r, b, k, &degree, ctrl, w, range, NULL));
        if (fmax(range[0], range[1]) < t - T_WINDOW || fmin(range[0], range[1]) > t + T_WINDOW)
            continue;
        double x[3], y[3];
        pc_test_piece_point(degree, ctrl, w, 0.0, x);
        for (int i = 1; i <= PIECE_SAMPLES; ++i) {
            pc_test_piece_point(degree, ctrl, w, (double)i / PIECE_SAMPLES, y);
            best = fmin(best, segment_distance(x, y, q));
            x[0] = y[0];
            x[1] = y[1];
            x[2] = y[2];
        }
    }
    return best;
}

/* Every interior grid-local minimum of |S - P(t)|, polished by Newton,
 * must be within MATCH_REL of the model size of a branch near t (its
 * composed pieces). */
static int missed_minima(const projcurve_surface *s, const projcurve_curve *c,
                         const projcurve_result *r, double t, double size)
{
    static double d[GRID + 1][GRID + 1];
    double dom[4], p[3];
    projcurve_surface_domain(NULL, s, dom);
    projcurve_curve_eval(NULL, c, t, 0, p);
    for (int i = 0; i <= GRID; ++i)
        for (int j = 0; j <= GRID; ++j) {
            double x[3];
            point_at(s, dom[0] + (dom[1] - dom[0]) * i / GRID, dom[2] + (dom[3] - dom[2]) * j / GRID,
                     x);
            d[i][j] = dist3(x, p);
        }
    int missed = 0;
    for (int i = 1; i < GRID; ++i)
        for (int j = 1; j < GRID; ++j) {
            int is_min = 1;
            for (int a = -1; a <= 1; ++a)
                for (int b = -1; b <= 1; ++b)
                    if ((a || b) && d[i + a][j + b] <= d[i][j])
                        is_min = 0;
            if (!is_min)
                continue;
            double uv[2] = {dom[0] + (dom[1] - dom[0]) * i / GRID,
                            dom[2] + (dom[3] - dom[2]) * j / GRID};
            double res = INFINITY;
            for (int it = 0; it < 30 && res > 1e-12 * size; ++it) {
                double step[2];
                res = foot_step(s, p, uv, step);
                uv[0] += step[0];
                uv[1] += step[1];
            }
            if (!(res <= 1e-9 * size) || uv[0] <= dom[0] || uv[0] >= dom[1] || uv[1] <= dom[2] ||
                uv[1] >= dom[3])
                continue;   /* not an interior foot point */
            double q[3], best = INFINITY;
            point_at(s, uv[0], uv[1], q);
            for (size_t b = 0; b < projcurve_result_branch_count(r); ++b)
                best = fmin(best, branch_distance(r, b, t, q));
            if (best > MATCH_REL * size) {
                printf("  t = %.6f: foot point (%.6f, %.6f) at distance %.3g from every branch\n", t,
                       uv[0], uv[1], best);
                ++missed;
            }
        }
    return missed;
}

static void run(const char *file)
{
    char rel[256];
    snprintf(rel, sizeof rel, "real/%s", file);
    projcurve_model *m = NULL;
    if (projcurve_model_read_file(NULL, pc_test_data_path(rel), &m) != PROJCURVE_OK) {
        pc_test_fail_at(__FILE__, __LINE__, "%s: not readable", file);
        return;
    }
    const projcurve_surface *s = projcurve_model_surface(m, 0);
    CHECK(s != NULL);
    double box[6];
    projcurve_surface_bounds(NULL, s, box);
    const double ext[3] = {box[3] - box[0], box[4] - box[1], box[5] - box[2]};
    const int thin = ext[0] <= ext[1] && ext[0] <= ext[2] ? 0 : (ext[1] <= ext[2] ? 1 : 2);
    const int a = (thin + 1) % 3, b = (thin + 2) % 3;
    const double size = sqrt(ext[0] * ext[0] + ext[1] * ext[1] + ext[2] * ext[2]);
    /* Five control points across the box (25% to 75%), waving, 5% of the
     * model size above it. */
    double ctrl[15], knots[9] = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    for (int i = 0; i < 5; ++i) {
        ctrl[3 * i + a] = box[a] + (0.25 + 0.125 * i) * ext[a];
        ctrl[3 * i + b] = box[b] + (0.5 + 0.2 * ((i % 2) ? 1.0 : -1.0)) * ext[b];
        ctrl[3 * i + thin] = box[thin + 3] + 0.05 * size;
    }
    projcurve_curve *c = NULL;
    CHECK_OK(projcurve_curve_create_nurbs(NULL, 3, 5, ctrl, NULL, knots, &c));
    projcurve_result *r = NULL;
    projcurve_context *ctx = NULL;
    projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx);
    const projcurve_status st = projcurve_project_orthogonal(ctx, s, c, NULL, &r);
    if (st != PROJCURVE_OK)
        printf("%s: %s\n", file, projcurve_context_message(ctx));
    CHECK_OK(st);
    const size_t nb = projcurve_result_branch_count(r);
    double **pts = calloc(nb + 1, sizeof *pts);
    size_t *n = calloc(nb + 1, sizeof *n);
    double worst = 0.0;
    size_t pieces_total = 0;
    for (size_t k = 0; k < nb; ++k) {
        size_t got = 0, pieces = 0;
        projcurve_result_branch_info(NULL, r, k, NULL, NULL, NULL, &n[k], &pieces);
        pieces_total += pieces;
        pts[k] = malloc(3 * (n[k] + 1) * sizeof **pts);
        CHECK_OK(projcurve_result_branch_points(NULL, r, k, n[k], pts[k], &got));
        for (size_t i = 0; i < got; ++i) {
            double p[3], step[2];
            projcurve_curve_eval(NULL, c, pts[k][3 * i], 0, p);
            worst = fmax(worst, foot_step(s, p, pts[k] + 3 * i + 1, step) -
                                    residual_floor(s, p, pts[k] + 3 * i + 1, size));
        }
    }
    int missed = 0;
    for (int i = 0; i < T_SAMPLES; ++i)
        missed += missed_minima(s, c, r, (i + 0.5) / T_SAMPLES, size);
    printf("%s: %zu branches, %zu pieces, worst foot residual beyond its rounding floor %.1e (size %.3g), %d minima missed\n",
           file, nb, pieces_total, worst, size, missed);
    CHECK(worst <= RESIDUAL_REL * size);
    CHECK(missed == 0);
    CHECK(nb == 0 || pieces_total > 0);
    for (size_t k = 0; k < nb; ++k)
        free(pts[k]);
    free(pts);
    free(n);
    projcurve_result_destroy(r);
    projcurve_context_destroy(ctx);
    projcurve_curve_destroy(c);
    projcurve_model_destroy(m);
}

int main(void)
{
    run("sunglasses_lens.igs");
    run("bladex_upper.iges");
    run("horn.xml");
    run("egg.xml");
    return pc_test_finish("test_ortho_real");
}
