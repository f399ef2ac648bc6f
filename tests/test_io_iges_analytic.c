/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * IGES analytic surfaces (src/io/iges_analytic.c) read from small files
 * written here (the formatter of test_io_iges_entities.c): each NURBS
 * checked on dense samples against the implicit equation of its surface
 * (sphere, torus, plane, cone band, cylinder, bilinear patch), the bounded
 * plane covering its boundary curve, the global section's units and
 * resolution, refused values and unbounded surfaces listed as skipped.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "io/iges.h"
#include "projcurve.h"

#define MAX_ENTITIES 16
#define PI 3.14159265358979323846
/* Samples are exact to rounding: a few 1e-16 of the size. */
#define TIGHT 1e-12

static projcurve_context *ctx;

typedef struct entity {
    int type, form;
    const char *status; /* 8 digits */
    const char *params; /* without the type, ending with the record delimiter */
} entity;

#define PART "00010000" /* physically dependent: read through its parent */

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
    char plines[MAX_ENTITIES][64][65];
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

static const char *const k_global_mm =
    "1H,,1H;,4Htest,8Htest.igs,,,32,308,15,308,15,,1.,2,2HMM,1,0.01;";
static const char *const k_global_inch =
    "1H,,1H;,4Htest,8Htest.igs,,,32,308,15,308,15,,1.,1,2HIN,1,0.01,15H20260101.000000,"
    "0.0001,1000.;";

static projcurve_model *read_entities(const entity *e, int n, const char *global)
{
    char *text = format_iges(e, n, global);
    projcurve_model *m = NULL;
    if (projcurve_model_read_memory(ctx, text, strlen(text), &m) != PROJCURVE_OK)
        pc_test_fail_at(__FILE__, __LINE__, "read failed: %s", projcurve_context_message(ctx));
    free(text);
    return m;
}

typedef double (*implicit_fn)(const double p[3]);

/* Every sample of the surface satisfies its implicit equation; returns the
 * z range of the samples. */
static void samples_on(const projcurve_surface *s, implicit_fn f, double size, double zr[2])
{
    double dom[4];
    CHECK_OK(projcurve_surface_domain(ctx, s, dom));
    zr[0] = HUGE_VAL;
    zr[1] = -HUGE_VAL;
    /* 32 steps: the quarter-turn knots, where the arcs reach their
     * extremes, are among the samples */
    for (int i = 0; i <= 32; ++i)
        for (int j = 0; j <= 32; ++j) {
            double p[3];
            CHECK_OK(projcurve_surface_eval(ctx, s, dom[0] + (dom[1] - dom[0]) * i / 32.0,
                                            dom[2] + (dom[3] - dom[2]) * j / 32.0, 0, p));
            CHECK_NEAR(f(p), 0.0, TIGHT * size);
            zr[0] = fmin(zr[0], p[2]);
            zr[1] = fmax(zr[1], p[2]);
        }
}

static double on_sphere(const double p[3])
{
    return hypot(hypot(p[0] - 1.0, p[1] - 2.0), p[2] - 3.0) - 2.5;
}
static double on_torus(const double p[3])
{
    return hypot(hypot(p[0], p[1]) - 4.0, p[2]) - 1.0;
}
static double on_plane(const double p[3]) { return p[2] - 2.0; }
static double on_cone_band(const double p[3]) { return hypot(p[0], p[1]) - (2.0 + p[2]); }
static double on_cylinder(const double p[3]) { return hypot(p[0], p[1]) - 1.5; }
static double on_ruled(const double p[3]) { return p[2] - p[1]; }

static const char *kind(const projcurve_model *m, size_t i)
{
    const char *k = projcurve_model_surface_kind(m, i);
    return k ? k : "(none)";
}

static void elementary(void)
{
    const entity e[] = {
        {116, 0, PART, "1.,2.,3.;"},         /* DE 1 */
        {196, 0, NULL, "1,2.5;"},            /* DE 3: sphere */
        {116, 0, PART, "0.,0.,0.;"},         /* DE 5 */
        {123, 0, PART, "0.,0.,1.;"},         /* DE 7 */
        {123, 0, PART, "1.,0.,0.;"},         /* DE 9 */
        {198, 1, NULL, "5,7,4.,1.,9;"},      /* DE 11: torus */
        {192, 0, NULL, "5,7,1.;"},           /* DE 13: cylinder, unbounded */
        {196, 0, NULL, "1,-1.;"},            /* DE 15: refused */
        {198, 0, NULL, "5,7,1.,2.;"},        /* DE 17: spindle, refused */
    };
    projcurve_model *m = read_entities(e, 9, k_global_mm);
    if (m == NULL)
        return;
    CHECK(projcurve_model_surface_count(m) == 2);
    CHECK(strcmp(kind(m, 0), "sphere") == 0 && strcmp(kind(m, 1), "torus") == 0);
    double zr[2];
    samples_on(projcurve_model_surface(m, 0), on_sphere, 5.0, zr);
    CHECK_NEAR(zr[0], 0.5, TIGHT);
    CHECK_NEAR(zr[1], 5.5, TIGHT);
    samples_on(projcurve_model_surface(m, 1), on_torus, 10.0, zr);
    CHECK_NEAR(zr[1], 1.0, TIGHT);
    size_t listed = 0;
    for (size_t i = 0; i < projcurve_model_skipped_count(m); ++i) {
        const char *s = projcurve_model_skipped(m, i);
        listed += strstr(s, "entity 192 at DE 13 (unbounded") != NULL;
        listed += strstr(s, "entity 196 at DE 15 (radius -1 is not positive") != NULL;
        listed += strstr(s, "entity 198 at DE 17 (torus minor radius 2 exceeds") != NULL;
        CHECK(strstr(s, "entity 116") == NULL && strstr(s, "entity 123") == NULL);
    }
    CHECK(listed == 3);
    double unit = 0.0;
    CHECK(projcurve_model_length_unit(m, &unit) == 1);
    CHECK_NEAR(unit, 0.001, 0.0);
    CHECK(projcurve_model_precision(m, NULL) == 0);
    projcurve_model_destroy(m);
}

static void planes(void)
{
    const entity e[] = {
        {108, 0, NULL, "0.,0.,1.,2.,0,1.,1.,2.,3.;"},       /* DE 1: z = 2, display size 3 */
        {100, 0, PART, "2.,0.,0.,1.,0.,1.,0.;"},            /* DE 3: unit circle at z = 2 */
        {108, 1, NULL, "0.,0.,2.,4.,3,0.,0.,0.,0.;"},       /* DE 5: z = 2 bounded by it */
        {108, 0, NULL, "0.,0.,1.,2.,0,1.,1.,2.,0.;"},       /* DE 7: no size: skipped */
    };
    projcurve_model *m = read_entities(e, 4, k_global_inch);
    if (m == NULL)
        return;
    CHECK(projcurve_model_surface_count(m) == 2);
    double zr[2], box[6];
    samples_on(projcurve_model_surface(m, 0), on_plane, 5.0, zr);
    CHECK_OK(projcurve_surface_bounds(ctx, projcurve_model_surface(m, 0), box));
    /* the square of half width 3 around the symbol's point (1, 1) */
    CHECK_NEAR(box[3] - box[0], 6.0, TIGHT);
    CHECK_NEAR(box[4] - box[1], 6.0, TIGHT);
    CHECK_NEAR(box[0] + box[3], 2.0, TIGHT);
    samples_on(projcurve_model_surface(m, 1), on_plane, 5.0, zr);
    for (int i = 0; i < 64; ++i) { /* the boundary circle lies on the bounded plane */
        const double p[3] = {cos(2 * PI * i / 64), sin(2 * PI * i / 64), 2.0};
        double uv[2], d = 1.0;
        CHECK_OK(projcurve_surface_closest_point(ctx, projcurve_model_surface(m, 1), p, uv, NULL, &d));
        CHECK_NEAR(d, 0.0, TIGHT);
    }
    CHECK(projcurve_model_skipped_count(m) == 1 &&
          strstr(projcurve_model_skipped(m, 0), "without a display size") != NULL);
    double unit = 0.0, res = 0.0;
    CHECK(projcurve_model_length_unit(m, &unit) == 1 && projcurve_model_precision(m, &res) == 1);
    CHECK_NEAR(unit, 0.0254, 0.0);
    CHECK_NEAR(res, 1e-4, 0.0);
    projcurve_model_destroy(m);
}

static void swept(void)
{
    const entity e[] = {
        {110, 0, PART, "0.,0.,0.,0.,0.,1.;"},       /* DE 1: axis */
        {110, 0, PART, "2.,0.,0.,3.,0.,1.;"},       /* DE 3: generatrix */
        {120, 0, NULL, "1,3,0.,3.14159265358979;"}, /* DE 5: half a cone band */
        {100, 0, PART, "0.,0.,0.,1.5,0.,1.5,0.;"},  /* DE 7: circle r 1.5 */
        {122, 0, NULL, "7,1.5,0.,4.;"},             /* DE 9: cylinder of height 4 */
        {110, 0, PART, "0.,0.,0.,1.,0.,0.;"},       /* DE 11 */
        {110, 0, PART, "0.,1.,1.,1.,1.,1.;"},       /* DE 13 */
        {118, 0, NULL, "11,13,0,0;"},               /* DE 15: z = y */
        {126, 0, PART, "2,2,0,0,1,0,0.,0.,0.,1.,1.,1.,1.,1.,1.,0.,0.,0.,1.,0.,0.,2.,1.,0.,0.,1.;"},
        {118, 0, NULL, "11,17,0,0;"},               /* DE 19: degrees differ */
    };
    projcurve_model *m = read_entities(e, 10, k_global_mm);
    if (m == NULL)
        return;
    CHECK(projcurve_model_surface_count(m) == 3);
    CHECK(strcmp(kind(m, 0), "revolution") == 0);
    CHECK(strcmp(kind(m, 1), "extrusion") == 0);
    CHECK(strcmp(kind(m, 2), "ruled") == 0);
    double zr[2], box[6];
    samples_on(projcurve_model_surface(m, 0), on_cone_band, 5.0, zr);
    CHECK_OK(projcurve_surface_bounds(ctx, projcurve_model_surface(m, 0), box));
    CHECK(box[1] > -1e-12); /* half a turn: y >= 0 */
    samples_on(projcurve_model_surface(m, 1), on_cylinder, 5.0, zr);
    CHECK_NEAR(zr[0], 0.0, TIGHT);
    CHECK_NEAR(zr[1], 4.0, TIGHT);
    samples_on(projcurve_model_surface(m, 2), on_ruled, 2.0, zr);
    CHECK(projcurve_model_skipped_count(m) == 1 &&
          strstr(projcurve_model_skipped(m, 0), "entity 118 at DE 19 (curves of different") != NULL);
    projcurve_model_destroy(m);
}

/* The unbounded 190, 192, 194 over the box of given points, as the
 * topology reader will build them (pc_iges_analytic_surface). */
static double on_unit_cylinder(const double p[3]) { return hypot(p[0], p[1]) - 1.0; }
static double on_cone30(const double p[3])
{
    return hypot(p[0], p[1]) - (1.0 + p[2] * tan(PI / 6));
}
static double on_xy_plane(const double p[3]) { return p[2]; }

static void unbounded_over_points(void)
{
    const entity e[] = {
        {116, 0, PART, "0.,0.,0.;"},    /* DE 1 */
        {123, 0, PART, "0.,0.,1.;"},    /* DE 3 */
        {192, 0, NULL, "1,3,1.;"},      /* DE 5 */
        {194, 0, NULL, "1,3,1.,30.;"},  /* DE 7 */
        {190, 0, NULL, "1,3;"},         /* DE 9 */
    };
    char *text = format_iges(e, 5, k_global_mm);
    pc_arena arena;
    pc_arena_init(&arena, 1 << 14);
    size_t work = 0;
    pc_iges_file f;
    memset(&f, 0, sizeof f);
    f.ctx = ctx;
    f.arena = &arena;
    f.work_done = &work;
    f.work_limit = (size_t)-1;
    CHECK_OK(pc_iges_split(&f, text, strlen(text)));
    CHECK_OK(pc_iges_read_global(&f));
    CHECK_OK(pc_iges_read_directory(&f));
    const double pts[6] = {1.0, 0.0, -1.0, 0.0, 1.0, 3.0};
    const size_t des[3] = {5, 7, 9};
    const implicit_fn fns[3] = {on_unit_cylinder, on_cone30, on_xy_plane};
    const char *kinds[3] = {"cylinder", "cone", "plane"};
    for (int k = 0; k < 3; ++k) {
        pc_io_surface s;
        const char *kd = NULL, *skip = NULL;
        long uses[PC_IGES_MAX_USES];
        size_t n_uses = 0;
        CHECK_OK(pc_iges_analytic_surface(&f, des[k], NULL, 0, &s, &kd, uses, &n_uses, &skip));
        CHECK(skip != NULL && strstr(skip, "unbounded") != NULL);
        /* the plane's points: (1, 0, 0) and (0, 1, 0) after projection */
        const double plane_pts[6] = {1.0, 0.0, 0.0, 0.0, 1.0, 0.0};
        /* on the cone: radius 1 + z tan 30 deg at z = -1 and 3 */
        const double cone_pts[6] = {1.0 - tan(PI / 6), 0.0, -1.0, 0.0, 1.0 + 3.0 * tan(PI / 6), 3.0};
        const double *given = k == 0 ? pts : (k == 1 ? cone_pts : plane_pts);
        skip = NULL;
        CHECK_OK(pc_iges_analytic_surface(&f, des[k], given, 2, &s, &kd, uses, &n_uses, &skip));
        CHECK(skip == NULL && kd != NULL && strcmp(kd, kinds[k]) == 0);
        CHECK(n_uses == 2);
        if (skip != NULL)
            continue;
        projcurve_surface *h = NULL;
        CHECK_OK(projcurve_surface_create_nurbs(ctx, s.deg_u, s.deg_v, s.n_u, s.n_v, s.ctrl,
                                                s.weights, s.knots_u, s.knots_v, &h));
        if (h == NULL)
            continue;
        double zr[2];
        samples_on(h, fns[k], 5.0, zr);
        if (k < 2) { /* heights -1 .. 3 widened by 1 % of 4 and 1e-3 of 3 */
            CHECK_NEAR(zr[0], -1.0 - 0.04 - 0.003, 1e-12);
            CHECK_NEAR(zr[1], 3.0 + 0.04 + 0.003, 1e-12);
        }
        projcurve_surface_destroy(h);
    }
    pc_arena_release(&arena);
    free(text);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    elementary();
    planes();
    swept();
    unbounded_over_points();
    projcurve_context_destroy(ctx);
    return pc_test_finish("io_iges_analytic");
}
