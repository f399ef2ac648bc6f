/* SPDX-License-Identifier: BSD-3-Clause */
/*
 * G+Smo XML geometry: <Geometry type="TensorBSpline2"> (or TensorNurbs2)
 * holding two <KnotVector degree="p"> (u then v), <coefs geoDim="3"> with
 * one control point per row, u index fastest, and for NURBS <weights> (not
 * premultiplied). Curves: type="BSpline" / "Nurbs" with one knot vector.
 * The reader scans for these elements only; it is not a general XML parser
 * (entities, CDATA and comments inside them are not expected).
 */
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#include "common/error.h"
#include "io/io_model.h"
#include "io/io_text.h"

#define PC_GISMO_MAX_TYPE 48
#define PC_GISMO_MAX_KNOT_VECTORS 2

typedef struct gismo_span {
    size_t begin, end; /* [begin, end) of an element's content */
} gismo_span;

/* Next occurrence of needle in s[from, to), or `to`. */
static size_t find(const char *s, size_t from, size_t to, const char *needle)
{
    const size_t n = strlen(needle);
    for (size_t i = from; i + n <= to; ++i)
        if (s[i] == needle[0] && memcmp(s + i, needle, n) == 0)
            return i;
    return to;
}

/* Value of attribute `name` in the tag starting at s[tag] (up to '>'),
 * copied into out; 0 when absent. */
static int attribute(const char *s, size_t tag, size_t to, const char *name, char *out,
                     size_t cap)
{
    const size_t close = find(s, tag, to, ">");
    /* XML allows either quote around attribute values. */
    char pattern[32];
    snprintf(pattern, sizeof pattern, " %s=\"", name);
    size_t at = find(s, tag, close, pattern);
    if (at >= close) {
        snprintf(pattern, sizeof pattern, " %s='", name);
        at = find(s, tag, close, pattern);
    }
    if (at >= close)
        return 0;
    const size_t v = at + strlen(pattern);
    const char quote[2] = {pattern[strlen(pattern) - 1], '\0'};
    const size_t q = find(s, v, close, quote);
    if (q >= close || q - v >= cap)
        return 0;
    memcpy(out, s + v, q - v);
    out[q - v] = '\0';
    return 1;
}

/* Start of the first tag <name ...> in [from, to), or `to`. */
static size_t opening(const char *s, size_t from, size_t to, const char *name)
{
    char open[32];
    snprintf(open, sizeof open, "<%s", name);
    for (size_t t = find(s, from, to, open); t < to; t = find(s, t + 1, to, open)) {
        const char next = s[t + strlen(open)]; /* s[to] is the terminating NUL */
        if (next == ' ' || next == '>' || next == '\t' || next == '\n' || next == '\r')
            return t;
    }
    return to;
}

/* Content span of the first <name ...>...</name> in [from, to). */
static int element(const char *s, size_t from, size_t to, const char *name, size_t *tag,
                   gismo_span *content)
{
    char close[32];
    snprintf(close, sizeof close, "</%s>", name);
    const size_t t = opening(s, from, to, name);
    if (t >= to)
        return 0;
    const size_t gt = find(s, t, to, ">");
    if (gt >= to)
        return 0;
    const size_t end = find(s, gt + 1, to, close);
    if (end >= to)
        return 0;
    *tag = t;
    content->begin = gt + 1;
    content->end = end;
    return 1;
}

/* The whitespace-separated reals of a span, in the arena. */
static projcurve_status numbers(projcurve_context *ctx, pc_arena *arena, pc_text_cursor *cur,
                                const gismo_span *sp, const char *what, double **out,
                                size_t *n_out)
{
    static const char space[] = " \t\r\n";
    size_t n = 0;
    for (size_t i = sp->begin; i < sp->end; ++i)
        n += (strchr(space, cur->s[i]) == NULL) &&
             (i == sp->begin || strchr(space, cur->s[i - 1]) != NULL);
    double *v = pc_arena_calloc(arena, n + 1, sizeof *v);
    if (v == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading G+Smo %s", what);
    pc_text_seek(cur, sp->begin);
    for (size_t k = 0; k < n; ++k) {
        pc_text_skip(cur, space);
        const size_t used = pc_text_parse_real(cur->s + cur->pos, sp->end - cur->pos, &v[k]);
        if (used == 0 || (cur->pos + used < sp->end && strchr(space, cur->s[cur->pos + used]) == NULL))
            return pc_fail(ctx, PROJCURVE_ERR_PARSE, "G+Smo line %zu: a %s value is not a number",
                           cur->line, what);
        pc_text_seek(cur, cur->pos + used);
    }
    *out = v;
    *n_out = n;
    return PROJCURVE_OK;
}

typedef struct gismo_geometry {
    int dim; /* parametric dimension: 1 curve, 2 surface */
    int rational;
    int degree[PC_GISMO_MAX_KNOT_VECTORS];
    double *knots[PC_GISMO_MAX_KNOT_VECTORS];
    size_t n_knots[PC_GISMO_MAX_KNOT_VECTORS];
    double *coefs, *weights;
    size_t n_coefs, n_weights;
    long geo_dim;
} gismo_geometry;

static projcurve_status parse_parts(projcurve_context *ctx, pc_arena *arena, pc_text_cursor *cur,
                                    size_t from, size_t to, size_t line, gismo_geometry *g)
{
    size_t pos = from;
    for (int k = 0; k < g->dim; ++k) {
        size_t tag;
        gismo_span sp;
        char deg[16];
        if (!element(cur->s, pos, to, "KnotVector", &tag, &sp) ||
            !attribute(cur->s, tag, to, "degree", deg, sizeof deg))
            return pc_fail(ctx, PROJCURVE_ERR_PARSE,
                           "G+Smo geometry at line %zu: knot vector %d with a degree is missing",
                           line, k + 1);
        char *end = NULL;
        const long d = strtol(deg, &end, 10);
        if (*end != '\0' || d < 1 || d > PROJCURVE_MAX_DEGREE)
            return pc_fail(ctx, PROJCURVE_ERR_PARSE,
                           "G+Smo geometry at line %zu: knot vector degree \"%s\" is not in 1..%d",
                           line, deg, PROJCURVE_MAX_DEGREE);
        g->degree[k] = (int)d;
        projcurve_status st = numbers(ctx, arena, cur, &sp, "knot", &g->knots[k], &g->n_knots[k]);
        if (st != PROJCURVE_OK)
            return st;
        pos = sp.end;
    }
    size_t tag;
    gismo_span sp;
    char gd[16] = "3";
    if (!element(cur->s, from, to, "coefs", &tag, &sp))
        return pc_fail(ctx, PROJCURVE_ERR_PARSE, "G+Smo geometry at line %zu: no <coefs>", line);
    attribute(cur->s, tag, to, "geoDim", gd, sizeof gd);
    g->geo_dim = strtol(gd, NULL, 10);
    if (g->geo_dim < 1 || g->geo_dim > 3)
        return pc_fail(ctx, PROJCURVE_ERR_UNSUPPORTED,
                       "G+Smo geometry at line %zu: geoDim \"%s\" (1, 2 or 3 are read)", line, gd);
    projcurve_status st = numbers(ctx, arena, cur, &sp, "coefs", &g->coefs, &g->n_coefs);
    if (st != PROJCURVE_OK || !g->rational)
        return st;
    if (!element(cur->s, from, to, "weights", &tag, &sp))
        return pc_fail(ctx, PROJCURVE_ERR_PARSE, "G+Smo NURBS at line %zu: no <weights>", line);
    return numbers(ctx, arena, cur, &sp, "weights", &g->weights, &g->n_weights);
}

/* Control points as 3D (missing coordinates are 0). */
static double *points3(pc_arena *arena, const gismo_geometry *g, size_t n)
{
    double *p = pc_arena_calloc(arena, 3 * n + 1, sizeof *p);
    if (p != NULL)
        for (size_t i = 0; i < n; ++i)
            for (size_t d = 0; d < (size_t)g->geo_dim; ++d)
                p[3 * i + d] = g->coefs[i * (size_t)g->geo_dim + d];
    return p;
}

static projcurve_status build(projcurve_context *ctx, pc_arena *arena, projcurve_model *model,
                              const gismo_geometry *g, size_t line)
{
    size_t n[2] = {1, 1};
    for (int k = 0; k < g->dim; ++k) {
        if (g->n_knots[k] < (size_t)(2 * g->degree[k] + 2))
            return pc_fail(ctx, PROJCURVE_ERR_PARSE,
                           "G+Smo geometry at line %zu: knot vector %d has %zu knots, too few for "
                           "degree %d",
                           line, k + 1, g->n_knots[k], g->degree[k]);
        n[k] = g->n_knots[k] - (size_t)g->degree[k] - 1;
    }
    const size_t count = n[0] * n[1];
    if (g->n_coefs != count * (size_t)g->geo_dim || (g->rational && g->n_weights != count))
        return pc_fail(ctx, PROJCURVE_ERR_PARSE,
                       "G+Smo geometry at line %zu: %zu coefficients and %zu weights for %zu "
                       "control points of dimension %ld",
                       line, g->n_coefs, g->n_weights, count, g->geo_dim);
    double *ctrl = points3(arena, g, count);
    if (ctrl == NULL)
        return pc_fail(ctx, PROJCURVE_ERR_NO_MEMORY, "out of memory reading G+Smo");
    char origin[64];
    snprintf(origin, sizeof origin, "G+Smo geometry at line %zu", line);
    if (g->dim == 1) {
        const pc_io_curve c = {.degree = g->degree[0], .n_ctrl = n[0], .ctrl = ctrl,
                               .weights = g->rational ? g->weights : NULL, .knots = g->knots[0]};
        return pc_model_add_curve(ctx, model, &c, origin);
    }
    const pc_io_surface s = {.deg_u = g->degree[0], .deg_v = g->degree[1], .n_u = n[0],
                             .n_v = n[1], .ctrl = ctrl, .weights = g->rational ? g->weights : NULL,
                             .knots_u = g->knots[0], .knots_v = g->knots[1]};
    return pc_model_add_surface(ctx, model, &s, origin);
}

projcurve_status pc_gismo_read(projcurve_context *ctx, const char *data, size_t len,
                               projcurve_model *model)
{
    pc_text_cursor cur;
    pc_text_init(&cur, data, len);
    pc_arena arena;
    pc_arena_init(&arena, 1u << 16);
    projcurve_status st = PROJCURVE_OK;
    size_t pos = 0;
    size_t tag;
    gismo_span body;
    while (st == PROJCURVE_OK && element(data, pos, len, "Geometry", &tag, &body)) {
        pc_text_seek(&cur, tag);
        const size_t line = cur.line;
        char type[PC_GISMO_MAX_TYPE] = "";
        attribute(data, tag, len, "type", type, sizeof type);
        gismo_geometry g;
        memset(&g, 0, sizeof g);
        if (strcmp(type, "TensorBSpline2") == 0 || strcmp(type, "TensorNurbs2") == 0)
            g.dim = 2;
        else if (strcmp(type, "BSpline") == 0 || strcmp(type, "Nurbs") == 0)
            g.dim = 1;
        g.rational = strstr(type, "Nurbs") != NULL;
        if (g.dim == 0) {
            st = pc_model_add_skipped(ctx, model, "G+Smo Geometry type=\"%s\" at line %zu", type,
                                      line);
        } else {
            st = parse_parts(ctx, &arena, &cur, body.begin, body.end, line, &g);
            if (st == PROJCURVE_OK)
                st = build(ctx, &arena, model, &g, line);
        }
        pos = body.end;
        pc_arena_release(&arena);
    }
    /* A <Geometry> left open (a truncated file) is an error, not the end. */
    const size_t unclosed = st == PROJCURVE_OK ? opening(data, pos, len, "Geometry") : len;
    if (unclosed < len) {
        pc_text_seek(&cur, unclosed);
        st = pc_fail(ctx, PROJCURVE_ERR_PARSE,
                     "G+Smo XML line %zu: <Geometry> is not closed by </Geometry> (the file is "
                     "truncated?)",
                     cur.line);
    }
    if (st == PROJCURVE_OK && model->n_surfaces == 0 && model->n_curves == 0 &&
        model->n_skipped == 0)
        st = pc_fail(ctx, PROJCURVE_ERR_PARSE, "G+Smo XML: no <Geometry> element found");
    pc_arena_release(&arena);
    return st;
}
