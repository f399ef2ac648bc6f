/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * The directional cases of tests/data/cases (MANIFEST.tsv): each IGES file
 * holds one surface and its test curve(s); the projection along the listed
 * direction must give the expected number of branches, every vertex on the
 * projection, nothing missed by brute force, boundary ends exactly on the
 * boundary and on the crossing found by exit_oracle, the start and end
 * reasons the MANIFEST notes state; and, composed (the default options),
 * pieces joined into a curve that lies on the surface.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "exit_oracle.h"
#include "trace_oracle.h"

/* Brute force at 10,000 evenly spaced t (issue 5). */
#define N_SAMPLES 10000
#define RESIDUAL_TOL 1e-9
/* Boundary ends on the exact crossing of the projection with the boundary
 * (exit_oracle), relative to the model size (issue 5: to 1e-10). */
#define EXIT_TOL 1e-10

/* How the branches of a case start and end, where its MANIFEST notes say
 * (in any order). */
typedef struct expected_reasons {
    const char *name;
    size_t n;
    projcurve_branch_start start[2];
    projcurve_branch_end end[2];
} expected_reasons;

static const expected_reasons REASONS[] = {
    /* "from x=40 out past the x=100 edge and back": the first branch ends
     * on the boundary, the second starts there */
    {"bumpy_boundary_exit_reenter", 2,
     {PROJCURVE_START_CURVE_START, PROJCURVE_START_BOUNDARY},
     {PROJCURVE_END_BOUNDARY, PROJCURVE_END_CURVE_END}},
    /* "bottom starts at x~0 edge, top appears mid-curve at x~20 (top sheet
     * edge)": both born on an edge, both run to the curve's end */
    {"fold_c_sheet_jump", 2,
     {PROJCURVE_START_BOUNDARY, PROJCURVE_START_BOUNDARY},
     {PROJCURVE_END_CURVE_END, PROJCURVE_END_CURVE_END}},
    /* "1 branch over the whole curve" */
    {"song_yong_example1", 1, {PROJCURVE_START_CURVE_START}, {PROJCURVE_END_CURVE_END}},
    {"bumpy_bicubic_8x8_down", 1, {PROJCURVE_START_CURVE_START}, {PROJCURVE_END_CURVE_END}},
};

static const expected_reasons *reasons_of(const char *name)
{
    for (size_t k = 0; k < sizeof REASONS / sizeof REASONS[0]; ++k)
        if (strcmp(REASONS[k].name, name) == 0)
            return &REASONS[k];
    return NULL;
}

typedef struct manifest_row {
    char name[128], mode[32];
    double dir[3], tol_distance, tol_angle;
    int expected;
} manifest_row;

static int parse_row(const char *line, manifest_row *row)
{
    return sscanf(line, "%127[^\t]\t%31[^\t]\t%lf\t%lf\t%lf\t%lf\t%lf\t%d", row->name, row->mode,
                  &row->dir[0], &row->dir[1], &row->dir[2], &row->tol_distance,
                  &row->tol_angle, &row->expected) == 8;
}

static int on_boundary(const projcurve_surface *s, double u, double v)
{
    double dom[4];
    projcurve_surface_domain(NULL, s, dom);
    return u == dom[0] || u == dom[1] || v == dom[2] || v == dom[3];
}

/* Trace only: branch count, oracle, exact boundary ends. */
static size_t check_traced(const manifest_row *row, const projcurve_surface *s,
                           const projcurve_curve *c)
{
    projcurve_options *o = NULL;
    projcurve_options_create(NULL, &o);
    projcurve_options_set_int(NULL, o, PROJCURVE_OPT_COMPOSE, 0);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, row->dir, o, &r));
    projcurve_options_destroy(o);
    const size_t nb = projcurve_result_branch_count(r);
    const expected_reasons *ex = reasons_of(row->name);
    int used[2] = {0, 0};
    if (ex != NULL)
        CHECK(nb == ex->n);
    for (size_t i = 0; i < nb; ++i) {
        projcurve_branch_start start;
        projcurve_branch_end end;
        size_t n = 0;
        projcurve_result_branch_info(NULL, r, i, NULL, &start, &end, &n, NULL);
        if (ex != NULL) {
            int found = 0;
            for (size_t k = 0; k < ex->n && !found; ++k)
                if (!used[k] && ex->start[k] == start && ex->end[k] == end)
                    found = used[k] = 1;
            if (!found)
                pc_test_fail_at(__FILE__, __LINE__,
                                "%s: branch %zu starts %d, ends %d: not expected", row->name, i,
                                (int)start, (int)end);
        }
        double *p = malloc(3 * n * sizeof *p);
        projcurve_result_branch_points(NULL, r, i, n, p, &n);
        if (start == PROJCURVE_START_BOUNDARY)
            CHECK(on_boundary(s, p[1], p[2]));
        if (end == PROJCURVE_END_BOUNDARY)
            CHECK(on_boundary(s, p[3 * n - 2], p[3 * n - 1]));
        printf("  branch %zu: t [%.6f, %.6f], %zu points, start %d, end %d\n", i, p[0],
               p[3 * n - 3], n, (int)start, (int)end);
        free(p);
    }
    exit_oracle_report ends;
    exit_oracle_check_ends(s, c, row->dir, r, &ends);
    exit_oracle_print(row->name, &ends);
    CHECK(ends.not_found == 0);
    CHECK(ends.max_dist <= EXIT_TOL);
    CHECK(ends.max_margin == 0.0);
    trace_oracle_report rep;
    trace_oracle_check(s, c, row->dir, r, N_SAMPLES, &rep);
    trace_oracle_print(row->name, &rep);
    CHECK(rep.uncovered_far == 0);
    CHECK(rep.max_residual <= RESIDUAL_TOL);
    CHECK(rep.behind == 0);
    projcurve_result_destroy(r);
    return nb;
}

/* The pcurve of a piece (Bezier of degree 1 or 3 in (u, v)) at s, by de
 * Casteljau. */
static void pcurve_point(int degree, const double *ctrl, double s, double uv[2])
{
    double w[2 * PROJCURVE_MAX_PCURVE_POINTS];
    for (int k = 0; k < 2 * (degree + 1); ++k)
        w[k] = ctrl[k];
    for (int level = degree; level > 0; --level)
        for (int k = 0; k < 2 * level; ++k)
            w[k] += s * (w[k + 2] - w[k]);
    uv[0] = w[0];
    uv[1] = w[1];
}

/* Composed with the manifest's tolerances: each piece is S composed with
 * the straight (u, v) segment of its range, so the joined curve at
 * t0 + s (t1 - t0) equals S at the (u, v) interpolated with s. */
static void check_composed(const manifest_row *row, const projcurve_surface *s,
                           const projcurve_curve *c, size_t expected)
{
    projcurve_options *o = NULL;
    projcurve_options_create(NULL, &o);
    projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, row->tol_distance);
    projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_ANGLE_DEG, row->tol_angle);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_directional(NULL, s, c, row->dir, o, &r));
    projcurve_options_destroy(o);
    CHECK(projcurve_result_branch_count(r) == expected);
    double worst = 0.0;
    size_t joined_count = 0;
    for (size_t i = 0; i < projcurve_result_branch_count(r); ++i) {
        size_t n_pieces = 0;
        projcurve_result_branch_info(NULL, r, i, NULL, NULL, NULL, NULL, &n_pieces);
        CHECK(n_pieces > 0);
        projcurve_curve *joined = NULL;
        if (projcurve_result_branch_curve(NULL, r, i, &joined) != PROJCURVE_OK)
            continue; /* a degree above PROJCURVE_MAX_DEGREE cannot be joined */
        ++joined_count;
        for (size_t k = 0; k < n_pieces; ++k) {
            double range[2], ctrl[2 * PROJCURVE_MAX_PCURVE_POINTS];
            int degree = 0;
            projcurve_result_piece(NULL, r, i, k, NULL, NULL, NULL, range, NULL);
            CHECK_OK(projcurve_result_piece_pcurve(NULL, r, i, k, &degree, ctrl));
            for (int j = 0; j <= 4; ++j) {
                const double f = j / 4.0;
                double x[3], y[3], uv[2];
                pcurve_point(degree, ctrl, f, uv);
                projcurve_curve_eval(NULL, joined, range[0] + f * (range[1] - range[0]), 0, x);
                projcurve_surface_eval(NULL, s, uv[0], uv[1], 0, y);
                worst = fmax(worst, fmax(fabs(x[0] - y[0]), fmax(fabs(x[1] - y[1]), fabs(x[2] - y[2]))));
            }
        }
        projcurve_curve_destroy(joined);
    }
    printf("  composed: %zu joined curves, on S to %.3g\n", joined_count, worst);
    CHECK(worst <= 1e-9);
    projcurve_result_destroy(r);
}

static void run_case(const manifest_row *row)
{
    char rel[256];
    snprintf(rel, sizeof rel, "cases/%s.igs", row->name);
    projcurve_model *m = NULL;
    const projcurve_status st = projcurve_model_read_file(NULL, pc_test_data_path(rel), &m);
    CHECK_OK(st);
    if (st != PROJCURVE_OK)
        return;
    CHECK(projcurve_model_surface_count(m) == 1 && projcurve_model_curve_count(m) >= 1);
    const projcurve_surface *s = projcurve_model_surface(m, 0);
    size_t total = 0;
    printf("%s: expect %d\n", row->name, row->expected);
    for (size_t i = 0; s && i < projcurve_model_curve_count(m); ++i)
        total += check_traced(row, s, projcurve_model_curve(m, i));
    CHECK(total == (size_t)row->expected);
    if (s && projcurve_model_curve_count(m) == 1)
        check_composed(row, s, projcurve_model_curve(m, 0), (size_t)row->expected);
    projcurve_model_destroy(m);
}

int main(void)
{
    FILE *f = fopen(pc_test_data_path("cases/MANIFEST.tsv"), "r");
    if (f == NULL)
        pc_test_missing_data("cases/MANIFEST.tsv");
    char line[2048];
    int cases = 0;
    while (fgets(line, sizeof line, f)) {
        manifest_row row;
        if (line[0] == '#' || !parse_row(line, &row) || strcmp(row.mode, "directional") != 0)
            continue;
        run_case(&row);
        ++cases;
    }
    fclose(f);
    CHECK(cases >= 7);
    return pc_test_finish("test_trace_cases");
}
