/*
 * Public IGES writer: surfaces (128), curves (126) and projection results,
 * each composed branch as its 3D curve (126), its (u, v) pcurve (126 in the
 * plane z = 0: of degree 1 through the refined polyline, or, with cubic
 * pcurves (PROJCURVE_OPT_PCURVE_DEGREE 3), the pieces' cubics) and a curve on
 * surface (142, "projection of a curve onto the surface") tying them to the
 * surface. A surface is written once however often it is added (entities
 * are compared by their parameter text, i.e. exactly).
 */
#include <stdlib.h>
#include <string.h>

#include "api/handles.h"
#include "common/error.h"
#include "io/iges_write.h"

#define PC_IGES_CURVE_ON_SURFACE 142
#define PC_IGES_COS_PROJECTION 1 /* CRTN: created as a projection */
#define PC_IGES_COS_PREFER_3D 2  /* PREF: the 3D curve is exact, the pcurve a polyline */
#define PC_IGES_COS_PREFER_2D 1

struct projcurve_iges_writer {
    pc_iges_out out;
};

projcurve_status projcurve_iges_writer_create(projcurve_context *ctx,
                                              projcurve_iges_writer **out)
{
    PC_REQUIRE(ctx, out, "out");
    projcurve_iges_writer *w = calloc(1, sizeof *w);
    if (w == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory creating an IGES writer");
    *out = w;
    return PROJCURVE_OK;
}

void projcurve_iges_writer_destroy(projcurve_iges_writer *writer)
{
    if (writer == NULL)
        return;
    pc_iges_out_free(&writer->out);
    free(writer);
}

/* Adds entity 128 unless an identical one is there; *de gets its pointer. */
static projcurve_status add_surface(projcurve_context *ctx, projcurve_iges_writer *w,
                                    const projcurve_surface *s, size_t *de)
{
    pc_text_buf b = {0};
    pc_iges_format_surface(&b, &s->nurbs);
    if (b.failed) {
        free(b.text);
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory formatting a surface");
    }
    for (size_t i = 0; i < w->out.count; ++i)
        if (w->out.entities[i].type == 128 && strcmp(w->out.entities[i].params, b.text) == 0) {
            free(b.text);
            *de = 2 * i + 1;
            return PROJCURVE_OK;
        }
    const projcurve_status st =
        pc_iges_out_add(ctx, &w->out, 128, 0, PC_IGES_STATUS_INDEPENDENT, &b, de);
    free(b.text);
    return st;
}

projcurve_status projcurve_iges_writer_add_surface(projcurve_context *ctx,
                                                   projcurve_iges_writer *w,
                                                   const projcurve_surface *s)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, s, "surface");
    size_t de;
    return add_surface(ctx, w, s, &de);
}

static projcurve_status add_curve(projcurve_context *ctx, projcurve_iges_writer *w,
                                  const projcurve_curve *c, const char *status, size_t *de)
{
    if (c->kind != PC_CURVE_NURBS)
        return pc_fail(ctx, PROJCURVE_ERR_WRONG_KIND,
                       "a callback curve has no NURBS form to write");
    pc_text_buf b = {0};
    pc_iges_format_curve(&b, &c->nurbs, 0);
    const projcurve_status st = pc_iges_out_add(ctx, &w->out, 126, 0, status, &b, de);
    free(b.text);
    return st;
}

projcurve_status projcurve_iges_writer_add_curve(projcurve_context *ctx,
                                                 projcurve_iges_writer *w,
                                                 const projcurve_curve *c)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, c, "curve");
    size_t de;
    return add_curve(ctx, w, c, PC_IGES_STATUS_INDEPENDENT, &de);
}

/* The branch's traced (u, v) points as a degree-1 pcurve in z = 0,
 * parametrised by the curve parameter t (repeated t values dropped). */
static projcurve_status add_pcurve(projcurve_context *ctx, projcurve_iges_writer *w,
                                   const projcurve_result *r, size_t branch, size_t *de)
{
    size_t n = 0;
    double probe[3];
    projcurve_status st = projcurve_result_branch_points(ctx, r, branch, 0, probe, &n);
    if (st != PROJCURVE_OK)
        return st;
    if (n < 2) {
        *de = 0;
        return PROJCURVE_OK;
    }
    double *tuv = malloc(3 * n * sizeof *tuv);
    double *xyz = malloc(3 * n * sizeof *xyz);
    double *t = malloc(n * sizeof *t);
    if (tuv == NULL || xyz == NULL || t == NULL) {
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory writing a pcurve");
        goto cleanup;
    }
    size_t got = 0;
    if ((st = projcurve_result_branch_points(ctx, r, branch, n, tuv, &got)) != PROJCURVE_OK)
        goto cleanup;
    /* Branches may be traced with t decreasing: keep t increasing. */
    const int reversed = tuv[0] > tuv[3 * (got - 1)];
    size_t m = 0;
    for (size_t k = 0; k < got; ++k) {
        const size_t i = reversed ? got - 1 - k : k;
        if (m > 0 && !(tuv[3 * i] > t[m - 1]))
            continue;
        t[m] = tuv[3 * i];
        xyz[3 * m] = tuv[3 * i + 1];
        xyz[3 * m + 1] = tuv[3 * i + 2];
        xyz[3 * m + 2] = 0.0;
        ++m;
    }
    *de = 0;
    if (m >= 2) {
        pc_text_buf b = {0};
        pc_iges_format_polyline(&b, xyz, t, m, 1);
        st = pc_iges_out_add(ctx, &w->out, 126, 0, PC_IGES_STATUS_PARAMETRIC_PART, &b, de);
        free(b.text);
    }
cleanup:
    free(tuv);
    free(xyz);
    free(t);
    return st;
}

/* Piece k's pcurve as 4 cubic Bezier control points (u, v) and its t range,
 * both towards increasing t (a straight pcurve raised to degree 3). */
static projcurve_status cubic_pcurve(projcurve_context *ctx, const projcurve_result *r,
                                     size_t branch, size_t k, double uv[8], double range[2])
{
    int degree = 0;
    double ctrl[2 * PROJCURVE_MAX_PCURVE_POINTS];
    projcurve_status st = projcurve_result_piece_pcurve(ctx, r, branch, k, &degree, ctrl);
    if (st == PROJCURVE_OK)
        st = projcurve_result_piece(ctx, r, branch, k, NULL, NULL, NULL, range, NULL);
    if (st != PROJCURVE_OK)
        return st;
    for (int i = 0; i < 4; ++i)
        for (int c = 0; c < 2; ++c) /* degree 1: P0, (2 P0 + P1) / 3, (P0 + 2 P1) / 3, P1 */
            uv[2 * i + c] = degree == 3 ? ctrl[2 * i + c]
                                        : ((3 - i) * ctrl[c] + i * ctrl[2 + c]) / 3.0;
    if (range[0] > range[1]) { /* a branch traced towards decreasing t */
        for (int i = 0; i < 2; ++i)
            for (int c = 0; c < 2; ++c) {
                const double x = uv[2 * i + c];
                uv[2 * i + c] = uv[2 * (3 - i) + c];
                uv[2 * (3 - i) + c] = x;
            }
        const double t = range[0];
        range[0] = range[1];
        range[1] = t;
    }
    return PROJCURVE_OK;
}

/* 1 when some piece of the branch has a cubic pcurve. */
static int has_cubic_pcurve(const projcurve_result *r, size_t branch, size_t n_pieces)
{
    for (size_t k = 0; k < n_pieces; ++k) {
        int degree = 1;
        if (projcurve_result_piece_pcurve(NULL, r, branch, k, &degree, NULL) == PROJCURVE_OK &&
            degree == 3)
            return 1;
    }
    return 0;
}

/* The pieces' pcurves (PROJCURVE_OPT_PCURVE_DEGREE 3) as one cubic B-spline
 * in z = 0 parametrised by t, knots of multiplicity 3 at the joins: exactly
 * the pieces' (u, v) curves, the 2D side of the 142. */
static projcurve_status add_cubic_pcurve(projcurve_context *ctx, projcurve_iges_writer *w,
                                         const projcurve_result *r, size_t branch, size_t np,
                                         size_t *de)
{
    const size_t n_ctrl = 3 * np + 1;
    double first[2], last[2];
    projcurve_status st = projcurve_result_piece(ctx, r, branch, 0, NULL, NULL, NULL, first, NULL);
    if (st == PROJCURVE_OK)
        st = projcurve_result_piece(ctx, r, branch, np - 1, NULL, NULL, NULL, last, NULL);
    if (st != PROJCURVE_OK)
        return st;
    const int descending = first[0] > last[1];
    double *cw = malloc(4 * n_ctrl * sizeof *cw);
    double *knots = malloc((n_ctrl + 4) * sizeof *knots);
    if (cw == NULL || knots == NULL) {
        st = pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory writing a pcurve");
        goto cleanup;
    }
    double range[2] = {0.0, 0.0};
    for (size_t i = 0; i < np && st == PROJCURVE_OK; ++i) {
        double uv[8];
        st = cubic_pcurve(ctx, r, branch, descending ? np - 1 - i : i, uv, range);
        for (size_t j = (i == 0 ? 0 : 1); j < 4; ++j) {
            double *c = cw + 4 * (3 * i + j);
            c[0] = uv[2 * j];
            c[1] = uv[2 * j + 1];
            c[2] = 0.0;
            c[3] = 1.0;
        }
        for (size_t j = 0; j < (i == 0 ? 4 : 3); ++j)
            knots[(i == 0 ? 0 : 3 * i + 1) + j] = range[0];
    }
    if (st != PROJCURVE_OK)
        goto cleanup;
    for (size_t j = 0; j < 4; ++j)
        knots[n_ctrl + j] = range[1];
    const pc_nurbs_curve c = {3, n_ctrl, knots, cw, 0, knots[0], range[1], NULL};
    pc_text_buf b = {0};
    pc_iges_format_curve(&b, &c, 1);
    st = pc_iges_out_add(ctx, &w->out, 126, 0, PC_IGES_STATUS_PARAMETRIC_PART, &b, de);
    free(b.text);
cleanup:
    free(cw);
    free(knots);
    return st;
}

static projcurve_status add_branch(projcurve_context *ctx, projcurve_iges_writer *w,
                                   size_t surface_de, const projcurve_result *r, size_t branch)
{
    size_t pcurve_de = 0, curve_de = 0, n_pieces = 0;
    projcurve_status st =
        projcurve_result_branch_info(ctx, r, branch, NULL, NULL, NULL, NULL, &n_pieces);
    if (st != PROJCURVE_OK)
        return st;
    st = has_cubic_pcurve(r, branch, n_pieces)
             ? add_cubic_pcurve(ctx, w, r, branch, n_pieces, &pcurve_de)
             : add_pcurve(ctx, w, r, branch, &pcurve_de);
    if (st != PROJCURVE_OK)
        return st;
    projcurve_curve *c = NULL;
    st = projcurve_result_branch_curve(ctx, r, branch, &c);
    if (st == PROJCURVE_OK) {
        st = add_curve(ctx, w, c, PC_IGES_STATUS_PART, &curve_de);
        projcurve_curve_destroy(c);
    } else if (st == PROJCURVE_ERR_INVALID_ARGUMENT) {
        st = PROJCURVE_OK; /* not composed: the pcurve alone describes it */
    }
    if (st != PROJCURVE_OK || (pcurve_de == 0 && curve_de == 0))
        return st;
    pc_text_buf b = {0};
    pc_text_buf_int(&b, PC_IGES_COS_PROJECTION);
    pc_text_buf_int(&b, (long long)surface_de);
    pc_text_buf_int(&b, (long long)pcurve_de);
    pc_text_buf_int(&b, (long long)curve_de);
    pc_text_buf_int(&b, curve_de ? PC_IGES_COS_PREFER_3D : PC_IGES_COS_PREFER_2D);
    pc_text_buf_end(&b);
    size_t de;
    st = pc_iges_out_add(ctx, &w->out, PC_IGES_CURVE_ON_SURFACE, 0, PC_IGES_STATUS_INDEPENDENT, &b,
                         &de);
    free(b.text);
    return st;
}

projcurve_status projcurve_iges_writer_add_result(projcurve_context *ctx,
                                                  projcurve_iges_writer *w,
                                                  const projcurve_surface *s,
                                                  const projcurve_result *r)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, s, "surface");
    PC_REQUIRE(ctx, r, "result");
    if (projcurve_result_point_dim(r) != 3)
        return pc_fail(ctx, PROJCURVE_ERR_INVALID_ARGUMENT,
                       "the result is not on a parametric surface (implicit projection)");
    size_t surface_de;
    projcurve_status st = add_surface(ctx, w, s, &surface_de);
    const size_t n = projcurve_result_branch_count(r);
    for (size_t b = 0; st == PROJCURVE_OK && b < n; ++b)
        st = add_branch(ctx, w, surface_de, r, b);
    return st;
}

projcurve_status projcurve_iges_writer_write(projcurve_context *ctx,
                                             const projcurve_iges_writer *w, const char *path)
{
    PC_REQUIRE(ctx, w, "writer");
    PC_REQUIRE(ctx, path, "path");
    return pc_iges_out_write(ctx, &w->out, path);
}
