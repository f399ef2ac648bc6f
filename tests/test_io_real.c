/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * Every file of tests/data/real loads, with the surface counts, degrees,
 * net sizes and rational flags that tests/data/real/SOURCES.md states
 * (an independent description of the files), and every case of
 * tests/data/cases loads with one surface and one curve.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>

#include "check.h"
#include "projcurve.h"

typedef struct real_file {
    const char *name;
    size_t surfaces;     /* SOURCES.md */
    size_t rational;     /* surfaces with varying weights, SOURCES.md (-1: not stated) */
} real_file;

static const real_file files[] = {
    {"sunglasses_lens.igs", 9, 0},
    {"bladex_upper.iges", 1, 0},
    {"hammer.iges", 45, 27},
    {"bearing.iges", 213, 0},
    {"linkrods.step", 37, 29}, /* 18 B-splines (16 rational), 6 planes, 4 cylinders, 9 tori */
    {"test-joinsurf_01.stp", 2, 0},
    {"test-joinsurf_04.stp", 2, 0},
    {"test_pipe_out_true.step", 6, 4},
    {"car_shell1.xml", 8, 0},
    {"horn.xml", 1, 0},
    {"shroud_kaplan.xml", 2, 0},
    {"egg.xml", 1, 1},
    {"teapot_newell_spd.txt", 32, 0},
};

static projcurve_model *load(projcurve_context *ctx, const char *relative)
{
    projcurve_model *m = NULL;
    const char *path = pc_test_data_path(relative);
    const projcurve_status st = projcurve_model_read_file(ctx, path, &m);
    if (st != PROJCURVE_OK)
        pc_test_fail_at(__FILE__, __LINE__, "%s: %s: %s", relative, projcurve_status_string(st),
                        projcurve_context_message(ctx));
    return m;
}

/* Each real file is read once (reading the large ones is most of this
 * test's time under the sanitizers) and kept here until the end. */
static projcurve_model *loaded[sizeof files / sizeof *files];

/* The model of a real file, read on first use; NULL if it failed. */
static const projcurve_model *real(projcurve_context *ctx, const char *name)
{
    for (size_t f = 0; f < sizeof files / sizeof *files; ++f)
        if (strcmp(files[f].name, name) == 0) {
            if (loaded[f] == NULL) {
                char rel[256];
                snprintf(rel, sizeof rel, "real/%s", name);
                loaded[f] = load(ctx, rel);
            }
            return loaded[f];
        }
    pc_test_fail_at(__FILE__, __LINE__, "%s is not in the table of real files", name);
    return NULL;
}

/* Surface i has the given degrees, net and span counts. */
static void check_shape(projcurve_context *ctx, const projcurve_model *m, size_t i, int du, int dv,
                        size_t nu, size_t nv, size_t su, size_t sv)
{
    int a, b, rat;
    size_t n_u, n_v, s_u, s_v;
    CHECK_OK(projcurve_surface_info(ctx, projcurve_model_surface(m, i), &a, &b, &n_u, &n_v, &s_u,
                                    &s_v, &rat));
    CHECK(a == du && b == dv);
    CHECK(n_u == nu && n_v == nv);
    CHECK(s_u == su && s_v == sv);
    if (!(a == du && b == dv && n_u == nu && n_v == nv && s_u == su && s_v == sv))
        fprintf(stderr, "  surface %zu: degree (%d,%d) net %zux%zu spans %zux%zu\n", i, a, b, n_u,
                n_v, s_u, s_v);
}

static void check_counts(projcurve_context *ctx)
{
    for (size_t f = 0; f < sizeof files / sizeof *files; ++f) {
        const projcurve_model *m = real(ctx, files[f].name);
        if (m == NULL)
            continue;
        const size_t n = projcurve_model_surface_count(m);
        if (n != files[f].surfaces)
            pc_test_fail_at(__FILE__, __LINE__, "%s: %zu surfaces, SOURCES.md says %zu",
                            files[f].name, n, files[f].surfaces);
        size_t rational = 0;
        for (size_t i = 0; i < n; ++i) {
            int r = 0;
            CHECK_OK(projcurve_surface_info(ctx, projcurve_model_surface(m, i), NULL, NULL, NULL,
                                            NULL, NULL, NULL, &r));
            rational += (size_t)r;
        }
        if (rational != files[f].rational)
            pc_test_fail_at(__FILE__, __LINE__, "%s: %zu rational surfaces, SOURCES.md says %zu",
                            files[f].name, rational, files[f].rational);
        printf("%-26s %4zu surfaces (%zu rational), %4zu curves, %4zu skipped\n", files[f].name, n,
               rational, projcurve_model_curve_count(m), projcurve_model_skipped_count(m));
    }
}

/* Shapes stated in SOURCES.md for single-surface files and samples. */
static void check_shapes(projcurve_context *ctx)
{
    const projcurve_model *m = real(ctx, "bladex_upper.iges");
    if (m)
        check_shape(ctx, m, 0, 3, 2, 526, 13, 523, 11);
    m = real(ctx, "sunglasses_lens.igs");
    if (m) {
        for (size_t i = 0; i < projcurve_model_surface_count(m); ++i)
            check_shape(ctx, m, i, 3, 3, 16, 16, 13, 13);
    }
    m = real(ctx, "test-joinsurf_04.stp");
    if (m) {
        check_shape(ctx, m, 0, 3, 3, 88, 88, 85, 85);
        check_shape(ctx, m, 1, 3, 3, 88, 88, 85, 85);
    }
    m = real(ctx, "horn.xml");
    if (m)
        check_shape(ctx, m, 0, 3, 3, 24, 8, 21, 5);
    m = real(ctx, "egg.xml");
    if (m)
        check_shape(ctx, m, 0, 2, 3, 9, 20, 4, 17);
    m = real(ctx, "teapot_newell_spd.txt");
    if (m) {
        check_shape(ctx, m, 0, 3, 3, 4, 4, 1, 1);
        /* Rim patch 1 starts at vertex 1 = (1.4, 0, 2.4) (the file's first vertex). */
        double p[3];
        CHECK_OK(projcurve_surface_eval(ctx, projcurve_model_surface(m, 0), 0.0, 0.0, 0, p));
        CHECK_NEAR(p[0], 1.4, 1e-15);
        CHECK_NEAR(p[1], 0.0, 1e-15);
        CHECK_NEAR(p[2], 2.4, 1e-15);
    }
}

/* linkrods.step: degrees (6,10) x 6 (the largest with 7 x 286 poles and
 * 1 x 30 spans), (6,8) x 6, (6,3) x 4, (3,1) x 2. The pole counts per
 * direction tell whether STEP's u-outer point lists were stored u fastest. */
static void check_linkrods_degrees(projcurve_context *ctx)
{
    const projcurve_model *m = real(ctx, "linkrods.step");
    if (m == NULL)
        return;
    int n610 = 0, n68 = 0, n63 = 0, n31 = 0, largest = 0;
    for (size_t i = 0; i < projcurve_model_surface_count(m); ++i) {
        int a, b;
        size_t nu, nv, su, sv;
        CHECK_OK(projcurve_surface_info(ctx, projcurve_model_surface(m, i), &a, &b, &nu, &nv,
                                        &su, &sv, NULL));
        n610 += (a == 6 && b == 10);
        n68 += (a == 6 && b == 8);
        n63 += (a == 6 && b == 3);
        n31 += (a == 3 && b == 1);
        if (a == 6)
            CHECK(nu == 7 && su == 1);
        largest += (a == 6 && b == 10 && nu == 7 && nv == 286 && su == 1 && sv == 30);
    }
    CHECK(n610 == 6 && n68 == 6 && n63 == 4 && n31 == 2);
    CHECK(largest > 0);
}

/* test_pipe_out_true.step: 4 rational (1,2) surfaces with 31 x 32 poles and
 * 30 x 30 spans, 2 bilinear 31 x 31. car_shell1.xml: nets 19x22, 28x22,
 * 18x68 and 31x41, each twice. */
static void check_nets(projcurve_context *ctx)
{
    const projcurve_model *m = real(ctx, "test_pipe_out_true.step");
    if (m) {
        int rational12 = 0, bilinear = 0;
        for (size_t i = 0; i < projcurve_model_surface_count(m); ++i) {
            int a, b, r;
            size_t nu, nv, su, sv;
            CHECK_OK(projcurve_surface_info(ctx, projcurve_model_surface(m, i), &a, &b, &nu, &nv,
                                            &su, &sv, &r));
            rational12 += (a == 1 && b == 2 && r && nu == 31 && nv == 32 && su == 30 && sv == 30);
            bilinear += (a == 1 && b == 1 && nu == 31 && nv == 31);
        }
        CHECK(rational12 == 4 && bilinear == 2);
    }
    m = real(ctx, "car_shell1.xml");
    if (m) {
        static const size_t nets[4][2] = {{19, 22}, {28, 22}, {18, 68}, {31, 41}};
        int found[4] = {0, 0, 0, 0};
        for (size_t i = 0; i < projcurve_model_surface_count(m); ++i) {
            size_t nu, nv;
            CHECK_OK(projcurve_surface_info(ctx, projcurve_model_surface(m, i), NULL, NULL, &nu,
                                            &nv, NULL, NULL, NULL));
            for (int k = 0; k < 4; ++k)
                found[k] += (nu == nets[k][0] && nv == nets[k][1]);
        }
        CHECK(found[0] == 2 && found[1] == 2 && found[2] == 2 && found[3] == 2);
    }
}

typedef struct degree_tally {
    int du, dv;
    int count;
} degree_tally;

/* The file's surfaces have these degrees, this many of each (SOURCES.md);
 * single_span: every surface is one Bezier patch. */
static void check_degrees(projcurve_context *ctx, const char *name, const degree_tally *want,
                          size_t n_want, int single_span)
{
    const projcurve_model *m = real(ctx, name);
    if (m == NULL)
        return;
    int got[16] = {0}, other = 0, multi_span = 0;
    for (size_t i = 0; i < projcurve_model_surface_count(m); ++i) {
        int a, b;
        size_t su, sv;
        CHECK_OK(projcurve_surface_info(ctx, projcurve_model_surface(m, i), &a, &b, NULL, NULL,
                                        &su, &sv, NULL));
        multi_span += (su != 1 || sv != 1);
        size_t k = 0;
        while (k < n_want && !(want[k].du == a && want[k].dv == b))
            ++k;
        if (k < n_want)
            ++got[k];
        else
            ++other;
    }
    for (size_t k = 0; k < n_want; ++k)
        if (got[k] != want[k].count)
            pc_test_fail_at(__FILE__, __LINE__, "%s: %d surfaces of degree (%d,%d), SOURCES.md "
                            "says %d", name, got[k], want[k].du, want[k].dv, want[k].count);
    CHECK(other == 0);
    if (single_span)
        CHECK(multi_span == 0);
    pc_test_checks += (int)n_want;
}

static void check_degree_tallies(projcurve_context *ctx)
{
    static const degree_tally hammer[] = {{2, 2, 12}, {1, 2, 15}, {1, 1, 14}, {3, 1, 4}};
    static const degree_tally bearing[] = {{3, 3, 87}, {3, 1, 69}, {5, 3, 18},
                                           {4, 3, 18}, {1, 3, 11}, {6, 3, 4},
                                           {1, 1, 4},  {2, 3, 1},  {8, 3, 1}};
    check_degrees(ctx, "hammer.iges", hammer, sizeof hammer / sizeof *hammer, 0);
    check_degrees(ctx, "bearing.iges", bearing, sizeof bearing / sizeof *bearing, 1);
    /* test-joinsurf_01.stp: one 5 x 21 net with 2 x 18 spans, one 4 x 18
     * with 1 x 15; shroud_kaplan.xml: two 15 x 10 nets, 13 x 8 spans. */
    const projcurve_model *m = real(ctx, "test-joinsurf_01.stp");
    if (m) {
        check_shape(ctx, m, 0, 3, 3, 4, 18, 1, 15);
        check_shape(ctx, m, 1, 3, 3, 5, 21, 2, 18);
    }
    m = real(ctx, "shroud_kaplan.xml");
    if (m) {
        check_shape(ctx, m, 0, 2, 2, 15, 10, 13, 8);
        check_shape(ctx, m, 1, 2, 2, 15, 10, 13, 8);
    }
}

static void check_cases(projcurve_context *ctx)
{
    static const char *const cases[] = {
        "song_yong_example1",       "song_yong_example1_paperdir", "bumpy_bicubic_8x8_down",
        "bumpy_boundary_exit_reenter", "deg5_quintic_9x8_down",   "nurbs_half_cylinder_down",
        "fold_c_sheet_jump",        "ortho_bumpy_bicubic_hover",   "ortho_nurbs_half_cylinder"};
    for (size_t i = 0; i < sizeof cases / sizeof *cases; ++i) {
        char rel[256];
        snprintf(rel, sizeof rel, "cases/%s.igs", cases[i]);
        projcurve_model *m = load(ctx, rel);
        if (m == NULL)
            continue;
        CHECK(projcurve_model_surface_count(m) == 1);
        CHECK(projcurve_model_curve_count(m) == 1);
        CHECK(projcurve_model_skipped_count(m) == 0);
        projcurve_model_destroy(m);
    }
}

int main(void)
{
    FILE *probe = fopen(pc_test_data_path("real/SOURCES.md"), "r");
    if (probe == NULL)
        pc_test_missing_data("real/SOURCES.md");
    fclose(probe);
    projcurve_context *ctx = NULL;
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    check_counts(ctx);
    check_shapes(ctx);
    check_linkrods_degrees(ctx);
    check_nets(ctx);
    check_degree_tallies(ctx);
    check_cases(ctx);
    for (size_t f = 0; f < sizeof files / sizeof *files; ++f)
        projcurve_model_destroy(loaded[f]);
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_io_real");
}
