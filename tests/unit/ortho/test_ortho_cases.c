/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The orthogonal cases of tests/data/cases (MANIFEST.tsv, mode "orthogonal"):
 * read each IGES file, project its curve onto its surface with the
 * manifest's tolerances, and compare the branch count with the manifest's.
 * Every traced vertex must satisfy the foot-point condition: the tangential
 * part of S - P, F^T g^-1 F, within 1e-9 of the model size. Every joint of
 * consecutive composed pieces of a branch, as the public API returns them,
 * turns by at most the manifest's eps_T: the angle between the end tangent
 * of one rational Bezier piece (along its last two distinct control
 * points, whatever the weights) and the start tangent of the next.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"

#ifndef M_PI
#define M_PI 3.14159265358979323846
#endif

#define LINE_CAPACITY 4096

static double foot_residual(const projcurve_surface *s, const projcurve_curve *c,
                            const double tuv[3])
{
    double sd[9], p[3];
    if (projcurve_surface_eval(NULL, s, tuv[1], tuv[2], 1, sd) != PROJCURVE_OK ||
        projcurve_curve_eval(NULL, c, tuv[0], 0, p) != PROJCURVE_OK)
        return INFINITY;
    double d[3], f[2] = {0, 0}, g[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
        d[i] = sd[i] - p[i];
        f[0] += d[i] * sd[3 + i];
        f[1] += d[i] * sd[6 + i];
        g[0] += sd[3 + i] * sd[3 + i];
        g[1] += sd[3 + i] * sd[6 + i];
        g[2] += sd[6 + i] * sd[6 + i];
    }
    const double det = g[0] * g[2] - g[1] * g[1];
    const double x0 = (g[2] * f[0] - g[1] * f[1]) / det, x1 = (g[0] * f[1] - g[1] * f[0]) / det;
    return sqrt(fmax(0.0, f[0] * x0 + f[1] * x1));
}

/* Unit tangent at the start (at_end = 0) or the end of piece k of branch b:
 * along the first (last) control points that differ. 0 if none differ. */
static int piece_tangent(const projcurve_result *r, size_t b, size_t k, int at_end, double t[3])
{
    int deg = 0;
    double ctrl[3 * PROJCURVE_MAX_PIECE_POINTS], w[PROJCURVE_MAX_PIECE_POINTS];
    if (projcurve_result_piece(NULL, r, b, k, &deg, ctrl, w, NULL, NULL) != PROJCURVE_OK)
        return 0;
    for (int j = 1; j <= deg; ++j) {
        const double *a = at_end ? ctrl + 3 * (deg - j) : ctrl;
        const double *c = at_end ? ctrl + 3 * deg : ctrl + 3 * j;
        const double d[3] = {c[0] - a[0], c[1] - a[1], c[2] - a[2]};
        const double n = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
        if (n > 0.0) {
            for (int i = 0; i < 3; ++i)
                t[i] = d[i] / n;
            return 1;
        }
    }
    return 0;
}

/* Largest joint angle (degrees) between consecutive pieces of branch b. */
static double max_joint_angle(const projcurve_result *r, size_t b, size_t pieces)
{
    double worst = 0.0;
    for (size_t k = 0; k + 1 < pieces; ++k) {
        double e[3], s[3];
        if (!piece_tangent(r, b, k, 1, e) || !piece_tangent(r, b, k + 1, 0, s)) {
            worst = INFINITY;   /* a piece without a direction */
            continue;
        }
        const double c = e[0] * s[0] + e[1] * s[1] + e[2] * s[2];
        worst = fmax(worst, acos(fmin(1.0, fmax(-1.0, c))) * 180.0 / M_PI);
    }
    return worst;
}

static void run_case(const char *name, double tol_dist, double tol_angle, size_t expected)
{
    char rel[300];
    snprintf(rel, sizeof rel, "cases/%s.igs", name);
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    projcurve_model *model = NULL;
    const projcurve_status st = projcurve_model_read_file(ctx, pc_test_data_path(rel), &model);
    CHECK_OK(st);
    if (st != PROJCURVE_OK) {
        printf("%s: %s\n", name, projcurve_context_message(ctx));
        projcurve_context_destroy(ctx);
        return;
    }
    CHECK(projcurve_model_surface_count(model) >= 1);
    CHECK(projcurve_model_curve_count(model) >= 1);
    const projcurve_surface *surf = projcurve_model_surface(model, 0);
    const projcurve_curve *curve = projcurve_model_curve(model, 0);
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(ctx, &o));
    CHECK_OK(projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TOL_DISTANCE, tol_dist));
    CHECK_OK(projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TOL_ANGLE_DEG, tol_angle));
    projcurve_result *r = NULL;
    if (surf && curve)
        CHECK_OK(projcurve_project_orthogonal(ctx, surf, curve, o, &r));
    double box[6] = {0, 0, 0, 0, 0, 0};
    projcurve_surface_bounds(NULL, surf, box);
    const double size = hypot(hypot(box[3] - box[0], box[4] - box[1]), box[5] - box[2]);
    const size_t nb = projcurve_result_branch_count(r);
    printf("%-28s branches %zu (manifest %zu)\n", name, nb, expected);
    CHECK(nb == expected);
    double worst = 0.0, worst_joint = 0.0;
    for (size_t b = 0; b < nb; ++b) {
        size_t n = 0, got = 0, pieces = 0;
        projcurve_result_branch_info(NULL, r, b, NULL, NULL, NULL, &n, &pieces);
        CHECK(pieces > 0);
        worst_joint = fmax(worst_joint, max_joint_angle(r, b, pieces));
        double *pts = malloc(3 * n * sizeof *pts);
        CHECK_OK(projcurve_result_branch_points(NULL, r, b, n, pts, &got));
        for (size_t i = 0; i < got; ++i)
            worst = fmax(worst, foot_residual(surf, curve, pts + 3 * i));
        free(pts);
    }
    printf("%-28s worst foot residual %.1e (model size %.1f)\n", name, worst, size);
    CHECK(worst <= 1e-9 * size);
    /* the angle is computed to ~1e-7 degrees (acos near 1 of unit vectors
     * to rounding): the same relative margin as test_refine's */
    printf("%-28s largest joint angle %.4f deg (eps_T %.4g)\n", name, worst_joint, tol_angle);
    CHECK(worst_joint <= tol_angle * (1.0 + 1e-9) + 1e-6);
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_model_destroy(model);
    projcurve_context_destroy(ctx);
}

int main(void)
{
    FILE *f = fopen(pc_test_data_path("cases/MANIFEST.tsv"), "r");
    if (f == NULL)
        pc_test_missing_data("cases/MANIFEST.tsv");
    char line[LINE_CAPACITY];
    int cases = 0;
    while (fgets(line, sizeof line, f)) {
        char name[256], mode[64];
        double dx, dy, dz, tol_dist, tol_angle;
        unsigned long expected;
        if (line[0] == '#')
            continue;
        if (sscanf(line, "%255s %63s %lf %lf %lf %lf %lf %lu", name, mode, &dx, &dy, &dz,
                   &tol_dist, &tol_angle, &expected) != 8)
            continue;
        if (strcmp(mode, "orthogonal") != 0)
            continue;
        run_case(name, tol_dist, tol_angle, (size_t)expected);
        ++cases;
    }
    fclose(f);
    CHECK(cases >= 2);
    return pc_test_finish("test_ortho_cases");
}
