/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * IGES trimmed surfaces (144) on analytic base surfaces (iges_face_map.c):
 * the boundaries come from the 142s' model-space curves, inverted onto the
 * exact NURBS the reader builds (mapped exactly where it is affine: the
 * plane). Files written here (the formatter of
 * test_io_iges_analytic.c): a 120 cylinder segment (a quarter turn; its
 * NURBS's u is the rational angle map of the turn, not the angle) trimmed
 * to theta in [0.2, 1.2], z in [0.5, 1.5], and a 108 plane trimmed to a
 * square with a round hole. Oracles are analytic: one face with the loops
 * written; points of known (theta, z) or (x, y) classified IN or OUT as the
 * trim says; every loop piece's 3D image S(q(t)) on the boundary written
 * (the arcs, lines and circle) within the model tolerance, its ends at the
 * boundary's corners; the cylinder's inverted pieces are cubics of few
 * poles (fit/resampled.h). The same for bounded surfaces (143) on those bases,
 * whose 141 boundaries' model-space curves (CRVPT) are mapped; a 141 with
 * no model-space curve leaves its face unbuilt, with the reason.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "projcurve.h"

#define MAX_ENTITIES 24

static projcurve_context *ctx;

typedef struct entity {
    int type, form;
    const char *status; /* 8 digits */
    const char *params; /* without the type, ending with the record delimiter */
} entity;

#define PART "00010000"  /* physically dependent: read through its parent */
#define PARAM "00010500" /* dependent, 2D parametric */

static void record(char *out, size_t *len, const char *data, char section, int seq)
{
    *len += (size_t)sprintf(out + *len, "%-72.72s%c%7d\n", data, section, seq);
}

static char *format_iges(const entity *e, int n, const char *global)
{
    char *out = malloc(1 << 20);
    size_t len = 0;
    record(out, &len, "test file", 'S', 1);
    int g = 0;
    for (size_t at = 0; at < strlen(global); at += 72) {
        char piece[73];
        snprintf(piece, sizeof piece, "%.72s", global + at);
        record(out, &len, piece, 'G', ++g);
    }
    static char plines[MAX_ENTITIES][64][65];
    int pcount[MAX_ENTITIES], pstart[MAX_ENTITIES];
    int seq = 1;
    for (int i = 0; i < n; ++i) {
        char text[4096];
        snprintf(text, sizeof text, "%d,%s", e[i].type, e[i].params);
        const size_t tl = strlen(text);
        pcount[i] = 0;
        pstart[i] = seq;
        for (size_t at = 0; at < tl; at += 64) {
            snprintf(plines[i][pcount[i]++], 65, "%.64s", text + at);
            ++seq;
        }
    }
    for (int i = 0; i < n; ++i) {
        char d[128];
        snprintf(d, sizeof d, "%8d%8d%8d%8d%8d%8d%8d%8d%8s", e[i].type, pstart[i], 0, 0, 0, 0, 0, 0,
                 e[i].status ? e[i].status : "00000000");
        record(out, &len, d, 'D', 2 * i + 1);
        snprintf(d, sizeof d, "%8d%8d%8d%8d%8d%8s%8s%8s%8d", e[i].type, 0, 0, pcount[i], e[i].form,
                 "", "", "", 0);
        record(out, &len, d, 'D', 2 * i + 2);
    }
    seq = 1;
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < pcount[i]; ++k)
            len += (size_t)sprintf(out + len, "%-64s %7dP%7d\n", plines[i][k], 2 * i + 1, seq++);
    char t[80];
    snprintf(t, sizeof t, "S%7dG%7dD%7dP%7d", 1, g, 2 * n, seq - 1);
    record(out, &len, t, 'T', 1);
    out[len] = '\0';
    return out;
}

/* Millimetres, no resolution: the reader's default, 1e-7 of the size. */
static const char *const k_global_mm =
    "1H,,1H;,4Htest,8Htest.igs,,,32,308,15,308,15,,1.,2,2HMM,1,0.01;";

static projcurve_model *read_entities(const entity *e, int n)
{
    char *text = format_iges(e, n, k_global_mm);
    projcurve_model *m = NULL;
    if (projcurve_model_read_memory(ctx, text, strlen(text), &m) != PROJCURVE_OK)
        pc_test_fail_at(__FILE__, __LINE__, "read failed: %s", projcurve_context_message(ctx));
    free(text);
    return m;
}

/* The distance of x from the face's analytic boundary. */
typedef double (*boundary_fn)(const double x[3]);

/* Every piece of every loop: S(q(t)) at dense t within tol of the
 * boundary; *corner_gap the largest distance of a piece's end from the
 * nearest of the n corners. */
static void check_loops(const projcurve_face *face, boundary_fn off, double tol,
                        const double (*corners)[3], size_t n_corners)
{
    const projcurve_surface *s = projcurve_face_surface(face);
    double worst = 0.0, corner_gap = 0.0;
    for (size_t l = 0; l < projcurve_face_loop_count(face); ++l) {
        size_t n = 0;
        CHECK_OK(projcurve_face_loop_piece_count(ctx, face, l, &n));
        for (size_t k = 0; k < n; ++k) {
            int degree = 0;
            size_t n_ctrl = 0;
            const double *ctrl = NULL, *weights = NULL, *knots = NULL;
            CHECK_OK(projcurve_face_piece_curve(ctx, face, l, k, &degree, &n_ctrl, &ctrl,
                                                &weights, &knots, NULL));
            if (ctrl == NULL || n_ctrl < 2)
                continue;
            double xyz[3 * 2];
            projcurve_curve *q = NULL;
            double *lifted = malloc(3 * n_ctrl * sizeof *lifted);
            for (size_t i = 0; i < n_ctrl; ++i) {
                lifted[3 * i] = ctrl[2 * i];
                lifted[3 * i + 1] = ctrl[2 * i + 1];
                lifted[3 * i + 2] = 0.0;
            }
            CHECK_OK(projcurve_curve_create_nurbs(ctx, degree, n_ctrl, lifted, weights, knots, &q));
            free(lifted);
            if (q == NULL)
                continue;
            double t0, t1;
            CHECK_OK(projcurve_curve_domain(ctx, q, &t0, &t1));
            for (int i = 0; i <= 1000; ++i) {
                double uv[3], x[3];
                CHECK_OK(projcurve_curve_eval(ctx, q, t0 + (t1 - t0) * i / 1000.0, 0, uv));
                CHECK_OK(projcurve_surface_eval(ctx, s, uv[0], uv[1], 0, x));
                worst = fmax(worst, off(x));
                if (i == 0 || i == 1000) {
                    double best = INFINITY;
                    for (size_t c = 0; c < n_corners; ++c)
                        best = fmin(best, hypot(hypot(x[0] - corners[c][0], x[1] - corners[c][1]),
                                                x[2] - corners[c][2]));
                    corner_gap = fmax(corner_gap, best);
                    memcpy(xyz + 3 * (i != 0), x, sizeof x);
                }
            }
            projcurve_curve_destroy(q);
        }
    }
    if (!(worst <= tol))
        pc_test_fail_at(__FILE__, __LINE__, "a loop's 3D image is %g off its boundary (%g)",
                        worst, tol);
    if (!(corner_gap <= tol))
        pc_test_fail_at(__FILE__, __LINE__, "a piece ends %g from the boundary's corners (%g)",
                        corner_gap, tol);
    pc_test_checks += 2;
}

/* (u, v) of the surface point x (on the surface), then where the face
 * says it is. */
static projcurve_where where_is(const projcurve_face *face, const double x[3])
{
    double uv[2], d = 1.0;
    CHECK_OK(projcurve_surface_closest_point(ctx, projcurve_face_surface(face), x, uv, NULL, &d));
    CHECK(d <= 1e-9);
    projcurve_where w = PROJCURVE_ON;
    CHECK_OK(projcurve_face_classify(ctx, face, uv[0], uv[1], &w));
    return w;
}

/* ---- the cylinder segment ------------------------------------------------ */

#define TH0 0.2
#define TH1 1.2
#define Z0 0.5
#define Z1 1.5

static double off_cylinder_trim(const double x[3])
{
    const double r = hypot(x[0], x[1]), th = atan2(x[1], x[0]);
    const double radial = fabs(r - 1.0);
    /* the arcs z = Z0, Z1 over [TH0, TH1], the lines theta = TH0, TH1 over [Z0, Z1] */
    const double dth = th < TH0 ? TH0 - th : th > TH1 ? th - TH1 : 0.0;
    const double dz = x[2] < Z0 ? Z0 - x[2] : x[2] > Z1 ? x[2] - Z1 : 0.0;
    const double to_arcs = hypot(fmin(fabs(x[2] - Z0), fabs(x[2] - Z1)), dth);
    const double to_lines = hypot(fmin(fabs(th - TH0), fabs(th - TH1)), dz);
    return radial + fmin(to_arcs, to_lines);
}

/* The segment trimmed by a 144 (142 boundary), or bounded by a 143 (141
 * boundary); both give the model- and parameter-space curves. */
static void cylinder_segment(int bounded)
{
    static char arc_bottom[256], line_up[256], arc_top[512], line_down[256];
    const double c0 = cos(TH0), s0 = sin(TH0), c1 = cos(TH1), s1 = sin(TH1);
    const double h = 0.5 * (TH1 - TH0), cm = cos(0.5 * (TH0 + TH1)) / cos(h),
                 sm = sin(0.5 * (TH0 + TH1)) / cos(h);
    snprintf(arc_bottom, sizeof arc_bottom, "%.17g,0.,0.,%.17g,%.17g,%.17g,%.17g;", Z0, c0, s0,
             c1, s1);
    snprintf(line_up, sizeof line_up, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g;", c1, s1, Z0, c1, s1,
             Z1);
    /* from TH1 back to TH0 at Z1: a rational quadratic (a 100 turns
     * counterclockwise only), middle weight cos(h) */
    snprintf(arc_top, sizeof arc_top,
             "2,2,1,0,0,0,0.,0.,0.,1.,1.,1.,1.,%.17g,1.,%.17g,%.17g,%.17g,%.17g,%.17g,%.17g,"
             "%.17g,%.17g,%.17g,0.,1.,0.,0.,0.;",
             cos(h), c1, s1, Z1, cm, sm, Z1, c0, s0, Z1);
    snprintf(line_down, sizeof line_down, "%.17g,%.17g,%.17g,%.17g,%.17g,%.17g;", c0, s0, Z1, c0,
             s0, Z0);
    const entity e[] = {
        {110, 0, PART, "0.,0.,0.,0.,0.,1.;"},                  /* DE 1: axis */
        {110, 0, PART, "1.,0.,0.,1.,0.,2.;"},                  /* DE 3: generatrix */
        {120, 0, PART, "1,3,0.,1.5707963267948966;"},          /* DE 5: a quarter turn */
        {100, 0, PART, arc_bottom},                            /* DE 7 */
        {110, 0, PART, line_up},                               /* DE 9 */
        {126, 0, PART, arc_top},                               /* DE 11 */
        {110, 0, PART, line_down},                             /* DE 13 */
        {102, 0, PART, "4,7,9,11,13;"},                        /* DE 15: CPTR */
        {110, 0, PARAM, "0.2,0.5,0.,1.2,0.5,0.;"},             /* DE 17: BPTR in */
        {110, 0, PARAM, "1.2,0.5,0.,1.2,1.5,0.;"},             /* DE 19: (theta, z), */
        {110, 0, PARAM, "1.2,1.5,0.,0.2,1.5,0.;"},             /* DE 21: the analytic */
        {110, 0, PARAM, "0.2,1.5,0.,0.2,0.5,0.;"},             /* DE 23: parameters */
        {102, 0, PARAM, "4,17,19,21,23;"},                     /* DE 25 */
        {142, 0, PART, "1,5,25,15,2;"},                        /* DE 27 */
        {144, 0, NULL, "5,1,0,27;"},                           /* DE 29 */
    };
    /* DE 27: one boundary curve, CRVPT 15, SENSE 1, one PSCPT 25 */
    entity e143[sizeof e / sizeof e[0]];
    memcpy(e143, e, sizeof e);
    e143[13] = (entity){141, 0, PART, "1,1,5,1,15,1,1,25;"};
    e143[14] = (entity){143, 0, NULL, "1,5,1,27;"};
    projcurve_model *m = read_entities(bounded ? e143 : e, (int)(sizeof e / sizeof e[0]));
    if (m == NULL)
        return;
    CHECK(projcurve_model_surface_count(m) == 1);
    CHECK(projcurve_model_face_count(m) == 1);
    CHECK(projcurve_model_unbuilt_face_count(m) == 0);
    CHECK(projcurve_model_skipped_count(m) == 0); /* BPTR and CPTR read through the face */
    for (size_t i = 0;
         projcurve_model_face_count(m) != 1 && i < projcurve_model_unbuilt_face_count(m); ++i)
        fprintf(stderr, "unbuilt: %s\n", projcurve_model_unbuilt_face(m, i));
    const projcurve_face *face = projcurve_model_face(m, 0);
    if (face == NULL) {
        projcurve_model_destroy(m);
        return;
    }
    CHECK(projcurve_face_loop_count(face) == 1);
    size_t pieces = 0;
    CHECK_OK(projcurve_face_loop_piece_count(ctx, face, 0, &pieces));
    CHECK(pieces == 4);
    /* the inverted arcs are cubics (fit/resampled.h), not polylines */
    size_t poles = 0, cubics = 0;
    for (size_t k = 0; k < pieces; ++k) {
        int degree = 0;
        size_t n_ctrl = 0;
        CHECK_OK(projcurve_face_piece_curve(ctx, face, 0, k, &degree, &n_ctrl, NULL, NULL, NULL,
                                            NULL));
        poles += n_ctrl;
        cubics += degree == 3;
    }
    printf("cylinder segment (%s): %zu cubic pieces, %zu poles\n", bounded ? "143" : "144",
           cubics, poles);
    CHECK(cubics == 4 && poles <= 100);
    double tol_model = 0.0;
    CHECK_OK(projcurve_face_tolerance(ctx, face, NULL, &tol_model));
    CHECK(tol_model > 0.0 && tol_model < 1e-6);
    const double corners[4][3] = {{c0, s0, Z0}, {c1, s1, Z0}, {c1, s1, Z1}, {c0, s0, Z1}};
    check_loops(face, off_cylinder_trim, tol_model, corners, 4);
    /* (theta, z) on a grid: IN inside the trim, OUT outside, away from it */
    int wrong = 0;
    for (int i = 0; i <= 16; ++i)
        for (int j = 0; j <= 8; ++j) {
            const double th = 0.05 + 1.45 * i / 16.0, z = 0.05 + 1.9 * j / 8.0;
            const double x[3] = {cos(th), sin(th), z};
            const int in = th > TH0 && th < TH1 && z > Z0 && z < Z1;
            if (fabs(th - TH0) < 1e-3 || fabs(th - TH1) < 1e-3 || fabs(z - Z0) < 1e-3 ||
                fabs(z - Z1) < 1e-3)
                continue;
            wrong += where_is(face, x) != (in ? PROJCURVE_IN : PROJCURVE_OUT);
        }
    CHECK(wrong == 0);
    projcurve_model_destroy(m);
}

/* ---- the plane with a hole ------------------------------------------------ */

static double off_square_and_hole(const double x[3])
{
    /* the square [0, 4]^2 and the circle of radius 1 about (2, 2), at z = 0 */
    const double dx = fmax(fmax(-x[0], x[0] - 4.0), 0.0), dy = fmax(fmax(-x[1], x[1] - 4.0), 0.0);
    const double to_sides = fmin(fmin(hypot(fabs(x[0]), dy), hypot(fabs(x[0] - 4.0), dy)),
                                 fmin(hypot(fabs(x[1]), dx), hypot(fabs(x[1] - 4.0), dx)));
    const double to_circle = fabs(hypot(x[0] - 2.0, x[1] - 2.0) - 1.0);
    return fabs(x[2]) + fmin(to_sides, to_circle);
}

static void plane_with_hole(void)
{
    const entity e[] = {
        {110, 0, PART, "0.,0.,0.,4.,0.,0.;"},      /* DE 1 */
        {110, 0, PART, "4.,0.,0.,4.,4.,0.;"},      /* DE 3 */
        {110, 0, PART, "4.,4.,0.,0.,4.,0.;"},      /* DE 5 */
        {110, 0, PART, "0.,4.,0.,0.,0.,0.;"},      /* DE 7 */
        {102, 0, PART, "4,1,3,5,7;"},              /* DE 9: the square */
        {108, 1, PART, "0.,0.,1.,0.,9,0.,0.,0.,0.;"}, /* DE 11: z = 0 bounded by it */
        {100, 0, PART, "0.,2.,2.,3.,2.,3.,2.;"},   /* DE 13: the hole, a full circle */
        {142, 0, PART, "1,11,0,9,2;"},             /* DE 15: outer (no BPTR) */
        {142, 0, PART, "1,11,0,13,2;"},            /* DE 17: inner */
        {144, 0, NULL, "11,1,1,15,17;"},           /* DE 19 */
        {142, 0, PART, "1,11,0,0,2;"},             /* DE 21: neither curve */
        {144, 0, NULL, "11,1,0,21;"},              /* DE 23: unbuilt, with the reason */
    };
    projcurve_model *m = read_entities(e, (int)(sizeof e / sizeof e[0]));
    if (m == NULL)
        return;
    CHECK(projcurve_model_face_count(m) == 1);
    CHECK(projcurve_model_unbuilt_face_count(m) == 1);
    for (size_t i = 0;
         projcurve_model_face_count(m) != 1 && i < projcurve_model_unbuilt_face_count(m); ++i)
        fprintf(stderr, "unbuilt: %s\n", projcurve_model_unbuilt_face(m, i));
    CHECK(projcurve_model_unbuilt_face_count(m) == 1 &&
          strstr(projcurve_model_unbuilt_face(m, 0), "no model-space curve (CPTR 0)") != NULL);
    const projcurve_face *face = projcurve_model_face(m, 0);
    if (face == NULL) {
        projcurve_model_destroy(m);
        return;
    }
    CHECK(projcurve_face_loop_count(face) == 2);
    double tol_model = 0.0;
    CHECK_OK(projcurve_face_tolerance(ctx, face, NULL, &tol_model));
    /* the square's corners, and the circle's start and end (2 + 1, 2) */
    const double corners[5][3] = {{0, 0, 0}, {4, 0, 0}, {4, 4, 0}, {0, 4, 0}, {3, 2, 0}};
    check_loops(face, off_square_and_hole, tol_model, corners, 5);
    int wrong = 0;
    for (int i = 0; i <= 12; ++i)
        for (int j = 0; j <= 12; ++j) {
            const double x[3] = {0.05 + 3.9 * i / 12.0, 0.05 + 3.9 * j / 12.0, 0.0};
            const double r = hypot(x[0] - 2.0, x[1] - 2.0);
            if (fabs(r - 1.0) < 1e-3)
                continue;
            wrong += where_is(face, x) != (r > 1.0 ? PROJCURVE_IN : PROJCURVE_OUT);
        }
    CHECK(wrong == 0);
    projcurve_model_destroy(m);
}

/* The distance from the square [1, 3]^2 at z = 0. */
static double off_square(const double x[3])
{
    const double dx = fmax(fmax(1.0 - x[0], x[0] - 3.0), 0.0),
                 dy = fmax(fmax(1.0 - x[1], x[1] - 3.0), 0.0);
    return fabs(x[2]) + fmin(fmin(hypot(fabs(x[0] - 1.0), dy), hypot(fabs(x[0] - 3.0), dy)),
                             fmin(hypot(fabs(x[1] - 1.0), dx), hypot(fabs(x[1] - 3.0), dx)));
}

/* A 143 on a plane bounded by [0, 4]^2: its 141's model-space square
 * [1, 3]^2 (CRVPT) is the loop; a
 * second 143 whose 141 has no model-space curve is unbuilt, with why. */
static void bounded_143_on_plane(void)
{
    const entity e[] = {
        {110, 0, PART, "0.,0.,0.,4.,0.,0.;"},         /* DE 1 */
        {110, 0, PART, "4.,0.,0.,4.,4.,0.;"},         /* DE 3 */
        {110, 0, PART, "4.,4.,0.,0.,4.,0.;"},         /* DE 5 */
        {110, 0, PART, "0.,4.,0.,0.,0.,0.;"},         /* DE 7 */
        {102, 0, PART, "4,1,3,5,7;"},                 /* DE 9 */
        {108, 1, PART, "0.,0.,1.,0.,9,0.,0.,0.,0.;"}, /* DE 11 */
        {141, 0, PART, "1,1,11,1,29,1,1,29;"},        /* DE 13: the square [1, 3]^2 */
        {143, 0, NULL, "1,11,1,13;"},                 /* DE 15 */
        {141, 0, PART, "1,1,11,1,0,1,1,9;"},          /* DE 17: CRVPT 0 */
        {143, 0, NULL, "1,11,1,17;"},                 /* DE 19 */
        {110, 0, PART, "1.,1.,0.,3.,1.,0.;"},         /* DE 21 */
        {110, 0, PART, "3.,1.,0.,3.,3.,0.;"},         /* DE 23 */
        {110, 0, PART, "3.,3.,0.,1.,3.,0.;"},         /* DE 25 */
        {110, 0, PART, "1.,3.,0.,1.,1.,0.;"},         /* DE 27 */
        {102, 0, PART, "4,21,23,25,27;"},             /* DE 29 */
    };
    projcurve_model *m = read_entities(e, (int)(sizeof e / sizeof e[0]));
    if (m == NULL)
        return;
    CHECK(projcurve_model_face_count(m) == 1);
    CHECK(projcurve_model_unbuilt_face_count(m) == 1 &&
          strstr(projcurve_model_unbuilt_face(m, 0), "no model-space curve (CRVPT 0)") != NULL);
    for (size_t i = 0; i < projcurve_model_unbuilt_face_count(m); ++i)
        printf("unbuilt: %s\n", projcurve_model_unbuilt_face(m, i));
    const projcurve_face *face = projcurve_model_face(m, 0);
    if (face == NULL) {
        projcurve_model_destroy(m);
        return;
    }
    CHECK(projcurve_face_loop_count(face) == 1);
    size_t pieces = 0;
    CHECK_OK(projcurve_face_loop_piece_count(ctx, face, 0, &pieces));
    CHECK(pieces == 4);
    double tol_model = 0.0;
    CHECK_OK(projcurve_face_tolerance(ctx, face, NULL, &tol_model));
    const double corners[4][3] = {{1, 1, 0}, {3, 1, 0}, {3, 3, 0}, {1, 3, 0}};
    check_loops(face, off_square, tol_model, corners, 4);
    /* points over the plane's NURBS (the square [0, 4]^2 of its bound) */
    double box[6];
    CHECK_OK(projcurve_surface_bounds(ctx, projcurve_face_surface(face), box));
    int wrong = 0, outside = 0;
    for (int i = 0; i <= 12; ++i)
        for (int j = 0; j <= 12; ++j) {
            const double x[3] = {box[0] + (box[3] - box[0]) * (i + 0.37) / 13.0,
                                 box[1] + (box[4] - box[1]) * (j + 0.61) / 13.0, 0.0};
            const int in = x[0] > 1.0 && x[0] < 3.0 && x[1] > 1.0 && x[1] < 3.0;
            if (off_square(x) < 1e-3)
                continue;
            outside += !in;
            wrong += where_is(face, x) != (in ? PROJCURVE_IN : PROJCURVE_OUT);
        }
    CHECK(wrong == 0);
    CHECK(outside > 0);
    projcurve_model_destroy(m);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    cylinder_segment(0);
    cylinder_segment(1);
    plane_with_hole();
    bounded_143_on_plane();
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_io_iges_analytic_faces");
}
