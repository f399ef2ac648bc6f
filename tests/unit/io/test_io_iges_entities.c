/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * IGES entities 100, 102, 110, 124, 126 and 128 read from small files built
 * here with an independent formatter. Expected geometry is analytic (a
 * circle has every point at its radius; matrices move points where the
 * matrix says) and curves are evaluated with a Cox-de Boor evaluator in
 * this file, not the library's.
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "check.h"
#include "projcurve.h"

#define PI 3.14159265358979323846
#define MAX_ENTITIES 16
#define TIGHT 1e-13 /* a few ulps of the coordinates used (<= 10) */

static projcurve_context *ctx;

typedef struct entity {
    int type, form;
    int transform;       /* DE pointer of a 124, 0 for none */
    const char *status;  /* 8 digits */
    const char *params;  /* without the type, ending with the record delimiter */
} entity;

/* Appends one 80-column record. */
static void record(char *out, size_t *len, const char *data, char section, int seq)
{
    *len += (size_t)sprintf(out + *len, "%-72.72s%c%7d\n", data, section, seq);
}

/* Builds an IGES file: delims "1H,,1H;" unless global is given. */
static char *format_iges(const entity *e, int n, const char *global, char pdelim)
{
    char *out = malloc(1 << 20);
    size_t len = 0;
    record(out, &len, "test file", 'S', 1);
    record(out, &len, global ? global : "1H,,1H;,4Htest,8Htest.igs,,,32,308,15,308,15,,1.,2,2HMM,1,0.01;",
           'G', 1);
    /* Parameter text of each entity split into 64-column pieces. */
    char plines[MAX_ENTITIES][64][65];
    int pcount[MAX_ENTITIES], pstart[MAX_ENTITIES];
    int seq = 1;
    for (int i = 0; i < n; ++i) {
        char text[4096];
        snprintf(text, sizeof text, "%d%c%s", e[i].type, pdelim, e[i].params);
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
        snprintf(d, sizeof d, "%8d%8d%8d%8d%8d%8d%8d%8d%8s", e[i].type, pstart[i], 0, 0, 0, 0,
                 e[i].transform, 0, e[i].status ? e[i].status : "00000000");
        record(out, &len, d, 'D', 2 * i + 1);
        snprintf(d, sizeof d, "%8d%8d%8d%8d%8d%8s%8s%8s%8d", e[i].type, 0, 0, pcount[i], e[i].form,
                 "", "", "", 0);
        record(out, &len, d, 'D', 2 * i + 2);
    }
    seq = 1;
    for (int i = 0; i < n; ++i)
        for (int k = 0; k < pcount[i]; ++k) {
            len += (size_t)sprintf(out + len, "%-64s %7dP%7d\n", plines[i][k], 2 * i + 1, seq++);
        }
    char t[80];
    snprintf(t, sizeof t, "S%7dG%7dD%7dP%7d", 1, 1, 2 * n, seq - 1);
    record(out, &len, t, 'T', 1);
    out[len] = '\0';
    return out;
}

static projcurve_model *read_text(const char *text)
{
    projcurve_model *m = NULL;
    const projcurve_status st = projcurve_model_read_memory(ctx, text, strlen(text), &m);
    if (st != PROJCURVE_OK)
        pc_test_fail_at(__FILE__, __LINE__, "read failed: %s", projcurve_context_message(ctx));
    return m;
}

/* ---- an independent NURBS curve evaluator (Cox-de Boor) ---------------- */

typedef struct curve_data {
    int p;
    size_t n;
    double ctrl[3 * 64], w[64], u[96];
} curve_data;

static void fetch(const projcurve_curve *c, curve_data *d)
{
    size_t nk;
    int rational;
    CHECK_OK(projcurve_curve_nurbs_info(ctx, c, &d->p, &d->n, &nk, &rational));
    CHECK(d->n <= 64 && nk <= 96);
    if (d->n <= 64 && nk <= 96)
        CHECK_OK(projcurve_curve_nurbs_data(ctx, c, d->ctrl, d->w, d->u));
}

static double basis(const double *u, int i, int p, double t, double t_end)
{
    if (p == 0) {
        if (t == t_end)
            return (u[i] < t && u[i + 1] == t_end) ? 1.0 : 0.0;
        return (u[i] <= t && t < u[i + 1]) ? 1.0 : 0.0;
    }
    double a = 0.0, b = 0.0;
    if (u[i + p] > u[i])
        a = (t - u[i]) / (u[i + p] - u[i]) * basis(u, i, p - 1, t, t_end);
    if (u[i + p + 1] > u[i + 1])
        b = (u[i + p + 1] - t) / (u[i + p + 1] - u[i + 1]) * basis(u, i + 1, p - 1, t, t_end);
    return a + b;
}

static void eval(const curve_data *d, double t, double out[3])
{
    const double t_end = d->u[d->n];
    double num[3] = {0, 0, 0}, den = 0.0;
    for (size_t i = 0; i < d->n; ++i) {
        const double b = basis(d->u, (int)i, d->p, t, t_end) * d->w[i];
        for (int k = 0; k < 3; ++k)
            num[k] += b * d->ctrl[3 * i + (size_t)k];
        den += b;
    }
    for (int k = 0; k < 3; ++k)
        out[k] = num[k] / den;
}

static void domain(const curve_data *d, double *t0, double *t1)
{
    *t0 = d->u[d->p];
    *t1 = d->u[d->n];
}

static void check_point(const double p[3], double x, double y, double z, double tol)
{
    CHECK_NEAR(p[0], x, tol);
    CHECK_NEAR(p[1], y, tol);
    CHECK_NEAR(p[2], z, tol);
}

/* ---- cases ---------------------------------------------------------------- */

static void line_with_translation(void)
{
    const entity e[] = {
        {110, 0, 3, NULL, "0.,0.,0.,3.,4.,0.;"},
        {124, 0, 0, NULL, "1.,0.,0.,1.,0.,1.,0.,2.,0.,0.,1.,3.;"},
    };
    char *text = format_iges(e, 2, NULL, ',');
    projcurve_model *m = read_text(text);
    if (m) {
        CHECK(projcurve_model_curve_count(m) == 1);
        CHECK(projcurve_model_skipped_count(m) == 0); /* the 124 is used, not skipped */
        curve_data d;
        fetch(projcurve_model_curve(m, 0), &d);
        double t0, t1, p[3];
        domain(&d, &t0, &t1);
        CHECK_NEAR(t1 - t0, 5.0, TIGHT); /* parametrised by length */
        eval(&d, t0, p);
        check_point(p, 1, 2, 3, TIGHT);
        eval(&d, t1, p);
        check_point(p, 4, 6, 3, TIGHT);
        projcurve_model_destroy(m);
    }
    free(text);
}

/* Every sample of an arc at distance r from its centre, in its plane, with
 * the angle increasing from a0 to a1. */
static void check_arc(const curve_data *d, const double c[3], double r, double a0, double a1)
{
    double t0, t1;
    domain(d, &t0, &t1);
    double prev = -1e300;
    for (int s = 0; s <= 64; ++s) {
        const double t = t0 + (t1 - t0) * s / 64.0;
        double p[3];
        eval(d, t, p);
        CHECK_NEAR(hypot(p[0] - c[0], p[1] - c[1]), r, TIGHT * r);
        CHECK_NEAR(p[2], c[2], TIGHT);
        double a = atan2(p[1] - c[1], p[0] - c[0]);
        while (a < a0 - 1e-9 || a < prev - 1e-9)
            a += 2 * PI;
        CHECK(a >= prev - 1e-12);
        CHECK(a <= a1 + 1e-9);
        prev = a;
    }
    double p[3];
    eval(d, t0, p);
    check_point(p, c[0] + r * cos(a0), c[1] + r * sin(a0), c[2], TIGHT);
    eval(d, t1, p);
    check_point(p, c[0] + r * cos(a1), c[1] + r * sin(a1), c[2], TIGHT);
}

static void arcs(void)
{
    /* Quarter arc: centre (1,1) at z = 2, radius 2, from (3,1) to (1,3). */
    const entity quarter[] = {{100, 0, 0, NULL, "2.,1.,1.,3.,1.,1.,3.;"}};
    char *text = format_iges(quarter, 1, NULL, ',');
    projcurve_model *m = read_text(text);
    if (m) {
        curve_data d;
        fetch(projcurve_model_curve(m, 0), &d);
        CHECK(d.p == 2);
        const double c[3] = {1, 1, 2};
        check_arc(&d, c, 2.0, 0.0, PI / 2);
        projcurve_model_destroy(m);
    }
    free(text);
    /* 270 degrees, crossing the -x axis: from (1,0) to (0,-1) around 0. */
    const entity big[] = {{100, 0, 0, NULL, "0.,0.,0.,1.,0.,0.,-1.;"}};
    text = format_iges(big, 1, NULL, ',');
    m = read_text(text);
    if (m) {
        curve_data d;
        fetch(projcurve_model_curve(m, 0), &d);
        const double c[3] = {0, 0, 0};
        check_arc(&d, c, 1.0, 0.0, 1.5 * PI);
        CHECK(d.n == 7); /* three quarter segments */
        projcurve_model_destroy(m);
    }
    free(text);
    /* Full circle: start = end. */
    const entity full[] = {{100, 0, 0, NULL, "-1.,5.,5.,5.,8.,5.,8.;"}};
    text = format_iges(full, 1, NULL, ',');
    m = read_text(text);
    if (m) {
        curve_data d;
        fetch(projcurve_model_curve(m, 0), &d);
        const double c[3] = {5, 5, -1};
        check_arc(&d, c, 3.0, PI / 2, PI / 2 + 2 * PI);
        projcurve_model_destroy(m);
    }
    free(text);
}

/* A cubic B-spline whose V0, V1 select [0.25, 0.75] of [0, 1]. */
static const char cubic_params[] =
    "5,3,0,0,1,0,0.,0.,0.,0.,0.4,0.6,1.,1.,1.,1.,1.,1.,1.,1.,1.,1.,"
    "0.,0.,0.,1.,2.,0.,2.,-1.,1.,3.,1.,0.,4.,0.,2.,5.,2.,1.,0.25,0.75,0.,0.,1.;";

static void curve_subrange(void)
{
    const entity e[] = {{126, 0, 0, NULL, cubic_params}};
    char *text = format_iges(e, 1, NULL, ',');
    projcurve_model *m = read_text(text);
    if (m) {
        curve_data d;
        fetch(projcurve_model_curve(m, 0), &d);
        double t0, t1;
        domain(&d, &t0, &t1);
        CHECK_NEAR(t0, 0.25, 0.0);
        CHECK_NEAR(t1, 0.75, 0.0);
        /* Compare with the full curve evaluated here. */
        const curve_data full = {.p = 3, .n = 6,
                                 .ctrl = {0, 0, 0, 1, 2, 0, 2, -1, 1, 3, 1, 0, 4, 0, 2, 5, 2, 1},
                                 .w = {1, 1, 1, 1, 1, 1},
                                 .u = {0, 0, 0, 0, 0.4, 0.6, 1, 1, 1, 1}};
        for (int s = 0; s <= 20; ++s) {
            const double t = 0.25 + 0.5 * s / 20.0;
            double a[3], b[3];
            eval(&d, t, a);
            eval(&full, t, b);
            check_point(a, b[0], b[1], b[2], 1e-14);
        }
        projcurve_model_destroy(m);
    }
    free(text);
}

static void composite(void)
{
    /* Line (0,0,0)-(2,0,0), quarter arc centre (2,1) radius 1 from (2,0) to
     * (3,1), then the line (3,1,0)-(3,4,0); members physically dependent. */
    const entity e[] = {
        {102, 0, 0, NULL, "3,3,5,7;"},
        {110, 0, 0, "00010000", "0.,0.,0.,2.,0.,0.;"},
        {100, 0, 0, "00010000", "0.,2.,1.,2.,0.,3.,1.;"},
        {110, 0, 0, "00010000", "3.,1.,0.,3.,4.,0.;"},
    };
    char *text = format_iges(e, 4, NULL, ',');
    projcurve_model *m = read_text(text);
    if (m) {
        CHECK(projcurve_model_curve_count(m) == 1);
        CHECK(projcurve_model_skipped_count(m) == 0);
        curve_data d;
        fetch(projcurve_model_curve(m, 0), &d);
        CHECK(d.p == 2);
        double t0, t1, p[3];
        domain(&d, &t0, &t1);
        CHECK_NEAR(t1 - t0, 2.0 + PI / 2 + 3.0, 1e-12); /* each part keeps its length */
        eval(&d, t0, p);
        check_point(p, 0, 0, 0, TIGHT);
        eval(&d, t0 + 2.0, p);
        check_point(p, 2, 0, 0, TIGHT);
        eval(&d, t0 + 2.0 + PI / 4, p);
        check_point(p, 2 + sqrt(0.5), 1 - sqrt(0.5), 0, TIGHT);
        eval(&d, t0 + 2.0 + PI / 2, p);
        check_point(p, 3, 1, 0, TIGHT);
        eval(&d, t1, p);
        check_point(p, 3, 4, 0, TIGHT);
        /* The line parts stay straight after degree elevation. */
        eval(&d, t0 + 1.0, p);
        check_point(p, 1, 0, 0, TIGHT);
        projcurve_model_destroy(m);
    }
    free(text);
    /* A gap between members: the composite is skipped with the reason. */
    const entity gap[] = {
        {102, 0, 0, NULL, "2,3,5;"},
        {110, 0, 0, "00010000", "0.,0.,0.,2.,0.,0.;"},
        {110, 0, 0, "00010000", "2.5,0.,0.,3.,4.,0.;"},
    };
    text = format_iges(gap, 3, NULL, ',');
    m = read_text(text);
    if (m) {
        CHECK(projcurve_model_curve_count(m) == 0);
        CHECK(projcurve_model_skipped_count(m) == 3);
        CHECK(strstr(projcurve_model_skipped(m, 0), "do not connect") != NULL);
        projcurve_model_destroy(m);
    }
    free(text);
}

static void surface_with_chained_transforms(void)
{
    /* Bilinear patch; 124 at DE 3 translates by (1,0,0) and points at the
     * 124 at DE 5, a rotation by 90 degrees about z: x -> R (x + (1,0,0)). */
    const entity e[] = {
        {128, 0, 3, NULL,
         "1,1,1,1,0,0,1,0,0,0.,0.,1.,1.,0.,0.,1.,1.,1.,1.,1.,1.,"
         "0.,0.,0.,1.,0.,0.,0.,1.,0.,1.,1.,1.,0.,1.,0.,1.;"},
        {124, 0, 5, NULL, "1.,0.,0.,1.,0.,1.,0.,0.,0.,0.,1.,0.;"},
        {124, 0, 0, NULL, "0.,-1.,0.,0.,1.,0.,0.,0.,0.,0.,1.,0.;"},
    };
    char *text = format_iges(e, 3, NULL, ',');
    projcurve_model *m = read_text(text);
    if (m) {
        CHECK(projcurve_model_surface_count(m) == 1);
        double p[3];
        /* Corner (0,0,0) -> (1,0,0) -> (0,1,0); corner (1,1,1) -> (2,1,1) -> (-1,2,1). */
        CHECK_OK(projcurve_surface_eval(ctx, projcurve_model_surface(m, 0), 0.0, 0.0, 0, p));
        check_point(p, 0, 1, 0, TIGHT);
        CHECK_OK(projcurve_surface_eval(ctx, projcurve_model_surface(m, 0), 1.0, 1.0, 0, p));
        check_point(p, -1, 2, 1, TIGHT);
        projcurve_model_destroy(m);
    }
    free(text);
    /* A cycle of matrices is refused. */
    const entity cycle[] = {
        {110, 0, 3, NULL, "0.,0.,0.,3.,4.,0.;"},
        {124, 0, 5, NULL, "1.,0.,0.,1.,0.,1.,0.,0.,0.,0.,1.,0.;"},
        {124, 0, 3, NULL, "1.,0.,0.,1.,0.,1.,0.,0.,0.,0.,1.,0.;"},
    };
    text = format_iges(cycle, 3, NULL, ',');
    projcurve_model *bad = NULL;
    CHECK_STATUS(projcurve_model_read_memory(ctx, text, strlen(text), &bad), PROJCURVE_ERR_PARSE);
    CHECK(strstr(projcurve_context_message(ctx), "chained") != NULL);
    CHECK(bad == NULL);
    free(text);
}

/* Rational tensor-product point by the same Cox-de Boor basis. */
static void eval_surface(int pu, int pv, size_t nu, size_t nv, const double *ctrl,
                         const double *w, const double *ku, const double *kv, double u, double v,
                         double out[3])
{
    double num[3] = {0, 0, 0}, den = 0.0;
    for (size_t j = 0; j < nv; ++j)
        for (size_t i = 0; i < nu; ++i) {
            const double b = basis(ku, (int)i, pu, u, ku[nu]) * basis(kv, (int)j, pv, v, kv[nv]) *
                             w[j * nu + i];
            for (int k = 0; k < 3; ++k)
                num[k] += b * ctrl[3 * (j * nu + i) + (size_t)k];
            den += b;
        }
    for (int k = 0; k < 3; ++k)
        out[k] = num[k] / den;
}

static void surface_subdomain(void)
{
    /* Degree (2, 1), 4 x 2 net, varying weights; U0..U1 = [0.2, 0.9],
     * V0..V1 = [0.25, 0.75] inside the knot domain [0, 1]^2. */
    static const double ku[] = {0, 0, 0, 0.5, 1, 1, 1}, kv[] = {0, 0, 1, 1};
    static const double w[] = {1, 0.5, 2, 1, 1.5, 1, 0.7, 1};
    static const double ctrl[] = {0, 0, 0, 1, 0, 1, 2, 0, -1, 3, 0, 0,
                                  0, 2, 1, 1, 2, 2, 2, 2, 0, 3, 2, 1};
    char params[2048];
    size_t n = (size_t)snprintf(params, sizeof params, "3,1,2,1,0,0,0,0,0,");
    for (size_t i = 0; i < 7; ++i)
        n += (size_t)snprintf(params + n, sizeof params - n, "%.17g,", ku[i]);
    for (size_t i = 0; i < 4; ++i)
        n += (size_t)snprintf(params + n, sizeof params - n, "%.17g,", kv[i]);
    for (size_t i = 0; i < 8; ++i)
        n += (size_t)snprintf(params + n, sizeof params - n, "%.17g,", w[i]);
    for (size_t i = 0; i < 24; ++i)
        n += (size_t)snprintf(params + n, sizeof params - n, "%.17g,", ctrl[i]);
    snprintf(params + n, sizeof params - n, "0.2,0.9,0.25,0.75;");
    const entity e[] = {{128, 0, 0, NULL, params}};
    char *text = format_iges(e, 1, NULL, ',');
    projcurve_model *m = read_text(text);
    if (m) {
        const projcurve_surface *s = projcurve_model_surface(m, 0);
        double d[4];
        CHECK_OK(projcurve_surface_domain(ctx, s, d));
        CHECK_NEAR(d[0], 0.2, 0.0);
        CHECK_NEAR(d[1], 0.9, 0.0);
        CHECK_NEAR(d[2], 0.25, 0.0);
        CHECK_NEAR(d[3], 0.75, 0.0);
        for (int i = 0; i <= 7; ++i)
            for (int j = 0; j <= 5; ++j) {
                const double u = 0.2 + 0.7 * i / 7.0, v = 0.25 + 0.5 * j / 5.0;
                double p[3], q[3];
                CHECK_OK(projcurve_surface_eval(ctx, s, u, v, 0, p));
                eval_surface(2, 1, 4, 2, ctrl, w, ku, kv, u, v, q);
                check_point(p, q[0], q[1], q[2], TIGHT);
            }
        projcurve_model_destroy(m);
    }
    free(text);
}

static void skipped_entities(void)
{
    const entity e[] = {
        {126, 0, 0, "00000500", cubic_params},      /* parameter space */
        {110, 1, 0, NULL, "0.,0.,0.,1.,0.,0.;"},    /* a ray: unbounded */
        {144, 0, 0, NULL, "1,1,0,3;"},              /* trimmed surface */
        {102, 0, 0, NULL, "1,9;"},                  /* a composite inside a composite */
        {102, 0, 0, "00010000", "1,3;"},
    };
    char *text = format_iges(e, 5, NULL, ',');
    projcurve_model *m = read_text(text);
    if (m) {
        CHECK(projcurve_model_curve_count(m) == 0);
        CHECK(projcurve_model_skipped_count(m) == 5);
        const char *expect[] = {"126 at DE 1 (a curve in parameter space)",
                                "110 at DE 3 (unbounded", "IGES entity 144 at DE 5",
                                "102 at DE 7 (a composite curve inside",
                                "102 at DE 9 (a part of another entity)"};
        /* Skips found while reading come first, the rest in DE order. */
        for (size_t k = 0; k < 5; ++k) {
            int found = 0;
            for (size_t i = 0; i < projcurve_model_skipped_count(m); ++i)
                found |= strstr(projcurve_model_skipped(m, i), expect[k]) != NULL;
            if (!found)
                pc_test_fail_at(__FILE__, __LINE__, "no skipped entry \"%s\"", expect[k]);
            ++pc_test_checks;
        }
        projcurve_model_destroy(m);
    }
    free(text);
}

/* 144 trimmed surfaces on one bilinear 128: the natural boundary (N1 = 0)
 * is a face; an outer 142 without parameter-space curve (BPTR 0) and an
 * outer boundary that points at no entity are listed with the reason,
 * naming the 144, and do not stop the file. */
static void trimmed_surfaces(void)
{
    static const char plane[] = "1,1,1,1,0,0,1,0,0,0.,0.,1.,1.,0.,0.,1.,1.,1.,1.,1.,1.,"
                                "0.,0.,0.,1.,0.,0.,0.,1.,0.,1.,1.,0.,0.,1.,0.,1.;";
    const entity e[] = {
        {128, 0, 0, "00010000", plane},
        {144, 0, 0, NULL, "1,0,0,0;"},
        {142, 0, 0, "00010000", "0,1,0,0,1;"},
        {144, 0, 0, NULL, "1,1,0,5;"},
        {144, 0, 0, NULL, "1,1,0,99;"},
    };
    char *text = format_iges(e, 5, NULL, ',');
    projcurve_model *m = read_text(text);
    if (m) {
        CHECK(projcurve_model_face_count(m) == 1);
        CHECK(projcurve_model_unbuilt_face_count(m) == 2);
        CHECK(projcurve_face_loop_count(projcurve_model_face(m, 0)) == 1);
        const char *expect[] = {"IGES entity 144 at DE 7: its curve on surface DE 5 has no "
                                "parameter-space curve",
                                "IGES entity 144 at DE 9"};
        for (size_t k = 0; k < 2; ++k) {
            const char *why = projcurve_model_unbuilt_face(m, k);
            if (why == NULL || strstr(why, expect[k]) == NULL)
                pc_test_fail_at(__FILE__, __LINE__, "unbuilt face %zu: \"%s\", expected \"%s\"", k,
                                why ? why : "(none)", expect[k]);
            ++pc_test_checks;
        }
        const char *why = projcurve_model_unbuilt_face(m, 1);
        CHECK(why != NULL && strstr(why, "99") != NULL);
        projcurve_where w;
        CHECK_OK(projcurve_face_classify(ctx, projcurve_model_face(m, 0), 0.5, 0.5, &w));
        CHECK(w == PROJCURVE_IN);
        projcurve_model_destroy(m);
    }
    free(text);
}

/* A 143 bounded surface: one 141 boundary whose parameter-space curve is
 * a closed degree-1 126 around [0.25, 0.75]^2 of a bilinear 128. */
static void bounded_surface(void)
{
    static const char plane[] = "1,1,1,1,0,0,1,0,0,0.,0.,1.,1.,0.,0.,1.,1.,1.,1.,1.,1.,"
                                "0.,0.,0.,1.,0.,0.,0.,1.,0.,1.,1.,0.,0.,1.,0.,1.;";
    static const char square[] = "4,1,0,0,1,0,0.,0.,1.,2.,3.,4.,4.,1.,1.,1.,1.,1.,"
                                 "0.25,0.25,0.,0.75,0.25,0.,0.75,0.75,0.,0.25,0.75,0.,"
                                 "0.25,0.25,0.,0.,4.,0.,0.,1.;";
    const entity e[] = {
        {128, 0, 0, "00010000", plane},
        {126, 0, 0, "00010500", square},
        {141, 0, 0, "00010000", "1,1,1,1,3,1,1,3;"},
        {143, 0, 0, NULL, "1,1,1,5;"},
    };
    char *text = format_iges(e, 4, NULL, ',');
    projcurve_model *m = read_text(text);
    if (m) {
        CHECK(projcurve_model_face_count(m) == 1);
        CHECK(projcurve_model_unbuilt_face_count(m) == 0);
        const projcurve_face *f = projcurve_model_face(m, 0);
        CHECK(projcurve_face_loop_count(f) == 1);
        const double pts[3][2] = {{0.5, 0.5}, {0.1, 0.1}, {0.25, 0.5}};
        const projcurve_where want[3] = {PROJCURVE_IN, PROJCURVE_OUT, PROJCURVE_ON};
        for (int k = 0; k < 3; ++k) {
            projcurve_where w = PROJCURVE_OUT;
            CHECK_OK(projcurve_face_classify(ctx, f, pts[k][0], pts[k][1], &w));
            CHECK(w == want[k]);
        }
        projcurve_model_destroy(m);
    }
    free(text);
}

static void custom_delimiters(void)
{
    /* Parameter delimiter '/', record delimiter '!'; a Hollerith string
     * holding both must not split fields. */
    const entity e[] = {{110, 0, 0, NULL, "0./0./0./3./4./0./0/0/4Ha/!b!"}};
    char *text = format_iges(e, 1, "1H/,1H!,4Ht/!x,8Htest.igs,,,32,308,15,308,15,,1.,2,2HMM!", '/');
    /* The G section above keeps ',' after the delimiters as IGES requires
     * the new one: rewrite it with '/' throughout. */
    char *g = strstr(text, "1H/,1H!,");
    if (g != NULL) {
        g[3] = '/';
        g[7] = '/';
        for (char *q = g + 8; *q && *q != 'G'; ++q)
            if (*q == ',')
                *q = '/';
    }
    projcurve_model *m = read_text(text);
    if (m) {
        CHECK(projcurve_model_curve_count(m) == 1);
        projcurve_model_destroy(m);
    }
    free(text);
}

int main(void)
{
    CHECK_OK(projcurve_context_create(PROJCURVE_VERSION_MAJOR, &ctx));
    line_with_translation();
    arcs();
    curve_subrange();
    composite();
    surface_with_chained_transforms();
    surface_subdomain();
    skipped_entities();
    custom_delimiters();
    trimmed_surfaces();
    bounded_surface();
    projcurve_context_destroy(ctx);
    return pc_test_finish("test_io_iges_entities");
}
