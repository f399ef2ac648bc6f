/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Cubic pcurves (PROJCURVE_OPT_PCURVE_DEGREE = 3) end to end, on the shapes
 * of the tracing tests (tests/support/trace_shapes) and on every directional
 * and orthogonal case of tests/data/cases: for eps_D = 1e-2, 1e-4, 1e-5 and
 * 1e-6 of the model size at eps_T = 1 degree,
 *  - every branch measured by the oracles of tests/support/piece_oracle
 *    (exact projection by the oracle's own Newton; Hausdorff both ways on
 *    dense samples <= eps_D, joints <= eps_T, joins, piece ends, one patch
 *    per piece) — the same bar as the straight pieces;
 *  - every piece equals S(u(s), v(s)) for its pcurve read through
 *    projcurve_result_piece_pcurve (Bernstein sums of the pcurve, the
 *    library's surface evaluation), and the pcurve's ends are the piece's
 *    (u, v) ends;
 *  - the piece count against straight pcurves at eps_D = 1e-5 (printed;
 *    the cubic pieces must be at most half as many).
 * Also: surfaces whose composed degree would exceed the limit fall back to
 * degree 1, bad option values and accessor misuse get their statuses.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "geom/curve.h"
#include "geom/surface.h"
#include "piece_oracle.h"
#include "shapes.h"
#include "trace_shapes.h"

#define MAX_CASES 32
#define NAME_LEN 96
#define PCURVE_SAMPLES 25
/* Composition accuracy promised by compose/ (test_compose_poly), with room
 * for the degree-30 pieces of quintic patches. */
#define ON_SURFACE_REL 1e-11

typedef struct projection_case {
    char name[NAME_LEN];
    const projcurve_surface *surface;
    const projcurve_curve *curve;
    int orthogonal;
    double dir[3];
} projection_case;

static double binomial(int n, int k)
{
    double c = 1.0;
    for (int i = 1; i <= k; ++i)
        c = c * (double)(n - k + i) / (double)i;
    return c;
}

/* Every piece is S at its pcurve; the pcurve's ends are the piece's ends. */
static void check_pcurves(const projcurve_result *r, const projcurve_surface *s, int degree,
                          size_t *cubic, size_t *straight)
{
    double worst = 0.0, worst_end = 0.0;
    for (size_t i = 0; i < r->n_branches; ++i) {
        const pc_branch *b = &r->branches[i];
        for (size_t k = 0; k < b->n_pieces; ++k) {
            int d = 0;
            double uv[2 * PROJCURVE_MAX_PCURVE_POINTS];
            CHECK_OK(projcurve_result_piece_pcurve(NULL, r, i, k, &d, uv));
            CHECK(d == 1 || d == degree);
            if (d != 1 && d != 3)
                continue;
            *(d == 3 ? cubic : straight) += 1;
            const pc_piece *pc = &b->pieces[k];
            worst_end = fmax(worst_end, fmax(fabs(uv[0] - pc->uv[0]), fabs(uv[1] - pc->uv[1])));
            worst_end = fmax(worst_end, fmax(fabs(uv[2 * d] - pc->uv[2]),
                                             fabs(uv[2 * d + 1] - pc->uv[3])));
            for (int j = 0; j <= PCURVE_SAMPLES; ++j) {
                const double sp = (double)j / PCURVE_SAMPLES;
                double q[2] = {0.0, 0.0}, x[3];
                for (int m = 0; m <= d; ++m) {
                    const double bm = binomial(d, m) * pow(sp, m) * pow(1.0 - sp, d - m);
                    q[0] += bm * uv[2 * m];
                    q[1] += bm * uv[2 * m + 1];
                }
                pc_vec3 y;
                pc_oracle_piece_eval(pc, sp, &y, NULL);
                CHECK_OK(projcurve_surface_eval(NULL, s, q[0], q[1], 0, x));
                worst = fmax(worst, vec3_dist(y, vec3_load(x)));
            }
        }
    }
    CHECK(worst_end == 0.0);
    if (!(worst <= ON_SURFACE_REL * s->size))
        fprintf(stderr, "pieces off S(pcurve) by %.3g (size %.3g)\n", worst, s->size);
    CHECK(worst <= ON_SURFACE_REL * s->size);
}

static projcurve_result *project(const projection_case *c, double rel_eps, double angle,
                                 int degree)
{
    const projcurve_surface *s = c->surface;
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_options_create(NULL, &o));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_DISTANCE, rel_eps * s->size));
    CHECK_OK(projcurve_options_set_double(NULL, o, PROJCURVE_OPT_TOL_ANGLE_DEG, angle));
    CHECK_OK(projcurve_options_set_int(NULL, o, PROJCURVE_OPT_PCURVE_DEGREE, degree));
    projcurve_result *r = NULL;
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    const projcurve_status st = c->orthogonal
                                    ? projcurve_project_orthogonal(ctx, s, c->curve, o, &r)
                                    : projcurve_project_directional(ctx, s, c->curve, c->dir, o, &r);
    CHECK_OK(st);
    if (st != PROJCURVE_OK)
        fprintf(stderr, "%s: %s\n", c->name, projcurve_context_message(ctx));
    projcurve_context_destroy(ctx);
    projcurve_options_destroy(o);
    return r;
}

/* Straight pcurves are projected for comparison at this eps_D (relative):
 * tight enough for the O(h^4) against O(h^2) difference to show, and the
 * straight pieces are still affordable in a sanitizer build. */
#define COMPARE_REL_EPS 1e-5

/* Projects c with cubic pcurves and measures the result; at COMPARE_REL_EPS
 * also with straight ones. */
static void run(const projection_case *c, double rel_eps, double angle)
{
    const projcurve_surface *s = c->surface;
    projcurve_result *r = project(c, rel_eps, angle, 3);
    projcurve_result *lin = rel_eps == COMPARE_REL_EPS ? project(c, rel_eps, angle, 1) : NULL;
    if (r == NULL) {
        projcurve_result_destroy(lin);
        return;
    }
    if (lin != NULL)
        CHECK(r->n_branches == lin->n_branches);
    pc_oracle_dir d;
    pc_projector proj;
    if (c->orthogonal)
        pc_oracle_projector_orthogonal(s, c->curve, &proj);
    else
        pc_oracle_projector(s, c->curve, c->dir, &d, &proj);
    pc_oracle_summary sum;
    pc_oracle_measure_result(r, &proj, &s->grid, &sum);
    size_t cubic = 0, straight = 0;
    check_pcurves(r, s, 3, &cubic, &straight);
    double lin_pieces = NAN;
    if (lin != NULL)
        CHECK_OK(projcurve_result_stat(NULL, lin, PROJCURVE_STAT_PIECES, &lin_pieces));
    printf("%-28s eps_D %.0e: %zu branches, pieces %5zu (cubic %zu, straight %zu) vs %5.0f "
           "in straight mode; Hausdorff %.2f eps_D, joints <= %.3f deg\n",
           c->name, rel_eps, r->n_branches, sum.pieces, cubic, straight, lin_pieces,
           sum.worst.hausdorff / (rel_eps * s->size), sum.worst.max_angle);
    CHECK(sum.branches_without_pieces == 0);
    CHECK(sum.failures == 0);
    CHECK(sum.worst.hausdorff <= rel_eps * s->size);
    CHECK(sum.worst.max_angle <= angle * (1.0 + 1e-9));
    CHECK(sum.worst.max_gap <= 1e-12 * s->size);
    CHECK(sum.worst.max_end_err <= 1e-9 * s->size);
    CHECK(sum.worst.off_patch == 0);
    CHECK(cubic > 0);
    /* O(h^4) against O(h^2): at tight tolerances far fewer pieces */
    if (lin != NULL)
        CHECK(2.0 * (double)sum.pieces <= lin_pieces);
    /* the joined branch has the cubic pieces' degree */
    for (size_t i = 0; i < r->n_branches; ++i) {
        projcurve_curve *joined = NULL;
        CHECK_OK(projcurve_result_branch_curve(NULL, r, i, &joined));
        projcurve_curve_destroy(joined);
    }
    projcurve_result_destroy(r);
    projcurve_result_destroy(lin);
}

static const double rel_eps[] = {1e-2, 1e-4, COMPARE_REL_EPS, 1e-6};
#define N_EPS (sizeof rel_eps / sizeof rel_eps[0])

static void test_shapes(void)
{
    const double plane_o[3] = {0, 0, 0}, plane_a[3] = {10, 0, 1}, plane_b[3] = {0, 10, 2};
    const double plane_curve[18] = {2, 2, 30, 4, 3, 31, 5, 6, 29, 6, 4, 30, 7, 7, 32, 8, 8, 30};
    const double cyl_curve[18] = {-25, 10, 50, -10, 30, 55, 0, 40, 45,
                                  10, 60, 50, 20, 70, 52, 25, 90, 50};
    const double sphere_line[6] = {-15, 3, 20, 15, 3, 20};
    const double bumpy_curve[15] = {0.1, 0.2, 1, 0.3, 0.8, 1.2, 0.5, 0.3,
                                    0.9, 0.7, 0.9, 1.1, 0.85, 0.6, 1};
    pc_shape_surface bumpy = pc_shape_bumpy(2024, 5, 5, 0.15, 1);
    projection_case cases[] = {
        {"plane", shape_plane(plane_o, plane_a, plane_b), shape_bspline_curve(3, 6, plane_curve),
         0, {0.05, -0.05, -1}},
        {"half cylinder", shape_half_cylinder(30.0, 100.0), shape_bspline_curve(3, 6, cyl_curve),
         0, {0, 0, -1}},
        {"sphere silhouettes", shape_sphere(10.0), shape_bspline_curve(1, 2, sphere_line), 0,
         {0, 0, -1}},
        {"rational bumpy", pc_shape_surface_create(&bumpy), shape_bspline_curve(3, 5, bumpy_curve),
         0, {0.05, 0.02, -1}},
        {"example 1", shape_example1_surface(), shape_example1_curve(), 0, {-1, 0, 0}},
    };
    pc_shape_surface_free(&bumpy);
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; ++k) {
        CHECK(cases[k].surface != NULL && cases[k].curve != NULL);
        if (cases[k].surface != NULL && cases[k].curve != NULL)
            for (size_t e = 0; e < N_EPS; ++e)
                run(&cases[k], rel_eps[e], 1.0);
        projcurve_surface_destroy((projcurve_surface *)(void *)cases[k].surface);
        projcurve_curve_destroy((projcurve_curve *)(void *)cases[k].curve);
    }
}

/* Directional and orthogonal rows of MANIFEST.tsv (name, mode, dir_x,
 * dir_y, dir_z, ...) with at least one branch expected. */
static void test_shared_cases(void)
{
    FILE *f = fopen(pc_test_data_path("cases/MANIFEST.tsv"), "r");
    if (f == NULL)
        pc_test_missing_data("cases/MANIFEST.tsv");
    char line[2048];
    while (fgets(line, sizeof line, f) != NULL) {
        projection_case c;
        char mode[32];
        double tol_d, tol_a;
        long branches;
        if (line[0] == '#' ||
            sscanf(line, "%95s %31s %lf %lf %lf %lf %lf %ld", c.name, mode, &c.dir[0],
                   &c.dir[1], &c.dir[2], &tol_d, &tol_a, &branches) != 8 ||
            branches < 1 || (strcmp(mode, "directional") != 0 && strcmp(mode, "orthogonal") != 0))
            continue;
        c.orthogonal = strcmp(mode, "orthogonal") == 0;
        char rel[NAME_LEN + 16];
        snprintf(rel, sizeof rel, "cases/%.*s.igs", NAME_LEN - 1, c.name);
        projcurve_model *model = NULL;
        CHECK_OK(projcurve_model_read_file(NULL, pc_test_data_path(rel), &model));
        c.surface = projcurve_model_surface(model, 0);
        c.curve = projcurve_model_curve(model, 0);
        CHECK(c.surface != NULL && c.curve != NULL);
        if (c.surface != NULL && c.curve != NULL)
            for (size_t e = 0; e < N_EPS; ++e)
                run(&c, rel_eps[e], 1.0);
        projcurve_model_destroy(model);
    }
    fclose(f);
}

/* Cubic pcurves where 3 (p + q) <= PROJCURVE_MAX_DEGREE (composed degree
 * 3 (p + q)), straight ones above (degree p + q): a p x q plane. */
static void check_degree_rule(int p, int q)
{
    pc_shape_surface plane = pc_shape_plane(p, q, 1, 1);
    projcurve_surface *s = pc_shape_surface_create(&plane);
    pc_shape_surface_free(&plane);
    CHECK(s != NULL);
    if (s == NULL)
        return;
    const double line[6] = {0.1, 0.2, 5.0, 0.8, 0.7, 5.0};
    projection_case c = {"plane p x q", s, shape_bspline_curve(1, 2, line), 0, {0, 0, -1}};
    projcurve_result *r = project(&c, 1e-4, 1.0, 3);
    CHECK(r != NULL && r->n_branches == 1);
    if (r != NULL && r->n_branches == 1) {
        const int cubic_ok = 3 * (p + q) <= PROJCURVE_MAX_DEGREE;
        size_t cubic = 0, straight = 0;
        check_pcurves(r, s, cubic_ok ? 3 : 1, &cubic, &straight);
        if (cubic_ok)
            CHECK(cubic > 0 && straight == 0);
        else
            CHECK(cubic == 0 && straight > 0);
        CHECK(r->branches[0].pieces[0].degree == (cubic_ok ? 3 : 1) * (p + q));
    }
    projcurve_result_destroy(r);
    projcurve_curve_destroy((projcurve_curve *)(void *)c.curve);
    projcurve_surface_destroy(s);
}

static void test_degree_fallback(void)
{
    check_degree_rule(5, 5);   /* composed degree 30: cubic */
    check_degree_rule(6, 5);   /* 33: straight */
    check_degree_rule(6, 8);   /* 42, the linkrods.step surfaces: straight */
    check_degree_rule(12, 10); /* 66: straight */
}

/* The sphere |x|^2 = 100 as an implicit surface. */
static int sphere_fn(void *user, const double x[3], double *value, double grad[3],
                     double hess[9])
{
    (void)user;
    *value = x[0] * x[0] + x[1] * x[1] + x[2] * x[2] - 100.0;
    for (int i = 0; i < 3; ++i) {
        grad[i] = 2.0 * x[i];
        for (int j = 0; j < 3; ++j)
            hess[3 * i + j] = i == j ? 2.0 : 0.0;
    }
    return 0;
}

/* A result on an implicit surface has pieces but no (u, v) pcurve. */
static void test_implicit_has_no_pcurve(projcurve_context *ctx)
{
    const double line[6] = {-5, 3, 20, 5, 3, 20};
    projcurve_curve *curve = shape_bspline_curve(1, 2, line);
    projcurve_result *r = NULL;
    CHECK_OK(projcurve_project_orthogonal_implicit(ctx, sphere_fn, NULL, 20.0, curve, NULL, &r));
    size_t n_pieces = 0;
    if (r != NULL && projcurve_result_branch_count(r) > 0)
        CHECK_OK(projcurve_result_branch_info(ctx, r, 0, NULL, NULL, NULL, NULL, &n_pieces));
    CHECK(n_pieces > 0);
    if (n_pieces > 0) {
        int degree = -7;
        CHECK_STATUS(projcurve_result_piece_pcurve(ctx, r, 0, 0, &degree, NULL),
                     PROJCURVE_ERR_INVALID_ARGUMENT);
        CHECK(degree == -7);
    }
    projcurve_result_destroy(r);
    projcurve_curve_destroy(curve);
}

/* The option's bad values and the accessor's bad arguments. */
static void test_bad_input(void)
{
    projcurve_context *ctx = NULL;
    projcurve_options *o = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK_OK(projcurve_options_create(ctx, &o));
    const long long bad[] = {0, 2, 4, -1, 1LL << 40};
    for (size_t i = 0; i < sizeof bad / sizeof bad[0]; ++i)
        CHECK_STATUS(projcurve_options_set_int(ctx, o, PROJCURVE_OPT_PCURVE_DEGREE, bad[i]),
                     PROJCURVE_ERR_OUT_OF_RANGE);
    CHECK_STATUS(projcurve_options_set_double(ctx, o, PROJCURVE_OPT_PCURVE_DEGREE, 3.0),
                 PROJCURVE_ERR_WRONG_KIND);
    projcurve_options_destroy(o);

    const double plane_o[3] = {0, 0, 0}, plane_a[3] = {10, 0, 0}, plane_b[3] = {0, 10, 0};
    const double line[6] = {1, 1, 5, 9, 8, 5};
    projection_case c = {"plane", shape_plane(plane_o, plane_a, plane_b),
                         shape_bspline_curve(1, 2, line), 0, {0, 0, -1}};
    projcurve_result *r = project(&c, 1e-3, 1.0, 3);
    int degree = -7;
    double uv[8];
    CHECK_STATUS(projcurve_result_piece_pcurve(ctx, NULL, 0, 0, &degree, uv),
                 PROJCURVE_ERR_NULL_ARGUMENT);
    CHECK_STATUS(projcurve_result_piece_pcurve(ctx, r, 1, 0, &degree, uv), PROJCURVE_ERR_INDEX);
    CHECK_STATUS(projcurve_result_piece_pcurve(ctx, r, 0, 1000000, &degree, uv),
                 PROJCURVE_ERR_INDEX);
    CHECK(degree == -7);
    CHECK_OK(projcurve_result_piece_pcurve(ctx, r, 0, 0, NULL, NULL));
    CHECK_OK(projcurve_result_piece_pcurve(ctx, r, 0, 0, &degree, NULL));
    CHECK(degree == 3);
    projcurve_result_destroy(r);
    test_implicit_has_no_pcurve(ctx);
    projcurve_surface_destroy((projcurve_surface *)(void *)c.surface);
    projcurve_curve_destroy((projcurve_curve *)(void *)c.curve);
    projcurve_context_destroy(ctx);
}

/* The piece limit stops the cubic march with a readable prefix. */
static void test_piece_limit(void)
{
    projcurve_surface *s = shape_example1_surface();
    projcurve_curve *curve = shape_example1_curve();
    const double dir[3] = {-1.0, 0.0, 0.0};
    projcurve_options *o = NULL;
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    CHECK_OK(projcurve_options_create(ctx, &o));
    CHECK_OK(projcurve_options_set_int(ctx, o, PROJCURVE_OPT_PCURVE_DEGREE, 3));
    CHECK_OK(projcurve_options_set_int(ctx, o, PROJCURVE_OPT_MAX_PIECES, 3));
    CHECK_OK(projcurve_options_set_double(ctx, o, PROJCURVE_OPT_TOL_DISTANCE, 1e-6 * s->size));
    projcurve_result *r = NULL;
    CHECK_STATUS(projcurve_project_directional(ctx, s, curve, dir, o, &r),
                 PROJCURVE_ERR_LIMIT_REACHED);
    size_t n_pieces = 0;
    projcurve_branch_end end = PROJCURVE_END_CURVE_END;
    if (r != NULL && projcurve_result_branch_count(r) == 1)
        CHECK_OK(projcurve_result_branch_info(ctx, r, 0, NULL, NULL, &end, NULL, &n_pieces));
    CHECK(n_pieces >= 1 && n_pieces <= 3);
    CHECK(end == PROJCURVE_END_LIMIT);
    for (size_t k = 0; k < n_pieces; ++k) {
        int degree = 0;
        CHECK_OK(projcurve_result_piece_pcurve(ctx, r, 0, k, &degree, NULL));
        CHECK(degree == 3);
    }
    projcurve_result_destroy(r);
    projcurve_options_destroy(o);
    projcurve_context_destroy(ctx);
    projcurve_curve_destroy(curve);
    projcurve_surface_destroy(s);
}

int main(void)
{
    test_piece_limit();
    test_bad_input();
    test_degree_fallback();
    test_shapes();
    test_shared_cases();
    return pc_test_finish("test_refine_cubic");
}
