/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The main job of libprojcurve in one program: a wavy cubic curve is
 * projected onto a bicubic B-spline surface, first along a direction (seed
 * 000), then orthogonally ([PW96]). For each branch the program prints how
 * it starts and ends, its size, and how well its traced points satisfy the
 * projection equations, evaluated independently here from the surface and
 * the curve. With a path argument it also writes everything as IGES.
 */
#include <projcurve.h>

#include <math.h>
#include <stdio.h>
#include <stdlib.h>

#define DEMO_MAX_POINTS 200000

static const char *const start_names[] = {"curve start", "jump", "boundary", "silhouette"};
static const char *const end_names[] = {"curve end", "boundary", "silhouette",
                                        "curvature centre", "limit", "failed"};

/* A 4 x 4 bicubic Bezier patch over [0, 4] x [0, 4] with a hill in the middle. */
static projcurve_status make_surface(projcurve_context *ctx, projcurve_surface **out)
{
    static const double heights[4][4] = {
        {0.0, 0.2, 0.2, 0.0}, {0.2, 1.8, 1.2, 0.2}, {0.2, 1.2, 1.6, 0.2}, {0.0, 0.2, 0.2, 0.0}};
    double net[4 * 4 * 3];
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 4; ++i) {
            double *p = &net[3 * (j * 4 + i)];
            p[0] = 4.0 * i / 3.0;
            p[1] = 4.0 * j / 3.0;
            p[2] = heights[j][i];
        }
    static const double knots[] = {0, 0, 0, 0, 1, 1, 1, 1};
    return projcurve_surface_create_nurbs(ctx, 3, 3, 4, 4, net, NULL, knots, knots, out);
}

/* A cubic B-spline wave above the surface, from x = 0.3 to x = 3.7. */
static projcurve_status make_curve(projcurve_context *ctx, projcurve_curve **out)
{
    static const double ctrl[] = {0.3, 0.8, 3.0, 1.0, 3.4, 3.0, 2.0, -0.4, 3.0,
                                  3.0, 3.6, 3.0, 3.7, 2.2, 3.0};
    static const double knots[] = {0, 0, 0, 0, 0.5, 1, 1, 1, 1};
    return projcurve_curve_create_nurbs(ctx, 3, 5, ctrl, NULL, knots, out);
}

/* Largest residual of the projection equations over a branch's points:
 * |(S - P) x dir| for a directional result (dir != NULL), and
 * max(|(S - P).Su|, |(S - P).Sv|) / |S - P| for an orthogonal one. */
static double branch_residual(projcurve_context *ctx, const projcurve_surface *s,
                              const projcurve_curve *c, const double *dir,
                              const double *points, size_t n)
{
    double worst = 0.0;
    for (size_t k = 0; k < n; ++k) {
        const double *tuv = &points[3 * k];
        double sd[9], pc[3];
        if (projcurve_surface_eval(ctx, s, tuv[1], tuv[2], 1, sd) != PROJCURVE_OK ||
            projcurve_curve_eval(ctx, c, tuv[0], 0, pc) != PROJCURVE_OK)
            return INFINITY;
        const double d[3] = {sd[0] - pc[0], sd[1] - pc[1], sd[2] - pc[2]};
        double r;
        if (dir != NULL) {
            const double x[3] = {d[1] * dir[2] - d[2] * dir[1], d[2] * dir[0] - d[0] * dir[2],
                                 d[0] * dir[1] - d[1] * dir[0]};
            r = sqrt(x[0] * x[0] + x[1] * x[1] + x[2] * x[2]);
        } else {
            const double len = sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]);
            const double a = fabs(d[0] * sd[3] + d[1] * sd[4] + d[2] * sd[5]);
            const double b = fabs(d[0] * sd[6] + d[1] * sd[7] + d[2] * sd[8]);
            r = len > 0.0 ? fmax(a, b) / len : 0.0;
        }
        worst = fmax(worst, r);
    }
    return worst;
}

static int report(projcurve_context *ctx, const char *title, const projcurve_surface *s,
                  const projcurve_curve *c, const double *dir, const projcurve_result *r,
                  double *points)
{
    const size_t n_branches = projcurve_result_branch_count(r);
    printf("%s: %zu branch(es)\n", title, n_branches);
    printf("  %-6s %-21s %-13s %-16s %8s %7s %10s\n", "branch", "t range", "starts at",
           "ends at", "points", "pieces", "residual");
    for (size_t b = 0; b < n_branches; ++b) {
        double t_range[2];
        projcurve_branch_start start;
        projcurve_branch_end end;
        size_t n_points = 0, n_pieces = 0, count = 0;
        if (projcurve_result_branch_info(ctx, r, b, t_range, &start, &end, &n_points,
                                         &n_pieces) != PROJCURVE_OK ||
            projcurve_result_branch_points(ctx, r, b, DEMO_MAX_POINTS, points, &count) !=
                PROJCURVE_OK)
            return 1;
        if (count > DEMO_MAX_POINTS)
            count = DEMO_MAX_POINTS;
        printf("  %-6zu [%8.5f, %8.5f] %-13s %-16s %8zu %7zu %10.2e\n", b, t_range[0],
               t_range[1], start_names[start], end_names[end], n_points, n_pieces,
               branch_residual(ctx, s, c, dir, points, count));
    }
    return 0;
}

int main(int argc, char **argv)
{
    projcurve_context *ctx = NULL;
    projcurve_surface *surface = NULL;
    projcurve_curve *curve = NULL;
    projcurve_result *directional = NULL, *orthogonal = NULL;
    projcurve_iges_writer *writer = NULL;
    double *points = malloc(3 * sizeof(double) * DEMO_MAX_POINTS);
    const double down[3] = {0.0, 0.0, -1.0};
    int failed = 1;

    if (points == NULL || projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx) != PROJCURVE_OK)
        goto cleanup;
    if (make_surface(ctx, &surface) != PROJCURVE_OK || make_curve(ctx, &curve) != PROJCURVE_OK ||
        projcurve_project_directional(ctx, surface, curve, down, NULL, &directional) !=
            PROJCURVE_OK ||
        projcurve_project_orthogonal(ctx, surface, curve, NULL, &orthogonal) != PROJCURVE_OK)
        goto cleanup;

    printf("libprojcurve %s: a cubic curve onto a bicubic hill\n\n", projcurve_version_string());
    if (report(ctx, "directional projection along (0, 0, -1)", surface, curve, down,
               directional, points) != 0 ||
        report(ctx, "\northogonal projection", surface, curve, NULL, orthogonal, points) != 0)
        goto cleanup;

    if (argc > 1) {
        if (projcurve_iges_writer_create(ctx, &writer) != PROJCURVE_OK ||
            projcurve_iges_writer_add_curve(ctx, writer, curve) != PROJCURVE_OK ||
            projcurve_iges_writer_add_result(ctx, writer, surface, directional) != PROJCURVE_OK ||
            projcurve_iges_writer_write(ctx, writer, argv[1]) != PROJCURVE_OK)
            goto cleanup;
        printf("\nwrote %s\n", argv[1]);
    }
    failed = 0;

cleanup:
    if (failed)
        fprintf(stderr, "project_demo: %s (%s)\n", projcurve_context_message(ctx),
                projcurve_status_string(projcurve_context_status(ctx)));
    projcurve_iges_writer_destroy(writer);
    projcurve_result_destroy(orthogonal);
    projcurve_result_destroy(directional);
    projcurve_curve_destroy(curve);
    projcurve_surface_destroy(surface);
    projcurve_context_destroy(ctx);
    free(points);
    return failed;
}
